// SPDX-License-Identifier: BSD-3-Clause
// Offscreen rendering through vtkShadingLabPolyDataMapper with the same
// inputs and output as the CPU renderer (the interchangeable-evaluator idea
// of OpenSubdiv's cpu/gpu evaluators): mesh + camera + lights + material +
// mode -> image.
#pragma once

#include "shadinglab/cpu/SoftwareRenderer.h"

#include <string>

class vtkPolyData;

namespace shadinglab::gl
{

/// True when an X display with OpenGL >= 3.2 answers; else false and `why`
/// says what is missing. Never aborts (checks DISPLAY and XOpenDisplay before
/// any VTK window exists).
bool GpuAvailable(std::string& why);

/**
 * Renders `mesh` offscreen with the mapper. The options' mode, size, ssaa
 * (box filter over an N-times larger framebuffer), interpolation space and
 * background apply; threads, polygon handling and culling are the GPU's.
 * Lights are given in world coordinates and become scene vtkLights; with
 * none, VTK's automatic headlight is used.
 * Returns the linear image as floats in [0, 1] (8-bit framebuffer precision)
 * with `covered` from the framebuffer's depth. Throws std::invalid_argument
 * for a mode/material mismatch (as cpu::Render) and std::runtime_error for a
 * failed GL render.
 */
cpu::Image RenderGpu(vtkPolyData* mesh, const cpu::Camera& camera, const Lighting<double>& lighting,
  const Material<double>& material, const cpu::RenderOptions& options,
  int* shaderBuilds = nullptr);

} // namespace shadinglab::gl
