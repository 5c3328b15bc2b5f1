// SPDX-License-Identifier: BSD-3-Clause
// The software rasterizer's primitives: screen vertices with their
// interpolated attributes, the transforms, and scan
// conversion as the lecture does it (edge walk in y, span in x with
// I_{p+1} = I_p + dI; docs/model.md eq. 2.3-2.4). Nothing here knows the
// shading mode: the stages (ShadingStages.h) pass their pixel functions in.
#pragma once

#include "WideShading.h"

#include "shadinglab/model/Vec3.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace shadinglab::cpu::raster
{

/// z, 1/w, then up to 9 interpolated values (normal, position, colour).
constexpr int kMaxAttributes = 11;
constexpr int kAttrZ = 0;
constexpr int kAttrInvW = 1;
constexpr int kAttrFirst = 2;

/// Rows per band. Bands are dealt to threads round-robin: 16 rows gives ~70
/// bands at 1080p, fine enough that two threads get even work on any image,
/// coarse enough that a typical small triangle touches one band only.
constexpr int kBandRows = 16;

/// Screen-space polygon area (pixels^2) below which a polygon is skipped as
/// degenerate: it cannot contain a pixel centre except on its own edges,
/// which the half-open fill rule assigns to neighbours anyway. 1e-10 is far
/// below any real sliver (a 1e-5 x 1e-5 pixel triangle).
constexpr float kDegenerateArea = 1e-10f;

/// Largest polygon after near-plane clipping: one more vertex than the input.
constexpr int kMaxPolygonVertices = 64;

/// A hint that `address` will be read soon (a no-op where the compiler
/// has none).
inline void Prefetch(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address, 0, 3);
#else
  (void)address;
#endif
}

/// ceil(x) as an int for the pixel-centre rules, without a libm call (this
/// build targets baseline x86-64, where std::ceil is not a single
/// instruction). x is clamped to +-1e9 pixels first: beyond any viewport, and
/// the int conversion stays defined.
inline int CeilToInt(float x)
{
  x = x < -1e9f ? -1e9f : (x > 1e9f ? 1e9f : x);
  const int i = static_cast<int>(x);
  return i + (x > static_cast<float>(i) ? 1 : 0);
}

/// Sutherland-Hodgman against the near plane z + w >= 0 in clip space, on
/// a polygon of n vertices whose clip coordinates clipOf(k) gives: in
/// order, keep(k) for each vertex in front and cross(inside, outside, t)
/// for each edge that crosses the plane, the crossing at t from its inside
/// end towards its outside end (so two polygons sharing an edge get
/// bit-identical crossings). The rasterizer's clipping and its binning of
/// clipped polygons both walk polygons through this one function.
template<typename ClipOf, typename Keep, typename Cross>
void ClipToNearPlane(int n, ClipOf&& clipOf, Keep&& keep, Cross&& cross)
{
  for (int k = 0; k < n; ++k)
  {
    const int next = (k + 1) % n;
    const double* a = clipOf(k);
    const double* b = clipOf(next);
    const double da = a[2] + a[3], db = b[2] + b[3];
    const bool aIn = da >= 0, bIn = db >= 0;
    if (aIn)
    {
      keep(k);
    }
    if (aIn != bIn)
    {
      const double di = aIn ? da : db, dout = aIn ? db : da;
      cross(aIn ? k : next, aIn ? next : k, di / (di - dout));
    }
  }
}

/// The clip coordinates of an edge's crossing (ClipToNearPlane), landed
/// exactly on the plane so that 1/w stays finite.
inline void NearPlaneCrossing(const double inside[4], const double outside[4], double t, double x[4])
{
  for (int i = 0; i < 4; ++i)
  {
    x[i] = inside[i] + t * (outside[i] - inside[i]);
  }
  x[2] = -x[3];
}

struct ScreenVertex
{
  float x, y;
  float a[kMaxAttributes];
};

