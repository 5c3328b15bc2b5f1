// SPDX-License-Identifier: BSD-3-Clause
#include "Orientation.h"

#include "TwoThreads.h"
#include "VertexBuckets.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <numeric>

namespace shadinglab::mesh
{

namespace
{

/// Outgoing directed edges per vertex (CSR): for vertex u, the corners k
/// in [start[u], start[u + 1]) of `corner` start an edge u -> next(k).
struct OutgoingEdges
{
  std::vector<int64_t> start, corner, target;
};

OutgoingEdges MakeOutgoingEdges(const MeshView& mesh)
{
  OutgoingEdges out;
  const int64_t faces = mesh.numberOfPolygons;
  const int64_t corners = faces > 0 ? mesh.offsets[faces] : 0;
  out.start.assign(static_cast<size_t>(mesh.numberOfPoints) + 1, 0);
  for (int64_t k = 0; k < corners; ++k)
  {
    ++out.start[static_cast<size_t>(mesh.connectivity[k]) + 1];
  }
  std::partial_sum(out.start.begin(), out.start.end(), out.start.begin());
  std::vector<int64_t> fill(out.start.begin(), out.start.end() - 1);
  out.corner.resize(static_cast<size_t>(corners));
  out.target.resize(static_cast<size_t>(corners));
  for (int64_t f = 0; f < faces; ++f)
  {
    const int64_t b = mesh.offsets[f], e = mesh.offsets[f + 1];
    for (int64_t k = b; k < e; ++k)
    {
      const int64_t at = fill[mesh.connectivity[k]]++;
      out.corner[at] = k;
      out.target[at] = mesh.connectivity[k + 1 < e ? k + 1 : b];
    }
  }
  return out;
}

} // namespace

int64_t FindFaceNeighbours(
  const MeshView& mesh, FaceNeighbourLists& neighbours, std::vector<uint8_t>& touchesOpenEdge)
{
  const int64_t faces = mesh.numberOfPolygons;
  const int64_t corners = faces > 0 ? mesh.offsets[faces] : 0;
  const OutgoingEdges edges = MakeOutgoingEdges(mesh);
  std::vector<int64_t> faceOf(static_cast<size_t>(corners));
  for (int64_t f = 0; f < faces; ++f)
  {
    std::fill(faceOf.begin() + mesh.offsets[f], faceOf.begin() + mesh.offsets[f + 1], f);
  }
  neighbours.face.assign(static_cast<size_t>(corners), -1);
  neighbours.same.assign(static_cast<size_t>(corners), 0);
  touchesOpenEdge.assign(static_cast<size_t>(faces), 0);
  int64_t nonManifold = 0;
  for (int64_t f = 0; f < faces; ++f)
  {
    const int64_t b = mesh.offsets[f], e = mesh.offsets[f + 1];
    for (int64_t k = b; k < e; ++k)
    {
      const int64_t u = mesh.connectivity[k], v = mesh.connectivity[k + 1 < e ? k + 1 : b];
      // The other uses of edge {u, v}: v -> u (opposite way) and u -> v
      // from another corner (the same way); the lowest corner of all of
      // them counts a non-manifold edge once.
      int64_t uses = 1, other = -1, lowest = k;
      bool same = false;
      if (u != v)
      {
        for (int64_t at = edges.start[v]; at < edges.start[v + 1]; ++at)
        {
          if (edges.target[at] == u)
          {
            ++uses;
            other = edges.corner[at];
            same = false;
            lowest = std::min(lowest, other);
          }
        }
        for (int64_t at = edges.start[u]; at < edges.start[u + 1]; ++at)
        {
          if (edges.target[at] == v && edges.corner[at] != k)
          {
            ++uses;
            other = edges.corner[at];
            same = true;
            lowest = std::min(lowest, other);
          }
        }
      }
      if (uses == 2)
      {
        neighbours.face[k] = faceOf[other];
        neighbours.same[k] = same ? 1 : 0;
      }
      else
      {
        touchesOpenEdge[f] = 1; // open (one use), degenerate (u == v) or non-manifold
        nonManifold += uses > 2 && lowest == k;
      }
    }
  }
  return nonManifold;
}

std::vector<uint8_t> OrientComponents(const MeshView& mesh, const FaceNeighbourLists& neighbours,
  const std::vector<uint8_t>& touchesOpenEdge, int64_t& components)
{
  const int64_t faces = mesh.numberOfPolygons;
  std::vector<uint8_t> flip(static_cast<size_t>(faces), 0);
  std::vector<int64_t> component(static_cast<size_t>(faces), -1);
  std::vector<int64_t> members;
  for (int64_t root = 0; root < faces; ++root)
  {
    if (component[root] >= 0)
    {
      continue;
    }
    const int64_t id = components++;
    members.clear();
    // Breadth-first: `members` is the queue, in visiting order.
    members.push_back(root);
    component[root] = id;
    bool closed = true;
    for (size_t next = 0; next < members.size(); ++next)
    {
      const int64_t f = members[next];
      closed &= touchesOpenEdge[f] == 0;
      for (int64_t k = mesh.offsets[f]; k < mesh.offsets[f + 1]; ++k)
      {
        const int64_t g = neighbours.face[k];
        if (g < 0 || component[g] >= 0)
        {
          continue;
        }
        component[g] = id;
        flip[g] = static_cast<uint8_t>(flip[f] ^ neighbours.same[k]);
        members.push_back(g);
      }
    }
    if (closed)
    {
      // Signed volume of the component as it will be oriented (divergence
      // theorem: the sum of p0 . (p1 x p2) over the fan triangles, x6).
      double volume = 0;
      for (int64_t f : members)
      {
        const int64_t b = mesh.offsets[f], e = mesh.offsets[f + 1];
        const double* p0 = &mesh.points[3 * mesh.connectivity[b]];
        for (int64_t k = b + 1; k + 1 < e; ++k)
        {
          const double* p1 = &mesh.points[3 * mesh.connectivity[k]];
          const double* p2 = &mesh.points[3 * mesh.connectivity[k + 1]];
          const double v = p0[0] * (p1[1] * p2[2] - p1[2] * p2[1]) -
            p0[1] * (p1[0] * p2[2] - p1[2] * p2[0]) + p0[2] * (p1[0] * p2[1] - p1[1] * p2[0]);
          volume += flip[f] ? -v : v;
        }
      }
      if (volume < 0)
      {
        for (int64_t f : members)
        {
          flip[f] ^= 1;
        }
      }
    }
  }
  return flip;
}

namespace
{

/// Vertex degrees up to which duplicate targets are found by comparing
/// every pair (at most 120 comparisons, no allocation); a vertex of more
/// outgoing edges sorts them. A closed triangle mesh averages 6.
constexpr int64_t kPairwiseDegree = 16;

/// Whether vertex range [begin, end) has an outgoing edge twice.
template <typename Id>
bool DuplicateEdgeAmong(const std::vector<Id>& start, std::vector<Id>& target, int64_t begin, int64_t end)
{
  for (int64_t u = begin; u < end; ++u)
  {
    const int64_t b = static_cast<int64_t>(start[static_cast<size_t>(u)]);
    const int64_t e = static_cast<int64_t>(start[static_cast<size_t>(u) + 1]);
    Id* t = target.data();
    if (e - b <= kPairwiseDegree)
    {
      for (int64_t i = b; i < e; ++i)
      {
        for (int64_t j = i + 1; j < e; ++j)
        {
          if (t[i] == t[j] && static_cast<int64_t>(t[i]) != u) // u -> u: a repeated vertex
          {
            return true;
          }
        }
      }
      continue;
    }
    std::sort(t + b, t + e);
    for (int64_t i = b; i + 1 < e; ++i)
    {
      if (t[i] == t[i + 1] && static_cast<int64_t>(t[i]) != u)
      {
        return true;
      }
    }
  }
  return false;
}

/// HasInconsistentOrientation with ids of type Id: the outgoing edges'
/// targets per vertex (CSR), then duplicates per vertex, the vertices
/// split between two threads.
template <typename Id, typename View>
bool HasDuplicateDirectedEdge(const View& mesh)
{
  const int64_t faces = mesh.numberOfPolygons, points = mesh.numberOfPoints;
  const int64_t corners = mesh.offsets[faces];
  std::vector<Id> start;
  std::vector<Id> target(static_cast<size_t>(corners));
  BucketCornersByVertex(mesh, start, [&](int64_t, int64_t b, int64_t e, int64_t k, int64_t slot) {
    target[static_cast<size_t>(slot)] = static_cast<Id>(mesh.connectivity[k + 1 < e ? k + 1 : b]);
  });
  const int64_t half = points / 2;
  bool first = false, second = false;
  RunBoth(true, [&] { first = DuplicateEdgeAmong(start, target, 0, half); },
    [&] { second = DuplicateEdgeAmong(start, target, half, points); });
  return first || second;
}

template <typename View>
bool HasInconsistentOrientationOf(const View& mesh)
{
  if (mesh.numberOfPolygons == 0 || mesh.numberOfPoints == 0)
  {
    return false;
  }
  // 32-bit ids halve the table's memory and traffic when they fit.
  const int64_t corners = mesh.offsets[mesh.numberOfPolygons];
  if (mesh.numberOfPoints < INT32_MAX && corners < INT32_MAX)
  {
    return HasDuplicateDirectedEdge<int32_t>(mesh);
  }
  return HasDuplicateDirectedEdge<int64_t>(mesh);
}

} // namespace

bool HasInconsistentOrientation(const MeshView& mesh)
{
  return HasInconsistentOrientationOf(mesh);
}

bool HasInconsistentOrientation(const NarrowMeshView& mesh)
{
  return HasInconsistentOrientationOf(mesh);
}

std::vector<uint8_t> ConsistentOrientationFlips(const MeshView& mesh)
{
  FaceNeighbourLists neighbours;
  std::vector<uint8_t> touchesOpenEdge;
  FindFaceNeighbours(mesh, neighbours, touchesOpenEdge);
  int64_t components = 0;
  return OrientComponents(mesh, neighbours, touchesOpenEdge, components);
}

int64_t FlipFaces(
  const MeshView& mesh, const std::vector<uint8_t>& flips, std::vector<int64_t>& connectivity)
{
  const int64_t faces = mesh.numberOfPolygons;
  connectivity.assign(mesh.connectivity, mesh.connectivity + (faces > 0 ? mesh.offsets[faces] : 0));
  int64_t flipped = 0;
  for (int64_t f = 0; f < faces; ++f)
  {
    if (flips[static_cast<size_t>(f)])
    {
      std::reverse(connectivity.begin() + mesh.offsets[f], connectivity.begin() + mesh.offsets[f + 1]);
      ++flipped;
    }
  }
  return flipped;
}

std::vector<int64_t> CoincidentPointRepresentatives(const double* points, int64_t numberOfPoints)
{
  // Points compared by the bits of their coordinates: a strict order even
  // with NaN among them; + 0.0 turns -0.0 into 0.0, the one pair of equal
  // values with different bits.
  using Bits = std::array<uint64_t, 3>;
  std::vector<std::pair<Bits, int64_t>> keys(static_cast<size_t>(numberOfPoints));
  for (int64_t i = 0; i < numberOfPoints; ++i)
  {
    Bits bits;
    for (int c = 0; c < 3; ++c)
    {
      const double x = points[3 * i + c] + 0.0;
      std::memcpy(&bits[c], &x, sizeof x);
    }
    keys[static_cast<size_t>(i)] = { bits, i };
  }
  std::sort(keys.begin(), keys.end()); // equal positions by increasing index
  std::vector<int64_t> representative(static_cast<size_t>(numberOfPoints));
  for (size_t k = 0; k < keys.size(); ++k)
  {
    const bool sameAsPrevious = k > 0 && keys[k].first == keys[k - 1].first;
    representative[keys[k].second] = sameAsPrevious ? representative[keys[k - 1].second] : keys[k].second;
  }
  return representative;
}

} // namespace shadinglab::mesh
