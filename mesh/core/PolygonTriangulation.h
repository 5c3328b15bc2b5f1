// SPDX-License-Identifier: BSD-3-Clause
// Polygons as triangles that cover exactly what the polygon covers:
// concave ones, polygons with collinear runs, and weakly simple ones (a
// ring cut open by a slit whose two sides run over each other, "keyholes").
// Ear clipping (Meisters 1975; Eberly, "Triangulation by Ear Clipping",
// 2002) in the polygon's own plane, the way earcut.js takes holes bridged
// into slits; no VTK. The one triangulation of the CPU renderer's conversion
// and the GL mapper (docs/model.md section 3, "Polygons as they are").
#pragma once

#include "Geometry.h"

#include <cstdint>
#include <vector>

namespace shadinglab::mesh
{

/**
 * Triangulates polygon 0..n-1 (point(k) its k-th corner, any type with x,
 * y, z) by ear clipping in the plane of its Newell normal. Appends the
 * triangles to `triangles` as corner indices (three each, in the polygon's
 * winding). Corners that repeat their predecessor or lie on a straight run
 * make no triangle; the triangles' areas sum to the polygon's (a
 * non-planar polygon: to its projection's). Returns false, appending
 * nothing, for a polygon without area (fewer than three distinct corners
 * or all collinear). Non-simple polygons (edges crossing) get triangles
 * too, by the same rule, but not their even-odd area.
 */
template <typename PointAt>
bool TriangulatePolygon(int64_t n, PointAt&& point, std::vector<int64_t>& triangles);

/// True when every corner of polygon 0..n-1 turns the way its Newell
/// normal says (collinear corners allowed): a fan covers it exactly. (A
/// star polygon such as the pentagram also turns one way at every corner,
/// twice round; its edges cross and no triangles cover it alone: it is
/// fanned, as VTK fans it. --polygons direct scans it by the even-odd rule.)
template <typename PointAt>
bool IsConvexPolygon(int64_t n, PointAt&& point)
{
  auto at = [&](int64_t k) {
    const auto p = point(k % n);
    return Vec3<double>(p.x, p.y, p.z);
  };
  const Vec3<double> normal = NewellAreaVector<double>(n, at);
  for (int64_t k = 0; k < n; ++k)
  {
    const Vec3<double> a = at(k), b = at(k + 1), c = at(k + 2);
    if (Dot(Cross(b - a, c - b), normal) < 0)
    {
      return false;
    }
  }
  return true;
}

/// The 2D kernel: corners (x[k], y[k]) counter-clockwise.
bool TriangulateCounterClockwise(
  const std::vector<double>& x, const std::vector<double>& y, std::vector<int64_t>& triangles);

template <typename PointAt>
bool TriangulatePolygon(int64_t n, PointAt&& point, std::vector<int64_t>& triangles)
{
  if (n < 3)
  {
    return false;
  }
  const Vec3<double> N = NewellAreaVector<double>(n, [&](int64_t k) {
    const auto p = point(k);
    return Vec3<double>(p.x, p.y, p.z);
  });
  const double ax = std::abs(N.x), ay = std::abs(N.y), az = std::abs(N.z);
  if (!(ax + ay + az > 0))
  {
    return false;
  }
  // Project along the dominant axis, mirrored so the polygon runs
  // counter-clockwise in (u, v).
  const int drop = az >= ax && az >= ay ? 2 : (ay >= ax ? 1 : 0);
  const double sign = (drop == 2 ? N.z : drop == 1 ? N.y : N.x) > 0 ? 1.0 : -1.0;
  std::vector<double> u(static_cast<size_t>(n)), v(static_cast<size_t>(n));
  for (int64_t k = 0; k < n; ++k)
  {
    const auto p = point(k);
    const double c[3] = { static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(p.z) };
    // (u, v) = the two kept axes in cyclic order after `drop`: their cross
    // product is +drop, so sign makes the winding counter-clockwise.
    u[static_cast<size_t>(k)] = c[(drop + 1) % 3];
    v[static_cast<size_t>(k)] = sign * c[(drop + 2) % 3];
  }
  return TriangulateCounterClockwise(u, v, triangles);
}

} // namespace shadinglab::mesh
