// SPDX-License-Identifier: BSD-3-Clause
// Binning's per-polygon tests (Rasterizer::BinPolygon) on four triangles
// at once, with SSE2 (x86-64's baseline): their screen bounds, pixel rows,
// trivial reject, column test and facing, the same floats and doubles in
// the same order as the scalar tests, so that every triangle is binned,
// culled and counted exactly as one by one. Binning tests every triangle of
// a mesh every frame (a million on ParaView's sphere), and one by one its
// four ceil conversions were a third of its time.
#pragma once

#include "Raster.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <cfloat>
#include <limits>

namespace shadinglab::cpu
{

/// A vertex's screen position, depth and attribute scale (ScreenVertex's
/// x, y, a[kAttrZ], a[kAttrInvW]): all that binning reads of a vertex.
struct ProjectedVertex
{
  float x, y, z, invW;
};

/// Pixels added on each side of a polygon's x range by the column test
/// of binning: the plane scan computes each row's crossings in float from
/// an edge's endpoints, which can land a few ulps outside the vertices'
/// range (an ulp is 0.008 px at 65,536 px, the widest supersampled
/// frame); 1/16 px is well above that, and a polygon kept by the margin
/// only costs a set-up that finds no pixel. (The lecture's incremental
/// scan carries its crossings from row to row, its error growing with
/// the rows: no column test there.)
inline constexpr float kBinColumnMargin = 1.0f / 16.0f;

/// One polygon's binning tests (Rasterizer::BinPolygon's), from its
/// vertices' screen bounds: rows [j0, j1) (in [0, height]); rejected: left,
/// right or beyond the far plane (DrawPolygon's trivial reject, same test,
/// same floats); noColumn: no pixel centre i + 0.5 in [xmin, xmax) with
/// columnTest (Rasterizer::ColumnTest), as between rows; and twice its
/// signed area (raster::TwiceSignedArea), whose facing FacingOf reads.
struct PolygonTests
{
  int j0, j1;
  bool hasRow, rejected, noColumn;
  double twiceArea;
};

/// The scalar tests, for n vertices (N = n known at compile time, or 0).
/// TestFourTriangles computes them lane for lane.
template<int N = 0>
inline PolygonTests TestPolygon(
  const ProjectedVertex* const* sv, int n, int width, int height, bool columnTest)
{
  using raster::CeilToInt;
  const int count = N > 0 ? N : n;
  float ymin = std::numeric_limits<float>::infinity(), ymax = -ymin;
  float xmin = ymin, xmax = -ymin, zmin = ymin;
  for (int k = 0; k < count; ++k)
  {
    ymin = std::min(ymin, sv[k]->y);
    ymax = std::max(ymax, sv[k]->y);
    xmin = std::min(xmin, sv[k]->x);
    xmax = std::max(xmax, sv[k]->x);
    zmin = std::min(zmin, sv[k]->z);
  }
  PolygonTests t;
  t.j0 = std::max(0, CeilToInt(ymin - 0.5f));
  t.j1 = std::min(height, CeilToInt(ymax - 0.5f));
  t.hasRow = t.j1 > t.j0;
  t.rejected = (xmax < 0) | (xmin > width) | (zmin > 1.0f);
  t.noColumn = columnTest &
    (CeilToInt(xmax - 0.5f + kBinColumnMargin) <= CeilToInt(xmin - 0.5f - kBinColumnMargin));
  t.twiceArea = raster::TwiceSignedArea(sv, count);
  return t;
}

/// The tests of four triangles, lane t for triangle t: rows [j0, j1) (in
/// [0, height]), and bit t of each mask.
struct FourTriangleTests
{
  int j0[4], j1[4];
  int hasRow = 0, rejected = 0, noColumn = 0;
  int degenerate = 0; ///< FacingOf's Degenerate: no area, or not finite
  int back = 0;       ///< positive twice-signed area (y down): a back face
};

#if defined(__SSE2__)
/// raster::CeilToInt of four floats: clamped to +-1e9, truncated, plus one
/// where the value lies above its truncation (a NaN, unordered, stays
/// INT_MIN as the scalar conversion leaves it).
inline __m128i CeilToInt4(__m128 x)
{
  x = _mm_min_ps(_mm_set1_ps(1e9f), _mm_max_ps(_mm_set1_ps(-1e9f), x));
  const __m128i t = _mm_cvttps_epi32(x);
  const __m128i above = _mm_castps_si128(_mm_cmpgt_ps(x, _mm_cvtepi32_ps(t)));
  return _mm_sub_epi32(t, above); // above is -1 where set
}

/// v[k][t]: vertex k of triangle t. Always inlined: GCC kept it a call
/// once the rasterizer grew, which cost BM_CpuParaViewSphere ~2%. width, height: the frame's; columnTest:
/// Rasterizer::ColumnTest.
[[gnu::always_inline]] inline FourTriangleTests TestFourTriangles(
  const ProjectedVertex* const v[3][4], int width, int height, bool columnTest)
{
  __m128 x[3], y[3], z[3];
  for (int k = 0; k < 3; ++k)
  {
    __m128 r0 = _mm_loadu_ps(&v[k][0]->x), r1 = _mm_loadu_ps(&v[k][1]->x);
    __m128 r2 = _mm_loadu_ps(&v[k][2]->x), r3 = _mm_loadu_ps(&v[k][3]->x);
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
    x[k] = r0;
    y[k] = r1;
    z[k] = r2;
  }
  // std::min(m, v) from m = +inf over the three vertices, as the scalar
  // loop: (v < m) ? v : m is minps(v, m) (and std::max's (m < v) ? v : m
  // is maxps(v, m)), which keeps m where v is NaN, as std::min does.
  const __m128 inf = _mm_set1_ps(std::numeric_limits<float>::infinity());
  const __m128 ninf = _mm_set1_ps(-std::numeric_limits<float>::infinity());
  auto least = [&](const __m128* c)
  { return _mm_min_ps(c[2], _mm_min_ps(c[1], _mm_min_ps(c[0], inf))); };
  auto greatest = [&](const __m128* c)
  { return _mm_max_ps(c[2], _mm_max_ps(c[1], _mm_max_ps(c[0], ninf))); };
  const __m128 xmin = least(x), xmax = greatest(x);
  const __m128 ymin = least(y), ymax = greatest(y);
  const __m128 zmin = least(z);
  const __m128 half = _mm_set1_ps(0.5f);
  __m128i j0 = CeilToInt4(_mm_sub_ps(ymin, half));
  __m128i j1 = CeilToInt4(_mm_sub_ps(ymax, half));
  // max(0, j0) and min(height, j1) without SSE4.1's pmaxsd / pminsd.
  j0 = _mm_and_si128(j0, _mm_cmpgt_epi32(j0, _mm_setzero_si128()));
  const __m128i h = _mm_set1_epi32(height);
  const __m128i below = _mm_cmplt_epi32(j1, h);
  j1 = _mm_or_si128(_mm_and_si128(below, j1), _mm_andnot_si128(below, h));
  FourTriangleTests out;
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out.j0), j0);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out.j1), j1);
  out.hasRow = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(j1, j0)));
  out.rejected = _mm_movemask_ps(_mm_or_ps(_mm_or_ps(_mm_cmplt_ps(xmax, _mm_setzero_ps()),
    _mm_cmpgt_ps(xmin, _mm_set1_ps(static_cast<float>(width)))),
    _mm_cmpgt_ps(zmin, _mm_set1_ps(1.0f))));
  if (columnTest)
  {
    const __m128 margin = _mm_set1_ps(kBinColumnMargin);
    const __m128i right = CeilToInt4(_mm_add_ps(_mm_sub_ps(xmax, half), margin));
    const __m128i left = CeilToInt4(_mm_sub_ps(_mm_sub_ps(xmin, half), margin));
    out.noColumn = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(right, left))) ^ 0xF;
  }
  // raster::TwiceSignedArea in double, lanes {0, 1} then {2, 3}: the sum
  // from 0 over the edges (0, 1), (1, 2), (2, 0) of a.x b.y - b.x a.y.
  for (int half2 = 0; half2 < 2; ++half2)
  {
    __m128d xd[3], yd[3];
    for (int k = 0; k < 3; ++k)
    {
      xd[k] = _mm_cvtps_pd(half2 ? _mm_movehl_ps(x[k], x[k]) : x[k]);
      yd[k] = _mm_cvtps_pd(half2 ? _mm_movehl_ps(y[k], y[k]) : y[k]);
    }
    __m128d area = _mm_setzero_pd();
    for (int k = 0; k < 3; ++k)
    {
      const int n = k + 1 < 3 ? k + 1 : 0;
      area = _mm_add_pd(area,
        _mm_sub_pd(_mm_mul_pd(xd[k], yd[n]), _mm_mul_pd(xd[n], yd[k])));
    }
    // FacingOf: degenerate unless |area| / 2 >= kDegenerateArea and finite.
    const __m128d magnitude = _mm_andnot_pd(_mm_set1_pd(-0.0), area);
    const __m128d sized = _mm_and_pd(
      _mm_cmpge_pd(_mm_mul_pd(magnitude, _mm_set1_pd(0.5)), _mm_set1_pd(raster::kDegenerateArea)),
      _mm_cmple_pd(magnitude, _mm_set1_pd(DBL_MAX)));
    out.degenerate |= (_mm_movemask_pd(sized) ^ 0x3) << (2 * half2);
    out.back |= _mm_movemask_pd(_mm_cmpgt_pd(area, _mm_setzero_pd())) << (2 * half2);
  }
  return out;
}
#endif

} // namespace shadinglab::cpu
