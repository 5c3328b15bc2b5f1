// SPDX-License-Identifier: BSD-3-Clause
// Back faces that no pixel can show, culled without being asked.
//
// Seen from outside, every ray through a closed surface whose components
// all face outward enters a front face before it can reach a back face:
// back faces are hidden whatever the lighting, and drawing them (half the
// triangles of any closed mesh) only costs set-up and depth tests. They
// are culled before set-up when
//   - every polygon is a triangle (a non-planar polygon can face both ways),
//   - every edge is used exactly twice, once in each direction (closed and
//     consistently oriented), and every connected component encloses a
//     positive volume (outward), and
//   - the whole bounding box is in front of the near plane (the camera is
//     outside the mesh and no front face is cut away by the near plane).
// The test is cached against the mesh's content hash (render::Mesh::ContentHash).
#pragma once

#include "shadinglab/render/Scene.h"

#include "MeshCache.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace shadinglab::cpu
{

/// Whether the mesh is a closed, consistently and outward oriented triangle
/// mesh, remembered for the last mesh seen (recomputed when its arrays change).
class ClosedMeshCache
{
public:
  /// `fingerprint`: the mesh's content hash (render::Mesh::ContentHash),
  /// the cache key, which the renderer computes once a frame for all its
  /// caches. `mayTest`: whether the test may run on a mesh's first frame
  /// if the answer is not cached (it costs ~120 ns per triangle, once);
  /// without it an unknown mesh is treated as open on that frame, and
  /// tested on its second (SecondSighting).
  bool IsClosedOutward(const render::Mesh& mesh, uint64_t fingerprint, bool mayTest);

private:
  std::optional<uint64_t> Fingerprint; ///< the mesh the answer is for
  bool Closed = false;
  SecondSighting Sightings; ///< meshes drawn without the test
};

/// The test itself, without the cache.
bool IsClosedOutwardTriangleMesh(const render::Mesh& mesh);

/*
 * Back faces culled by the run, before binning reads them: the cone of
 * normals (Shirman & Abi-Ezzi 1993, "The Cone of Normals Technique for Fast
 * Processing of Curved Patches"), over runs of consecutive triangles as
 * meshoptimizer's cluster bounds. A run's unit face normals lie in a cone
 * (axis a, half-angle theta) and its points in a sphere (centre c, radius
 * r). For the eye e, d = c - e and phi the angle between a and d, every
 * point p of every triangle of the run has
 *   n . (p - e) = n . d + n . (p - c) >= |d| cos(phi + theta) - r,
 * so when that bound is positive every triangle faces away (its normal
 * points away from the eye: a back face, whose facing is its plane's, the
 * same at every point). In parallel projection the bound is cos(phi + theta)
 * with phi measured from the view direction. On a closed mesh seen from
 * outside half the triangles face away, in runs wherever a mesh's
 * neighbours are near in index order (every VTK source, marching cubes, a
 * scanned mesh's strips), and binning skips such a run whole.
 */

/// Triangles per run: a run of 64 of ParaView's 1M sphere spans ~12 degrees
/// of normals, so runs within ~15 degrees of the silhouette are left to the
/// per-triangle test; shorter runs cost more tests for few more skipped
/// triangles.
inline constexpr int64_t kClusterPolygons = 64;

/// A run's cone of normals and bounding sphere; `usable` false when the run
/// has a polygon that is not a triangle, a triangle without a normal (zero
/// area, not finite) or normals spread over a half-space or more. Every run
/// has its vertex range: the vertices its polygons use lie in
/// [firstVertex, endVertex) (empty for a run without a valid vertex).
struct ClusterCone
{
  double centre[3] = { 0, 0, 0 };
  double radius = 0;
  double axis[3] = { 0, 0, 0 };
  double cosSpread = 0, sinSpread = 1; ///< cos and sin of the half-angle theta
  bool usable = false;
  int64_t firstVertex = 0, endVertex = 0;
};

/// The cones of every run of kClusterPolygons polygons (the last may be shorter).
std::vector<ClusterCone> ClusterConesOf(
  const render::Mesh& mesh, const render::Mesh::TaskRunner& run = {});

/// The eye as the cone test needs it: position and unit view direction.
struct ClusterEye
{
  double position[3] = { 0, 0, 0 };
  double forward[3] = { 0, 0, -1 };
  bool parallel = false;
};

/// Whether every triangle of the run faces away from the eye, with a
/// margin (kClusterFacingMargin in the .cpp) so that no triangle the
/// per-triangle test of projected float coordinates could find facing the
/// eye is among them.
bool ClusterFacesAway(const ClusterCone& cone, const ClusterEye& eye);

/// The cones of the last mesh culled, built on the second frame a mesh is
/// drawn with back faces culled (SecondFrameCache; ~20 ns a triangle).
class ClusterConeCache
{
public:
  /// nullptr on a mesh's first frame; `fingerprint` its content hash.
  const std::vector<ClusterCone>* ConesOf(
    const render::Mesh& mesh, uint64_t fingerprint, const render::Mesh::TaskRunner& run);

private:
  SecondFrameCache<std::vector<ClusterCone>> Cones;
};

} // namespace shadinglab::cpu
