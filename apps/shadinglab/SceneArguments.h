// SPDX-License-Identifier: BSD-3-Clause
// The one place a render request is built from the command line: options,
// material, mesh (read and prepared), camera and lights, then the backend.
// 'render' and 'compare' both start here.
#pragma once

#include "CliArgs.h"

#include "shadinglab/render/Renderer.h"
#include "shadinglab/render/ColorMap.h"
#include "shadinglab/render/Settings.h"

#include <memory>
#include <string>

namespace shadinglab::cli
{

/// Everything a render needs, parsed from the command line and the input file.
struct SceneArguments
{
  explicit SceneArguments(Arguments arguments)
    : args(std::move(arguments))
  {
  }
  Arguments args;
  bool helpShown = false;
  std::string input;
  render::Backend backend = render::Backend::Auto; ///< --backend
  /// A CPU-only feature asked for (--scan incremental), for the chooser.
  std::string cpuOnly;
  render::Mesh mesh;    ///< in `frame`'s local coordinates
  render::WorldFrame frame;
  render::Scene scene; ///< scene.mesh points at `mesh`
  /// Everything the settings table's flags set; settings.render has the
  /// image size too, settings.display the display transform.
  render::Settings settings;
  /// --color-by: the map (its range resolved) scene.colorMap points at, and
  /// the legend's title ("Elevation", "Velocity Magnitude").
  render::ColorMap colorMap;
  std::string colorTitle;
  std::string notices; ///< said after success (errors stay one line)
  /// Vertex normals were made for the input (none there, a smooth mode):
  /// --stats reports them as computed, as the renderers' own.
  bool normalsMade = false;
  double readMs = 0;    ///< reading (and checking) the input file
  double prepareMs = 0; ///< the repair check, repair, conversion
  double readPeakMb = 0, preparePeakMb = 0; ///< peak resident memory after each (PeakRssMb)
};

/// The options 'render' and 'compare' accept, in their --help.
std::string SceneOptionsHelp();

/**
 * Parses argv (after the command name). `extraValued` are further valued
 * options of the calling command. With --help prints `help` and the
 * material help and returns with helpShown set. Throws UsageError.
 */
std::unique_ptr<SceneArguments> SceneFromArguments(int argc, char** argv, const std::string& help,
  const std::vector<std::string>& extraValued = {});

/**
 * The renderer render::ChooseBackend takes for `scene`'s --backend, its
 * CPU-only features and `cpuOnly` (the command's own: a polarization
 * output), from what answers here (an X display with OpenGL >= 3.2, its
 * GL_RENDERER) and the mesh's size. Auto's choice of the CPU is explained in
 * `autoNotice`, which the caller prints after success so that an error stays
 * one line; a request that cannot be honoured is a UsageError.
 */
std::unique_ptr<render::Renderer> MakeRenderer(const SceneArguments& scene, std::string cpuOnly,
  const char* command, std::string& autoNotice);

/// Renders, turning the renderer's exceptions into UsageError.
const render::Image& RenderOrExplain(render::Renderer& renderer, const render::Scene& scene,
  const render::RenderOptions& options, render::RenderStats* stats, const std::string& context);

} // namespace shadinglab::cli
