// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/gl/GpuRenderer.h"

#include "shadinglab/render/Display.h"

#include "GpuScene.h"

#include "vtkShadingLabOpenGLPolyDataMapper.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "PolyDataMesh.h"
#include "VtkCamera.h"

#include <X11/Xlib.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>

namespace shadinglab::gl
{

bool GpuAvailable(std::string& why, std::string* glRenderer)
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    why = "no DISPLAY (this VTK is built for X only)";
    return false;
  }
  Display* dpy = XOpenDisplay(nullptr);
  if (!dpy)
  {
    why = std::string("cannot open X display '") + display + "'";
    return false;
  }
  XCloseDisplay(dpy);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(8, 8);
  if (!window->SupportsOpenGL())
  {
    why = "the X display has no OpenGL >= 3.2";
    return false;
  }
  if (glRenderer)
  {
    window->Start(); // makes the context (vtkOpenGLRenderWindow::Start)
    *glRenderer = render::GlRendererFromReport(window->ReportCapabilities());
    window->Finalize();
  }
  return true;
}

struct GpuRenderer::Internals
{
  vtkNew<vtkShadingLabOpenGLPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  render::Image Output;
  /// The mesh last uploaded, by content: a frame of the same mesh (the
  /// steady state of a viewer or a benchmark) converts and uploads nothing.
  uint64_t MeshHash = 0;
  vtkSmartPointer<vtkPolyData> MeshData;

  Internals()
  {
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
  }

  void ReadBack(int W, int H, int ssaa);
};

void GpuRenderer::Internals::ReadBack(int W, int H, int ssaa)
{
  std::vector<float> rgb;
  std::vector<uint8_t> covered;
  if (!ReadFrame(this->Window, W, H, rgb, covered))
  {
    throw std::runtime_error("GPU read-back failed");
  }
  // The same resolve as the CPU renderer.
  render::DownsampleBox(rgb, covered, W, H, ssaa, this->Output);
}

GpuRenderer::GpuRenderer()
  : Impl(new Internals)
{
}

GpuRenderer::~GpuRenderer() = default;

const render::Image& GpuRenderer::Render(
  const render::Scene& scene, const render::RenderOptions& options, render::RenderStats* stats)
{
  const std::string error = render::ValidateRequest(scene, options);
  if (!error.empty())
  {
    throw std::invalid_argument(error);
  }
  if (options.mode == render::ShadingMode::FastPhong &&
    options.expansion != ExpansionPoint::Vertex)
  {
    throw std::invalid_argument("the GPU expands fast-phong about the provoking vertex only "
                                "(a fragment shader cannot see its triangle's centroid): use "
                                "--expansion vertex or --backend cpu");
  }
  if (options.scan != render::ScanConversion::Plane)
  {
    throw std::invalid_argument("the incremental scan is the CPU renderer's (the GPU's rasterizer "
                                "interpolates in hardware): use --backend cpu");
  }
  const auto start = std::chrono::steady_clock::now();
  Internals& in = *this->Impl;
  const Material<double>& material = scene.material;
  const uint64_t hash = scene.meshHash ? *scene.meshHash : scene.mesh->ContentHash();
  if (!in.MeshData || hash != in.MeshHash)
  {
    in.MeshData.TakeReference(render::PolyDataFromMesh(*scene.mesh));
    in.MeshHash = hash;
    in.Mapper->SetInputData(in.MeshData);
  }
  ConfigureActor(options, material, in.Mapper, in.Actor);
  const bool scalars = !scene.mesh->scalars.empty() || !scene.mesh->cellScalars.empty();
  ConfigureColoring(scalars ? scene.colorMap : nullptr, "Scalars", !scene.mesh->cellScalars.empty(),
    -1, in.Mapper);
  // The shader writes display values (ApplyDisplay; the 8-bit framebuffer
  // would clip linear ones): the background is given as one too.
  const Vec3<float> background = render::ApplyDisplay(options.display, options.background);
  in.Renderer->SetBackground(background.x, background.y, background.z);
  ApplyLighting(scene.lighting, in.Renderer);
  render::ApplyToVtkCamera(scene.camera, in.Renderer->GetActiveCamera());
  const int ssaa = options.ssaa;
  const int W = options.width * ssaa, H = options.height * ssaa;
  in.Window->SetSize(W, H);
  const int buildsBefore = in.Mapper->GetShaderBuildCount();
  in.Window->Render();
  if (in.Mapper->GetFailedSubstitutionCount() > 0)
  {
    throw std::runtime_error("GPU shader substitution failed (see log)");
  }
  in.ReadBack(W, H, ssaa);
  in.Output.displayApplied = true;
  in.Output.appliedDisplay = options.display;
  if (stats)
  {
    *stats = render::RenderStats();
    stats->milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats->polygons = scene.mesh->NumberOfPolygons();
    stats->triangles = scene.mesh->NumberOfTriangles();
    for (uint8_t c : in.Output.covered)
    {
      stats->pixelsCovered += c;
    }
    stats->shaderBuilds = in.Mapper->GetShaderBuildCount() - buildsBefore;
    stats->drawnMode = static_cast<render::ShadingMode>(in.Mapper->GetDrawnMode());
    stats->autoChoice = in.Mapper->GetAutoChoice();
    stats->normalsComputed =
      scene.mesh->normals.empty() && stats->drawnMode != render::ShadingMode::Flat;
  }
  return in.Output;
}

} // namespace shadinglab::gl
