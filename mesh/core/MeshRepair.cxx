// SPDX-License-Identifier: BSD-3-Clause
#include "MeshRepair.h"

#include "Geometry.h"
#include "Orientation.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <queue>
#include <unordered_map>

namespace shadinglab::mesh
{

namespace
{

/// Spatial-hash cells visited per T-junction edge query before falling back
/// to scanning every point: bounds the cost of one very long edge.
constexpr int64_t kMaxCellsPerQuery = 100000;

/// T-junction parameters within this of an edge end are the end itself.
constexpr double kEdgeEndEpsilon = 1e-9;

struct Key
{
  int64_t x, y, z;
  bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct KeyHash
{
  size_t operator()(const Key& k) const
  {
    return static_cast<size_t>(k.x * 73856093LL ^ k.y * 19349663LL ^ k.z * 83492791LL);
  }
};

double Diagonal(const double* points, int64_t n, double lo[3])
{
  double hi[3];
  for (int c = 0; c < 3; ++c)
  {
    lo[c] = std::numeric_limits<double>::infinity();
    hi[c] = -lo[c];
  }
  for (int64_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      lo[c] = std::min(lo[c], points[3 * i + c]);
      hi[c] = std::max(hi[c], points[3 * i + c]);
    }
  }
  if (n == 0)
  {
    return 0.0;
  }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
    (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

std::array<double, 3> Newell(const OwnedMesh& m, int64_t p)
{
  const int64_t b = m.offsets[p], e = m.offsets[p + 1];
  const Vec3<double> n = NewellAreaVector<double>(
    e - b, [&](int64_t k) { return PointOf(m.points.data(), m.connectivity[b + k]); });
  return { n.x, n.y, n.z };
}

/// Welding: each point's representative, the first earlier point within
/// the tolerance (relative to the bounding diagonal), found on a grid of
/// cells of that size; itself when none is (or when welding is off).
std::vector<int64_t> WeldRepresentatives(const double* points, int64_t np,
  const RepairOptions& opt, double diagonal, const double lo[3], RepairReport& report)
{
  std::vector<int64_t> representative(static_cast<size_t>(np));
  for (int64_t i = 0; i < np; ++i)
  {
    representative[i] = i;
  }
  if (opt.weld && np > 0)
  {
    const double tol = opt.weldTolerance * diagonal;
    // Cell size: the tolerance, but not so small that coordinates overflow
    // the integer cell index (diagonal * 1e-12 keeps |index| < 1e12).
    const double cell = std::max(tol, diagonal * 1e-12 + std::numeric_limits<double>::min());
    std::unordered_map<Key, std::vector<int64_t>, KeyHash> grid;
    grid.reserve(static_cast<size_t>(np));
    for (int64_t i = 0; i < np; ++i)
    {
      const double* p = points + 3 * i;
      const Key k{ static_cast<int64_t>(std::floor((p[0] - lo[0]) / cell)),
        static_cast<int64_t>(std::floor((p[1] - lo[1]) / cell)),
        static_cast<int64_t>(std::floor((p[2] - lo[2]) / cell)) };
      int64_t found = -1;
      for (int64_t dx = -1; dx <= 1 && found < 0; ++dx)
      {
        for (int64_t dy = -1; dy <= 1 && found < 0; ++dy)
        {
          for (int64_t dz = -1; dz <= 1 && found < 0; ++dz)
          {
            const auto it = grid.find(Key{ k.x + dx, k.y + dy, k.z + dz });
            if (it == grid.end())
            {
              continue;
            }
            for (int64_t r : it->second)
            {
              const double* q = points + 3 * r;
              const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                (p[2] - q[2]) * (p[2] - q[2]);
              const bool sameSeam = !opt.seamKeys || (*opt.seamKeys)[i] == (*opt.seamKeys)[r];
              if (d2 <= tol * tol && sameSeam)
              {
                found = r;
                break;
              }
            }
          }
        }
      }
      if (found >= 0)
      {
        representative[i] = found;
        ++report.welded;
      }
      else
      {
        grid[k].push_back(i);
      }
    }
  }

  return representative;
}

} // namespace

OwnedMesh RepairMesh(const double* points, int64_t np, const int64_t* offsets,
  const int64_t* connectivity, int64_t nf, const RepairOptions& opt, RepairReport& report)
{
  report = RepairReport();
  double lo[3];
  const double diagonal = Diagonal(points, np, lo);

  // 1. Weld.
  const std::vector<int64_t> representative =
    WeldRepresentatives(points, np, opt, diagonal, lo, report);

  // Compact the points: representatives only, in input order.
  OwnedMesh mesh;
  std::vector<int64_t> newIndex(static_cast<size_t>(np), -1);
  for (int64_t i = 0; i < np; ++i)
  {
    if (representative[i] == i)
    {
      newIndex[i] = static_cast<int64_t>(mesh.pointIds.size());
      mesh.pointIds.push_back(i);
      mesh.points.insert(mesh.points.end(), points + 3 * i, points + 3 * i + 3);
    }
  }

  // 2. Faces: remap, drop repeated consecutive vertices, drop degenerates.
  const double minArea = kDegenerateRelativeArea * diagonal * diagonal;
  std::vector<int64_t> face;
  for (int64_t f = 0; f < nf; ++f)
  {
    face.clear();
    for (int64_t k = offsets[f]; k < offsets[f + 1]; ++k)
    {
      const int64_t v = newIndex[representative[connectivity[k]]];
      if (face.empty() || face.back() != v)
      {
        face.push_back(v);
      }
    }
    while (face.size() > 1 && face.front() == face.back())
    {
      face.pop_back();
    }
    // A vertex repeated non-consecutively (a pinched polygon) also degenerates it.
    std::vector<int64_t> sorted(face);
    std::sort(sorted.begin(), sorted.end());
    const bool repeated = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
    if (face.size() < 3 || repeated)
    {
      ++report.degenerateRemoved;
      continue;
    }
    mesh.connectivity.insert(mesh.connectivity.end(), face.begin(), face.end());
    mesh.offsets.push_back(static_cast<int64_t>(mesh.connectivity.size()));
    mesh.cellIds.push_back(f);
    const auto n = Newell(mesh, mesh.NumberOfPolygons() - 1);
    if (std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) * 0.5 <= minArea)
    {
      mesh.connectivity.resize(static_cast<size_t>(mesh.offsets[mesh.offsets.size() - 2]));
      mesh.offsets.pop_back();
      mesh.cellIds.pop_back();
      ++report.degenerateRemoved;
    }
  }

