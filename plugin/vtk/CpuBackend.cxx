// SPDX-License-Identifier: BSD-3-Clause
#include "CpuBackend.h"

#include "shadinglab/render/ColorMap.h"
#include "shadinglab/render/Stokes.h"

#include "PolyDataMesh.h"
#include "VtkCamera.h"
#include "VtkLights.h"
#include "shadinglab/render/Display.h"
#include "shadinglab_handover_glsl.h"

#include <vtkOpenGLQuadHelper.h>
#include "VtkOpenGL.h" // GL_DEPTH_TEST, GL_TRUE
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkScalarsToColors.h>
#include <vtkShaderProgram.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace shadinglab::vtk
{

namespace
{

/// Entries of the colour map sampled from a VTK lookup table: ParaView's
/// default table has 256, and its transfer functions are smooth at that
/// resolution (the GL path's colour texture has 256 texels too).
constexpr int kLookupSamples = 256;

} // namespace

CpuBackend::CpuBackend() = default;

CpuBackend::~CpuBackend() = default;

void CpuBackend::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
  this->ColorTexture->ReleaseGraphicsResources(window);
  this->DepthTexture->ReleaseGraphicsResources(window);
}

namespace
{

/// The smallest rectangle [i0, i1] x [j0, j1] of covered pixels (i1 < i0:
/// none), each row searched from both ends with the C library's vectorized
/// byte search (std::find compared a byte at a time: ~0.5 ms a 1080p frame).
void CoveredRectangle(const render::Image& image, int width, int height, int& i0, int& i1,
  int& j0, int& j1)
{
  i0 = width;
  i1 = -1;
  j0 = height;
  j1 = -1;
  for (int j = 0; j < height; ++j)
  {
    const uint8_t* row = &image.covered[static_cast<size_t>(j) * width];
    const auto* first = static_cast<const uint8_t*>(std::memchr(row, 1, static_cast<size_t>(width)));
    if (!first)
    {
      continue;
    }
#if defined(__GLIBC__)
    const auto* last = static_cast<const uint8_t*>(memrchr(row, 1, static_cast<size_t>(width)));
#else
    const uint8_t* last = row + width - 1;
    while (*last != 1)
    {
      --last;
    }
#endif
    i0 = std::min(i0, static_cast<int>(first - row));
    i1 = std::max(i1, static_cast<int>(last - row));
    j0 = std::min(j0, j);
    j1 = std::max(j1, j);
  }
}

} // namespace

std::string CpuBackend::Draw(
  vtkRenderer* ren, const CpuDrawInputs& inputs, const render::Settings& settings)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!window || !inputs.polydata)
  {
    return "no OpenGL render window to hand the image to";
  }
  int width = 0, height = 0, x = 0, y = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  if (width < 1 || height < 1)
  {
    return "empty viewport";
  }
  std::string problem = this->Convert(inputs);
  if (!problem.empty())
  {
    return problem;
  }
  const render::Scene scene = this->SceneFor(ren, inputs, settings);
  render::RenderOptions options = settings.render;
  options.width = width;
  options.height = height;
  options.ssaa = 1;
  options.keepDepth = true;
  options.traceRow = -1;
  // Fast Phong as asked, the GL path's quadratic: the CPU renderer's own
  // switch to exact Phong on small triangles is a speed choice of the
  // command line, and would make the backends' pictures differ.
  options.fastPhongFallback = false;
  const render::Image* image = nullptr;
  problem = this->RenderImage(scene, options, settings.polarizationImage, image);
  if (!problem.empty())
  {
    return problem;
  }
  const int viewport[4] = { x, y, width, height };
  return this->HandOver(window, viewport, *image);
}

