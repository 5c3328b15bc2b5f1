// SPDX-License-Identifier: BSD-3-Clause
// How a render request becomes VTK state for vtkShadingLabPolyDataMapper:
// the one place both GL front ends (GpuRenderer's offscreen window and the
// explorer's QVTKOpenGLNativeWidget panels) set up mapper, actor and lights.
#pragma once

#include "shadinglab/render/Options.h"
#include "shadinglab/model/Shading.h"

class vtkActor;
class vtkRenderer;
class vtkShadingLabPolyDataMapper;

namespace shadinglab::gl
{

/**
 * Mode, interpolation space, material and fast-Phong spread limit on the
 * mapper; colours as direct scalars; the actor's property as the mapper
 * expects it (diffuse 1 with the material's albedo, no VTK ambient or
 * specular) and back-face culling from the options.
 */
void ConfigureActor(const render::RenderOptions& options, const Material<double>& material,
  vtkShadingLabPolyDataMapper* mapper, vtkActor* actor);

/**
 * The lights (world coordinates) as scene vtkLights and the ambient
 * intensity as the renderer's ambient. With no light, VTK's automatic
 * headlight.
 */
void ApplyLighting(const Lighting<double>& lighting, vtkRenderer* renderer);

} // namespace shadinglab::gl
