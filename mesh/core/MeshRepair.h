// SPDX-License-Identifier: BSD-3-Clause
// Topology repair of polygon soups: welding, degenerate faces, consistent
// orientation, non-manifold configurations (via OpenMesh), T-junctions.
#pragma once

#include "Geometry.h"

#include <cstdint>
#include <vector>

namespace shadinglab::mesh
{

/// A polygon mesh owning its arrays; pointIds maps each point to the input
/// point it came from (for carrying point data), cellIds each polygon to its
/// input polygon.
struct OwnedMesh
{
  std::vector<double> points;
  std::vector<int64_t> offsets{ 0 };
  std::vector<int64_t> connectivity;
  std::vector<int64_t> pointIds;
  std::vector<int64_t> cellIds;
  int64_t NumberOfPoints() const { return static_cast<int64_t>(points.size() / 3); }
  int64_t NumberOfPolygons() const { return static_cast<int64_t>(offsets.size()) - 1; }
  MeshView View() const
  {
    return { points.data(), NumberOfPoints(), offsets.data(), connectivity.data(),
      NumberOfPolygons() };
  }
};

struct RepairOptions
{
  bool weld = false;
  /// Weld distance relative to the bounding-box diagonal.
  double weldTolerance = 1e-6;
  /// Per-point keys: when given (one per point), points are welded only if
  /// their keys are equal (e.g. a hash of their attributes), keeping seams.
  const std::vector<uint64_t>* seamKeys = nullptr;
  bool fixOrientation = true;
  /// Resolve non-manifold edges and vertices through OpenMesh: faces it
  /// refuses get their own copies of the offending vertices.
  bool resolveNonManifold = true;
};

struct RepairReport
{
  int64_t welded = 0;              ///< points merged into another
  int64_t degenerateRemoved = 0;   ///< faces with < 3 distinct vertices or zero area
  int64_t flipped = 0;             ///< faces whose orientation was reversed
  int64_t nonManifoldEdges = 0;    ///< edges shared by more than two faces
  int64_t duplicatedVertices = 0;  ///< vertices copied so OpenMesh accepts every face
  int64_t components = 0;
};

OwnedMesh RepairMesh(const double* points, int64_t numberOfPoints, const int64_t* offsets,
  const int64_t* connectivity, int64_t numberOfPolygons, const RepairOptions& options,
  RepairReport& report);

/// Splits polygon edges at vertices lying on them (within tolerance relative
/// to the bounding-box diagonal), so interpolation is continuous across the
/// junction. Returns the number of vertices inserted into edges.
int64_t FixTJunctions(OwnedMesh& mesh, double relativeTolerance);

} // namespace shadinglab::mesh
