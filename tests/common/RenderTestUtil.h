// SPDX-License-Identifier: BSD-3-Clause
// Renders through the one render::Renderer interface, for tests: the scene
// assembled from its parts (lighting and material in float or double; the
// float values cast to double and back are exact).
#pragma once

#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/render/Renderer.h"

namespace shadinglab::test
{

template <typename T>
render::Image RenderWith(render::Renderer& renderer, const render::Mesh& mesh,
  const render::Camera& camera, const Lighting<T>& lighting, const Material<T>& material,
  const render::RenderOptions& options, render::RenderStats* stats = nullptr)
{
  const render::Scene scene{ &mesh, camera, lighting.template Cast<double>(),
    material.template Cast<double>() };
  return renderer.Render(scene, options, stats);
}

/// A parallel camera under which world (x, y) is pixel (x, height - y) of a
/// width x height image, looking down -z from z = 10 (near 1, far 20).
inline render::Camera PixelCamera(int width, int height)
{
  render::Camera cam;
  cam.position = { width / 2.0, height / 2.0, 10.0 };
  cam.focalPoint = { width / 2.0, height / 2.0, 0.0 };
  cam.parallel = true;
  cam.parallelScale = height / 2.0;
  cam.nearClip = 1.0;
  cam.farClip = 20.0;
  return cam;
}

/// One frame of a fresh CPU renderer.
template <typename T>
render::Image RenderCpu(const render::Mesh& mesh, const render::Camera& camera,
  const Lighting<T>& lighting, const Material<T>& material, const render::RenderOptions& options,
  render::RenderStats* stats = nullptr)
{
  cpu::SoftwareRenderer renderer;
  return RenderWith(renderer, mesh, camera, lighting, material, options, stats);
}

} // namespace shadinglab::test
