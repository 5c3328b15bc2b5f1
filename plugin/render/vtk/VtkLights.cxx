// SPDX-License-Identifier: BSD-3-Clause
#include "VtkLights.h"

#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkRenderer.h>

namespace shadinglab::render
{

Lighting<double> LightingFromVtk(vtkRenderer* renderer, double intensityScale, double solidAngle)
{
  Lighting<double> lighting;
  lighting.lightCount = 0; // (the default is one light; none is a headlight)
  const double* ia = renderer->GetAmbient();
  lighting.ambientIntensity = Vec3<double>(ia[0], ia[1], ia[2]);
  vtkLightCollection* collection = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    if (!light->GetSwitch() || lighting.lightCount >= kMaxLights)
    {
      continue;
    }
    const double* c = light->GetDiffuseColor();
    const double i = light->GetIntensity() * intensityScale;
    Light<double>& l = lighting.lights[lighting.lightCount++];
    l.intensity = Vec3<double>(c[0] * i, c[1] * i, c[2] * i);
    l.solidAngle = solidAngle;
    double pos[3], fp[3];
    light->GetTransformedPosition(pos);
    light->GetTransformedFocalPoint(fp);
    const Vec3d position(pos[0], pos[1], pos[2]), focal(fp[0], fp[1], fp[2]);
    if (light->GetPositional())
    {
      const double* att = light->GetAttenuationValues();
      l.type = LightType::Point;
      l.vector = position;
      l.attenuation = Vec3d(att[0], att[1], att[2]);
      if (light->GetConeAngle() <= 90.0)
      {
        l.spotDirection = NormalizeOr(focal - position, Vec3d(0, 0, -1));
        l.coneAngle = light->GetConeAngle();
        l.coneExponent = light->GetExponent();
      }
    }
    else
    {
      l.type = LightType::Directional;
      l.vector = NormalizeOr(position - focal, Vec3d(0, 0, 1));
    }
  }
  return lighting;
}

} // namespace shadinglab::render
