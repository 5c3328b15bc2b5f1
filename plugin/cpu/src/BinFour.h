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

/// Triangles of at most this many pixel rows get binning's span test
/// (TestPolygon). On ParaView's 1M sphere at 1080p, of the ~409,000
/// triangles in view that reach a pixel row and column, those of one row
/// are half and those of two nearly all the rest: ~200,000 two-row ones,
/// 76,000 of them with no pixel centre inside and 102,000 with one. Three
/// rows take in the few thousand more of a pixel or none; beyond that a
/// triangle mostly has pixels, and the test would only cost.
inline constexpr int kBinSpanRows = 3;

/// One polygon's binning tests (Rasterizer::BinPolygon's), from its
/// vertices' screen bounds: rows [j0, j1) (in [0, height]); rejected: left,
/// right or beyond the far plane (DrawPolygon's trivial reject, same test,
/// same floats); noPixel, with columnTest (the plane scan,
/// Rasterizer::ColumnTest): no pixel centre i + 0.5 in [xmin, xmax), as
/// between rows, or a triangle of at most kBinSpanRows rows whose span in
/// each row (raster::TriangleEdges::Span, the scan's own test) holds no
/// pixel centre; and twice its signed area (raster::TwiceSignedArea), whose
/// facing FacingOf reads. pixel: where those spans hold a single pixel,
/// its row (from j0) and column (the draw then scans nothing:
/// ScanTriangle's onePixel); column -1 otherwise.
///
/// The span test: ParaView's 1M sphere at 1080p has ~409,000 triangles in
/// view that reach a pixel row and column for 291,000 covered pixels; a
/// triangle of a pixel or less often has a pixel centre in its bounds and
/// none inside, and each such one cost a bin entry, a set-up in its band
/// and its vertices' lighting for nothing.
struct PolygonTests
{
  int j0, j1;
  bool hasRow, rejected, noPixel;
  double twiceArea;
  raster::OnePixel pixel;
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
  t.noPixel = columnTest &
    (CeilToInt(xmax - 0.5f + kBinColumnMargin) <= CeilToInt(xmin - 0.5f - kBinColumnMargin));
  if (columnTest && count == 3 && t.hasRow && t.j1 - t.j0 <= kBinSpanRows && !t.noPixel)
  {
    const raster::TriangleEdges edges(sv);
    int pixels = 0;
    raster::OnePixel last;
    for (int r = 0; r < t.j1 - t.j0; ++r)
    {
      float xl, xr;
      int i0, i1;
      if (edges.Span(t.j0 + r, width, xl, xr, i0, i1))
      {
        pixels += i1 - i0;
        last = { r, i0 };
      }
    }
    t.noPixel = pixels == 0;
    t.pixel = pixels == 1 ? last : raster::OnePixel{};
  }
  t.twiceArea = raster::TwiceSignedArea(sv, count);
  return t;
}

/// The tests of four triangles, lane t for triangle t: rows [j0, j1) (in
/// [0, height]), and bit t of each mask.
struct FourTriangleTests
{
  int j0[4], j1[4];
  int hasRow = 0, rejected = 0, noPixel = 0;
  int degenerate = 0; ///< FacingOf's Degenerate: no area, or not finite
  int back = 0;       ///< positive twice-signed area (y down): a back face
  raster::OnePixel pixel[4]; ///< PolygonTests::pixel
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

/// a where mask is set, else b (SSE4.1's blendvps in SSE2).
inline __m128 Select4(__m128 mask, __m128 a, __m128 b)
{
  return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}

/// a where mask is set, else b, for ints (Select4's twin).
inline __m128i SelectInt4(__m128i mask, __m128i a, __m128i b)
{
  return _mm_or_si128(_mm_and_si128(mask, a), _mm_andnot_si128(mask, b));
}

/// max(lo, a) and min(a, hi) of four ints without SSE4.1's pmaxsd / pminsd.
inline __m128i AtLeast4(__m128i a, __m128i lo)
{
  return SelectInt4(_mm_cmpgt_epi32(a, lo), a, lo);
}
inline __m128i AtMost4(__m128i a, __m128i hi)
{
  return SelectInt4(_mm_cmplt_epi32(a, hi), a, hi);
}

/// The edges of four triangles (vertices x[k], y[k] lane t), as
/// raster::TriangleEdges holds them: built once, read for every row.
struct FourTriangleEdges
{
  __m128 px[3], py[3], qy[3], invSlope[3];

  FourTriangleEdges(const __m128 x[3], const __m128 y[3])
  {
    for (int k = 0; k < 3; ++k)
    {
      const int n = k + 1 < 3 ? k + 1 : 0;
      // Edge (p, q) = (k, n): base point the lower end; std::min(p.y, q.y)
      // is (q.y < p.y) ? q.y : p.y, minps(q.y, p.y), and std::max likewise.
      this->px[k] = Select4(_mm_cmple_ps(y[k], y[n]), x[k], x[n]);
      this->py[k] = _mm_min_ps(y[n], y[k]);
      this->qy[k] = _mm_max_ps(y[n], y[k]);
      // raster::InverseSlope: (q.x - p.x) / dy where dy != 0 (NaN included), else 0.
      const __m128 dy = _mm_sub_ps(y[n], y[k]);
      this->invSlope[k] = _mm_and_ps(
        _mm_cmpneq_ps(dy, _mm_setzero_ps()), _mm_div_ps(_mm_sub_ps(x[n], x[k]), dy));
    }
  }

