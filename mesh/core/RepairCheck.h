// SPDX-License-Identifier: BSD-3-Clause
// A cheap look at a mesh for what the repair step would change: degenerate
// faces, neighbours with opposite orientations, edges of more than two
// faces, closed components facing inward. Flat arrays, no halfedge
// structure: a vertex-to-face table and one pass over the edges, so that
// a clean 5M-triangle mesh does not pay for OpenMesh (docs/cli.md, mesh
// preparation).
#pragma once

#include "Geometry.h"

#include <cstdint>

namespace shadinglab::mesh
{

struct RepairNeeds
{
  int64_t degenerate = 0;         ///< faces with a repeated vertex or zero area
  int64_t inconsistentEdges = 0;  ///< edges whose two faces run them the same way
  int64_t nonManifoldEdges = 0;   ///< edges of more than two faces
  int64_t inwardComponents = 0;   ///< closed components with negative volume

  bool Any() const
  {
    return degenerate + inconsistentEdges + nonManifoldEdges + inwardComponents > 0;
  }
};

/**
 * What the repair step (RepairMesh with its defaults, no weld, no
 * T-junctions) would find. Non-manifold vertices (fans touching at a
 * vertex) are not looked for: they change no normal and no picture.
 */
RepairNeeds CheckRepairNeeds(const MeshView& mesh);
/// The same on a fast reader's arrays in place (float points, 32-bit ids).
RepairNeeds CheckRepairNeeds(const FloatNarrowMeshView& mesh);

} // namespace shadinglab::mesh