/// Twice the signed screen area of a polygon's n projected vertices (y
/// down: front faces negative). Binning, the flat stage and
/// DrawSourcePolygon (with its bounds) sum in this order, so the facing
/// each finds is the same. Vertex: anything with x and y (ScreenVertex,
/// binning's ProjectedVertex).
template<typename Vertex>
double TwiceSignedArea(const Vertex* const* sv, int n)
{
  double area = 0;
  for (int k = 0; k < n; ++k)
  {
    const Vertex& a = *sv[k];
    const Vertex& b = *sv[k + 1 < n ? k + 1 : 0];
    area += static_cast<double>(a.x) * b.y - static_cast<double>(b.x) * a.y;
  }
  return area;
}

/// Where a scan reports the ends of the spans of one row (the scanline
/// inspector's trace): x and every attribute slot (z, 1/w, then the
/// stage's), as the scan computed them.
struct SpanTrace
{
  int row;
  std::function<void(float xl, const float* al, float xr, const float* ar)> record;
};

/// An edge's inverse slope dx/dy, 0 for a horizontal edge (never crossed):
/// the same quotient from either end, both differences changing sign
/// exactly.
inline float InverseSlope(float px, float py, float qx, float qy)
{
  const float dy = qy - py;
  return dy != 0.0f ? (qx - px) / dy : 0.0f;
}

/// Where an edge crosses the scanline yc, from its lower end (lx, ly)
/// (docs/model.md eq. 2.3 on x). Every scan computes its crossings with
/// this one expression: a triangle and a polygon sharing an edge
/// (--polygons direct on a mesh of both) get the same x, bit for bit, and
/// the half-open rule gives a pixel centre on the edge to exactly one of
/// them. (ScanPolygon interpolated x as its attributes, p.x + t (q.x -
/// p.x): an ulp off the triangle's x on 0.7% of crossings within an ulp
/// of a pixel centre, a hole or a double pixel each.)
inline float CrossingX(float lx, float ly, float invSlope, float yc)
{
  return lx + (yc - ly) * invSlope;
}

/// An edge's canonical direction (lower y first, then lower x): the
/// polygons sharing an edge compute its crossings from the same end with
/// the same numbers, bit-identical, so the fill rule stays watertight.
inline void CanonicalEdge(const ScreenVertex*& p, const ScreenVertex*& q)
{
  if (q->y < p->y || (q->y == p->y && q->x < p->x))
  {
    std::swap(p, q);
  }
}

/// A triangle's edges as the plane scan crosses them, and one row's span:
/// ScanTriangle draws with these, and binning asks them whether a triangle
/// of one pixel row covers a pixel centre (TestPolygon), so the two agree
/// bit for bit. The edges are in canonical order (CanonicalEdge) without
/// its swap, a coin toss for the branch predictor on triangles of a pixel
/// or less: the order only picks the base point (the lower end), since a
/// horizontal edge is never crossed and the slope is the same quotient
/// from either end (both differences change sign exactly): every crossing
/// is the one CanonicalEdge's order gives, bit for bit.
struct TriangleEdges
{
  struct Edge
  {
    float px, py, qy, invSlope;
  };
  Edge edges[3];

  /// V: anything with float x, y (ScreenVertex, ProjectedVertex).
  template<typename V>
  explicit TriangleEdges(const V* const* verts)
  {
    for (int k = 0; k < 3; ++k)
    {
      const V& p = *verts[k];
      const V& q = *verts[k + 1 < 3 ? k + 1 : 0];
      const bool pLower = p.y <= q.y;
      this->edges[k] = { pLower ? p.x : q.x, std::min(p.y, q.y), std::max(p.y, q.y),
        InverseSlope(p.x, p.y, q.x, q.y) };
    }
  }

