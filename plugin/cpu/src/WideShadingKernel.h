// SPDX-License-Identifier: BSD-3-Clause
// The wide kernel of WideShading.h: the model's Shade() on a batch type B
// (xsimd::batch<float, Arch>, model/WideLanes.h). Included only by
// WideShadingSse2.cpp and WideShadingAvx2.cpp, each compiled for its
// instruction set with -ffp-contract=off, so +, -, *, / and sqrt round as in
// the scalar model and only pow, exp and cos (xsimd's, not libm's) differ.
#pragma once

#include "WideShading.h"

#include "shadinglab/model/WideLanes.h"

namespace shadinglab::cpu
{

template <typename B>
void ShadeQueueWith(const PixelUniforms& u, PixelQueue& q)
{
  constexpr int W = static_cast<int>(B::size);
  if (q.count == 0)
  {
    return;
  }
  // The frame's uniforms in every lane, once per queue.
  const Material<B> material = u.material->template Cast<B>();
  const Lighting<B> lighting = u.lighting->template Cast<B>();
  const Vec3<B> toEye(u.toEye), eye(u.eye);
  const Vec3<B> diffuse(u.material->diffuseColor);
  // The last batch is padded with copies of the last pixel (results dropped).
  const int last = q.count - 1;
  for (int k = q.count; k % W != 0; ++k)
  {
    q.nx[k] = q.nx[last];
    q.ny[k] = q.ny[last];
    q.nz[k] = q.nz[last];
    q.px[k] = q.px[last];
    q.py[k] = q.py[last];
    q.pz[k] = q.pz[last];
    q.cr[k] = q.cr[last];
    q.cg[k] = q.cg[last];
    q.cb[k] = q.cb[last];
  }
  for (int k = 0; k < q.count; k += W)
  {
    const Vec3<B> n(B::load_unaligned(q.nx + k), B::load_unaligned(q.ny + k),
      B::load_unaligned(q.nz + k));
    Vec3<B> P;
    if (u.hasPosition)
    {
      P = Vec3<B>(B::load_unaligned(q.px + k), B::load_unaligned(q.py + k),
        B::load_unaligned(q.pz + k));
    }
    const Vec3<B> color = u.hasColor
      ? Vec3<B>(B::load_unaligned(q.cr + k), B::load_unaligned(q.cg + k),
          B::load_unaligned(q.cb + k))
      : diffuse;
    const Vec3<B> I = ShadeQueuedPixel(material, lighting, eye, toEye, u.parallel, n, P, color);
    alignas(32) float r[W], g[W], b[W];
    I.x.store_aligned(r);
    I.y.store_aligned(g);
    I.z.store_aligned(b);
    const int lanes = std::min(W, q.count - k);
    for (int i = 0; i < lanes; ++i)
    {
      float* out = q.out[k + i];
      out[0] = r[i];
      out[1] = g[i];
      out[2] = b[i];
    }
  }
  q.count = 0;
}

} // namespace shadinglab::cpu
