// SPDX-License-Identifier: BSD-3-Clause
// Fast Phong shading: Bishop & Weimer 1986, "Fast Phong Shading",
// SIGGRAPH '86, pp. 103-106.
//
// Over a triangle the interpolated, unnormalized normal is affine in screen
// coordinates, N(x, y) = A x + B y + C, so the Lambert term
//
//   I(x, y) = (L.N) / |N|
//           = (a x + b y + c) / sqrt(d x^2 + e x y + f y^2 + g x + h y + i)
//
// with a = L.A, b = L.B, c = L.C, d = A.A, e = 2 A.B, f = B.B, g = 2 A.C,
// h = 2 B.C, i = C.C. Bishop & Weimer replace I by its second-order Taylor
// expansion about a point (x0, y0) of the triangle,
//
//   I ~ T5 u^2 + T4 u v + T3 v^2 + T2 u + T1 v + T0,   u = x - x0, v = y - y0,
//
// and evaluate it along a scanline by forward differences: two additions per
// pixel. The specular term is treated the same way with H in place of L and
// then raised to the power n.
//
// Derivation (ours; the paper gives the result in its own notation). Write
// the numerator n(u,v) = n0 + a u + b v with n0 = a x0 + b y0 + c, and the
// denominator q(u,v) = q0 + qx u + qy v + d u^2 + e u v + f v^2 with
// q0 = |N(x0,y0)|^2, qx = 2 d x0 + e y0 + g, qy = e x0 + 2 f y0 + h. With
// s = (q - q0)/q0, q^(-1/2) = q0^(-1/2) (1 - s/2 + 3 s^2/8 + O(s^3)).
// Keeping terms up to second order in (u, v), with r = q0^(-1/2),
// px = qx/q0, py = qy/q0:
//   T0 = r n0
//   T2 = r (a - n0 px / 2)                         (u)
//   T1 = r (b - n0 py / 2)                         (v)
//   T5 = r (-a px / 2 - n0 d / (2 q0) + 3 n0 px^2 / 8)                 (u^2)
//   T4 = r (-(a py + b px) / 2 - n0 e / (2 q0) + 3 n0 px py / 4)      (u v)
//   T3 = r (-b py / 2 - n0 f / (2 q0) + 3 n0 py^2 / 8)                 (v^2)
// The remainder is third order in the normal's variation over the triangle,
// so the error falls as (spread)^3: tested in tests/FastPhongTest.
#pragma once