  float YMin() const
  {
    return std::min(this->edges[0].py, std::min(this->edges[1].py, this->edges[2].py));
  }
  float YMax() const
  {
    return std::max(this->edges[0].qy, std::max(this->edges[1].qy, this->edges[2].qy));
  }

  /// Row j's crossings xl <= xr (the first two edges crossing yc = j +
  /// 0.5, half-open in y) and its pixels [i0, i1) within [0, width); false
  /// when the row has no pixel centre inside. TestFourTriangles computes
  /// the same lane for lane.
  bool Span(int j, int width, float& xl, float& xr, int& i0, int& i1) const
  {
    const float yc = static_cast<float>(j) + 0.5f;
    float xs[2];
    int nc = 0;
    for (int k = 0; k < 3 && nc < 2; ++k)
    {
      const Edge& e = this->edges[k];
      if (e.py <= yc && yc < e.qy)
      {
        xs[nc++] = CrossingX(e.px, e.py, e.invSlope, yc);
      }
    }
    if (nc < 2)
    {
      return false;
    }
    xl = std::min(xs[0], xs[1]);
    xr = std::max(xs[0], xs[1]);
    i0 = std::max(0, CeilToInt(xl - 0.5f));
    i1 = std::min(width, CeilToInt(xr - 0.5f));
    return i1 > i0;
  }
};

/// Binning's finding that a triangle covers exactly one pixel centre
/// (PolygonTests::pixel): row, counted from the triangle's first row, and
/// column; column < 0 where none was found. Binning gives it only to a
/// triangle within one band, whose first row is then the draw's rowBegin.
struct OnePixel
{
  int row = 0;
  int column = -1;
};

/// Sorts a scanline's few crossings by x (insertion sort: n is small).
template<typename Crossing>
void SortCrossings(Crossing* cross, int n)
{
  for (int a = 1; a < n; ++a)
  {
    for (int b = a; b > 0 && cross[b].x < cross[b - 1].x; --b)
    {
      std::swap(cross[b], cross[b - 1]);
    }
  }
}

struct Matrix4
{
  double m[4][4];
  void Apply(const double p[3], double out[4]) const
  {
    for (int r = 0; r < 4; ++r)
    {
      out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3];
    }
  }
};

inline Matrix4 Multiply(const Matrix4& a, const Matrix4& b)
{
  Matrix4 r{};
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      for (int k = 0; k < 4; ++k)
      {
        r.m[i][j] += a.m[i][k] * b.m[k][j];
      }
    }
  }
  return r;
}

/// Per-thread scratch space and counters of the raster stage. Each on its
/// own cache lines (kCacheLine): the threads' states sit side by side in one
/// vector, and one thread's counters shared a line with the next one's
/// queue count, both written per pixel.
inline constexpr size_t kCacheLine = 64;
struct alignas(kCacheLine) ThreadState
{
  std::vector<ScreenVertex> clipped; ///< vertices made by near-plane clipping
  PixelQueue queue;                  ///< depth-tested pixels awaiting the model (Phong)
  int64_t clippedPolygons = 0, degenerate = 0, rasterized = 0, shaded = 0, fastPhongExact = 0;
  int64_t binned = 0; ///< polygon-band pairs binned (RenderStats::binned)
  int64_t culled = 0; ///< back faces culled (by the binning worker or the owner)
  int64_t culledInClusters = 0; ///< polygons of runs binning skipped whole (Frame::Cones)
  int64_t triangles = 0; ///< triangles of the polygons this thread binned (n - 2 each)
  int64_t covered = 0; ///< covered pixels in this thread's bands (full resolution)
  /// The depth of the band being drawn (kBandRows rows), whose first pixel
  /// is pixel bandFirst of the frame: depth lives only while its band is
  /// drawn, so it is one band's buffer per thread, kept in the core's
  /// cache, not a frame's (8 MB at 1080p, cleared and written back to
  /// memory every frame).
  float* bandDepth = nullptr;
  size_t bandFirst = 0;
};