std::string CpuBackend::Convert(const CpuDrawInputs& inputs)
{
  // The mesh, converted when the input (or the array coloured by) changes:
  // a camera move re-renders without converting (the renderer's own
  // caches keep the normals and the closed-mesh test by content).
  std::string scalars;
  if (inputs.lookupTable && inputs.scalarName)
  {
    scalars = std::string(inputs.scalarsOnCells ? "CELLS:" : "POINTS:") + inputs.scalarName +
      ":" + std::to_string(inputs.scalarComponent);
  }
  if (inputs.polydata == this->From && inputs.polydata->GetMTime() == this->FromTime &&
    scalars == this->FromScalars)
  {
    return "";
  }
  try
  {
    if (scalars.empty())
    {
      this->Mesh = render::MeshFromPolyData(inputs.polydata, this->Frame);
    }
    else
    {
      render::ScalarField field;
      field.name = inputs.scalarName;
      field.association = inputs.scalarsOnCells ? render::ScalarField::Association::Cells
                                                : render::ScalarField::Association::Points;
      field.component = inputs.scalarComponent;
      double range[2];
      this->Mesh = render::MeshFromPolyData(inputs.polydata, this->Frame, field, range);
    }
  }
  catch (const std::invalid_argument& e)
  {
    return e.what();
  }
  // Hashed once per conversion, for the renderer's caches (Scene::meshHash).
  this->MeshHash = this->Mesh.ContentHash();
  this->From = inputs.polydata;
  this->FromTime = inputs.polydata->GetMTime();
  this->FromScalars = scalars;
  ++this->ConversionCount;
  return "";
}

render::Scene CpuBackend::SceneFor(
  vtkRenderer* ren, const CpuDrawInputs& inputs, const render::Settings& settings)
{
  render::Scene scene;
  scene.mesh = &this->Mesh;
  scene.meshHash = this->MeshHash;
  scene.camera = render::CameraFromVtk(ren->GetActiveCamera());
  render::ToLocal(this->Frame, scene.camera);
  scene.lighting =
    render::LightingFromVtk(ren, settings.lightIntensity, settings.lightSolidAngle);
  render::ToLocal(this->Frame, scene.lighting);
  scene.material = settings.material;
  if (inputs.albedo)
  {
    scene.material.diffuseColor = { inputs.albedo[0], inputs.albedo[1], inputs.albedo[2] };
  }
  if (!this->FromScalars.empty())
  {
    // The lookup table, sampled at its bins' centres over its range.
    const double* range = inputs.lookupTable->GetRange();
    this->Map.colors.resize(kLookupSamples);
    this->Map.rangeMin = range[0];
    this->Map.rangeMax = range[1];
    for (int k = 0; k < kLookupSamples; ++k)
    {
      double rgb[3];
      inputs.lookupTable->GetColor(
        range[0] + (k + 0.5) / kLookupSamples * (range[1] - range[0]), rgb);
      this->Map.colors[k] = Vec3<float>(static_cast<float>(rgb[0]), static_cast<float>(rgb[1]),
        static_cast<float>(rgb[2]));
    }
    scene.colorMap = &this->Map;
  }
  // Colours from data (mapped or direct RGB) keep no highlights unless asked.
  const bool colored = scene.colorMap || !this->Mesh.colors.empty();
  scene.material = render::MaterialForData(scene.material, settings.highlights, colored);
  return scene;
}