#include "shadinglab/model/Constants.h"
#include "shadinglab/model/Vec3.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace shadinglab
{

/// Where the Taylor expansion is taken. Bishop & Weimer expand about a
/// vertex: we take the triangle's last vertex, OpenGL's provoking vertex, so
/// the CPU renderer and the GPU mapper expand about the same point. The
/// centroid halves the largest distance to any point of the triangle and so
/// reduces the error (CPU only: a fragment shader has no centroid without a
/// geometry shader).
enum class ExpansionPoint
{
  Vertex,
  Centroid,
};

/// T5 u^2 + T4 u v + T3 v^2 + T2 u + T1 v + T0 about (x0, y0).
template <typename T>
struct FastPhongQuadratic
{
  T x0 = T(0), y0 = T(0);
  T T0 = T(0), T1 = T(0), T2 = T(0), T3 = T(0), T4 = T(0), T5 = T(0);

  T Evaluate(T x, T y) const
  {
    const T u = x - x0;
    const T v = y - y0;
    return ((T5 * u + T4 * v + T2) * u) + ((T3 * v + T1) * v) + T0;
  }
};

/**
 * Forward differencing of a FastPhongQuadratic along one scanline (fixed y),
 * stepping x by 1: I_{p+1} = I_p + dI, dI_{p+1} = dI_p + ddI.
 * Along the line I(u) = P u^2 + Q u + R with P = T5, Q = T2 + T4 v,
 * R = T0 + T1 v + T3 v^2; dI(u) = P (2u + 1) + Q and ddI = 2P.
 */
template <typename T>
struct FastPhongScanline
{
  T value = T(0);
  T delta = T(0);
  T delta2 = T(0);

  void Begin(const FastPhongQuadratic<T>& q, T x, T y)
  {
    const T u = x - q.x0;
    const T v = y - q.y0;
    const T P = q.T5;
    const T Q = q.T2 + q.T4 * v;
    const T R = q.T0 + (q.T1 + q.T3 * v) * v;
    value = (P * u + Q) * u + R;
    delta = P * (T(2) * u + T(1)) + Q;
    delta2 = T(2) * P;
  }

  /// Current value, then advance one pixel: two additions.
  T Next()
  {
    const T current = value;
    value += delta;
    delta += delta2;
    return current;
  }
};

/// The affine normal field N(x, y) = A x + B y + C of one screen triangle.
template <typename T>
struct FastPhongTriangle
{
  Vec3<T> A, B, C;
  T centroidX = T(0), centroidY = T(0);
  T vertexX = T(0), vertexY = T(0);
  /// False when the screen triangle was degenerate and N is constant.
  bool affine = false;

  /**
   * Solves N(x_i, y_i) = N_i for the three vertices (screen coordinates in
   * pixels, vertex normals not necessarily unit). A triangle with screen
   * area below kMinScreenArea gets the constant average normal.
   */
  void Setup(const T x[3], const T y[3], const Vec3<T> normals[3])
  {
    centroidX = (x[0] + x[1] + x[2]) / T(3);
    centroidY = (y[0] + y[1] + y[2]) / T(3);
    vertexX = x[2];
    vertexY = y[2];
    // Solve in coordinates relative to vertex 0 for conditioning.
    const T x1 = x[1] - x[0], y1 = y[1] - y[0];
    const T x2 = x[2] - x[0], y2 = y[2] - y[0];
    const T det = x1 * y2 - x2 * y1; // twice the signed area
    if (std::abs(det) < T(2) * kMinScreenArea<T>)
    {
      A = B = Vec3<T>();
      C = (normals[0] + normals[1] + normals[2]) / T(3);
      affine = false;
      return;
    }
    const Vec3<T> dn1 = normals[1] - normals[0];
    const Vec3<T> dn2 = normals[2] - normals[0];
    A = (dn1 * y2 - dn2 * y1) / det;
    B = (dn2 * x1 - dn1 * x2) / det;
    C = normals[0] - A * x[0] - B * y[0];
    affine = true;
  }

  /// The interpolated (unnormalized) normal at (x, y).
  Vec3<T> Normal(T x, T y) const { return A * x + B * y + C; }

  /**
   * The exact-shading rule of both backends (docs/model.md eq. 2.9): at
   * (x, y) the quadratic is trusted while the interpolated normal stays
   * within the spread limit of N0, the normal at the expansion point:
   * cos(N0, N(x, y)) >= minCos. Per pixel, because a fragment shader sees
   * only its own normal; the same test in sl_mapper_fs_impl.glsl.
   */
  bool WithinSpread(const Vec3<T>& N0, T x, T y, T minCos) const
  {
    // cos = d / sqrt(q) >= minCos, compared squared: no square root or
    // division per pixel (the GLSL twin divides; the two agree but for
    // rounding exactly at the limit).
    const Vec3<T> N = Normal(x, y);
    const T d = Dot(N0, N);
    const T q = std::max(Dot(N0, N0) * Dot(N, N), kMinNormalLengthSq<T> * kMinNormalLengthSq<T>);
    const T bound = minCos * minCos * q;
    return minCos >= T(0) ? (d >= T(0) && d * d >= bound) : (d >= T(0) || d * d <= bound);
  }

  /// Exact (L.N)/|N| at (x, y): what Phong shading computes. A normal with
  /// no direction (|N|^2 < kMinNormalLengthSq) gives 0.
  T Exact(const Vec3<T>& L, T x, T y) const
  {
    const Vec3<T> N = Normal(x, y);
    const T q = Dot(N, N);
    if (!(q >= kMinNormalLengthSq<T>))
    {
      return T(0);
    }
    return Dot(L, N) / std::sqrt(q);
  }

  /// The second-order expansion of (L.N)/|N| about the chosen point.
  FastPhongQuadratic<T> Expand(const Vec3<T>& L, ExpansionPoint where) const
  {
    return where == ExpansionPoint::Centroid ? ExpandAbout(L, centroidX, centroidY)
                                             : ExpandAbout(L, vertexX, vertexY);
  }

  FastPhongQuadratic<T> ExpandAbout(const Vec3<T>& L, T x0, T y0) const
  {
    FastPhongQuadratic<T> out;
    out.x0 = x0;
    out.y0 = y0;
    const T a = Dot(L, A), b = Dot(L, B), c = Dot(L, C);
    const T d = Dot(A, A), e = T(2) * Dot(A, B), f = Dot(B, B);
    const T g = T(2) * Dot(A, C), h = T(2) * Dot(B, C);
    const Vec3<T> N0 = Normal(x0, y0);
    const T q0 = Dot(N0, N0);
    if (!(q0 >= kMinNormalLengthSq<T>))
    {
      return out; // no direction at the expansion point: intensity 0
    }
    const T n0 = a * x0 + b * y0 + c;
    const T qx = T(2) * d * x0 + e * y0 + g;
    const T qy = e * x0 + T(2) * f * y0 + h;
    const T r = T(1) / std::sqrt(q0);
    const T px = qx / q0, py = qy / q0;
    out.T0 = r * n0;
    out.T2 = r * (a - T(0.5) * n0 * px);
    out.T1 = r * (b - T(0.5) * n0 * py);
    out.T5 = r * (-T(0.5) * a * px - T(0.5) * n0 * d / q0 + T(0.375) * n0 * px * px);
    out.T4 = r * (-T(0.5) * (a * py + b * px) - T(0.5) * n0 * e / q0 + T(0.75) * n0 * px * py);
    out.T3 = r * (-T(0.5) * b * py - T(0.5) * n0 * f / q0 + T(0.375) * n0 * py * py);
    return out;
  }
};

} // namespace shadinglab