/*
 * Triangles. The interpolation along the edges (docs/model.md eq. 2.3) and across
 * the span give, on a triangle, the one linear function of (x, y) through
 * the three vertex values. Each span starts from that plane's value at its
 * first pixel centre, I = I_0 + l1 (I_1 - I_0) + l2 (I_2 - I_0) with the
 * centre's barycentric weights l1, l2, and steps I_{p+1} = I_p + dI/dx
 * (eq. 2.4), the gradient computed only for a span of more than one pixel:
 * most triangles of a mesh finer than the pixels have one pixel, and the
 * weights cost two products per attribute where the gradients cost six.
 * Edge crossings are computed from each edge's canonical endpoint order,
 * as in ScanPolygon, so shared edges stay watertight.
 */
template<int NA, typename PixelFn, typename SpanFn>
void ScanTriangle(int width,
  const ScreenVertex* const* verts,
  int rowBegin,
  int rowEnd,
  SpanFn&& beginSpan,
  PixelFn&& pixel,
  SpanTrace* trace = nullptr,
  OnePixel onePixel = {})
{
  const ScreenVertex& v0 = *verts[0];
  const ScreenVertex& v1 = *verts[1];
  const ScreenVertex& v2 = *verts[2];
  const double e1x = v1.x - v0.x, e1y = v1.y - v0.y;
  const double e2x = v2.x - v0.x, e2y = v2.y - v0.y;
  const double det = e1x * e2y - e2x * e1y;
  if (!(std::abs(det) > 0.0))
  {
    return;
  }
  // The attributes' differences along the two edges from v0, taken on the
  // first span with pixels (most triangles of a very fine mesh cover no
  // pixel centre), and their x gradient on the first span that steps.
  double invDet = 0, d1[NA] = {}, d2[NA] = {};
  float stepX[NA] = {};
  bool differences = false, gradient = false;
  float value[kMaxAttributes] = {}; // full size: pixel functors index by slot
  // Row j's pixels [i0, i1), its crossings xl, xr (for the trace).
  auto drawSpan = [&](int j, int i0, int i1, float xl, float xr)
  {
    const float yc = static_cast<float>(j) + 0.5f;
    if (!differences)
    {
      invDet = 1.0 / det;
      for (int k = 0; k < NA; ++k)
      {
        d1[k] = static_cast<double>(v1.a[k]) - v0.a[k];
        d2[k] = static_cast<double>(v2.a[k]) - v0.a[k];
      }
      differences = true;
    }
    // The barycentric weights of (x, yc): Cramer's rule on
    // (x - x0, yc - y0) = l1 e1 + l2 e2.
    const double dy = static_cast<double>(yc) - v0.y;
    auto weights = [&](double x, double& l1, double& l2)
    {
      const double dx = x - v0.x;
      l1 = (dx * e2y - dy * e2x) * invDet;
      l2 = (dy * e1x - dx * e1y) * invDet;
    };
    double l1, l2;
    weights(static_cast<double>(i0) + 0.5, l1, l2);
    for (int k = 0; k < NA; ++k)
    {
      value[k] = static_cast<float>(v0.a[k] + l1 * d1[k] + l2 * d2[k]);
    }
    if (i1 - i0 > 1 && !gradient)
    {
      // dl1/dx = e2y / det, dl2/dx = -e1y / det.
      for (int k = 0; k < NA; ++k)
      {
        stepX[k] = static_cast<float>((d1[k] * e2y - d2[k] * e1y) * invDet);
      }
      gradient = true;
    }
    if (trace && j == trace->row)
    {
      // The plane's values at the crossings (eq. 2.3 on a triangle).
      float al[kMaxAttributes] = {}, ar[kMaxAttributes] = {};
      double l1l, l2l, l1r, l2r;
      weights(xl, l1l, l2l);
      weights(xr, l1r, l2r);
      for (int k = 0; k < NA; ++k)
      {
        al[k] = static_cast<float>(v0.a[k] + l1l * d1[k] + l2l * d2[k]);
        ar[k] = static_cast<float>(v0.a[k] + l1r * d1[k] + l2r * d2[k]);
      }
      trace->record(xl, al, xr, ar);
    }
    beginSpan(j, i0);
    for (int i = i0; i < i1; ++i)
    {
      pixel(j, i, value);
      for (int k = 0; k < NA; ++k)
      {
        value[k] += stepX[k];
      }
    }
  };
  if (onePixel.column >= 0 && !trace)
  {
    // Binning found the one pixel (TestPolygon: of the spans
    // TriangleEdges::Span finds in the triangle's few rows, one holds a
    // pixel, this one).
    drawSpan(rowBegin + onePixel.row, onePixel.column, onePixel.column + 1, 0.0f, 0.0f);
    return;
  }
  // Its edges and each row's span: TriangleEdges. (Selecting a row's two
  // crossings without branches cost larger triangles more than it saved:
  // x1.05 on the 100k torus.)
  const TriangleEdges edges(verts);
  const int j0 = std::max(rowBegin, CeilToInt(edges.YMin() - 0.5f));
  const int j1 = std::min(rowEnd, CeilToInt(edges.YMax() - 0.5f));
  for (int j = j0; j < j1; ++j)
  {
    float xl, xr;
    int i0, i1;
    if (edges.Span(j, width, xl, xr, i0, i1))
    {
      drawSpan(j, i0, i1, xl, xr);
    }
  }
}

