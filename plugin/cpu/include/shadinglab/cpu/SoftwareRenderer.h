// SPDX-License-Identifier: BSD-3-Clause
// The CPU software renderer: the lecture's scanline algorithms for the four
// shading modes, one implementation of render::Renderer (the GL renderer in
// plugin/gl is the other). Fallback where no OpenGL exists and reference for
// the GPU path. No VTK, no GL.
//
// The shading itself is the model library's (Shade(), and for fast Phong
// ShadeFromCosines()); this renderer only decides where it is evaluated:
// per polygon, per vertex, per pixel.
#pragma once

#include "shadinglab/render/Renderer.h"

#include <memory>
#include <vector>

namespace shadinglab::cpu
{

/**
 * The renderer as an object: its frame buffers, depth buffer and projected
 * vertices persist between frames, so rendering the same size again does not
 * reallocate (the steady state an interactive viewer sees). Output is
 * bit-identical whatever the thread count. The model is evaluated in float.
 */
class SoftwareRenderer final : public render::Renderer
{
public:
  SoftwareRenderer();
  ~SoftwareRenderer() override;
  SoftwareRenderer(const SoftwareRenderer&) = delete;
  SoftwareRenderer& operator=(const SoftwareRenderer&) = delete;

  render::Backend GetBackend() const override { return render::Backend::CPU; }

  const render::Image& Render(const render::Scene& scene, const render::RenderOptions& options,
    render::RenderStats* stats = nullptr) override;

  class Internals;

private:
  std::unique_ptr<Internals> Impl;
};

/// Area-weighted vertex normals (sum of unnormalized face cross products).
std::vector<float> AreaWeightedNormals(const render::Mesh& mesh);

/// Pixels the Phong stage shades per instruction: 8 (AVX2 with FMA), 4
/// (SSE2, every x86-64) or 1, the best this CPU has unless forced.
int PixelLanes();
/// Forces a lane count (1, 4, or 8 where the CPU has AVX2 and FMA), for
/// tests and benchmarks; 0 or any other value restores the best.
void SetPixelLanes(int lanes);

/// How the rasterizer keeps its screen records (projection and attributes
/// of the vertices it draws): by vertex id, or one per drawn vertex found
/// through a slot per vertex (a big mesh at screen size draws few of its
/// vertices). Auto chooses by the share drawn; the image is the same bits.
enum class ScreenRecords
{
  Auto,
  ByVertex,
  Compact,
};
/// Forces a layout, for tests and benchmarks; Auto restores the choice.
void SetScreenRecords(ScreenRecords layout);
ScreenRecords ForcedScreenRecords();

} // namespace shadinglab::cpu