namespace shadinglab
{

/**
 * x^n for x in [0, 1] by table lookup with linear interpolation, as Bishop &
 * Weimer evaluate the specular power. The table spans [x0, 1] where
 * x0^n = kPowTableFloor (below it the term is returned as 0), with a step
 * chosen so that the interpolation error, bounded by n(n-1) h^2 / 8 near
 * x = 1, stays under kPowTableTolerance.
 */
class SpecularPowerTable
{
public:
  /// Values of x^n below this are 0: 1e-6 of the peak is 4e-4 of one 8-bit
  /// display step even at the largest normalization (n + 8)/(8 pi) ~ 400.
  static constexpr double kPowTableFloor = 1e-6;
  /// Target interpolation error (absolute, relative to the peak 1).
  static constexpr double kPowTableTolerance = 1e-5;
  /// Entries cap: 4096 floats (16 KiB) stay in L1 cache.
  static constexpr int kMaxEntries = 4096;

  void Build(double n)
  {
    this->Exponent = n;
    // X0 rounded to float first: lookups subtract the float X0 from a float
    // x, and at n = 1e4 one float ulp of offset would shift values by 6e-4.
    this->X0 = static_cast<float>(n > 0 ? std::pow(kPowTableFloor, 1.0 / n) : 0.0);
    const double h = n > 1 ? std::sqrt(8.0 * kPowTableTolerance / (n * (n - 1))) : 1.0;
    int entries = static_cast<int>(std::ceil((1.0 - this->X0) / h)) + 1;
    entries = std::max(2, std::min(entries, kMaxEntries));
    this->Values.resize(static_cast<size_t>(entries));
    this->Step = (1.0 - this->X0) / (entries - 1);
    this->InvStep = static_cast<float>(1.0 / this->Step);
    for (int i = 0; i < entries; ++i)
    {
      this->Values[i] = static_cast<float>(std::pow(this->X0 + i * this->Step, n));
    }
    this->X0f = static_cast<float>(this->X0);
  }

  float Lookup(float x) const
  {
    if (!(x > this->X0f))
    {
      return 0.0f;
    }
    if (x >= 1.0f)
    {
      return 1.0f;
    }
    const float t = (x - this->X0f) * this->InvStep;
    const int i = std::min(static_cast<int>(t), static_cast<int>(this->Values.size()) - 2);
    const float f = t - static_cast<float>(i);
    return this->Values[i] + f * (this->Values[i + 1] - this->Values[i]);
  }

  int Size() const { return static_cast<int>(this->Values.size()); }

private:
  double Exponent = 1.0, X0 = 0.0, Step = 1.0;
  float X0f = 0.0f, InvStep = 1.0f;
  std::vector<float> Values;
};

} // namespace shadinglab