  // 3. Edges: face neighbours through manifold edges, open faces.
  const int64_t faces = mesh.NumberOfPolygons();
  FaceNeighbourLists neighbours;
  std::vector<uint8_t> touchesOpenEdge;
  report.nonManifoldEdges += FindFaceNeighbours(mesh.View(), neighbours, touchesOpenEdge);

  // 4. Consistent orientation per component, outward when closed.
  std::vector<uint8_t> flip =
    OrientComponents(mesh.View(), neighbours, touchesOpenEdge, report.components);
  if (!opt.fixOrientation)
  {
    flip.assign(flip.size(), 0); // components counted, nothing turned
  }
  for (int64_t f = 0; f < faces; ++f)
  {
    if (flip[f])
    {
      std::reverse(mesh.connectivity.begin() + mesh.offsets[f],
        mesh.connectivity.begin() + mesh.offsets[f + 1]);
      ++report.flipped;
    }
  }

  // 5. OpenMesh: a halfedge mesh accepts only manifold faces; add_face
  // refuses a face that would make a complex edge or vertex. Such a face
  // gets its own copies of its vertices instead of being dropped.
  if (opt.resolveNonManifold)
  {
    OpenMesh::PolyMesh_ArrayKernelT<> om;
    std::vector<OpenMesh::VertexHandle> handles;
    handles.reserve(static_cast<size_t>(mesh.NumberOfPoints()));
    for (int64_t i = 0; i < mesh.NumberOfPoints(); ++i)
    {
      handles.push_back(om.add_vertex(OpenMesh::PolyMesh_ArrayKernelT<>::Point(
        static_cast<float>(mesh.points[3 * i]), static_cast<float>(mesh.points[3 * i + 1]),
        static_cast<float>(mesh.points[3 * i + 2]))));
    }
    std::vector<OpenMesh::VertexHandle> fh;
    const int64_t originalPoints = mesh.NumberOfPoints();
    // OpenMesh reports refused faces on std::cerr; that is expected here.
    std::streambuf* saved = std::cerr.rdbuf(nullptr);
    for (int64_t f = 0; f < faces; ++f)
    {
      fh.clear();
      for (int64_t k = mesh.offsets[f]; k < mesh.offsets[f + 1]; ++k)
      {
        fh.push_back(handles[mesh.connectivity[k]]);
      }
      if (om.add_face(fh).is_valid())
      {
        continue;
      }
      for (int64_t k = mesh.offsets[f]; k < mesh.offsets[f + 1]; ++k)
      {
        const int64_t v = mesh.connectivity[k];
        const int64_t copy = mesh.NumberOfPoints();
        mesh.points.insert(mesh.points.end(), { mesh.points[3 * v], mesh.points[3 * v + 1],
                                                mesh.points[3 * v + 2] });
        mesh.pointIds.push_back(mesh.pointIds[v]);
        handles.push_back(om.add_vertex(OpenMesh::PolyMesh_ArrayKernelT<>::Point(
          static_cast<float>(mesh.points[3 * copy]), static_cast<float>(mesh.points[3 * copy + 1]),
          static_cast<float>(mesh.points[3 * copy + 2]))));
        mesh.connectivity[k] = copy;
      }
      fh.clear();
      for (int64_t k = mesh.offsets[f]; k < mesh.offsets[f + 1]; ++k)
      {
        fh.push_back(handles[mesh.connectivity[k]]);
      }
      om.add_face(fh);
    }
    std::cerr.rdbuf(saved);
    report.duplicatedVertices = mesh.NumberOfPoints() - originalPoints;
  }
  return mesh;
}

int64_t FixTJunctions(OwnedMesh& mesh, double relativeTolerance)
{
  const int64_t np = mesh.NumberOfPoints(), nf = mesh.NumberOfPolygons();
  if (np == 0 || nf == 0)
  {
    return 0;
  }
  double lo[3];
  const double diagonal = Diagonal(mesh.points.data(), np, lo);
  const double tol = relativeTolerance * diagonal;
  // Grid cell: the mean edge length, so a typical edge query visits few cells.
  double edgeSum = 0;
  for (int64_t f = 0; f < nf; ++f)
  {
    const int64_t b = mesh.offsets[f], e = mesh.offsets[f + 1];
    for (int64_t k = b; k < e; ++k)
    {
      const double* p = &mesh.points[3 * mesh.connectivity[k]];
      const double* q = &mesh.points[3 * mesh.connectivity[k + 1 < e ? k + 1 : b]];
      edgeSum += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
        (p[2] - q[2]) * (p[2] - q[2]));
    }
  }
  const double cell = std::max(edgeSum / static_cast<double>(mesh.connectivity.size()),
    diagonal * 1e-9 + std::numeric_limits<double>::min());
  std::unordered_map<Key, std::vector<int64_t>, KeyHash> grid;
  auto keyOf = [&](const double* p) {
    return Key{ static_cast<int64_t>(std::floor((p[0] - lo[0]) / cell)),
      static_cast<int64_t>(std::floor((p[1] - lo[1]) / cell)),
      static_cast<int64_t>(std::floor((p[2] - lo[2]) / cell)) };
  };
  for (int64_t i = 0; i < np; ++i)
  {
    grid[keyOf(&mesh.points[3 * i])].push_back(i);
  }
  int64_t inserted = 0;
  std::vector<int64_t> newOffsets{ 0 }, newConnectivity;
  newConnectivity.reserve(mesh.connectivity.size());
  std::vector<std::pair<double, int64_t>> onEdge;
  for (int64_t f = 0; f < nf; ++f)
  {
    const int64_t b = mesh.offsets[f], e = mesh.offsets[f + 1];
    for (int64_t k = b; k < e; ++k)
    {
      const int64_t ia = mesh.connectivity[k], ib = mesh.connectivity[k + 1 < e ? k + 1 : b];
      newConnectivity.push_back(ia);
      const double* a = &mesh.points[3 * ia];
      const double* c = &mesh.points[3 * ib];
      const double d[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
      const double len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      if (!(len2 > 0))
      {
        continue;
      }
      onEdge.clear();
      auto test = [&](int64_t v) {
        if (v == ia || v == ib)
        {
          return;
        }
        const double* p = &mesh.points[3 * v];
        const double w[3] = { p[0] - a[0], p[1] - a[1], p[2] - a[2] };
        const double t = (w[0] * d[0] + w[1] * d[1] + w[2] * d[2]) / len2;
        if (t <= kEdgeEndEpsilon || t >= 1 - kEdgeEndEpsilon)
        {
          return;
        }
        const double r[3] = { w[0] - t * d[0], w[1] - t * d[1], w[2] - t * d[2] };
        if (r[0] * r[0] + r[1] * r[1] + r[2] * r[2] <= tol * tol)
        {
          onEdge.push_back({ t, v });
        }
      };
      double qlo[3], qhi[3];
      for (int c3 = 0; c3 < 3; ++c3)
      {
        qlo[c3] = std::min(a[c3], c[c3]) - tol;
        qhi[c3] = std::max(a[c3], c[c3]) + tol;
      }
      const Key k0 = keyOf(qlo), k1 = keyOf(qhi);
      const double cells = double(k1.x - k0.x + 1) * double(k1.y - k0.y + 1) * double(k1.z - k0.z + 1);
      if (cells > kMaxCellsPerQuery)
      {
        for (int64_t v = 0; v < np; ++v)
        {
          test(v);
        }
      }
      else
      {
        for (int64_t x = k0.x; x <= k1.x; ++x)
        {
          for (int64_t y = k0.y; y <= k1.y; ++y)
          {
            for (int64_t z = k0.z; z <= k1.z; ++z)
            {
              const auto it = grid.find(Key{ x, y, z });
              if (it != grid.end())
              {
                for (int64_t v : it->second)
                {
                  test(v);
                }
              }
            }
          }
        }
      }
      std::sort(onEdge.begin(), onEdge.end());
      for (const auto& [t, v] : onEdge)
      {
        newConnectivity.push_back(v);
        ++inserted;
      }
    }
    newOffsets.push_back(static_cast<int64_t>(newConnectivity.size()));
  }
  mesh.offsets.swap(newOffsets);
  mesh.connectivity.swap(newConnectivity);
  return inserted;
}

} // namespace shadinglab::mesh