  /// The pixels of row j[t] of triangle t, 0 where its span holds no
  /// pixel centre, and in i0 the span's first column:
  /// raster::TriangleEdges::Span lane for lane, the same float operations
  /// in the same order.
  __m128i RowPixels(__m128i j, int width, __m128i& i0) const
  {
    const __m128 half = _mm_set1_ps(0.5f);
    const __m128 yc = _mm_add_ps(_mm_cvtepi32_ps(j), half);
    __m128 cross[3], at[3];
    for (int k = 0; k < 3; ++k)
    {
      cross[k] = _mm_and_ps(_mm_cmple_ps(this->py[k], yc), _mm_cmplt_ps(yc, this->qy[k]));
      at[k] = _mm_add_ps(this->px[k],
        _mm_mul_ps(_mm_sub_ps(yc, this->py[k]), this->invSlope[k])); // raster::CrossingX
    }
    // The first two crossing edges in order 0, 1, 2.
    const __m128 first = Select4(cross[0], at[0], Select4(cross[1], at[1], at[2]));
    const __m128 second = Select4(cross[0], Select4(cross[1], at[1], at[2]), at[2]);
    const __m128 two = _mm_or_ps(_mm_and_ps(cross[0], _mm_or_ps(cross[1], cross[2])),
      _mm_and_ps(cross[1], cross[2]));
    // std::min(xs0, xs1) is (xs1 < xs0) ? xs1 : xs0, minps(xs1, xs0); max likewise.
    const __m128 xl = _mm_min_ps(second, first), xr = _mm_max_ps(second, first);
    i0 = AtLeast4(CeilToInt4(_mm_sub_ps(xl, half)), _mm_setzero_si128());
    const __m128i i1 = AtMost4(CeilToInt4(_mm_sub_ps(xr, half)), _mm_set1_epi32(width));
    const __m128i pixels = _mm_and_si128(_mm_castps_si128(two), _mm_cmpgt_epi32(i1, i0));
    return _mm_and_si128(pixels, _mm_sub_epi32(i1, i0));
  }
};

/// TestPolygon's span test on the lanes in `candidates` (`rows` rows from
/// j0, at most kBinSpanRows): sets their noPixel bits and their pixel.
/// Inlined, as TestFourTriangles.
[[gnu::always_inline]] inline void SpanTest4(const __m128 x[3], const __m128 y[3], __m128i j0,
  __m128i rows, int width, int candidates, FourTriangleTests& out)
{
  const FourTriangleEdges edges(x, y);
  __m128i total = _mm_setzero_si128(), row = _mm_setzero_si128(), column = row;
  for (int r = 0; r < kBinSpanRows; ++r)
  {
    const __m128i inRow = _mm_cmpgt_epi32(rows, _mm_set1_epi32(r));
    if (!(_mm_movemask_ps(_mm_castsi128_ps(inRow)) & candidates))
    {
      break;
    }
    __m128i i0;
    const __m128i pixels =
      _mm_and_si128(inRow, edges.RowPixels(_mm_add_epi32(j0, _mm_set1_epi32(r)), width, i0));
    total = _mm_add_epi32(total, pixels);
    const __m128i some = _mm_cmpgt_epi32(pixels, _mm_setzero_si128());
    row = SelectInt4(some, _mm_set1_epi32(r), row);
    column = SelectInt4(some, i0, column);
  }
  const int none = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(total, _mm_setzero_si128())));
  const int one =
    _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(total, _mm_set1_epi32(1)))) & candidates;
  out.noPixel |= candidates & none;
  if (one)
  {
    int rowOf[4], columnOf[4];
    _mm_storeu_si128(reinterpret_cast<__m128i*>(rowOf), row);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(columnOf), column);
    for (int t = 0; t < 4; ++t)
    {
      if (one >> t & 1)
      {
        out.pixel[t] = { rowOf[t], columnOf[t] };
      }
    }
  }
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
  j0 = AtLeast4(j0, _mm_setzero_si128());
  j1 = AtMost4(j1, _mm_set1_epi32(height));
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
    out.noPixel = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(right, left))) ^ 0xF;
    const __m128i rows = _mm_sub_epi32(j1, j0);
    const int fewRows = _mm_movemask_ps(_mm_castsi128_ps(_mm_and_si128(
      _mm_cmpgt_epi32(rows, _mm_setzero_si128()),
      _mm_cmplt_epi32(rows, _mm_set1_epi32(kBinSpanRows + 1)))));
    const int candidates = fewRows & ~out.noPixel;
    if (candidates)
    {
      SpanTest4(x, y, j0, rows, width, candidates, out);
    }
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
