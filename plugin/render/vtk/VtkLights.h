// SPDX-License-Identifier: BSD-3-Clause
// A vtkRenderer's lights as the model's Lighting: the one conversion every
// VTK front end uses (the mapper's uniforms and its auto choice, the CPU
// path inside VTK).
#pragma once

#include "shadinglab/model/Shading.h"

class vtkRenderer;

namespace shadinglab::render
{

/**
 * The switched-on lights of `renderer` (at most kMaxLights, in collection
 * order) in world coordinates: I_L = intensity x diffuse colour x
 * `intensityScale` over the solid angle `solidAngle` (steradians, the
 * settings' light-solid-angle); positional lights with their
 * attenuation, and a cone when the cone angle is at most 90 degrees (VTK's
 * convention: larger is no cone). Ia is the renderer's ambient.
 */
Lighting<double> LightingFromVtk(
  vtkRenderer* renderer, double intensityScale = 1.0, double solidAngle = kPi<double>);

} // namespace shadinglab::render