std::string CpuBackend::RenderImage(const render::Scene& scene, render::RenderOptions options,
  render::PolarizationImage shown, const render::Image*& image)
{
  try
  {
    if (shown == render::PolarizationImage::Intensity)
    {
      options.displayBytes = true; // what the hand-over uploads
      image = &this->Renderer.Render(scene, options, &this->Stats);
      return "";
    }
    // What a polarization camera measures, in false colour (eq. 8.5): the
    // picture's depth, colours already display values.
    const render::StokesImage stokes =
      render::MeasureStokes(this->Renderer, scene, options, &this->Stats);
    const bool dolp = shown == render::PolarizationImage::Dolp;
    this->Polarization.width = stokes.width;
    this->Polarization.height = stokes.height;
    this->Polarization.covered = stokes.covered;
    this->Polarization.depth = stokes.depth;
    // Uncovered pixels are not handed over: their colour is never read.
    this->Polarization.rgb = render::FalseColour(stokes,
      dolp ? render::StokesQuantity::Dolp : render::StokesQuantity::Aop, Vec3<float>(0, 0, 0));
    this->Polarization.displayApplied = true;
    image = &this->Polarization;
    return "";
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
}

std::string CpuBackend::HandOver(
  vtkOpenGLRenderWindow* window, const int viewport[4], const render::Image& image)
{
  // The hand-over: colour (display bytes, alpha = covered) and depth of
  // the rectangle the surface covers (most of a view is background),
  // uploaded from the frame's own rows (the renderer wrote the bytes band by
  // band, RenderOptions::displayBytes; the polarization image, already
  // display values, is rounded here).
  const int x = viewport[0], y = viewport[1], width = viewport[2], height = viewport[3];
  if (this->FinishForTiming)
  {
    window->WaitForCompletion(); // glFinish
  }
  const auto start = std::chrono::steady_clock::now();
  const uint8_t* bytes = image.displayBytes.data();
  if (image.displayBytes.empty())
  {
    const size_t pixels = static_cast<size_t>(width) * height;
    this->Rgba.resize(4 * pixels);
    render::ToDisplayBytes(render::DisplayTransform::Clamp, image.rgb.data(), image.covered.data(), 0,
      pixels, this->Rgba.data());
    bytes = this->Rgba.data();
  }
  // The covered rectangle, on the calling thread while OpenGL waits.
  int i0, i1, j0, j1;
  CoveredRectangle(image, width, height, i0, i1, j0, j1);
  if (i1 < i0)
  {
    this->HandOverMs = 0;
    return ""; // nothing of the surface in view
  }
  const int w = i1 - i0 + 1, h = j1 - j0 + 1;
  // Texture row r is image row j0 + r (the image's row 0 is the top; the
  // quad's shader turns it over), read from the frame with its row length.
  const size_t corner = static_cast<size_t>(j0) * width + i0;
  window->GetState()->vtkglPixelStorei(GL_UNPACK_ROW_LENGTH, width);
  this->ColorTexture->SetContext(window);
  this->DepthTexture->SetContext(window);
  const bool uploaded =
    this->ColorTexture->Create2DFromRaw(w, h, 4, VTK_UNSIGNED_CHAR,
      const_cast<uint8_t*>(bytes + 4 * corner)) &&
    this->DepthTexture->Create2DFromRaw(w, h, 1, VTK_FLOAT,
      const_cast<float*>(image.depth.data() + corner));
  window->GetState()->vtkglPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  if (!uploaded)
  {
    return "could not upload the image as textures";
  }
  if (!this->Quad)
  {
    this->Quad = std::make_unique<vtkOpenGLQuadHelper>(
      window, nullptr, sl_cpu_handover_fs_glsl, "");
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  if (!this->Quad->Program || !this->Quad->Program->GetCompiled())
  {
    return "the hand-over shader did not compile";
  }
  vtkOpenGLState* state = window->GetState();
  // The quad covers the rectangle: a viewport of its size at its place in
  // the renderer's (OpenGL's y up: image row j1 is the rectangle's bottom).
  vtkOpenGLState::ScopedglViewport scopedViewport(state);
  state->vtkglViewport(x + i0, y + (height - 1 - j1), w, h);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_TRUE);
  this->ColorTexture->Activate();
  this->DepthTexture->Activate();
  this->Quad->Program->SetUniformi("slCpuColor", this->ColorTexture->GetTextureUnit());
  this->Quad->Program->SetUniformi("slCpuDepth", this->DepthTexture->GetTextureUnit());
  this->Quad->Render();
  this->ColorTexture->Deactivate();
  this->DepthTexture->Deactivate();
  if (this->FinishForTiming)
  {
    window->WaitForCompletion(); // glFinish
  }
  this->HandOverMs =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return "";
}

} // namespace shadinglab::vtk
