// SPDX-License-Identifier: BSD-3-Clause
// The crease pass of vertex normals (ComputeVertexNormals): a vertex-to-
// corner table, then per vertex its incident edges grouped, the faces on
// either side of each compared with the feature angle, the corners joined
// into groups by union-find, one output point per group.
#include "VertexNormals.h"
#include "VertexBuckets.h"

#include "Geometry.h"
#include "NormalKernels.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <thread>
#include <utility>

namespace shadinglab::mesh
{

using namespace kernels;

namespace
{

/// Vertex -> corners (CSR by counting sort): corner index c = offset + k,
/// the corners of vertex v at [start[v], start[v + 1]).
struct CornerTable
{
  std::vector<int64_t> start, corners64, cornerPolygon;
  std::vector<uint32_t> corners32;
  /// Corner indices in 4 bytes where they fit (every mesh up to 1.4 billion
  /// triangles; 60 MB less on 5M), in 8 otherwise.
  bool narrow = true;
  /// A mesh of triangles only finds a corner's polygon as c / 3; others keep
  /// a table (8 bytes a corner: 120 MB on 5M triangles).
  bool trianglesOnly = true;

  int64_t PolygonOf(int64_t c) const { return trianglesOnly ? c / 3 : cornerPolygon[c]; }
  /// A polygon's first corner and corner count, without reading the
  /// offsets of a mesh of triangles only.
  template <typename View>
  int64_t FirstCorner(const View& m, int64_t p) const { return trianglesOnly ? 3 * p : m.offsets[p]; }
  template <typename View>
  int64_t CornerCount(const View& m, int64_t p) const
  {
    return trianglesOnly ? int64_t(3) : m.offsets[p + 1] - m.offsets[p];
  }
};

template <typename Real, typename Id>
void BuildCornerTable(const MeshViewOf<Real, Id>& m, CornerTable& t)
{
  const int64_t np = m.numberOfPolygons;
  const int64_t nc = np > 0 ? m.offsets[np] : 0;
  t.narrow = nc <= static_cast<int64_t>(std::numeric_limits<uint32_t>::max());
  t.corners32.resize(t.narrow ? static_cast<size_t>(nc) : 0);
  t.corners64.resize(t.narrow ? 0 : static_cast<size_t>(nc));
  // Every offset must be 3p: the corner count alone would take a 2-gon
  // beside a quad for two triangles (one pass over the offsets, ~1 ms on
  // 5M triangles).
  t.trianglesOnly = nc == 3 * np;
  for (int64_t p = 0; t.trianglesOnly && p < np; ++p)
  {
    t.trianglesOnly = m.offsets[p] == 3 * p;
  }
  t.cornerPolygon.resize(t.trianglesOnly ? 0 : static_cast<size_t>(nc));
  BucketCornersByVertex(m, t.start, [&](int64_t p, int64_t, int64_t, int64_t c, int64_t slot) {
    if (t.narrow)
    {
      t.corners32[static_cast<size_t>(slot)] = static_cast<uint32_t>(c);
    }
    else
    {
      t.corners64[static_cast<size_t>(slot)] = c;
    }
    if (!t.trianglesOnly)
    {
      t.cornerPolygon[static_cast<size_t>(c)] = p;
    }
  });
}

/// Explicit feature edges, as sorted (min, max) pairs.
class FeatureEdges
{
public:
  explicit FeatureEdges(const std::vector<int64_t>& pairs)
  {
    for (size_t i = 0; i + 1 < pairs.size(); i += 2)
    {
      const int64_t a = pairs[i], b = pairs[i + 1];
      this->Edges.emplace_back(std::min(a, b), std::max(a, b));
    }
    std::sort(this->Edges.begin(), this->Edges.end());
  }
  bool Contains(int64_t a, int64_t b) const
  {
    return !this->Edges.empty() &&
      std::binary_search(
        this->Edges.begin(), this->Edges.end(), std::make_pair(std::min(a, b), std::max(a, b)));
  }

private:
  std::vector<std::pair<int64_t, int64_t>> Edges;
};

/// Per-vertex scratch: (other vertex, corner-local index) for both edges of
/// each incident corner, a union-find over the incident corners, their
/// groups' output points, and the area vector and its length of each
/// polygon around the vertex.
struct VertexScratch
{
  struct EdgeEnd
  {
    int64_t other;
    int32_t local;
  };
  std::vector<EdgeEnd> ends;
  std::vector<int32_t> parent;
  std::vector<int32_t> groupOf;
  std::vector<int64_t> groupPoint;
  std::vector<V3> area;
  std::vector<double> areaLength;

