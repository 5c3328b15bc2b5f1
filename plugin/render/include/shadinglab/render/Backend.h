// SPDX-License-Identifier: BSD-3-Clause
// Who draws the pixels: one enum and one chooser for every front end (the
// CLI's --backend, the explorer's, vtkShadingLabPolyDataMapper's and
// ParaView's Backend setting). A front end gathers the facts it has
// (BackendFacts) and asks ChooseBackend; none decides by itself.
#pragma once

#include <string>

namespace shadinglab::render
{

/// The settings table's "backend" choices, in its order (gpu, cpu, auto).
enum class Backend
{
  GPU, ///< plugin/gl: the GLSL shaders of the ShadingLab mapper (OpenGL >= 3.2)
  CPU, ///< plugin/cpu: the scanline software renderer (reference, no GL needed)
  /// CPU where OpenGL is missing, or is a software rasterizer (Mesa's
  /// llvmpipe, softpipe, swr) and the mesh is large enough for the CPU
  /// renderer to be faster (kAutoCpuMinPolygons); GPU otherwise.
  Auto
};

/// "gpu", "cpu" or "auto".
const char* BackendName(Backend backend);

/// Parses a backend name ("gpu", "cpu", "auto", any case) by the settings
/// table's row: "" or the table's one-line error.
std::string ParseBackend(const std::string& text, Backend& backend);

/// Auto's mesh size. On llvmpipe (bench/paraview_backends.py, pvbatch,
/// 1920x1080, 2 cores, median of 7 frames x 3 runs, docs/paraview.md) the
/// two backends tie at ~10,000 triangles (Phong 79 ms CPU, 76-83 ms GPU: the
/// CPU path's hand-over costs what llvmpipe saves) and the CPU is ahead from
/// ~30,000 on (31,680: Phong 76 against 84-88 ms, Cook-Torrance 79 against
/// 99) and further ahead the larger the mesh (996,000: 108 against 190).
inline constexpr long long kAutoCpuMinPolygons = 30000;

/// What a front end knows when it chooses.
struct BackendFacts
{
  /// Whether OpenGL >= 3.2 answers here, and if not why (a mapper drawing
  /// in a GL context leaves the default).
  bool glUsable = true;
  std::string glProblem;
  /// OpenGL's GL_RENDERER string ("" unknown: taken as hardware).
  std::string glRenderer;
  /// Polygons to draw.
  long long polygons = 0;
  /// A feature only the CPU renderer has (a polarization image, the
  /// incremental scan), named for the reason: "" none.
  std::string cpuOnly;
};

struct BackendChoice
{
  Backend backend = Backend::GPU; ///< GPU or CPU, never Auto
  /// Why, one line starting with the backend's name: "cpu: OpenGL renderer
  /// 'llvmpipe ...' is a software rasterizer, 996000 polygons >= 30000".
  std::string why;
  /// The request cannot be honoured as asked: GPU was asked for and a
  /// CPU-only feature is on (`backend` is then CPU), or OpenGL is not usable
  /// (`backend` is then CPU too). A command line refuses; a mapper draws on.
  std::string conflict;
};

/// The one chooser: a CPU-only feature takes the CPU; CPU and GPU are
/// honoured where they can be; Auto takes the CPU where OpenGL is missing or
/// a software rasterizer with at least kAutoCpuMinPolygons polygons.
BackendChoice ChooseBackend(Backend requested, const BackendFacts& facts);

/// Whether a GL_RENDERER string names a software rasterizer (Mesa's
/// llvmpipe, softpipe or swr).
bool IsSoftwareRasterizer(const std::string& glRenderer);

/// The GL_RENDERER string in VTK's capability report
/// (vtkRenderWindow::ReportCapabilities: "OpenGL renderer string:  NAME").
std::string GlRendererFromReport(const char* report);

} // namespace shadinglab::render
