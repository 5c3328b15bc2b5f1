// SPDX-License-Identifier: BSD-3-Clause
// The small geometry kernel every mesh algorithm shares (normals, repair,
// subdivision, the renderers' flat shading): the polygon area vector and the
// vector type. Header-only, no VTK; the vector is the model's Vec3, the
// project's one vector type.
#pragma once

#include "TwoThreads.h"
#include "shadinglab/model/Vec3.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace shadinglab::mesh
{

/// The one view of a polygon mesh the algorithms in mesh/ take: borrowed
/// flat arrays, polygon p using connectivity[offsets[p] .. offsets[p+1]).
/// Points in double (MeshView), or in float where a kernel reads a file's
/// float points in place (FloatMeshView: the vertex normals, which widen
/// each coordinate as they load it, so the same bits as from a double copy).
/// Ids in int64 (MeshView), or in int32 where a kernel reads a 32-bit
/// vtkCellArray in place (NarrowMeshView: the fast readers' cells, half
/// the memory of 64-bit ones).
template <typename Real, typename Id = int64_t>
struct MeshViewOf
{
  const Real* points = nullptr; ///< 3 per point
  int64_t numberOfPoints = 0;
  const Id* offsets = nullptr; ///< numberOfPolygons + 1 entries
  const Id* connectivity = nullptr;
  int64_t numberOfPolygons = 0;
};
using MeshView = MeshViewOf<double>;
using FloatMeshView = MeshViewOf<float>;
using NarrowMeshView = MeshViewOf<double, int32_t>;
using FloatNarrowMeshView = MeshViewOf<float, int32_t>;

/// Faces whose Newell area is below this fraction of the squared bounding
/// diagonal are degenerate. 1e-20 is ~100x double's epsilon squared (the
/// relative rounding of an area computed from coordinates of that scale),
/// so only faces that are zero up to rounding count as degenerate.
constexpr double kDegenerateRelativeArea = 1e-20;

/**
 * Newell's method (Newell 1972, as given by Sutherland, Sproull & Schumacker
 * 1974): the area vector of a polygon of n vertices, twice its area times
 * its unit normal for a planar polygon and a least-squares normal otherwise.
 * `point(k)` returns vertex k as a Vec3<T>; the sum runs over the edges
 * (k, k + 1 mod n) in order, so results are reproducible bit for bit.
 */
template <typename T, typename PointAt>
Vec3<T> NewellAreaVector(int64_t n, PointAt&& point)
{
  Vec3<T> N(T(0), T(0), T(0));
  for (int64_t k = 0; k < n; ++k)
  {
    const Vec3<T> a = point(k), b = point(k + 1 < n ? k + 1 : 0);
    N += Vec3<T>((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return N;
}

/// The area vector of a triangle: (p1 - p0) x (p2 - p0), twice its area
/// times its unit normal (equal to NewellAreaVector up to rounding).
template <typename T>
Vec3<T> TriangleAreaVector(const Vec3<T>& p0, const Vec3<T>& p1, const Vec3<T>& p2)
{
  return Cross(p1 - p0, p2 - p0);
}

/// Vertex i of a flat xyz array as a Vec3.
template <typename T>
Vec3<T> PointOf(const T* points, int64_t i)
{
  return Vec3<T>(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
}

/// Points from which PointBox splits its pass between two threads: a
/// thread's start (~50 us) is under a tenth of the pass over 2^20 points.
constexpr int64_t kParallelBoxPoints = int64_t(1) << 20;

/// The axis-aligned box (xmin, xmax, ymin, ymax, zmin, zmax) of n points
/// given as 3 T each, NaN coordinates skipped as vtkPoints::GetBounds
/// skips them; an empty box (min > max) for none. No VTK: the readers'
/// check and the renderers' conversion of 16M-point meshes. From
/// kParallelBoxPoints the two halves are boxed by two threads and joined
/// by the same comparison, first half first: the serial pass's result,
/// bit for bit (of equal values such as -0 and 0 the first is kept).
template <typename T>
void PointBox(const T* xyz, int64_t n, double box[6])
{
  auto pass = [xyz](int64_t i0, int64_t i1, T lo[3], T hi[3]) {
    for (int c = 0; c < 3; ++c)
    {
      lo[c] = std::numeric_limits<T>::infinity();
      hi[c] = -lo[c];
    }
    for (int64_t i = i0; i < i1; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        const T v = xyz[3 * i + c];
        lo[c] = v < lo[c] ? v : lo[c]; // NaN compares false: skipped
        hi[c] = v > hi[c] ? v : hi[c];
      }
    }
  };
  T lo[3], hi[3], lo2[3], hi2[3];
  const int64_t half = n < kParallelBoxPoints ? n : n / 2;
  RunBoth(half < n, [&] { pass(0, half, lo, hi); }, [&] { pass(half, n, lo2, hi2); });
  for (int c = 0; c < 3; ++c)
  {
    lo[c] = lo2[c] < lo[c] ? lo2[c] : lo[c];
    hi[c] = hi2[c] > hi[c] ? hi2[c] : hi[c];
  }
  for (int c = 0; c < 3; ++c)
  {
    box[2 * c] = static_cast<double>(lo[c]);
    box[2 * c + 1] = static_cast<double>(hi[c]);
  }
}

/// Root of v's set in a union-find forest (parent[v] == v at a root), with
/// path halving.
template <typename Index>
Index UnionFindRoot(std::vector<Index>& parent, Index v)
{
  while (parent[v] != v)
  {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

} // namespace shadinglab::mesh
