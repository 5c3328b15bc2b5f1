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

#include <cstdint>
#include <optional>

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
  /// tested on its second: a renderer that draws a mesh once (the CLI)
  /// does not pay for a test that frame cannot earn back, one that redraws
  /// it (the explorer, ParaView) pays once and culls from then on.
  bool IsClosedOutward(const render::Mesh& mesh, uint64_t fingerprint, bool mayTest);

private:
  std::optional<uint64_t> Fingerprint; ///< the mesh the answer is for
  bool Closed = false;
  std::optional<uint64_t> Untested; ///< a mesh drawn once without the test
};

/// The test itself, without the cache.
bool IsClosedOutwardTriangleMesh(const render::Mesh& mesh);

} // namespace shadinglab::cpu
