// SPDX-License-Identifier: BSD-3-Clause
// The mapper's CPU backend: one vtkShadingLabPolyDataMapper's input drawn by
// the software renderer (plugin/cpu) for the renderer's viewport size,
// camera and lights, then handed to OpenGL as colour and depth
// (plugin/vtk/glsl/sl_cpu_handover_fs.glsl), so that other actors, annotations and
// compositing see an ordinary depth-tested surface.
#pragma once

#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/render/ColorMap.h"
#include "shadinglab/render/Settings.h"

#include <vtkNew.h>
#include <vtkTextureObject.h>
#include <vtkType.h>

#include <memory>
#include <vector>

class vtkActor;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkRenderer;
class vtkScalarsToColors;
class vtkWindow;

namespace shadinglab::vtk
{

/// What of the mapper the CPU draw needs besides its settings.
struct CpuDrawInputs
{
  vtkPolyData* polydata = nullptr;  ///< with the normals the mapper prepared
  const double* albedo = nullptr;   ///< rho without scalar colouring (RGB)
  /// Colour by data: the point or cell array's name and component (-1:
  /// magnitude) and the lookup table over its range; nullptr: no mapping.
  const char* scalarName = nullptr;
  bool scalarsOnCells = false;
  int scalarComponent = -1;
  vtkScalarsToColors* lookupTable = nullptr;
};

class CpuBackend
{
public:
  CpuBackend();
  ~CpuBackend();

  /// Renders and hands over; returns "" or a one-line reason the CPU could
  /// not draw (the caller then draws with OpenGL).
  std::string Draw(vtkRenderer* ren, const CpuDrawInputs& inputs, const render::Settings& settings);
  void ReleaseGraphicsResources(vtkWindow* window);
  /// The last frame's renderer statistics (times, counts).
  const render::RenderStats& LastStats() const { return this->Stats; }
  /// Milliseconds of the last hand-over (texture uploads and the quad).
  double LastHandOverMilliseconds() const { return this->HandOverMs; }
  /// Timing: finish OpenGL's work before and after the hand-over (glFinish),
  /// so that LastHandOverMilliseconds includes the quad's fragments, which a
  /// software rasterizer otherwise runs later in the frame. Off in use: it
  /// stalls the pipeline (the render benchmark turns it on).
  void SetFinishForTiming(bool finish) { this->FinishForTiming = finish; }
  /// Times the mesh was converted (a camera move does not convert it).
  int Conversions() const { return this->ConversionCount; }

private:
  /// The stages of Draw, each "" or a one-line reason: the mesh converted
  /// when the input or the array coloured by changed; the scene of the
  /// renderer's camera, lights and lookup table; the frame (or the
  /// polarization image); its colour and depth handed to OpenGL in the
  /// viewport {x, y, width, height}.
  std::string Convert(const CpuDrawInputs& inputs);
  render::Scene SceneFor(vtkRenderer* ren, const CpuDrawInputs& inputs, const render::Settings& settings);
  std::string RenderImage(const render::Scene& scene, render::RenderOptions options,
    render::PolarizationImage shown, const render::Image*& image);
  std::string HandOver(vtkOpenGLRenderWindow* window, const int viewport[4], const render::Image& image);

  cpu::SoftwareRenderer Renderer;
  render::Mesh Mesh;
  uint64_t MeshHash = 0; ///< Mesh.ContentHash(), made when it is converted
  render::WorldFrame Frame;
  render::ColorMap Map;
  vtkPolyData* From = nullptr;
  vtkMTimeType FromTime = 0;
  std::string FromScalars;
  int ConversionCount = 0;
  render::RenderStats Stats;
  /// A polarization image's false colours (Settings::polarizationImage).
  render::Image Polarization;
  double HandOverMs = 0;
  bool FinishForTiming = false;
  /// The polarization image's display bytes (Image::displayBytes' layout).
  std::vector<unsigned char> Rgba;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  vtkNew<vtkTextureObject> ColorTexture;
  vtkNew<vtkTextureObject> DepthTexture;
};

} // namespace shadinglab::vtk
