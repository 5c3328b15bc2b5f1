// SPDX-License-Identifier: BSD-3-Clause
// The per-polygon and per-corner arithmetic of vertex normals that the
// crease-free pass (VertexNormals.cxx) and the crease pass
// (CreaseNormals.cxx) share: one home, so both give the same bits.
// Internal to mesh/core.
#pragma once

#include "Geometry.h"
#include "VertexNormals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace shadinglab::mesh::kernels
{

/// A weight (area, angle, ...) below this contributes nothing: a face of
/// area 1e-300 has no direction worth averaging, and squaring edge lengths
/// in Max's weight must not overflow into Inf. 1e-300 is far below any
/// real mesh's scale yet above double's smallest normal (2.2e-308).
constexpr double kTinyWeight = 1e-300;

/// The project's one vector type (the model's Vec3, in double).
using V3 = Vec3<double>;

/// a - b, each coordinate widened to double as it is loaded (float
/// points give the bits a double copy of them gives).
template <typename Real>
V3 Sub(const Real* a, const Real* b)
{
  return { double(a[0]) - double(b[0]), double(a[1]) - double(b[1]), double(a[2]) - double(b[2]) };
}

/// Point i in double.
template <typename Real>
V3 PointAt(const Real* points, int64_t i)
{
  return { double(points[3 * i]), double(points[3 * i + 1]), double(points[3 * i + 2]) };
}

/// Area vector of the polygon of n corners from corner b: twice its area
/// times the unit normal (Geometry.h).
template <typename Real, typename Id>
V3 AreaVectorAt(const MeshViewOf<Real, Id>& m, int64_t b, int64_t n)
{
  if (n == 3)
  {
    const Real* p0 = m.points + 3 * int64_t(m.connectivity[b]);
    const Real* p1 = m.points + 3 * int64_t(m.connectivity[b + 1]);
    const Real* p2 = m.points + 3 * int64_t(m.connectivity[b + 2]);
    return Cross(Sub(p1, p0), Sub(p2, p0));
  }
  return NewellAreaVector<double>(
    n, [&](int64_t k) { return PointAt(m.points, m.connectivity[b + k]); });
}

/// Area vector of polygon p.
template <typename Real, typename Id>
V3 AreaVector(const MeshViewOf<Real, Id>& m, int64_t p)
{
  return AreaVectorAt(m, m.offsets[p], m.offsets[p + 1] - m.offsets[p]);
}

/// The contribution of polygon p's corner k (vertex connectivity[b + k]).
template <typename Real, typename Id>
V3 CornerContribution(const MeshViewOf<Real, Id>& m,
  int64_t b,
  int64_t n,
  int64_t k,
  const V3& areaVector,
  double areaLength,
  NormalWeighting w)
{
  switch (w)
  {
    case NormalWeighting::Area:
      return areaVector;
    case NormalWeighting::Uniform:
    {
      if (areaLength < kTinyWeight)
      {
        return { 0, 0, 0 };
      }
      const double s = 1.0 / areaLength;
      return { areaVector.x * s, areaVector.y * s, areaVector.z * s };
    }
    case NormalWeighting::Angle:
    case NormalWeighting::Max:
    {
      const Real* v = m.points + 3 * int64_t(m.connectivity[b + k]);
      const Real* prev = m.points + 3 * int64_t(m.connectivity[b + (k + n - 1) % n]);
      const Real* next = m.points + 3 * int64_t(m.connectivity[b + (k + 1) % n]);
      const V3 e1 = Sub(next, v), e2 = Sub(prev, v);
      const double l1 = Dot(e1, e1), l2 = Dot(e2, e2);
      if (l1 < kTinyWeight || l2 < kTinyWeight || areaLength < kTinyWeight)
      {
        return { 0, 0, 0 };
      }
      if (w == NormalWeighting::Max)
      {
        // Max 1999, "Weights for Computing Vertex Normals from Facet
        // Normals", eq. 5: (e1 x e2) / (|e1|^2 |e2|^2).
        const V3 c = Cross(e1, e2);
        const double s = 1.0 / (l1 * l2);
        return { c.x * s, c.y * s, c.z * s };
      }
      // Thurmer & Wuthrich 1998: angle at the corner times the unit normal.
      const double cosA = std::clamp(Dot(e1, e2) / std::sqrt(l1 * l2), -1.0, 1.0);
      const double s = AcosAbramowitzStegun(cosA) / areaLength;
      return { areaVector.x * s, areaVector.y * s, areaVector.z * s };
    }
  }
  return { 0, 0, 0 };
}

inline void Normalize(double* n)
{
  const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (l > kTinyWeight && std::isfinite(l))
  {
    n[0] /= l;
    n[1] /= l;
    n[2] /= l;
  }
  else
  {
    n[0] = 0;
    n[1] = 0;
    n[2] = 1;
  }
}

} // namespace shadinglab::mesh::kernels
