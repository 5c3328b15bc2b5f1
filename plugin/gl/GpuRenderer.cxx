// SPDX-License-Identifier: BSD-3-Clause
#include "GpuRenderer.h"

#include "vtkShadingLabPolyDataMapper.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <X11/Xlib.h>

#include <cstdlib>
#include <stdexcept>

namespace shadinglab::gl
{

bool GpuAvailable(std::string& why)
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
  return true;
}

cpu::Image RenderGpu(vtkPolyData* mesh, const cpu::Camera& cam, const Lighting<double>& lighting,
  const Material<double>& material, const cpu::RenderOptions& options, int* shaderBuilds)
{
  // The same rule as the CPU renderer: fast Phong expands (N.L) and (N.H)
  // only, so it has no Cook-Torrance form.
  if (options.mode == cpu::ShadingMode::FastPhong &&
    material.model == ReflectanceModel::CookTorrance)
  {
    throw std::invalid_argument("fast-phong evaluates (N.L) and (N.H)^n quadratics: use a "
                                "lambert, phong or blinn-phong material");
  }
  const int ssaa = options.ssaa;
  const int W = options.width * ssaa, H = options.height * ssaa;
  vtkNew<vtkShadingLabPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  mapper->SetShadingMode(static_cast<int>(options.mode));
  mapper->SetPerspectiveCorrect(options.interpolation == cpu::InterpolationSpace::Perspective);
  mapper->SetMaterial(material);
  mapper->SetFastPhongMaxSpread(options.fastPhongMaxSpread);
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkProperty* prop = actor->GetProperty();
  prop->SetDiffuse(1.0);
  prop->SetDiffuseColor(material.diffuseColor.x, material.diffuseColor.y, material.diffuseColor.z);
  prop->SetAmbient(0.0);
  prop->SetSpecular(0.0);
  prop->SetBackfaceCulling(options.cullBackFaces);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(options.background.x, options.background.y, options.background.z);
  renderer->SetAmbient(lighting.ambientIntensity.x, lighting.ambientIntensity.y,
    lighting.ambientIntensity.z);
  // No lights given: VTK's automatic headlight (a light at the camera).
  renderer->SetAutomaticLightCreation(lighting.lightCount == 0);
  for (int j = 0; j < lighting.lightCount; ++j)
  {
    const Light<double>& l = lighting.lights[j];
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetIntensity(1.0);
    // The mapper multiplies by the model's solid angle pi; scale other dw.
    const double s = l.solidAngle / kPi<double>;
    light->SetDiffuseColor(l.intensity.x * s, l.intensity.y * s, l.intensity.z * s);
    if (l.type == LightType::Directional)
    {
      light->SetPositional(false);
      light->SetPosition(l.vector.x, l.vector.y, l.vector.z);
      light->SetFocalPoint(0, 0, 0);
    }
    else
    {
      light->SetPositional(true);
      light->SetPosition(l.vector.x, l.vector.y, l.vector.z);
      const Vec3<double> axis = NormalizeOr(l.spotDirection, Vec3<double>(0, 0, -1));
      light->SetFocalPoint(l.vector.x + axis.x, l.vector.y + axis.y, l.vector.z + axis.z);
      light->SetConeAngle(l.coneAngle);
      light->SetExponent(l.coneExponent);
      light->SetAttenuationValues(l.attenuation.x, l.attenuation.y, l.attenuation.z);
    }
    renderer->AddLight(light);
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(cam.position.x, cam.position.y, cam.position.z);
  camera->SetFocalPoint(cam.focalPoint.x, cam.focalPoint.y, cam.focalPoint.z);
  camera->SetViewUp(cam.viewUp.x, cam.viewUp.y, cam.viewUp.z);
  camera->SetViewAngle(cam.viewAngle);
  camera->SetParallelProjection(cam.parallel);
  camera->SetParallelScale(cam.parallelScale);
  camera->SetClippingRange(cam.nearClip, cam.farClip);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(W, H);
  window->AddRenderer(renderer);
  window->Render();
  if (mapper->GetFailedSubstitutionCount() > 0)
  {
    throw std::runtime_error("GPU shader substitution failed (see log)");
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkWindowToImageFilter> depthGrab;
  depthGrab->SetInput(window);
  depthGrab->SetInputBufferTypeToZBuffer();
  depthGrab->ReadFrontBufferOff();
  depthGrab->Update();
  vtkImageData* rgbImage = grab->GetOutput();
  auto* pixels = vtkUnsignedCharArray::SafeDownCast(rgbImage->GetPointData()->GetScalars());
  auto* depth = vtkFloatArray::SafeDownCast(depthGrab->GetOutput()->GetPointData()->GetScalars());
  if (!pixels || !depth)
  {
    throw std::runtime_error("GPU read-back failed");
  }
  if (shaderBuilds)
  {
    *shaderBuilds = mapper->GetShaderBuildCount();
  }
  // Frame to linear floats, rows top-down (VTK rows start at the bottom),
  // then the same resolve as the CPU renderer.
  std::vector<float> rgb(static_cast<size_t>(W) * H * 3);
  std::vector<uint8_t> covered(static_cast<size_t>(W) * H);
  for (int y = 0; y < H; ++y)
  {
    for (int x = 0; x < W; ++x)
    {
      const vtkIdType i = static_cast<vtkIdType>(H - 1 - y) * W + x;
      const size_t o = static_cast<size_t>(y) * W + x;
      for (int c = 0; c < 3; ++c)
      {
        rgb[3 * o + c] = pixels->GetTypedComponent(i, c) / 255.0f;
      }
      covered[o] = depth->GetValue(i) < 1.0f;
    }
  }
  cpu::Image image;
  cpu::DownsampleBox(rgb, covered, W, H, ssaa, image);
  return image;
}

} // namespace shadinglab::gl
