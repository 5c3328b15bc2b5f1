// SPDX-License-Identifier: BSD-3-Clause
#include "VertexNormals.h"

#include "Geometry.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

namespace shadinglab::mesh
{

namespace
{

/// A weight (area, angle, ...) below this contributes nothing: a face of
/// area 1e-300 has no direction worth averaging, and squaring edge lengths
/// in Max's weight must not overflow into Inf. 1e-300 is far below any
/// real mesh's scale yet above double's smallest normal (2.2e-308).
constexpr double kTinyWeight = 1e-300;

/// The project's one vector type (the model's Vec3, in double).
using V3 = Vec3<double>;

inline V3 Sub(const double* a, const double* b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

/// Area vector of polygon p: twice its area times the unit normal (Geometry.h).
V3 AreaVector(const MeshView& m, int64_t p)
{
  const int64_t b = m.offsets[p], e = m.offsets[p + 1];
  if (e - b == 3)
  {
    const double* p0 = m.points + 3 * m.connectivity[b];
    const double* p1 = m.points + 3 * m.connectivity[b + 1];
    const double* p2 = m.points + 3 * m.connectivity[b + 2];
    return Cross(Sub(p1, p0), Sub(p2, p0));
  }
  return NewellAreaVector<double>(
    e - b, [&](int64_t k) { return PointOf(m.points, m.connectivity[b + k]); });
}

/// The contribution of polygon p's corner k (vertex connectivity[b + k]).
inline V3 CornerContribution(const MeshView& m,
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
      const double* v = m.points + 3 * m.connectivity[b + k];
      const double* prev = m.points + 3 * m.connectivity[b + (k + n - 1) % n];
      const double* next = m.points + 3 * m.connectivity[b + (k + 1) % n];
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

void Normalize(double* n)
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

/// Polygon p's contribution to its vertices' normals (the per-polygon loop
/// body of ComputeVertexNormalsNoSplit).
void AddPolygon(const MeshView& m, int64_t p, NormalWeighting weighting, double* out)
{
  const int64_t b = m.offsets[p], n = m.offsets[p + 1] - b;
  if (n < 3)
  {
    return;
  }
  const V3 a = AreaVector(m, p);
  if (weighting == NormalWeighting::Area)
  {
    for (int64_t k = 0; k < n; ++k)
    {
      double* o = out + 3 * m.connectivity[b + k];
      o[0] += a.x;
      o[1] += a.y;
      o[2] += a.z;
    }
    return;
  }
  const double len = std::sqrt(Dot(a, a));
  if (n == 3 && weighting == NormalWeighting::Max && len >= kTinyWeight)
  {
    // Triangles: every corner's cross product is the area vector, so the
    // three corners share the edge lengths computed once. (Angle-weighted
    // triangles go through AddAngleWeightedTriangles.)
    const int64_t i0 = m.connectivity[b], i1 = m.connectivity[b + 1], i2 = m.connectivity[b + 2];
    const double* p0 = m.points + 3 * i0;
    const double* p1 = m.points + 3 * i1;
    const double* p2 = m.points + 3 * i2;
    const V3 e01 = Sub(p1, p0), e12 = Sub(p2, p1), e20 = Sub(p0, p2);
    const double l01 = Dot(e01, e01), l12 = Dot(e12, e12), l20 = Dot(e20, e20);
    if (l01 < kTinyWeight || l12 < kTinyWeight || l20 < kTinyWeight)
    {
      return;
    }
    // Max 1999: (e1 x e2)/(|e1|^2 |e2|^2) = area vector / (l l') here.
    // One division: 1/(l01 l20) = l12 / (l01 l12 l20), and so on.
    const double inv = 1.0 / (l01 * l12 * l20);
    const double w[3] = { l12 * inv, l20 * inv, l01 * inv };
    const int64_t ids[3] = { i0, i1, i2 };
    for (int k = 0; k < 3; ++k)
    {
      double* o = out + 3 * ids[k];
      o[0] += a.x * w[k];
      o[1] += a.y * w[k];
      o[2] += a.z * w[k];
    }
    return;
  }
  for (int64_t k = 0; k < n; ++k)
  {
    const V3 c = CornerContribution(m, b, n, k, a, len, weighting);
    double* o = out + 3 * m.connectivity[b + k];
    o[0] += c.x;
    o[1] += c.y;
    o[2] += c.z;
  }
}

/// Triangles per batch of the angle-weight path: its arrays (9 doubles a
/// triangle, 18 KB) stay in L1 between the passes.
constexpr int64_t kAngleBatch = 256;

/// atan(t) for t in [0, 1] as t P(t^2), P of degree 8: the Chebyshev fit of
/// atan(sqrt(u))/sqrt(u) on u in [0, 1] (mpmath.chebyfit, 9 terms). Worst
/// error 9.7e-9 rad over [0, 1] in double (checked at 200,001 points), half
/// that of the A&S acos of the corner formula (2e-8). Evaluated by Estrin's
/// scheme: a dependency chain of 5 multiply-adds instead of Horner's 9 (the
/// batched loop was waiting on the chain).
__attribute__((always_inline)) inline double AtanUnit(double t)
{
  // a0 .. a8, lowest power first.
  constexpr double a[9] = { 0.99999998178865568,
    -0.33333036709286273,
    0.19991872029109073,
    -0.14197797794085124,
    0.10618370636953849,
    -0.07456854826004547,
    0.042137623589193041,
    -0.015731249122183651,
    0.002766283501762026 };
  const double u = t * t, u2 = u * u, u4 = u2 * u2;
  const double q0 = a[0] + a[1] * u, q1 = a[2] + a[3] * u;
  const double q2 = a[4] + a[5] * u, q3 = a[6] + a[7] * u;
  const double r0 = q0 + q1 * u2, r1 = q2 + q3 * u2;
  return t * (r0 + u4 * (r1 + u4 * a[8]));
}

/// The angle in [0, pi] with tangent y / x for y >= 0 (atan2), given
/// t = min(|x|, y) / max(|x|, y): branch-free.
__attribute__((always_inline)) inline double AngleOf(double t, double y, double x)
{
  const double r = AtanUnit(t);
  const double q = y > std::abs(x) ? 1.57079632679489661923 - r : r;
  return x < 0 ? 3.14159265358979323846 - q : q;
}

/// One batch of the angle-weight path: edge vectors in, the three corner
/// weights out, and the area vector in place of e1 (a separate array for it
/// measured no faster: more stores).
struct AngleBatch
{
  alignas(64) double e1x[kAngleBatch], e1y[kAngleBatch], e1z[kAngleBatch];
  alignas(64) double e2x[kAngleBatch], e2y[kAngleBatch], e2z[kAngleBatch];
  alignas(64) double w0[kAngleBatch], w1[kAngleBatch], w2[kAngleBatch];
};

/// The batch's weights (vectorized, branch-free).
__attribute__((always_inline)) inline void AngleWeights(AngleBatch& b, int64_t count)
{
  for (int64_t i = 0; i < count; ++i)
  {
    // Area vector e1 x e2 (AreaVector's); squared edge lengths.
    const double ax = b.e1y[i] * b.e2z[i] - b.e1z[i] * b.e2y[i];
    const double ay = b.e1z[i] * b.e2x[i] - b.e1x[i] * b.e2z[i];
    const double az = b.e1x[i] * b.e2y[i] - b.e1y[i] * b.e2x[i];
    const double dx = b.e2x[i] - b.e1x[i], dy = b.e2y[i] - b.e1y[i], dz = b.e2z[i] - b.e1z[i];
    const double l01 = b.e1x[i] * b.e1x[i] + b.e1y[i] * b.e1y[i] + b.e1z[i] * b.e1z[i];
    const double l20 = b.e2x[i] * b.e2x[i] + b.e2y[i] * b.e2y[i] + b.e2z[i] * b.e2z[i];
    const double l12 = dx * dx + dy * dy + dz * dz;
    // Corner angles: a corner's two edges have the cross product's length
    // |e1 x e2| = len as |e||e'| sin and their dot product as |e||e'| cos,
    // so the angle is atan2(len, dot), with no normalization (the law of
    // cosines took four square roots more). The third angle is pi minus the
    // other two. Weights are angle / |area vector| (the area vector then
    // gives angle x unit normal); degenerate triangles weigh nothing.
    const double len = std::sqrt(ax * ax + ay * ay + az * az);
    // (& rather than &&: no branch, so that the loop vectorizes.)
    const bool usable =
      (len >= kTinyWeight) & (l01 >= kTinyWeight) & (l12 >= kTinyWeight) & (l20 >= kTinyWeight);
    // At p0: e1 . e2; at p1: (p0 - p1) . (p2 - p1) = -e1 . (e2 - e1).
    const double dot0 = b.e1x[i] * b.e2x[i] + b.e1y[i] * b.e2y[i] + b.e1z[i] * b.e2z[i];
    const double dot1 = -(b.e1x[i] * dx + b.e1y[i] * dy + b.e1z[i] * dz);
    const double big0 = std::max(std::abs(dot0), len), small0 = std::min(std::abs(dot0), len);
    const double big1 = std::max(std::abs(dot1), len), small1 = std::min(std::abs(dot1), len);
    const double inv = usable ? 1.0 / len : 0.0;
    const double t0 = usable ? small0 / big0 : 0.0;
    const double t1 = usable ? small1 / big1 : 0.0;
    const double a0 = AngleOf(t0, len, dot0);
    const double a1 = AngleOf(t1, len, dot1);
    b.e1x[i] = ax; // e1 is read no more
    b.e1y[i] = ay;
    b.e1z[i] = az;
    // (inv = 0 weighs unusable triangles out: their angles are finite.)
    b.w0[i] = a0 * inv;
    b.w1[i] = a1 * inv;
    b.w2[i] = (3.14159265358979323846 - a0 - a1) * inv;
  }
}

/// Angle weights (Thurmer & Wuthrich 1998) of the triangles [first, last),
/// all triangles, accumulated into `out`: gathered into arrays, the
/// weights computed in one branch-free loop (vectorized), then scattered.
__attribute__((always_inline)) inline void AngleWeightedTrianglesBody(const MeshView& m,
  int64_t first,
  int64_t last,
  double* out)
{
  AngleBatch b;
  for (int64_t start = first; start < last; start += kAngleBatch)
  {
    const int64_t count = std::min(kAngleBatch, last - start);
    // Every polygon of [first, last) is a triangle (the caller's run), so
    // triangle start + i begins 3 i after the batch's first corner.
    const int64_t* corners = m.connectivity + m.offsets[start];
    for (int64_t i = 0; i < count; ++i)
    {
      const int64_t* c = corners + 3 * i;
      const double* p0 = m.points + 3 * c[0];
      const double* p1 = m.points + 3 * c[1];
      const double* p2 = m.points + 3 * c[2];
      b.e1x[i] = p1[0] - p0[0];
      b.e1y[i] = p1[1] - p0[1];
      b.e1z[i] = p1[2] - p0[2];
      b.e2x[i] = p2[0] - p0[0];
      b.e2y[i] = p2[1] - p0[1];
      b.e2z[i] = p2[2] - p0[2];
    }
    AngleWeights(b, count);
    for (int64_t i = 0; i < count; ++i)
    {
      const int64_t* c = corners + 3 * i;
      const double w[3] = { b.w0[i], b.w1[i], b.w2[i] };
      for (int k = 0; k < 3; ++k)
      {
        double* o = out + 3 * c[k];
        o[0] += b.e1x[i] * w[k];
        o[1] += b.e1y[i] * w[k];
        o[2] += b.e1z[i] * w[k];
      }
    }
  }
}

/// The same loop compiled for AVX2 (4 doubles a lane group instead of
/// SSE2's 2): chosen at run time, so the binary still runs without AVX2.
__attribute__((target("avx2"))) void AngleWeightedTrianglesAvx2(const MeshView& m,
  int64_t first,
  int64_t last,
  double* out)
{
  AngleWeightedTrianglesBody(m, first, last, out);
}

void AngleWeightedTrianglesBaseline(const MeshView& m, int64_t first, int64_t last, double* out)
{
  AngleWeightedTrianglesBody(m, first, last, out);
}

std::atomic<bool> gWideSimd{ true };

void AddAngleWeightedTriangles(const MeshView& m, int64_t first, int64_t last, double* out)
{
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2 && gWideSimd.load(std::memory_order_relaxed))
  {
    AngleWeightedTrianglesAvx2(m, first, last, out);
  }
  else
  {
    AngleWeightedTrianglesBaseline(m, first, last, out);
  }
}

} // namespace

void SetWideSimd(bool enabled)
{
  gWideSimd.store(enabled, std::memory_order_relaxed);
}

bool WideSimdInUse()
{
  return __builtin_cpu_supports("avx2") && gWideSimd.load(std::memory_order_relaxed);
}

void ComputeVertexNormalsNoSplit(const MeshView& m,
  NormalWeighting weighting,
  std::vector<double>& normals)
{
  normals.assign(static_cast<size_t>(3 * m.numberOfPoints), 0.0);
  double* out = normals.data();
  for (int64_t p = 0; p < m.numberOfPolygons;)
  {
    // Angle weights: a run of triangles goes through the batched loop.
    int64_t q = p;
    while (weighting == NormalWeighting::Angle && q < m.numberOfPolygons &&
      m.offsets[q + 1] - m.offsets[q] == 3)
    {
      ++q;
    }
    if (q > p)
    {
      AddAngleWeightedTriangles(m, p, q, out);
      p = q;
    }
    else
    {
      AddPolygon(m, p++, weighting, out);
    }
  }
  for (int64_t v = 0; v < m.numberOfPoints; ++v)
  {
    Normalize(out + 3 * v);
  }
}

NormalResult ComputeVertexNormals(const MeshView& m, const NormalOptions& opt)
{
  NormalResult r;
  const int64_t nv = m.numberOfPoints, np = m.numberOfPolygons;
  const int64_t nc = np > 0 ? m.offsets[np] : 0;
  // Corners moved to a split copy of their vertex (corner, new point): the
  // output connectivity is made from them only if there are any.
  std::vector<std::pair<int64_t, int64_t>> moved;

  // Scratch arrays persist per thread across calls: a filter re-run on a
  // large mesh then reuses their pages instead of faulting in ~100 MB anew
  // (measured: a third of the time was the kernel zeroing fresh pages).
  // No per-polygon table of area vectors is kept (160 MB on 5M triangles):
  // the vertex pass computes the area vectors of the polygons around each
  // vertex as it reaches it, the same arithmetic, so the same bits.
  static thread_local std::vector<int64_t> start, corners64, cornerPolygon;
  static thread_local std::vector<uint32_t> corners32;

  // Vertex -> corners (CSR by counting sort): corner index c = offset + k.
  start.assign(static_cast<size_t>(nv + 1), 0);
  for (int64_t c = 0; c < nc; ++c)
  {
    ++start[m.connectivity[c] + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  // Corner indices in 4 bytes where they fit (every mesh up to 1.4 billion
  // triangles; 60 MB less on 5M), in 8 otherwise.
  const bool narrow = nc <= static_cast<int64_t>(std::numeric_limits<uint32_t>::max());
  corners32.resize(narrow ? static_cast<size_t>(nc) : 0);
  corners64.resize(narrow ? 0 : static_cast<size_t>(nc));
  // A mesh of triangles only finds a corner's polygon as c / 3; others keep
  // a table (8 bytes a corner: 120 MB on 5M triangles).
  // Every offset must be 3p: the corner count alone would take a 2-gon
  // beside a quad for two triangles (one pass over the offsets, ~1 ms on
  // 5M triangles).
  bool trianglesOnly = nc == 3 * np;
  for (int64_t p = 0; trianglesOnly && p < np; ++p)
  {
    trianglesOnly = m.offsets[p] == 3 * p;
  }
  cornerPolygon.resize(trianglesOnly ? 0 : static_cast<size_t>(nc));
  // start[v] serves as v's fill cursor, ending at the next vertex's start;
  // shifted back after (no second table of nv entries).
  for (int64_t p = 0; p < np; ++p)
  {
    for (int64_t c = m.offsets[p]; c < m.offsets[p + 1]; ++c)
    {
      const int64_t slot = start[m.connectivity[c]]++;
      if (narrow)
      {
        corners32[slot] = static_cast<uint32_t>(c);
      }
      else
      {
        corners64[slot] = c;
      }
      if (!trianglesOnly)
      {
        cornerPolygon[c] = p;
      }
    }
  }
  for (int64_t v = nv; v > 0; --v)
  {
    start[v] = start[v - 1];
  }
  start[0] = 0;
  auto polygonOf = [&](int64_t c) { return trianglesOnly ? c / 3 : cornerPolygon[c]; };
  // A polygon's first corner and corner count, without reading the offsets
  // of a mesh of triangles only.
  auto firstCorner = [&](int64_t p) { return trianglesOnly ? 3 * p : m.offsets[p]; };
  auto cornerCount = [&](int64_t p)
  { return trianglesOnly ? int64_t(3) : m.offsets[p + 1] - m.offsets[p]; };

  // Explicit feature edges, as sorted (min, max) pairs.
  std::vector<std::pair<int64_t, int64_t>> features;
  for (size_t i = 0; i + 1 < opt.featureEdges.size(); i += 2)
  {
    const int64_t a = opt.featureEdges[i], b = opt.featureEdges[i + 1];
    features.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(features.begin(), features.end());
  auto isFeature = [&](int64_t a, int64_t b)
  {
    return !features.empty() &&
      std::binary_search(
        features.begin(), features.end(), std::make_pair(std::min(a, b), std::max(a, b)));
  };
  const double cosFeature = std::cos(opt.featureAngle * 3.14159265358979323846 / 180.0);

  std::vector<double> normals(static_cast<size_t>(3 * nv), 0.0);
  r.originalPointIds.resize(static_cast<size_t>(nv));
  std::iota(r.originalPointIds.begin(), r.originalPointIds.end(), 0);

  // Per-vertex scratch: (other vertex, corner-local index) for both edges of
  // each incident corner, and a union-find over the incident corners.
  struct EdgeEnd
  {
    int64_t other;
    int32_t local;
  };
  std::vector<EdgeEnd> ends;
  std::vector<int32_t> parent;
  std::vector<int32_t> groupOf;
  std::vector<int64_t> groupPoint;
  // Area vector and its length of each polygon around the current vertex.
  std::vector<V3> area;
  std::vector<double> areaLength;
  // The vertex pass, compiled once per width of the corner table (no
  // per-corner branch on it).
  auto vertexPass = [&](const auto* cornerTable)
  {
    for (int64_t v = 0; v < nv; ++v)
    {
      const int64_t cb = start[v], ce = start[v + 1];
      const int32_t count = static_cast<int32_t>(ce - cb);
      if (count == 0)
      {
        normals[3 * v + 2] = 1.0;
        continue;
      }
      parent.resize(static_cast<size_t>(count));
      std::iota(parent.begin(), parent.end(), 0);
      area.resize(static_cast<size_t>(count));
      areaLength.resize(static_cast<size_t>(count));
      for (int32_t i = 0; i < count; ++i)
      {
        const int64_t p = polygonOf(static_cast<int64_t>(cornerTable[cb + i]));
        if (trianglesOnly)
        {
          // AreaVector's triangle case, without reading the offsets.
          const int64_t* t = m.connectivity + 3 * p;
          const double* p0 = m.points + 3 * t[0];
          area[i] = Cross(Sub(m.points + 3 * t[1], p0), Sub(m.points + 3 * t[2], p0));
        }
        else
        {
          area[i] = AreaVector(m, p);
        }
        areaLength[i] = std::sqrt(Dot(area[i], area[i]));
      }
      auto find = [&](int32_t x)
      {
        while (parent[x] != x)
        {
          parent[x] = parent[parent[x]];
          x = parent[x];
        }
        return x;
      };
      if (opt.splitting)
      {
        ends.resize(static_cast<size_t>(2 * count));
        for (int32_t i = 0; i < count; ++i)
        {
          const int64_t c = static_cast<int64_t>(cornerTable[cb + i]);
          const int64_t p = polygonOf(c);
          const int64_t b = firstCorner(p), n = cornerCount(p), k = c - b;
          ends[2 * i] = { m.connectivity[b + (k + 1 == n ? 0 : k + 1)], i };
          ends[2 * i + 1] = { m.connectivity[b + (k == 0 ? n - 1 : k - 1)], i };
        }
        // Insertion sort: a vertex has a handful of incident edges.
        for (size_t i = 1; i < ends.size(); ++i)
        {
          const EdgeEnd key = ends[i];
          size_t j = i;
          while (j > 0 &&
            (ends[j - 1].other > key.other ||
              (ends[j - 1].other == key.other && ends[j - 1].local > key.local)))
          {
            ends[j] = ends[j - 1];
            --j;
          }
          ends[j] = key;
        }
        for (size_t i = 0; i < ends.size();)
        {
          size_t j = i;
          while (j < ends.size() && ends[j].other == ends[i].other)
          {
            ++j;
          }
          const size_t faces = j - i;
          const int64_t w = ends[i].other;
          // Each undirected edge is seen from both its ends; count it at v < w.
          const bool countHere = v < w;
          if (faces == 1)
          {
            r.boundaryEdges += countHere;
          }
          else if (faces > 2)
          {
            r.nonManifoldEdges += countHere;
            if (!opt.splitNonManifold)
            {
              for (size_t k = i + 1; k < j; ++k)
              {
                parent[find(ends[k].local)] = find(ends[i].local);
              }
            }
          }
          else
          {
            const int32_t a = ends[i].local, b = ends[i + 1].local;
            // cos(dihedral) < cosFeature, without dividing: a.b < cos |a||b|.
            const bool crease =
              Dot(area[a], area[b]) < cosFeature * areaLength[a] * areaLength[b] ||
              isFeature(v, w);
            if (crease)
            {
              r.creaseEdges += countHere;
            }
            else
            {
              parent[find(a)] = find(b);
            }
          }
          i = j;
        }
      }
      else
      {
        for (int32_t i = 1; i < count; ++i)
        {
          parent[i] = 0;
        }
      }
      // One output point per group of corners; the first group keeps v.
      groupOf.assign(static_cast<size_t>(count), -1);
      int32_t groups = 0;
      groupPoint.clear();
      for (int32_t i = 0; i < count; ++i)
      {
        const int32_t root = find(i);
        if (groupOf[root] < 0)
        {
          groupOf[root] = groups++;
          int64_t point = v;
          if (groupOf[root] > 0)
          {
            point = static_cast<int64_t>(r.originalPointIds.size());
            r.originalPointIds.push_back(v);
            normals.insert(normals.end(), { 0.0, 0.0, 0.0 });
            ++r.splitPoints;
          }
          groupPoint.push_back(point);
        }
        const int64_t point = groupPoint[groupOf[root]];
        const int64_t c = static_cast<int64_t>(cornerTable[cb + i]);
        const int64_t p = polygonOf(c);
        const int64_t b = firstCorner(p), n = cornerCount(p);
        if (n < 3)
        {
          continue;
        }
        if (point != v)
        {
          moved.emplace_back(c, point);
        }
        const V3 w = CornerContribution(m, b, n, c - b, area[i], areaLength[i], opt.weighting);
        normals[3 * point] += w.x;
        normals[3 * point + 1] += w.y;
        normals[3 * point + 2] += w.z;
      }
    }
  };
  if (narrow)
  {
    vertexPass(corners32.data());
  }
  else
  {
    vertexPass(corners64.data());
  }
  for (size_t i = 0; i < normals.size(); i += 3)
  {
    Normalize(&normals[i]);
  }
  r.normals = std::move(normals);
  if (!moved.empty())
  {
    r.connectivity.assign(m.connectivity, m.connectivity + nc);
    for (const auto& [c, point] : moved)
    {
      r.connectivity[c] = point;
    }
  }
  return r;
}

} // namespace shadinglab::mesh
