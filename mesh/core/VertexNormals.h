// SPDX-License-Identifier: BSD-3-Clause
// Vertex normals from a polygon mesh held as flat arrays (the layout of
// vtkCellArray's offsets and connectivity), with selectable weights and
// crease splitting. Plain loops over the arrays: no halfedge structure is
// needed for this, and none is built (docs/contributing.md, "Mesh code").
#pragma once

#include "Geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace shadinglab::mesh
{

enum class NormalWeighting
{
  Uniform, ///< sum of unit face normals (Gouraud 1971; OpenMesh update_vertex_normals)
  Area,    ///< sum of face area vectors (area-weighted)
  Angle,   ///< corner angle times unit face normal (Thurmer & Wuthrich 1998)
  Max      ///< corner cross product / (|e1|^2 |e2|^2) (Max 1999), exact on spheres
};

struct NormalOptions
{
  NormalWeighting weighting = NormalWeighting::Area;
  /// Split normals across edges whose dihedral angle exceeds featureAngle.
  bool splitting = true;
  double featureAngle = 30.0; ///< degrees
  /// Explicit feature edges (pairs of point ids), split whatever their angle.
  std::vector<int64_t> featureEdges;
  /// Split across boundary edges and non-manifold edges (more than two faces).
  bool splitNonManifold = true;
  /// Threads of ComputeVertexNormals' vertex pass: 0, one per core (at
  /// most 8) on meshes of 100k vertices or more; else exactly this many.
  /// The result is the same bits for any number.
  int threads = 0;
};

struct NormalResult
{
  /// Unit normal per output point (3 per point).
  std::vector<double> normals;
  /// Output point -> input point (identity for the first copy of each point).
  std::vector<int64_t> originalPointIds;
  /// Output connectivity (same offsets as the input): corners re-pointed to
  /// the copy of their vertex on their side of a crease. Empty when no
  /// corner was moved (no split point, or only points of polygons with
  /// fewer than 3 corners): the input's connectivity holds.
  std::vector<int64_t> connectivity;
  int64_t creaseEdges = 0;       ///< edges split because of the feature angle or explicit marks
  int64_t nonManifoldEdges = 0;  ///< edges with more than two faces
  int64_t boundaryEdges = 0;
  int64_t splitPoints = 0;       ///< points added by splitting
};

/**
 * acos(x) for x in [-1, 1]: Abramowitz & Stegun, Handbook of Mathematical
 * Functions, eq. 4.4.46, acos(x) = sqrt(1 - x) (a0 + a1 x + ... + a7 x^7) on
 * [0, 1] with |error| <= 2e-8 rad, and acos(-x) = pi - acos(x). Used for
 * angle weights, where 2e-8 rad is far below any effect on a normal, at a
 * fraction of std::acos's cost (tested against it in NormalsTest).
 */
inline double AcosAbramowitzStegun(double x)
{
  const bool negative = x < 0;
  x = std::min(std::abs(x), 1.0);
  const double p = 1.5707963050 +
    x * (-0.2145988016 +
          x * (0.0889789874 +
                x * (-0.0501743046 +
                      x * (0.0308918810 +
                            x * (-0.0170881256 + x * (0.0066700901 + x * -0.0012624911))))));
  const double r = std::sqrt(1.0 - x) * p;
  return negative ? 3.14159265358979323846 - r : r;
}

/// Computes the normals. Zero-area polygons contribute nothing; a point with
/// no usable face gets (0, 0, 1) rather than NaN.
NormalResult ComputeVertexNormals(const MeshView& mesh, const NormalOptions& options);
/// The same from float points read in place (a file's): each coordinate
/// widened as it is loaded, so the result is the double copy's, bit for
/// bit, without the copy (192 MB on 16M triangles).
NormalResult ComputeVertexNormals(const FloatMeshView& mesh, const NormalOptions& options);
/// The same from 32-bit ids read in place (a fast reader's cells), double
/// or float points: the int64 views' results, bit for bit.
NormalResult ComputeVertexNormals(const NarrowMeshView& mesh, const NormalOptions& options);
NormalResult ComputeVertexNormals(const FloatNarrowMeshView& mesh, const NormalOptions& options);

/// Frees the calling thread's scratch table, which ComputeVertexNormals
/// keeps up to kKeptScratchCorners corners for its next call (a filter
/// re-run reuses its pages): a one-shot command calls it once the normals
/// are made (4M triangles: 64 MB that would otherwise live through the
/// render, and set its peak).
void ReleaseNormalScratch();

/**
 * The angle-weight loop runs 4 doubles wide (AVX2) when the CPU has AVX2,
 * else 2 wide (SSE2, every x86-64). SetWideSimd(false) forces the 2-wide
 * path (tests compare the two; results are identical: the same arithmetic
 * per lane). WideSimdInUse says which runs.
 */
void SetWideSimd(bool enabled);
bool WideSimdInUse();

/// The crease-free normals only (one per input point), the fast path.
void ComputeVertexNormalsNoSplit(
  const MeshView& mesh, NormalWeighting weighting, std::vector<double>& normals);
void ComputeVertexNormalsNoSplit(
  const FloatMeshView& mesh, NormalWeighting weighting, std::vector<double>& normals);
void ComputeVertexNormalsNoSplit(
  const NarrowMeshView& mesh, NormalWeighting weighting, std::vector<double>& normals);
void ComputeVertexNormalsNoSplit(
  const FloatNarrowMeshView& mesh, NormalWeighting weighting, std::vector<double>& normals);

/**
 * The crease-free normals at some points only, for a mesh of float points (a
 * renderer's), in several weightings at once: slotOfPoint[v] is v's row in
 * each normals[w] (3 per slot, `slots` rows) or -1 for a point not asked
 * for. One pass over the polygons, adding only the corners at points asked
 * for, with the same per-corner arithmetic as ComputeVertexNormalsNoSplit
 * (equal up to rounding). Polygons of more than 64 corners are skipped.
 */
void ComputeVertexNormalsAt(const float* points, const int64_t* offsets,
  const int64_t* connectivity, int64_t numberOfPolygons,
  const std::vector<NormalWeighting>& weightings, const std::vector<int64_t>& slotOfPoint,
  int64_t slots, std::vector<std::vector<double>>& normals);
/// The same for 32-bit ids (a fast reader's cells, shared in place).
void ComputeVertexNormalsAt(const float* points, const int32_t* offsets,
  const int32_t* connectivity, int64_t numberOfPolygons,
  const std::vector<NormalWeighting>& weightings, const std::vector<int64_t>& slotOfPoint,
  int64_t slots, std::vector<std::vector<double>>& normals);

} // namespace shadinglab::mesh

