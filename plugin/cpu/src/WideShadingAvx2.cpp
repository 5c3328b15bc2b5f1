// SPDX-License-Identifier: BSD-3-Clause
// The wide pixel kernel, 8 lanes: AVX2 with FMA. This file alone is compiled
// with -mavx2 -mfma; it is only called when the CPU has both (WideShading.cpp).
// xsimd's cos argument reduction for huge angles is a plain inline function
// (not a template on the instruction set): its AVX2 copy here could be the
// one the linker keeps for the SSE2 kernel too, and fault on a CPU without
// AVX2. Renamed in this file only. WideShadingSymbolsTest checks that this
// object defines no other shared symbol.
#define __kernel_rem_pio2 sl_avx2_kernel_rem_pio2
#define __ieee754_rem_pio2 sl_avx2_ieee754_rem_pio2
#include "WideShadingKernel.h"

namespace shadinglab::cpu
{

void ShadeQueueAvx2(const PixelUniforms& uniforms, PixelQueue& queue)
{
  ShadeQueueWith<xsimd::batch<float, xsimd::fma3<xsimd::avx2>>>(uniforms, queue);
}

} // namespace shadinglab::cpu
