// SPDX-License-Identifier: BSD-3-Clause
// The GL renderer: one implementation of render::Renderer (the CPU software
// renderer in plugin/cpu is the other), drawing through
// vtkShadingLabOpenGLPolyDataMapper into an offscreen VTK window.
#pragma once

#include "shadinglab/render/Renderer.h"

#include <memory>
#include <string>

namespace shadinglab::gl
{

/// True when an X display with OpenGL >= 3.2 answers; else false and `why`
/// says what is missing. Never aborts (checks DISPLAY and XOpenDisplay before
/// any VTK window exists). With `glRenderer`, a context is made to read its
/// GL_RENDERER string (render::ChooseBackend's fact).
bool GpuAvailable(std::string& why, std::string* glRenderer = nullptr);

/**
 * Renders offscreen with the mapper. The options' mode, size, ssaa (box
 * filter over an N-times larger framebuffer), interpolation space, culling
 * and background apply; threads and polygon handling are the GPU's. Lights
 * are given in world coordinates and become scene vtkLights; with none,
 * VTK's automatic headlight is used. The image is linear floats in [0, 1]
 * (8-bit framebuffer precision) with `covered` from the framebuffer's depth.
 * The window, renderer and mapper persist across calls, so VTK's shader
 * cache serves a variant compiled before, and a mesh whose arrays are
 * unchanged (hashed) is not converted or uploaded again.
 * Check GpuAvailable() first: without an X display VTK aborts.
 */
class GpuRenderer final : public render::Renderer
{
public:
  GpuRenderer();
  ~GpuRenderer() override;
  GpuRenderer(const GpuRenderer&) = delete;
  GpuRenderer& operator=(const GpuRenderer&) = delete;

  render::Backend GetBackend() const override { return render::Backend::GPU; }

  const render::Image& Render(const render::Scene& scene, const render::RenderOptions& options,
    render::RenderStats* stats = nullptr) override;

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

} // namespace shadinglab::gl
