// SPDX-License-Identifier: BSD-3-Clause
#include "HiddenBackFaces.h"

#include "Geometry.h"

#include <limits>
#include <numeric>
#include <vector>

namespace shadinglab::cpu
{

namespace
{

/// Union-find over vertices (mesh/core/Geometry.h).
uint32_t Root(std::vector<uint32_t>& parent, uint32_t v)
{
  return mesh::UnionFindRoot(parent, v);
}

} // namespace

bool IsClosedOutwardTriangleMesh(const render::Mesh& mesh)
{
  const int64_t nv = mesh.NumberOfPoints(), np = mesh.NumberOfPolygons();
  const int64_t corners = static_cast<int64_t>(mesh.connectivity.size());
  // 32-bit tables: a mesh with 2^31 points or corners is not looked at.
  if (np == 0 || nv >= std::numeric_limits<int32_t>::max() ||
    corners >= std::numeric_limits<int32_t>::max() || corners != 3 * np)
  {
    return false;
  }
  for (int64_t p = 0; p < np; ++p)
  {
    if (mesh.offsets[p + 1] - mesh.offsets[p] != 3)
    {
      return false;
    }
  }
  const int64_t* conn = mesh.connectivity.data();
  // Directed edges a -> b grouped by a (CSR).
  std::vector<uint32_t> start(static_cast<size_t>(nv) + 1, 0);
  for (int64_t k = 0; k < corners; ++k)
  {
    if (conn[k] < 0 || conn[k] >= nv)
    {
      return false;
    }
    ++start[conn[k] + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<uint32_t> head(static_cast<size_t>(corners));
  {
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (int64_t t = 0; t < np; ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int64_t a = conn[3 * t + k], b = conn[3 * t + (k + 1) % 3];
        if (a == b)
        {
          return false; // a collapsed edge
        }
        head[fill[a]++] = static_cast<uint32_t>(b);
      }
    }
  }
  // Each directed edge exactly once, its reverse exactly once.
  auto count = [&](uint32_t a, uint32_t b)
  {
    int c = 0;
    for (uint32_t k = start[a]; k < start[a + 1]; ++k)
    {
      c += head[k] == b;
    }
    return c;
  };
  for (uint32_t a = 0; a < static_cast<uint32_t>(nv); ++a)
  {
    for (uint32_t k = start[a]; k < start[a + 1]; ++k)
    {
      if (count(a, head[k]) != 1 || count(head[k], a) != 1)
      {
        return false;
      }
    }
  }
  // Components (by shared vertices) and their signed volumes, from the
  // bounding-box centre (divergence theorem: sum of det(p0, p1, p2) / 6).
  std::vector<uint32_t> parent(static_cast<size_t>(nv));
  std::iota(parent.begin(), parent.end(), 0u);
  double b[6];
  mesh.Bounds(b);
  const double centre[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  for (int64_t k = 0; k < corners; k += 3)
  {
    const uint32_t a = Root(parent, static_cast<uint32_t>(conn[k]));
    parent[Root(parent, static_cast<uint32_t>(conn[k + 1]))] = a;
    parent[Root(parent, static_cast<uint32_t>(conn[k + 2]))] = a;
  }
  std::vector<double> volume(static_cast<size_t>(nv), 0.0);
  for (int64_t t = 0; t < np; ++t)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        p[k][c] = double(mesh.points[3 * conn[3 * t + k] + c]) - centre[c];
      }
    }
    const double det = p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
      p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
      p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
    volume[Root(parent, static_cast<uint32_t>(conn[3 * t]))] += det;
  }
  for (uint32_t v = 0; v < static_cast<uint32_t>(nv); ++v)
  {
    // A component's volume sits at its root; vertices used by no triangle
    // are their own roots with volume 0 and do not count.
    if (parent[v] == v && start[v + 1] > start[v] && !(volume[v] > 0.0))
    {
      return false;
    }
  }
  return true;
}

bool ClosedMeshCache::IsClosedOutward(const render::Mesh& mesh, uint64_t fingerprint, bool mayTest)
{
  if (this->Fingerprint != fingerprint)
  {
    if (!mayTest && this->Untested != fingerprint) // not on the mesh's second frame
    {
      this->Untested = fingerprint;
      return false;
    }
    this->Closed = IsClosedOutwardTriangleMesh(mesh);
    this->Fingerprint = fingerprint;
  }
  return this->Closed;
}

} // namespace shadinglab::cpu
