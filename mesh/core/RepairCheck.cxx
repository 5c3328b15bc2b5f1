// SPDX-License-Identifier: BSD-3-Clause
#include "RepairCheck.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace shadinglab::mesh
{

namespace
{

/// Union-find over faces.
int64_t Find(std::vector<int64_t>& parent, int64_t f)
{
  return UnionFindRoot(parent, f);
}

} // namespace

namespace
{

/// Point i widened to double (float points give their double copy's bits).
template <typename Real>
Vec3<double> PointInDouble(const Real* points, int64_t i)
{
  return Vec3<double>(double(points[3 * i]), double(points[3 * i + 1]), double(points[3 * i + 2]));
}

template <typename Real, typename Id>
RepairNeeds CheckRepairNeedsOf(const MeshViewOf<Real, Id>& m)
{
  RepairNeeds needs;
  const int64_t nv = m.numberOfPoints, nf = m.numberOfPolygons;
  if (nv == 0 || nf == 0)
  {
    return needs;
  }
  Vec3<double> lo = PointInDouble(m.points, 0), hi = lo;
  for (int64_t i = 1; i < nv; ++i)
  {
    const Vec3<double> p = PointInDouble(m.points, i);
    lo = Vec3<double>(std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z));
    hi = Vec3<double>(std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z));
  }
  const Vec3<double> center = (lo + hi) * 0.5;
  const double minArea = kDegenerateRelativeArea * Dot(hi - lo, hi - lo);

  // Degenerate faces: a repeated vertex or no area.
  for (int64_t f = 0; f < nf; ++f)
  {
    const int64_t b = m.offsets[f], n = m.offsets[f + 1] - b;
    bool repeated = false;
    for (int64_t i = 0; i < n && !repeated; ++i)
    {
      for (int64_t j = i + 1; j < n && !repeated; ++j)
      {
        repeated = m.connectivity[b + i] == m.connectivity[b + j];
      }
    }
    const Vec3<double> area = NewellAreaVector<double>(
      n, [&](int64_t k) { return PointInDouble(m.points, m.connectivity[b + k]); });
    needs.degenerate += repeated || !(Length(area) > minArea);
  }

  // Vertex -> faces table (CSR).
  std::vector<int64_t> start(static_cast<size_t>(nv) + 1, 0);
  for (int64_t k = 0; k < m.offsets[nf]; ++k)
  {
    ++start[m.connectivity[k] + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int64_t> faces(static_cast<size_t>(m.offsets[nf]));
  std::vector<int64_t> fill(start.begin(), start.end() - 1);
  for (int64_t f = 0; f < nf; ++f)
  {
    for (int64_t k = m.offsets[f]; k < m.offsets[f + 1]; ++k)
    {
      faces[fill[m.connectivity[k]]++] = f;
    }
  }

  // Each edge (a, b) of face f against the other faces around a: same
  // direction is an orientation conflict, more than one other face a
  // non-manifold edge; shared edges join faces into components, and an
  // edge of one face leaves its component open.
  std::vector<int64_t> parent(static_cast<size_t>(nf));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> open(static_cast<size_t>(nf), 0);
  for (int64_t f = 0; f < nf; ++f)
  {
    const int64_t b = m.offsets[f], n = m.offsets[f + 1] - b;
    for (int64_t k = 0; k < n; ++k)
    {
      const int64_t u = m.connectivity[b + k], v = m.connectivity[b + (k + 1) % n];
      int others = 0;
      for (int64_t s = start[u]; s < start[u + 1]; ++s)
      {
        const int64_t g = faces[s];
        if (g == f)
        {
          continue;
        }
        const int64_t gb = m.offsets[g], gn = m.offsets[g + 1] - gb;
        for (int64_t i = 0; i < gn; ++i)
        {
          if (m.connectivity[gb + i] != u)
          {
            continue;
          }
          const bool same = m.connectivity[gb + (i + 1) % gn] == v;
          const bool opposite = m.connectivity[gb + (i + gn - 1) % gn] == v;
          if (same || opposite)
          {
            ++others;
            needs.inconsistentEdges += same && f < g; // counted once per pair
            parent[Find(parent, f)] = Find(parent, g);
          }
        }
      }
      needs.nonManifoldEdges += others > 1 && u < v;
      open[f] |= others == 0;
    }
  }

  // Closed components (no open edge, consistent) must enclose a positive
  // volume: sum of the signed tetrahedra (center, p0, pk, pk+1) / 6.
  std::vector<double> volume(static_cast<size_t>(nf), 0.0);
  std::vector<char> componentOpen(static_cast<size_t>(nf), 0);
  for (int64_t f = 0; f < nf; ++f)
  {
    const int64_t root = Find(parent, f);
    componentOpen[root] |= open[f];
    const int64_t b = m.offsets[f], n = m.offsets[f + 1] - b;
    const Vec3<double> p0 = PointInDouble(m.points, m.connectivity[b]) - center;
    for (int64_t k = 1; k + 1 < n; ++k)
    {
      const Vec3<double> p1 = PointInDouble(m.points, m.connectivity[b + k]) - center;
      const Vec3<double> p2 = PointInDouble(m.points, m.connectivity[b + k + 1]) - center;
      volume[root] += Dot(p0, Cross(p1, p2)) / 6.0;
    }
  }
  if (needs.inconsistentEdges == 0)
  {
    for (int64_t f = 0; f < nf; ++f)
    {
      needs.inwardComponents += Find(parent, f) == f && !componentOpen[f] && volume[f] < 0.0;
    }
  }
  return needs;
}

} // namespace

RepairNeeds CheckRepairNeeds(const MeshView& mesh)
{
  return CheckRepairNeedsOf(mesh);
}

RepairNeeds CheckRepairNeeds(const FloatNarrowMeshView& mesh)
{
  return CheckRepairNeedsOf(mesh);
}

} // namespace shadinglab::mesh
