// SPDX-License-Identifier: BSD-3-Clause
// Consistent orientation of a polygon mesh: faces that share an edge should
// run it in opposite directions, else their normals point to opposite sides
// and a vertex normal averaged over them cancels (speckles in smooth
// shading). One home for the check and the fix, used by mesh repair, the
// normals filter, the GPU mapper and the distributed normals in ParaView.
#pragma once

#include "Geometry.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace shadinglab::mesh
{

/// Per corner k of the connectivity (the edge from corner k to the next
/// corner of its face): the face across that edge when the edge is
/// manifold (exactly two faces), else -1; and whether the two faces run the
/// edge the same way (inconsistent orientation).
struct FaceNeighbourLists
{
  std::vector<int64_t> face;
  std::vector<uint8_t> same;
};

/// Fills `neighbours` and marks the faces touching an open, degenerate or
/// non-manifold edge; returns the number of non-manifold edges (more than
/// two faces). Linear in the corners (a per-vertex table of outgoing edges
/// stands in for a sort of all edges).
int64_t FindFaceNeighbours(
  const MeshView& mesh, FaceNeighbourLists& neighbours, std::vector<uint8_t>& touchesOpenEdge);

/// Consistent orientation per connected component (breadth-first over the
/// manifold edges from the component's lowest face, which keeps its
/// orientation), turned outward when the component is closed (its signed
/// volume positive): whether each face is to be flipped. `components`
/// receives the number of connected components.
std::vector<uint8_t> OrientComponents(const MeshView& mesh, const FaceNeighbourLists& neighbours,
  const std::vector<uint8_t>& touchesOpenEdge, int64_t& components);

/// Whether two faces run an edge the same way (a directed edge used twice).
/// Linear in the corners: a per-vertex table of outgoing edges, no sort of
/// the whole edge list, so a consistent mesh pays little for asking.
bool HasInconsistentOrientation(const MeshView& mesh);
/// The same for 32-bit ids (a fast reader's cells, in place; points unused).
bool HasInconsistentOrientation(const NarrowMeshView& mesh);

/// OrientComponents over FindFaceNeighbours: the faces to flip so that the
/// mesh is consistently oriented (outward on closed components).
std::vector<uint8_t> ConsistentOrientationFlips(const MeshView& mesh);

/// `connectivity` = the mesh's connectivity with the flagged faces reversed;
/// returns how many were.
int64_t FlipFaces(
  const MeshView& mesh, const std::vector<uint8_t>& flips, std::vector<int64_t>& connectivity);

/// Point representatives by exact coordinates: points at the same position
/// map to the lowest-numbered of them (pieces of one mesh written with
/// their own copies of the shared points are connected again).
std::vector<int64_t> CoincidentPointRepresentatives(const double* points, int64_t numberOfPoints);

} // namespace shadinglab::mesh