/*
 * General polygons (--polygons direct): the lecture's algorithm literally.
 * For each scanline, every edge crossing is interpolated along its edge in y
 * (eq. 2.3), crossings are paired left to right, and each span is
 * interpolated in x (eq. 2.4). For a polygon of more than three vertices the
 * result depends on the polygon's orientation on screen (docs/model.md eq. 3.2).
 */
template<typename PixelFn, typename SpanFn>
void ScanPolygon(int width,
  int numAttributes,
  const ScreenVertex* const* verts,
  int n,
  int rowBegin,
  int rowEnd,
  SpanFn&& beginSpan,
  PixelFn&& pixel,
  SpanTrace* trace = nullptr)
{
  const int na = kAttrFirst + numAttributes;
  float ymin = verts[0]->y, ymax = verts[0]->y;
  for (int k = 1; k < n; ++k)
  {
    ymin = std::min(ymin, verts[k]->y);
    ymax = std::max(ymax, verts[k]->y);
  }
  // Pixel centres at (i + 0.5, j + 0.5). Rows j with ymin <= j + 0.5 < ymax
  // and, within a row, pixels with xl <= i + 0.5 < xr: half-open on both
  // axes, so a pixel centre on an edge shared by two polygons belongs to
  // exactly one of them.
  const int j0 = std::max(rowBegin, CeilToInt(ymin - 0.5f));
  const int j1 = std::min(rowEnd, CeilToInt(ymax - 0.5f));
  struct Crossing
  {
    float x;
    float a[kMaxAttributes];
  };
  Crossing cross[kMaxPolygonVertices];
  float value[kMaxAttributes], delta[kMaxAttributes];
  for (int j = j0; j < j1; ++j)
  {
    const float yc = static_cast<float>(j) + 0.5f;
    int nc = 0;
    for (int k = 0; k < n; ++k)
    {
      const ScreenVertex* p = verts[k];
      const ScreenVertex* q = verts[(k + 1) % n];
      CanonicalEdge(p, q);
      if (!(p->y <= yc && yc < q->y))
      {
        continue;
      }
      // docs/model.md eq. 2.3: I_4 = (y_1 - y_4)/(y_1 - y_2) I_2 + (y_4 - y_2)/(y_1 - y_2) I_1.
      const float t = (yc - p->y) / (q->y - p->y);
      Crossing& c = cross[nc++];
      c.x = CrossingX(p->x, p->y, InverseSlope(p->x, p->y, q->x, q->y), yc);
      for (int i = 0; i < na; ++i)
      {
        c.a[i] = p->a[i] + t * (q->a[i] - p->a[i]);
      }
    }
    // Crossings by x, paired even-odd into spans.
    SortCrossings(cross, nc);
    for (int s = 0; s + 1 < nc; s += 2)
    {
      const Crossing& L = cross[s];
      const Crossing& R = cross[s + 1];
      const int i0 = std::max(0, CeilToInt(L.x - 0.5f));
      const int i1 = std::min(width, CeilToInt(R.x - 0.5f));
      if (i1 <= i0)
      {
        continue;
      }
      if (trace && j == trace->row)
      {
        trace->record(L.x, L.a, R.x, R.a);
      }
      // docs/model.md eq. 2.4: I_p = (x_5 - x_p)/(x_5 - x_4) I_4 + (x_p - x_4)/(x_5 - x_4) I_5,
      // then incrementally I_{p+1} = I_p + (I_5 - I_4)/(x_5 - x_4).
      const float invSpan = 1.0f / (R.x - L.x);
      const float start = (static_cast<float>(i0) + 0.5f - L.x);
      for (int i = 0; i < na; ++i)
      {
        delta[i] = (R.a[i] - L.a[i]) * invSpan;
        value[i] = L.a[i] + start * delta[i];
      }
      beginSpan(j, i0);
      for (int i = i0; i < i1; ++i)
      {
        pixel(j, i, value);
        for (int k = 0; k < na; ++k)
        {
          value[k] += delta[k];
        }
      }
    }
  }
}

