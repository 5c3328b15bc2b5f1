// SPDX-License-Identifier: BSD-3-Clause
#include "GpuScene.h"

#include "vtkShadingLabOpenGLPolyDataMapper.h"

#include <vtkActor.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>
#include <vtkLight.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace shadinglab::gl
{

void ConfigureActor(const render::RenderOptions& options, const Material<double>& material,
  vtkShadingLabOpenGLPolyDataMapper* mapper, vtkActor* actor)
{
  render::Settings settings = mapper->GetSettings();
  settings.render = options;
  settings.material = material;
  // The Renderer contract: the scene's material is drawn as given (front
  // ends apply render::MaterialForData before).
  settings.highlights = render::Highlights::On;
  // The Renderer contract: a mesh without normals gets the CPU renderer's
  // area-weighted normals, not split (front ends split before, as asked).
  settings.normals = render::NormalSettings();
  settings.normals.featureAngle = 180.0;
  mapper->SetSettings(settings);
  mapper->ScalarVisibilityOn();
  mapper->SetColorModeToDirectScalars();
  vtkProperty* prop = actor->GetProperty();
  prop->SetDiffuse(1.0);
  prop->SetDiffuseColor(material.diffuseColor.x, material.diffuseColor.y, material.diffuseColor.z);
  prop->SetAmbient(0.0);
  prop->SetSpecular(0.0);
  prop->SetBackfaceCulling(options.cullBackFaces);
}

void ConfigureColoring(const render::ColorMap* map, const std::string& array, bool cells,
  int component, vtkShadingLabOpenGLPolyDataMapper* mapper)
{
  if (!map)
  {
    mapper->SetColorModeToDirectScalars();
    mapper->SetScalarModeToDefault();
    mapper->InterpolateScalarsBeforeMappingOff();
    return;
  }
  vtkNew<vtkLookupTable> table;
  table->SetNumberOfTableValues(static_cast<vtkIdType>(map->colors.size()));
  for (size_t b = 0; b < map->colors.size(); ++b)
  {
    const Vec3<float>& c = map->colors[b];
    table->SetTableValue(static_cast<vtkIdType>(b), c.x, c.y, c.z, 1.0);
  }
  table->SetNanColor(map->nanColor.x, map->nanColor.y, map->nanColor.z, 1.0);
  table->SetTableRange(map->rangeMin, map->rangeMax);
  table->BuildSpecialColors();
  if (component >= 0)
  {
    table->SetVectorModeToComponent();
    table->SetVectorComponent(component);
  }
  else
  {
    table->SetVectorModeToMagnitude();
  }
  mapper->SetLookupTable(table);
  mapper->UseLookupTableScalarRangeOn();
  mapper->SetColorModeToMapScalars();
  if (cells)
  {
    mapper->SetScalarModeToUseCellFieldData();
  }
  else
  {
    mapper->SetScalarModeToUsePointFieldData();
  }
  mapper->SelectColorArray(array.c_str());
  mapper->InterpolateScalarsBeforeMappingOn();
}

void ApplyLighting(const Lighting<double>& lighting, vtkRenderer* renderer)
{
  renderer->RemoveAllLights();
  renderer->SetAmbient(
    lighting.ambientIntensity.x, lighting.ambientIntensity.y, lighting.ambientIntensity.z);
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
}

bool ReadFrame(vtkRenderWindow* window, int width, int height, std::vector<float>& rgb,
  std::vector<uint8_t>& covered)
{
  // ShouldRerender off: the frame drawn is the frame read (the filter's
  // default renders the window again first, once per buffer).
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ShouldRerenderOff();
  grab->ReadFrontBufferOff();
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  vtkNew<vtkWindowToImageFilter> depthGrab;
  depthGrab->SetInput(window);
  depthGrab->ShouldRerenderOff();
  depthGrab->ReadFrontBufferOff();
  depthGrab->SetInputBufferTypeToZBuffer();
  depthGrab->Update();
  auto* pixels =
    vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  auto* depth = vtkFloatArray::SafeDownCast(depthGrab->GetOutput()->GetPointData()->GetScalars());
  const vtkIdType n = static_cast<vtkIdType>(width) * height;
  if (!pixels || !depth || pixels->GetNumberOfTuples() != n || depth->GetNumberOfTuples() != n)
  {
    return false;
  }
  rgb.resize(static_cast<size_t>(n) * 3);
  covered.resize(static_cast<size_t>(n));
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const vtkIdType i = static_cast<vtkIdType>(height - 1 - y) * width + x; // VTK rows go up
      const size_t o = static_cast<size_t>(y) * width + x;
      for (int c = 0; c < 3; ++c)
      {
        rgb[3 * o + c] = pixels->GetTypedComponent(i, c) / 255.0f;
      }
      covered[o] = depth->GetValue(i) < 1.0f;
    }
  }
  return true;
}

} // namespace shadinglab::gl
