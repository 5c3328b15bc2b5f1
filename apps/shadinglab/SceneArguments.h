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
  std::string backend; ///< "cpu", "gpu" or "auto"
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
  double readMs = 0;    ///< reading (and checking) the input file
  double prepareMs = 0; ///< the repair check, repair, conversion
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
 * The renderer for --backend: the GL renderer when asked or (auto) when an
 * X display with OpenGL >= 3.2 answers, else the CPU renderer. An auto
 * fallback is explained in `autoNotice`, which the caller prints after
 * success so that an error stays one line.
 */
std::unique_ptr<render::Renderer> MakeRenderer(
  const std::string& backend, const char* command, std::string& autoNotice);

/// Renders, turning the renderer's exceptions into UsageError.
const render::Image& RenderOrExplain(render::Renderer& renderer, const render::Scene& scene,
  const render::RenderOptions& options, render::RenderStats* stats, const std::string& context);

} // namespace shadinglab::cli
