// SPDX-License-Identifier: BSD-3-Clause
// How a render request becomes VTK state for vtkShadingLabOpenGLPolyDataMapper:
// the one place both GL front ends (GpuRenderer's offscreen window and the
// explorer's QVTKOpenGLNativeWidget panels) set up mapper, actor and lights.
#pragma once

#include "shadinglab/render/ColorMap.h"
#include "shadinglab/render/Options.h"
#include "shadinglab/model/Shading.h"

#include <cstdint>
#include <string>
#include <vector>

class vtkActor;
class vtkRenderWindow;
class vtkRenderer;
class vtkShadingLabOpenGLPolyDataMapper;

namespace shadinglab::gl
{

/**
 * Mode, interpolation space, material and fast-Phong spread limit on the
 * mapper; colours as direct scalars; the actor's property as the mapper
 * expects it (diffuse 1 with the material's albedo, no VTK ambient or
 * specular) and back-face culling from the options.
 */
void ConfigureActor(const render::RenderOptions& options, const Material<double>& material,
  vtkShadingLabOpenGLPolyDataMapper* mapper, vtkActor* actor);

/**
 * Colour by data: with a colour map, the mapper maps the point (or, with
 * `cells`, cell) array `array` (component `component`, or -1: a vector's
 * magnitude) through a lookup table of the map's bins over its range,
 * interpolating the scalar before mapping (ParaView's default). Without a
 * map: the direct colours ConfigureActor set up.
 */
void ConfigureColoring(const render::ColorMap* map, const std::string& array, bool cells,
  int component, vtkShadingLabOpenGLPolyDataMapper* mapper);

/**
 * The lights (world coordinates) as scene vtkLights and the ambient
 * intensity as the renderer's ambient. With no light, VTK's automatic
 * headlight.
 */
void ApplyLighting(const Lighting<double>& lighting, vtkRenderer* renderer);

/**
 * The window's last frame, without rendering again: linear RGB floats
 * (8-bit framebuffer precision), row 0 at the top, and `covered` where the
 * depth buffer is nearer than the far plane. False when the read fails or
 * the window is not width x height.
 */
bool ReadFrame(vtkRenderWindow* window, int width, int height, std::vector<float>& rgb,
  std::vector<uint8_t>& covered);

} // namespace shadinglab::gl
