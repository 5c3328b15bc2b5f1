// SPDX-License-Identifier: BSD-3-Clause
#include "HiddenBackFaces.h"

#include "Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace shadinglab::cpu
{

namespace
{

/// The cosine by which ClusterFacesAway's bound must clear zero, relative
/// to the eye's distance: every triangle of a culled run then makes more
/// than ~87 degrees with every ray to it. The per-triangle test takes the
/// sign of the projected area in float screen coordinates, which for a
/// sub-pixel triangle a thousand pixels from the origin moves by ~1e-4 px^2
/// (coordinates to 6e-5 px); a triangle 0.1 px across tilted 3 degrees past
/// edge-on still projects to ~3e-4 px^2 with that sign, and one nearer
/// edge-on than that is left to the per-triangle test, which decides it as
/// it always did.
constexpr double kClusterFacingMargin = 0.05;

/// Union-find over vertices (mesh/core/Geometry.h).
uint32_t Root(std::vector<uint32_t>& parent, uint32_t v)
{
  return mesh::UnionFindRoot(parent, v);
}

/// IsClosedOutwardTriangleMesh on the connectivity in place, either width.
template <typename Id>
bool ClosedOutward(const render::Mesh& mesh, const Id* conn)
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
        p[k][c] = double(mesh.points[3 * int64_t(conn[3 * t + k]) + c]) - centre[c];
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

} // namespace

bool IsClosedOutwardTriangleMesh(const render::Mesh& mesh)
{
  return mesh.connectivity.Visit([&](const auto* conn) { return ClosedOutward(mesh, conn); });
}

std::vector<ClusterCone> ClusterConesOf(
  const render::Mesh& mesh, const render::Mesh::TaskRunner& run)
{
  const int64_t np = mesh.NumberOfPolygons(), nv = mesh.NumberOfPoints();
  const int64_t runs = (np + kClusterPolygons - 1) / kClusterPolygons;
  std::vector<ClusterCone> cones(static_cast<size_t>(runs));
  auto point = [&](int64_t v, double out[3])
  {
    for (int c = 0; c < 3; ++c)
    {
      out[c] = mesh.points[3 * v + c];
    }
  };
  auto build = [&](int64_t r)
  {
    ClusterCone& cone = cones[static_cast<size_t>(r)];
    const int64_t begin = r * kClusterPolygons, end = std::min(np, begin + kClusterPolygons);
    int64_t lowest = nv, highest = -1;
    for (int64_t i = mesh.offsets[begin]; i < mesh.offsets[end]; ++i)
    {
      const int64_t v = mesh.connectivity[i];
      if (v >= 0 && v < nv)
      {
        lowest = std::min(lowest, v);
        highest = std::max(highest, v);
      }
    }
    if (highest >= lowest)
    {
      cone.firstVertex = lowest;
      cone.endVertex = highest + 1;
    }
    double normals[kClusterPolygons][3];
    double sum[3] = { 0, 0, 0 };
    double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
    for (int64_t p = begin; p < end; ++p)
    {
      const int64_t first = mesh.offsets[p];
      if (mesh.offsets[p + 1] - first != 3)
      {
        return; // not a triangle: its facing may differ across its surface
      }
      double q[3][3];
      for (int k = 0; k < 3; ++k)
      {
        const int64_t v = mesh.connectivity[first + k];
        if (v < 0 || v >= nv)
        {
          return;
        }
        point(v, q[k]);
        for (int c = 0; c < 3; ++c)
        {
          lo[c] = std::min(lo[c], q[k][c]);
          hi[c] = std::max(hi[c], q[k][c]);
        }
      }
      const double e1[3] = { q[1][0] - q[0][0], q[1][1] - q[0][1], q[1][2] - q[0][2] };
      const double e2[3] = { q[2][0] - q[0][0], q[2][1] - q[0][1], q[2][2] - q[0][2] };
      double* n = normals[p - begin];
      n[0] = e1[1] * e2[2] - e1[2] * e2[1];
      n[1] = e1[2] * e2[0] - e1[0] * e2[2];
      n[2] = e1[0] * e2[1] - e1[1] * e2[0];
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (!(length > 0.0) || !std::isfinite(length))
      {
        return; // no normal: no facing to vouch for
      }
      for (int c = 0; c < 3; ++c)
      {
        n[c] /= length;
        sum[c] += n[c];
      }
    }
    const double length = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
    if (!(length > 0.0) || !std::isfinite(length))
    {
      return;
    }
    double cosSpread = 1.0;
    for (int c = 0; c < 3; ++c)
    {
      cone.axis[c] = sum[c] / length;
      cone.centre[c] = 0.5 * (lo[c] + hi[c]);
    }
    for (int64_t p = begin; p < end; ++p)
    {
      const double* n = normals[p - begin];
      cosSpread = std::min(cosSpread,
        n[0] * cone.axis[0] + n[1] * cone.axis[1] + n[2] * cone.axis[2]);
      for (int k = 0; k < 3; ++k)
      {
        double q[3];
        point(mesh.connectivity[mesh.offsets[p] + k], q);
        const double dx = q[0] - cone.centre[0], dy = q[1] - cone.centre[1],
                     dz = q[2] - cone.centre[2];
        cone.radius = std::max(cone.radius, std::sqrt(dx * dx + dy * dy + dz * dz));
      }
    }
    if (!(cosSpread > 0.0))
    {
      return; // normals over a half-space: the run never faces away whole
    }
    cone.cosSpread = cosSpread;
    cone.sinSpread = std::sqrt(std::max(0.0, 1.0 - cosSpread * cosSpread));
    cone.usable = std::isfinite(cone.radius);
  };
  const int tasks = static_cast<int>(std::min<int64_t>(runs, 64));
  auto task = [&](int t)
  {
    for (int64_t r = runs * t / tasks; r < runs * (t + 1) / tasks; ++r)
    {
      build(r);
    }
  };
  if (run && tasks > 1)
  {
    run(tasks, task);
  }
  else
  {
    for (int t = 0; t < tasks; ++t)
    {
      task(t);
    }
  }
  return cones;
}

bool ClusterFacesAway(const ClusterCone& cone, const ClusterEye& eye)
{
  if (!cone.usable)
  {
    return false;
  }
  // cos(phi + theta) = cos phi cos theta - sin phi sin theta: the least
  // cosine between a normal of the cone and the direction to the centre.
  auto leastCos = [&](double cosPhi)
  {
    cosPhi = std::clamp(cosPhi, -1.0, 1.0);
    return cosPhi * cone.cosSpread - std::sqrt(1.0 - cosPhi * cosPhi) * cone.sinSpread;
  };
  if (eye.parallel)
  {
    const double cosPhi = cone.axis[0] * eye.forward[0] + cone.axis[1] * eye.forward[1] +
      cone.axis[2] * eye.forward[2];
    return leastCos(cosPhi) > kClusterFacingMargin;
  }
  const double d[3] = { cone.centre[0] - eye.position[0], cone.centre[1] - eye.position[1],
    cone.centre[2] - eye.position[2] };
  const double distance = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(distance > cone.radius))
  {
    return false; // the eye inside the run's sphere
  }
  const double cosPhi = (cone.axis[0] * d[0] + cone.axis[1] * d[1] + cone.axis[2] * d[2]) / distance;
  // n . (p - e) > margin |p - e| for every point p, as |p - e| <= distance + radius.
  return distance * leastCos(cosPhi) - cone.radius >
    kClusterFacingMargin * (distance + cone.radius);
}

const std::vector<ClusterCone>* ClusterConeCache::ConesOf(
  const render::Mesh& mesh, uint64_t fingerprint, const render::Mesh::TaskRunner& run)
{
  return this->Cones.Get(
    fingerprint, [&](std::vector<ClusterCone>& cones) { cones = ClusterConesOf(mesh, run); });
}

bool ClosedMeshCache::IsClosedOutward(const render::Mesh& mesh, uint64_t fingerprint, bool mayTest)
{
  if (this->Fingerprint != fingerprint)
  {
    if (!mayTest && !this->Sightings.SeenBefore(fingerprint))
    {
      return false;
    }
    this->Closed = IsClosedOutwardTriangleMesh(mesh);
    this->Fingerprint = fingerprint;
  }
  return this->Closed;
}

} // namespace shadinglab::cpu
