// SPDX-License-Identifier: BSD-3-Clause
// The model's arithmetic on SIMD batches of floats (xsimd, Debian's
// libxsimd-dev): LaneTraits for xsimd::batch<float, Arch>, so every model
// formula (Shade, EvaluateBrdf and their terms) runs on 4 (SSE2) or 8
// (AVX2) pixels at once. Only the CPU renderer's wide pixel stage includes
// this header, once per instruction set, each in its own translation unit
// compiled for it (plugin/cpu/src/WideShading*.cpp).
//
// Why xsimd: header-only, packaged by Debian 12 (8.1), and it has the
// vector pow, exp and cos the model needs with stated accuracy (a few ulp:
// docs/model.md section 2 gives the bound the tests hold the images to).
// Highway 1.0 (Debian's libhwy-dev) has no pow; hand-written intrinsics
// would be a second copy of the model's maths per instruction set.
#pragma once

#include "shadinglab/model/Lanes.h"

#include <xsimd/xsimd.hpp>

namespace shadinglab
{

template <typename A>
struct LaneTraits<xsimd::batch<float, A>>
{
  using T = xsimd::batch<float, A>;
  using Scalar = float;
  using Mask = xsimd::batch_bool<float, A>;

  static T Select(const Mask& c, const T& a, const T& b) { return xsimd::select(c, a, b); }
  static T Min(const T& a, const T& b) { return xsimd::min(a, b); }
  static T Max(const T& a, const T& b) { return xsimd::max(a, b); }
  static T Clamp(const T& v, const T& lo, const T& hi) { return xsimd::min(xsimd::max(v, lo), hi); }
  static T Abs(const T& a) { return xsimd::abs(a); }
  static T Sqrt(const T& a) { return xsimd::sqrt(a); }
  static T Pow(const T& a, const T& b) { return xsimd::pow(a, b); }
  static T Exp(const T& a) { return xsimd::exp(a); }
  static T Cos(const T& a) { return xsimd::cos(a); }
  static Mask IsFinite(const T& a) { return xsimd::isfinite(a); }
};

} // namespace shadinglab
