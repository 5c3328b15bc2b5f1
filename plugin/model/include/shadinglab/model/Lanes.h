// SPDX-License-Identifier: BSD-3-Clause
// The model's arithmetic on one value or on a batch of SIMD lanes.
//
// Every formula of the model is a template over its number type T: float
// and double (the GPU's precision and the reference's), and, in the CPU
// renderer's pixel stage, a batch of 4 or 8 floats (model/WideLanes.h, on
// xsimd). A batch cannot branch per lane, so the model's guards are written
// as selects, as its GLSL twin already is:
//
//   const auto lit = NoL > T(0);                // a bool, or a lane mask
//   if (!AnyOf(lit)) return T(0);               // every lane out: skip the work
//   return Select(lit, value, T(0));            // else per lane
//
// For one value Select is the conditional operator and AnyOf the bool
// itself, so the scalar model computes exactly what it computed with early
// returns (same operations, same order: bit-identical results).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

/// Forces inlining of the small model functions into the renderers' pixel
/// loops, where the compiler's own heuristics give up on the nested calls
/// (measured: the per-pixel Shade() chain stayed out of line at -O3).
#if defined(__GNUC__) || defined(__clang__)
#define SL_INLINE inline __attribute__((always_inline))
#else
#define SL_INLINE inline
#endif

namespace shadinglab
{

/// What a number type is made of: its scalar and its comparison result.
/// Specialized for SIMD batches in model/WideLanes.h.
template <typename T>
struct LaneTraits
{
  using Scalar = T;
  using Mask = bool;

  static T Select(bool c, T a, T b) { return c ? a : b; }
  static T Min(T a, T b) { return std::min(a, b); }
  static T Max(T a, T b) { return std::max(a, b); }
  static T Clamp(T v, T lo, T hi) { return std::clamp(v, lo, hi); }
  static T Abs(T a) { return std::abs(a); }
  static T Sqrt(T a) { return std::sqrt(a); }
  static T Pow(T a, T b) { return std::pow(a, b); }
  static T Exp(T a) { return std::exp(a); }
  static T Cos(T a) { return std::cos(a); }
  static bool IsFinite(T a) { return std::isfinite(a); }
};

template <typename T>
using ScalarOf = typename LaneTraits<T>::Scalar;
template <typename T>
using MaskOf = typename LaneTraits<T>::Mask;

/// Per lane: c ? a : b (both sides are evaluated for a batch).
template <typename T>
SL_INLINE T Select(const MaskOf<T>& c, const T& a, const T& b)
{
  return LaneTraits<T>::Select(c, a, b);
}
template <typename T>
SL_INLINE T Min(const T& a, const T& b)
{
  return LaneTraits<T>::Min(a, b);
}
template <typename T>
SL_INLINE T Max(const T& a, const T& b)
{
  return LaneTraits<T>::Max(a, b);
}
/// std::clamp for one value (NaN stays NaN), min(max()) for a batch.
template <typename T>
SL_INLINE T Clamp(const T& v, const T& lo, const T& hi)
{
  return LaneTraits<T>::Clamp(v, lo, hi);
}
template <typename T>
SL_INLINE T Abs(const T& a)
{
  return LaneTraits<T>::Abs(a);
}
template <typename T>
SL_INLINE T Sqrt(const T& a)
{
  return LaneTraits<T>::Sqrt(a);
}
template <typename T>
SL_INLINE T Pow(const T& a, const T& b)
{
  return LaneTraits<T>::Pow(a, b);
}
template <typename T>
SL_INLINE T Exp(const T& a)
{
  return LaneTraits<T>::Exp(a);
}
template <typename T>
SL_INLINE T Cos(const T& a)
{
  return LaneTraits<T>::Cos(a);
}
template <typename T>
SL_INLINE MaskOf<T> IsFinite(const T& a)
{
  return LaneTraits<T>::IsFinite(a);
}
/// Whether any / every lane of a mask is set (the bool itself for one value).
template <typename M>
SL_INLINE bool AnyOf(const M& m)
{
  if constexpr (std::is_same_v<M, bool>)
  {
    return m;
  }
  else
  {
    return any(m); // found by argument-dependent lookup in the SIMD library
  }
}
template <typename M>
SL_INLINE bool AllOf(const M& m)
{
  if constexpr (std::is_same_v<M, bool>)
  {
    return m;
  }
  else
  {
    return all(m);
  }
}

} // namespace shadinglab
