// SPDX-License-Identifier: BSD-3-Clause
// Small 3-vector used by the shading model. Templated on the scalar so every
// formula exists in float (what the GPU and the CPU renderer use) and double
// (the reference the float path is tested against).
#pragma once

#include "shadinglab/model/Lanes.h"

#include <algorithm>
#include <cmath>


namespace shadinglab
{

template <typename T>
struct Vec3
{
  T x{}, y{}, z{};

  constexpr Vec3() = default;
  constexpr Vec3(T x_, T y_, T z_)
    : x(x_)
    , y(y_)
    , z(z_)
  {
  }
  template <typename U>
  constexpr explicit Vec3(const Vec3<U>& o)
    : x(static_cast<T>(o.x))
    , y(static_cast<T>(o.y))
    , z(static_cast<T>(o.z))
  {
  }

  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3 operator+(const Vec3& o) const { return { x + o.x, y + o.y, z + o.z }; }
  constexpr Vec3 operator-(const Vec3& o) const { return { x - o.x, y - o.y, z - o.z }; }
  constexpr Vec3 operator-() const { return { -x, -y, -z }; }
  constexpr Vec3 operator*(T s) const { return { x * s, y * s, z * s }; }
  constexpr Vec3 operator/(T s) const { return { x / s, y / s, z / s }; }
  // Component-wise product: colours (RGB) share this type.
  constexpr Vec3 operator*(const Vec3& o) const { return { x * o.x, y * o.y, z * o.z }; }
  Vec3& operator+=(const Vec3& o)
  {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  Vec3& operator*=(T s)
  {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
};

template <typename T>
constexpr Vec3<T> operator*(T s, const Vec3<T>& v)
{
  return v * s;
}

template <typename T>
constexpr T Dot(const Vec3<T>& a, const Vec3<T>& b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <typename T>
constexpr Vec3<T> Cross(const Vec3<T>& a, const Vec3<T>& b)
{
  return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}

template <typename T>
SL_INLINE T MaxAbsComponent(const Vec3<T>& v)
{
  return Max(Abs(v.x), Max(Abs(v.y), Abs(v.z)));
}

/// Per lane: c ? a : b, component-wise (model/Lanes.h).
template <typename T>
SL_INLINE Vec3<T> Select(const MaskOf<T>& c, const Vec3<T>& a, const Vec3<T>& b)
{
  return { Select(c, a.x, b.x), Select(c, a.y, b.y), Select(c, a.z, b.z) };
}

/// s > 0 and finite, for s a largest absolute component (never negative).
template <typename T>
SL_INLINE MaskOf<T> PositiveFinite(const T& s)
{
  return s > T(0) && s <= T(std::numeric_limits<ScalarOf<T>>::max());
}

/// Squared lengths inside [kSafeMinLengthSq, kSafeMaxLengthSq] are computed
/// directly; outside it (denormal or huge components, zero, NaN) the slow
/// path rescales first. The bounds sit a factor 1e8 inside float's normal
/// range (1.2e-38 .. 3.4e38) so the direct square cannot have under- or
/// overflowed.
template <typename T>
constexpr T kSafeMinLengthSq = T(1e-30);
template <typename T>
constexpr T kSafeMaxLengthSq = T(1e30);

template <typename T>
SL_INLINE T Length(const Vec3<T>& v)
{
  using S = ScalarOf<T>;
  const T d = Dot(v, v);
  const auto safe = d >= T(kSafeMinLengthSq<S>) && d <= T(kSafeMaxLengthSq<S>);
  if (AllOf(safe))
  {
    return Sqrt(d);
  }
  // Scale by the largest component first so neither huge (1e30f squared
  // overflows float) nor denormal components (whose squares flush to 0) lose
  // the length. Zero, NaN or infinite: s itself.
  const T s = MaxAbsComponent(v);
  const Vec3<T> u = v / s;
  return Select(safe, Sqrt(d), Select(PositiveFinite(s), s * Sqrt(Dot(u, u)), s));
}

/**
 * Unit vector along v, or `fallback` when v has no usable direction (zero,
 * NaN or infinite components). Robust against overflow and denormals: outside
 * the safe range the vector is scaled by its largest component before
 * squaring.
 */
template <typename T>
SL_INLINE Vec3<T> NormalizeOr(const Vec3<T>& v, const Vec3<T>& fallback)
{
  using S = ScalarOf<T>;
  const T d = Dot(v, v);
  const auto safe = d >= T(kSafeMinLengthSq<S>) && d <= T(kSafeMaxLengthSq<S>);
  const Vec3<T> direct = v * (T(1) / Sqrt(d));
  if (AllOf(safe))
  {
    return direct;
  }
  const T s = MaxAbsComponent(v);
  const Vec3<T> u = v / s;
  return Select(safe, direct, Select(PositiveFinite(s), u / Sqrt(Dot(u, u)), fallback));
}

template <typename T>
bool IsFinite(const Vec3<T>& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Mirror direction of L about N (both unit, pointing away from the surface).
template <typename T>
constexpr Vec3<T> Reflect(const Vec3<T>& L, const Vec3<T>& N)
{
  return N * (T(2) * Dot(N, L)) - L;
}

using Vec3f = Vec3<float>;
using Vec3d = Vec3<double>;
using RGBf = Vec3<float>;
using RGBd = Vec3<double>;

} // namespace shadinglab
