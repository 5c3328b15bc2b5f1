// SPDX-License-Identifier: BSD-3-Clause
// Crease-free vertex normals (ComputeVertexNormalsNoSplit): one pass over
// the polygons, angle weights of runs of triangles in SIMD batches. The
// crease pass is CreaseNormals.cxx; what both compute per polygon and
// corner is NormalKernels.h.
#include "VertexNormals.h"

#include "Geometry.h"
#include "NormalKernels.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>

namespace shadinglab::mesh
{

using namespace kernels;

namespace
{

/// Polygon p's contribution to its vertices' normals (the per-polygon loop
/// body of ComputeVertexNormalsNoSplit).
template <typename Real, typename Id>
void AddPolygon(const MeshViewOf<Real, Id>& m, int64_t p, NormalWeighting weighting, double* out)
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
      double* o = out + 3 * int64_t(m.connectivity[b + k]);
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
    const Real* p0 = m.points + 3 * i0;
    const Real* p1 = m.points + 3 * i1;
    const Real* p2 = m.points + 3 * i2;
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
    double* o = out + 3 * int64_t(m.connectivity[b + k]);
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
template <typename Real, typename Id>
__attribute__((always_inline)) inline void AngleWeightedTrianglesBody(const MeshViewOf<Real, Id>& m,
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
    const Id* corners = m.connectivity + m.offsets[start];
    for (int64_t i = 0; i < count; ++i)
    {
      const Id* c = corners + 3 * i;
      const V3 e1 = Sub(m.points + 3 * int64_t(c[1]), m.points + 3 * int64_t(c[0]));
      const V3 e2 = Sub(m.points + 3 * int64_t(c[2]), m.points + 3 * int64_t(c[0]));
      b.e1x[i] = e1.x;
      b.e1y[i] = e1.y;
      b.e1z[i] = e1.z;
      b.e2x[i] = e2.x;
      b.e2y[i] = e2.y;
      b.e2z[i] = e2.z;
    }
    AngleWeights(b, count);
    for (int64_t i = 0; i < count; ++i)
    {
      const Id* c = corners + 3 * i;
      const double w[3] = { b.w0[i], b.w1[i], b.w2[i] };
      for (int k = 0; k < 3; ++k)
      {
        double* o = out + 3 * int64_t(c[k]);
        o[0] += b.e1x[i] * w[k];
        o[1] += b.e1y[i] * w[k];
        o[2] += b.e1z[i] * w[k];
      }
    }
  }
}

/// The same loop compiled for AVX2 (4 doubles a lane group instead of
/// SSE2's 2): chosen at run time, so the binary still runs without AVX2.
template <typename Real, typename Id>
__attribute__((target("avx2"))) void AngleWeightedTrianglesAvx2(const MeshViewOf<Real, Id>& m,
  int64_t first,
  int64_t last,
  double* out)
{
  AngleWeightedTrianglesBody(m, first, last, out);
}

template <typename Real, typename Id>
void AngleWeightedTrianglesBaseline(const MeshViewOf<Real, Id>& m, int64_t first, int64_t last, double* out)
{
  AngleWeightedTrianglesBody(m, first, last, out);
}

std::atomic<bool> gWideSimd{ true };

template <typename Real, typename Id>
void AddAngleWeightedTriangles(const MeshViewOf<Real, Id>& m, int64_t first, int64_t last, double* out)
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

namespace
{

template <typename Real, typename Id>
void NoSplitNormals(const MeshViewOf<Real, Id>& m, NormalWeighting weighting, std::vector<double>& normals)
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

} // namespace

void ComputeVertexNormalsNoSplit(
  const MeshView& mesh, NormalWeighting weighting, std::vector<double>& normals)
{
  NoSplitNormals(mesh, weighting, normals);
}

void ComputeVertexNormalsNoSplit(
  const FloatMeshView& mesh, NormalWeighting weighting, std::vector<double>& normals)
{
  NoSplitNormals(mesh, weighting, normals);
}

void ComputeVertexNormalsNoSplit(
  const NarrowMeshView& mesh, NormalWeighting weighting, std::vector<double>& normals)
{
  NoSplitNormals(mesh, weighting, normals);
}

void ComputeVertexNormalsNoSplit(
  const FloatNarrowMeshView& mesh, NormalWeighting weighting, std::vector<double>& normals)
{
  NoSplitNormals(mesh, weighting, normals);
}

/// Polygons of more corners than this are skipped by ComputeVertexNormalsAt
/// (their corners are copied to a stack buffer); meshes a renderer draws
/// have 3-8, and one skipped polygon changes an estimate by its share only.
constexpr int64_t kMaxCornersAt = 64;

namespace
{

template <typename Id>
void NormalsAt(const float* points,
  const Id* offsets,
  const Id* connectivity,
  int64_t numberOfPolygons,
  const std::vector<NormalWeighting>& weightings,
  const std::vector<int64_t>& slotOfPoint,
  int64_t slots,
  std::vector<std::vector<double>>& normals)
{
  normals.resize(weightings.size());
  for (auto& n : normals)
  {
    n.assign(static_cast<size_t>(3 * slots), 0.0);
  }
  double local[3 * kMaxCornersAt];
  int64_t corners[kMaxCornersAt];
  for (int64_t p = 0; p < numberOfPolygons; ++p)
  {
    const int64_t b = offsets[p], n = offsets[p + 1] - b;
    if (n < 3 || n > kMaxCornersAt)
    {
      continue;
    }
    bool listed = false;
    for (int64_t k = 0; k < n && !listed; ++k)
    {
      listed = slotOfPoint[connectivity[b + k]] >= 0;
    }
    if (!listed)
    {
      continue;
    }
    // The polygon on its own, in double: the shared kernels then give what
    // the whole-mesh pass gives, up to rounding.
    for (int64_t k = 0; k < n; ++k)
    {
      const float* q = points + 3 * int64_t(connectivity[b + k]);
      local[3 * k] = q[0];
      local[3 * k + 1] = q[1];
      local[3 * k + 2] = q[2];
      corners[k] = k;
    }
    const int64_t ends[2] = { 0, n };
    const MeshView one{ local, n, ends, corners, 1 };
    const V3 a = AreaVector(one, 0);
    const double len = std::sqrt(Dot(a, a));
    for (int64_t k = 0; k < n; ++k)
    {
      const int64_t slot = slotOfPoint[connectivity[b + k]];
      if (slot < 0)
      {
        continue;
      }
      for (size_t w = 0; w < weightings.size(); ++w)
      {
        const V3 c = CornerContribution(one, 0, n, k, a, len, weightings[w]);
        double* o = normals[w].data() + 3 * slot;
        o[0] += c.x;
        o[1] += c.y;
        o[2] += c.z;
      }
    }
  }
  for (auto& n : normals)
  {
    for (int64_t v = 0; v < slots; ++v)
    {
      Normalize(n.data() + 3 * v);
    }
  }
}

} // namespace

void ComputeVertexNormalsAt(const float* points, const int64_t* offsets,
  const int64_t* connectivity, int64_t numberOfPolygons,
  const std::vector<NormalWeighting>& weightings, const std::vector<int64_t>& slotOfPoint,
  int64_t slots, std::vector<std::vector<double>>& normals)
{
  NormalsAt(points, offsets, connectivity, numberOfPolygons, weightings, slotOfPoint, slots, normals);
}

void ComputeVertexNormalsAt(const float* points, const int32_t* offsets,
  const int32_t* connectivity, int64_t numberOfPolygons,
  const std::vector<NormalWeighting>& weightings, const std::vector<int64_t>& slotOfPoint,
  int64_t slots, std::vector<std::vector<double>>& normals)
{
  NormalsAt(points, offsets, connectivity, numberOfPolygons, weightings, slotOfPoint, slots, normals);
}

} // namespace shadinglab::mesh