/// ScanTriangle<na> for a run-time attribute count na in [NA,
/// kMaxAttributes]; false (nothing drawn) for a count outside it.
template<int NA, typename PixelFn, typename SpanFn>
bool ScanTriangleOf(int na,
  int width,
  const ScreenVertex* const* verts,
  int rowBegin,
  int rowEnd,
  SpanFn&& beginSpan,
  PixelFn&& pixel,
  SpanTrace* trace,
  OnePixel onePixel)
{
  if constexpr (NA <= kMaxAttributes)
  {
    if (na == NA)
    {
      ScanTriangle<NA>(width, verts, rowBegin, rowEnd, beginSpan, pixel, trace, onePixel);
      return true;
    }
    return ScanTriangleOf<NA + 1>(
      na, width, verts, rowBegin, rowEnd, beginSpan, pixel, trace, onePixel);
  }
  return false;
}

/**
 * Scan-converts one polygon part (a triangle, or a whole polygon with
 * --polygons direct) into rows [rowBegin, rowEnd): beginSpan(j, i0) at the
 * start of every span, pixel(j, i, attributes) at every pixel centre inside.
 * onePixel: a triangle's one pixel, where binning found it.
 */
template<typename PixelFn, typename SpanFn>
void ScanConvert(int width,
  int numAttributes,
  const ScreenVertex* const* verts,
  int n,
  int rowBegin,
  int rowEnd,
  SpanFn&& beginSpan,
  PixelFn&& pixel,
  SpanTrace* trace = nullptr,
  OnePixel onePixel = {})
{
  // The attribute count is fixed per frame; a compile-time count lets the
  // span loop unroll. Every count has its instance (colour by data adds a
  // slot: 3, 6, 9; without theirs, coloured triangles went through
  // ScanPolygon's per-row crossings and sort).
  if (n != 3 ||
    !ScanTriangleOf<kAttrFirst>(
      kAttrFirst + numAttributes, width, verts, rowBegin, rowEnd, beginSpan, pixel, trace, onePixel))
  {
    ScanPolygon(width, numAttributes, verts, n, rowBegin, rowEnd, beginSpan, pixel, trace);
  }
}

} // namespace shadinglab::cpu::raster