  int32_t Find(int32_t x)
  {
    while (this->parent[x] != x)
    {
      this->parent[x] = this->parent[this->parent[x]];
      x = this->parent[x];
    }
    return x;
  }
};

/// Splitting: joins the `count` corners of vertex v (at `corners`) across
/// the edges where their faces meet at less than the feature angle
/// (cos: `cosFeature`) and that are no feature edge; counts the boundary,
/// non-manifold and crease edges at their lower vertex.
template <typename Real, typename Id, typename CornerT>
void JoinAcrossSmoothEdges(const MeshViewOf<Real, Id>& m, const CornerTable& t, const CornerT* corners,
  int64_t v, int32_t count, const NormalOptions& opt, const FeatureEdges& features,
  double cosFeature, VertexScratch& s, NormalResult& r)
{
  std::vector<VertexScratch::EdgeEnd>& ends = s.ends;
  ends.resize(static_cast<size_t>(2 * count));
  for (int32_t i = 0; i < count; ++i)
  {
    const int64_t c = static_cast<int64_t>(corners[i]);
    const int64_t p = t.PolygonOf(c);
    const int64_t b = t.FirstCorner(m, p), n = t.CornerCount(m, p), k = c - b;
    ends[2 * i] = { m.connectivity[b + (k + 1 == n ? 0 : k + 1)], i };
    ends[2 * i + 1] = { m.connectivity[b + (k == 0 ? n - 1 : k - 1)], i };
  }
  // Insertion sort: a vertex has a handful of incident edges.
  for (size_t i = 1; i < ends.size(); ++i)
  {
    const VertexScratch::EdgeEnd key = ends[i];
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
          s.parent[s.Find(ends[k].local)] = s.Find(ends[i].local);
        }
      }
    }
    else
    {
      const int32_t a = ends[i].local, b = ends[i + 1].local;
      // cos(dihedral) < cosFeature, without dividing: a.b < cos |a||b|.
      const bool crease =
        Dot(s.area[a], s.area[b]) < cosFeature * s.areaLength[a] * s.areaLength[b] ||
        features.Contains(v, w);
      if (crease)
      {
        r.creaseEdges += countHere;
      }
      else
      {
        s.parent[s.Find(a)] = s.Find(b);
      }
    }
    i = j;
  }
}

} // namespace

namespace
{

/// Scratch arrays persist per thread across calls: a filter re-run on a
/// large mesh then reuses their pages instead of faulting in ~100 MB anew
/// (measured: a third of the time was the kernel zeroing fresh pages).
/// Above kKeptScratchCorners they are freed after the pass instead, and
/// ReleaseNormalScratch frees them for a caller that will not call again.
thread_local CornerTable tableOfThisThread;

/// Corners above which the table is freed as soon as the vertex pass is
/// done instead of kept: 2^24 corners (5.6M triangles) are a table of
/// about 100 MB, the size where holding it through the caller's output
/// arrays costs more than re-faulting its pages costs the next run
/// (16M triangles: 256 MB of a 1.5 GB peak, against ~0.1 s).
constexpr int64_t kKeptScratchCorners = int64_t(1) << 24;

/// Vertices below which the pass runs on the calling thread alone: a
/// thread's start (~50 us) costs more than ~20k vertices' work.
constexpr int64_t kParallelVertices = 100000;

/// What one range of vertices makes: the split points it adds (numbered
/// from 0 in the range, renumbered when the ranges are joined in order),
/// their normals and input points, the corners moved to them, and its
/// edge counts. The normals of the range's own vertices go straight into
/// the shared array (the ranges are disjoint).
struct RangeResult
{
  std::vector<double> splitNormals;
  std::vector<int64_t> splitOrigins;
  std::vector<std::pair<int64_t, int64_t>> moved; ///< (corner, split point in the range)
  NormalResult counts;
};

/// The vertex pass over [v0, v1) (see ComputeVertexNormals).
template <typename Real, typename Id, typename CornerT>
void VertexPass(const MeshViewOf<Real, Id>& m, const CornerTable& table, const CornerT* cornerTable,
  const NormalOptions& opt, const FeatureEdges& features, double cosFeature, int64_t v0,
  int64_t v1, double* normals, RangeResult& out)
{
  VertexScratch s;
  for (int64_t v = v0; v < v1; ++v)
  {
    const int64_t cb = table.start[v], ce = table.start[v + 1];
    const int32_t count = static_cast<int32_t>(ce - cb);
    if (count == 0)
    {
      normals[3 * v + 2] = 1.0;
      continue;
    }
    s.parent.resize(static_cast<size_t>(count));
    std::iota(s.parent.begin(), s.parent.end(), 0);
    s.area.resize(static_cast<size_t>(count));
    s.areaLength.resize(static_cast<size_t>(count));
    for (int32_t i = 0; i < count; ++i)
    {
      const int64_t p = table.PolygonOf(static_cast<int64_t>(cornerTable[cb + i]));
      s.area[i] = AreaVectorAt(m, table.FirstCorner(m, p), table.CornerCount(m, p));
      s.areaLength[i] = std::sqrt(Dot(s.area[i], s.area[i]));
    }
    if (opt.splitting)
    {
      JoinAcrossSmoothEdges(m, table, cornerTable + cb, v, count, opt, features, cosFeature, s, out.counts);
    }
    else
    {
      for (int32_t i = 1; i < count; ++i)
      {
        s.parent[i] = 0;
      }
    }
    // One output point per group of corners; the first group keeps v
    // (-1: v itself; k >= 0: the range's split point k).
    s.groupOf.assign(static_cast<size_t>(count), -1);
    int32_t groups = 0;
    s.groupPoint.clear();
    for (int32_t i = 0; i < count; ++i)
    {
      const int32_t root = s.Find(i);
      if (s.groupOf[root] < 0)
      {
        s.groupOf[root] = groups++;
        int64_t split = -1;
        if (s.groupOf[root] > 0)
        {
          split = static_cast<int64_t>(out.splitOrigins.size());
          out.splitOrigins.push_back(v);
          out.splitNormals.insert(out.splitNormals.end(), { 0.0, 0.0, 0.0 });
        }
        s.groupPoint.push_back(split);
      }
      const int64_t split = s.groupPoint[s.groupOf[root]];
      const int64_t c = static_cast<int64_t>(cornerTable[cb + i]);
      const int64_t p = table.PolygonOf(c);
      const int64_t b = table.FirstCorner(m, p), n = table.CornerCount(m, p);
      if (n < 3)
      {
        continue;
      }
      if (split >= 0)
      {
        out.moved.emplace_back(c, split);
      }
      const V3 w = CornerContribution(m, b, n, c - b, s.area[i], s.areaLength[i], opt.weighting);
      double* to = split >= 0 ? &out.splitNormals[3 * split] : &normals[3 * v];
      to[0] += w.x;
      to[1] += w.y;
      to[2] += w.z;
    }
  }
}

} // namespace

