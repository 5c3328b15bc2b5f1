// SPDX-License-Identifier: BSD-3-Clause
// The Phong stage's pixel shading, in SIMD batches. The rasterizer's pixel
// loop depth-tests each pixel at once and queues the survivors' interpolated
// normal, position and colour; a full queue (and each thread's last one) is
// shaded by the model (Shade, docs/model.md eq. 1.1) on 8 pixels at a time
// with AVX2, 4 with SSE2 (every x86-64), or one at a time, chosen at run
// time by the CPU's features. Queued results are written in queue order, so
// a pixel drawn twice keeps its last fragment's colour, as when each pixel
// was shaded in turn.
#pragma once

#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/model/Shading.h"

#include <cstdint>

namespace shadinglab::cpu
{

/// Pixels waiting for the model, structure of arrays. 256 pixels amortize
/// the per-batch set-up (the material and lights broadcast to every lane)
/// over 32 AVX2 batches, and stay in L1 (11 KB).
struct PixelQueue
{
  static constexpr int kCapacity = 256;
  int count = 0;
  float nx[kCapacity], ny[kCapacity], nz[kCapacity]; ///< interpolated normal, not unit
  float px[kCapacity], py[kCapacity], pz[kCapacity]; ///< world position (if used)
  float cr[kCapacity], cg[kCapacity], cb[kCapacity]; ///< diffuse colour (if per vertex)
  float* out[kCapacity];                             ///< the pixel's RGB

  /// Appends a pixel: its normal, position and colour (either may be left
  /// unused, by PixelUniforms), shaded into out[0..2]. True when the queue
  /// is then full.
  bool Push(const Vec3<float>& n, const Vec3<float>& P, const Vec3<float>& c, float* rgb)
  {
    const int k = this->count;
    this->nx[k] = n.x;
    this->ny[k] = n.y;
    this->nz[k] = n.z;
    this->px[k] = P.x;
    this->py[k] = P.y;
    this->pz[k] = P.z;
    this->cr[k] = c.x;
    this->cg[k] = c.y;
    this->cb[k] = c.z;
    this->out[k] = rgb;
    return ++this->count == kCapacity;
  }
};

/// What the model needs besides the pixels: the frame's uniforms.
struct PixelUniforms
{
  const Material<float>* material;
  const Lighting<float>* lighting;
  Vec3<float> eye, toEye;
  bool parallel;    ///< orthographic camera: V = toEye everywhere
  bool hasPosition; ///< px/py/pz are filled (else P = 0: directional lights, parallel view)
  bool hasColor;    ///< cr/cg/cb are filled (else the material's diffuse colour)
};

/// The model at one queued pixel, or at a batch of them (T an xsimd batch):
/// docs/model.md eq. 2.5, the interpolated normal renormalized first; V
/// towards the eye, or the view direction for a parallel camera. The one
/// formula of the scalar path and the wide kernels.
template <typename T>
inline Vec3<T> ShadeQueuedPixel(const Material<T>& material, const Lighting<T>& lighting,
  const Vec3<T>& eye, const Vec3<T>& toEye, bool parallel, const Vec3<T>& n, const Vec3<T>& P,
  const Vec3<T>& color)
{
  const Vec3<T> N = NormalizeOr(n, toEye);
  const Vec3<T> V = parallel ? toEye : NormalizeOr(eye - P, toEye);
  return Shade(material, lighting, color, P, N, V);
}

/// Shades and writes every queued pixel, then empties the queue.
void ShadeQueue(const PixelUniforms& uniforms, PixelQueue& queue);

/// PixelLanes() and SetPixelLanes() choose the kernel (SoftwareRenderer.h).

/// The kernels, one per instruction set, each in its own translation unit.
void ShadeQueueSse2(const PixelUniforms& uniforms, PixelQueue& queue);
void ShadeQueueAvx2(const PixelUniforms& uniforms, PixelQueue& queue);

} // namespace shadinglab::cpu
