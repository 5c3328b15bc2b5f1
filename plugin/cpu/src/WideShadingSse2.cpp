// SPDX-License-Identifier: BSD-3-Clause
// The wide pixel kernel, 4 lanes: SSE2, which every x86-64 CPU has.
#include "WideShadingKernel.h"

namespace shadinglab::cpu
{

void ShadeQueueSse2(const PixelUniforms& uniforms, PixelQueue& queue)
{
  ShadeQueueWith<xsimd::batch<float, xsimd::sse2>>(uniforms, queue);
}

} // namespace shadinglab::cpu
