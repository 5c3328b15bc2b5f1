// SPDX-License-Identifier: BSD-3-Clause
#include "Orientation.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <numeric>
#include <queue>

namespace shadinglab::mesh
{

int64_t FindFaceNeighbours(
  const MeshView& mesh, FaceNeighbourLists& neighbours, std::vector<uint8_t>& touchesOpenEdge)
{
  // The edges as (min, max, face, forward) uses, sorted: a run of equal
  // (min, max) is one edge.
  const int64_t faces = mesh.numberOfPolygons;
  struct EdgeUse
  {
    int64_t a, b, face;
    bool forward;
  };
  std::vector<EdgeUse> uses;
  uses.reserve(static_cast<size_t>(faces > 0 ? mesh.offsets[faces] : 0));
  for (int64_t f = 0; f < faces; ++f)
  {
    const int64_t b = mesh.offsets[f], e = mesh.offsets[f + 1];
    for (int64_t k = b; k < e; ++k)
    {
      const int64_t u = mesh.connectivity[k], v = mesh.connectivity[k + 1 < e ? k + 1 : b];
      uses.push_back({ std::min(u, v), std::max(u, v), f, u < v });
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.a < y.a || (x.a == y.a && (x.b < y.b || (x.b == y.b && x.face < y.face)));
  });
  neighbours.assign(static_cast<size_t>(faces), {});
  touchesOpenEdge.assign(static_cast<size_t>(faces), 0);
  int64_t nonManifold = 0;
  for (size_t i = 0; i < uses.size();)
  {
    size_t j = i;
    while (j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b)
    {
      ++j;
    }
    if (j - i == 2)
    {
      const bool same = uses[i].forward == uses[i + 1].forward;
      neighbours[uses[i].face].push_back({ uses[i + 1].face, same });
      neighbours[uses[i + 1].face].push_back({ uses[i].face, same });
    }
    else
    {
      nonManifold += j - i > 2;
      for (size_t k = i; k < j; ++k)
      {
        touchesOpenEdge[uses[k].face] = 1;
      }
    }
    i = j;
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
    std::queue<int64_t> queue;
    queue.push(root);
    component[root] = id;
    bool closed = true;
    while (!queue.empty())
    {
      const int64_t f = queue.front();
      queue.pop();
      members.push_back(f);
      closed &= touchesOpenEdge[f] == 0;
      for (const auto& [g, same] : neighbours[f])
      {
        if (component[g] >= 0)
        {
          continue;
        }
        component[g] = id;
        flip[g] = static_cast<uint8_t>(flip[f] ^ (same ? 1 : 0));
        queue.push(g);
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

bool HasInconsistentOrientation(const MeshView& mesh)
{
  const int64_t faces = mesh.numberOfPolygons, points = mesh.numberOfPoints;
  if (faces == 0 || points == 0)
  {
    return false;
  }
  // Outgoing directed edges per vertex (CSR), then duplicates per vertex.
  std::vector<int64_t> start(static_cast<size_t>(points) + 1, 0);
  for (int64_t f = 0; f < faces; ++f)
  {
    for (int64_t k = mesh.offsets[f]; k < mesh.offsets[f + 1]; ++k)
    {
      ++start[static_cast<size_t>(mesh.connectivity[k]) + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int64_t> fill(start.begin(), start.end() - 1);
  std::vector<int64_t> target(static_cast<size_t>(start.back()));
  for (int64_t f = 0; f < faces; ++f)
  {
    const int64_t b = mesh.offsets[f], e = mesh.offsets[f + 1];
    for (int64_t k = b; k < e; ++k)
    {
      target[fill[mesh.connectivity[k]]++] = mesh.connectivity[k + 1 < e ? k + 1 : b];
    }
  }
  for (int64_t u = 0; u < points; ++u)
  {
    auto first = target.begin() + start[u], last = target.begin() + start[u + 1];
    std::sort(first, last);
    for (auto it = first; it != last && it + 1 != last; ++it)
    {
      if (*it == *(it + 1) && *it != u) // u -> u: a repeated vertex, not an edge
      {
        return true;
      }
    }
  }
  return false;
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
