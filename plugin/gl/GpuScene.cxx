// SPDX-License-Identifier: BSD-3-Clause
#include "GpuScene.h"

#include "vtkShadingLabPolyDataMapper.h"

#include <vtkActor.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace shadinglab::gl
{

void ConfigureActor(const render::RenderOptions& options, const Material<double>& material,
  vtkShadingLabPolyDataMapper* mapper, vtkActor* actor)
{
  mapper->SetShadingMode(static_cast<int>(options.mode));
  mapper->SetPerspectiveCorrect(options.interpolation == render::InterpolationSpace::Perspective);
  mapper->SetMaterial(material);
  mapper->SetFastPhongMaxSpread(options.fastPhongMaxSpread);
  mapper->ScalarVisibilityOn();
  mapper->SetColorModeToDirectScalars();
  vtkProperty* prop = actor->GetProperty();
  prop->SetDiffuse(1.0);
  prop->SetDiffuseColor(material.diffuseColor.x, material.diffuseColor.y, material.diffuseColor.z);
  prop->SetAmbient(0.0);
  prop->SetSpecular(0.0);
  prop->SetBackfaceCulling(options.cullBackFaces);
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

} // namespace shadinglab::gl