namespace
{

template <typename Real, typename Id>
NormalResult CreaseNormals(const MeshViewOf<Real, Id>& m, const NormalOptions& opt)
{
  NormalResult r;
  const int64_t nv = m.numberOfPoints, np = m.numberOfPolygons;
  const int64_t nc = np > 0 ? m.offsets[np] : 0;
  // No per-polygon table of area vectors is kept (160 MB on 5M triangles):
  // the vertex pass computes the area vectors of the polygons around each
  // vertex as it reaches it, the same arithmetic, so the same bits.
  CornerTable& table = tableOfThisThread; // the workers read the caller's table
  BuildCornerTable(m, table);
  const FeatureEdges features(opt.featureEdges);
  const double cosFeature = std::cos(opt.featureAngle * 3.14159265358979323846 / 180.0);
  std::vector<double> normals(static_cast<size_t>(3 * nv), 0.0);
  // The vertex pass over ranges of vertices, one per thread, joined in
  // vertex order: split points are numbered as one pass in order numbers
  // them, so the result is the same bits on any number of threads.
  const int threads = opt.threads > 0 ? opt.threads
    : nv < kParallelVertices
    ? 1
    : static_cast<int>(std::clamp<unsigned>(std::thread::hardware_concurrency(), 1u, 8u));
  std::vector<RangeResult> ranges(static_cast<size_t>(threads));
  auto pass = [&](int k) {
    const int64_t v0 = nv * k / threads, v1 = nv * (k + 1) / threads;
    if (table.narrow)
    {
      VertexPass(m, table, table.corners32.data(), opt, features, cosFeature, v0, v1, normals.data(), ranges[k]);
    }
    else
    {
      VertexPass(m, table, table.corners64.data(), opt, features, cosFeature, v0, v1, normals.data(), ranges[k]);
    }
  };
  std::vector<std::thread> workers;
  for (int k = 1; k < threads; ++k)
  {
    workers.emplace_back(pass, k);
  }
  pass(0);
  for (std::thread& w : workers)
  {
    w.join();
  }
  if (nc > kKeptScratchCorners)
  {
    table = CornerTable();
  }
  r.originalPointIds.resize(static_cast<size_t>(nv));
  std::iota(r.originalPointIds.begin(), r.originalPointIds.end(), 0);
  std::vector<std::pair<int64_t, int64_t>> moved; // (corner, output point)
  for (RangeResult& range : ranges)
  {
    const int64_t base = static_cast<int64_t>(r.originalPointIds.size());
    r.originalPointIds.insert(r.originalPointIds.end(), range.splitOrigins.begin(), range.splitOrigins.end());
    normals.insert(normals.end(), range.splitNormals.begin(), range.splitNormals.end());
    for (const auto& [c, split] : range.moved)
    {
      moved.emplace_back(c, base + split);
    }
    r.creaseEdges += range.counts.creaseEdges;
    r.nonManifoldEdges += range.counts.nonManifoldEdges;
    r.boundaryEdges += range.counts.boundaryEdges;
    r.splitPoints += static_cast<int64_t>(range.splitOrigins.size());
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

} // namespace

void ReleaseNormalScratch()
{
  tableOfThisThread = CornerTable();
}

NormalResult ComputeVertexNormals(const MeshView& mesh, const NormalOptions& options)
{
  return CreaseNormals(mesh, options);
}

NormalResult ComputeVertexNormals(const FloatMeshView& mesh, const NormalOptions& options)
{
  return CreaseNormals(mesh, options);
}

NormalResult ComputeVertexNormals(const NarrowMeshView& mesh, const NormalOptions& options)
{
  return CreaseNormals(mesh, options);
}

NormalResult ComputeVertexNormals(const FloatNarrowMeshView& mesh, const NormalOptions& options)
{
  return CreaseNormals(mesh, options);
}

} // namespace shadinglab::mesh
