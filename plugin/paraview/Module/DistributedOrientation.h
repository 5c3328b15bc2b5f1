// SPDX-License-Identifier: BSD-3-Clause
// Consistent orientation across partitions. Made per partition, each rank
// would pick its own side for a component cut by a partition boundary, and
// a boundary vertex would average opposite normals from the two sides: a
// seam. So when any rank finds faces running a shared edge the same way
// (its own faces plus the neighbours' borrowed ones, BoundaryGhosts.h), the
// polygons are gathered on rank 0, connected again where partitions hold
// their own copies of a point (exact coordinates), oriented once as one
// rank would orient the whole mesh (mesh/core/Orientation.h: consistent per
// component, outward when closed), and each rank gets back which of its
// polygons to turn. Memory on rank 0 is the whole mesh's polygons, paid
// only when the orientation is inconsistent. Collective on every rank.
#pragma once

#include "GatheredPolyData.h"
#include "MeshArrays.h"
#include "Orientation.h"

#include <vtkCellArray.h>
#include <vtkCommunicator.h>
#include <vtkIntArray.h>
#include <vtkMultiProcessController.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <vector>

namespace shadinglab::paraview
{

/// Message tag of the flip flags sent back by rank 0.
constexpr int kFlipsTag = 48214;

/// nullptr when every rank's `work` (its polygons with the neighbours'
/// faces appended) is consistently oriented; else a copy of `input` (this
/// rank's own polygons, no borrowed faces) with the polygons turned that
/// orienting the whole mesh at once turns. `input` is not modified.
inline vtkSmartPointer<vtkPolyData> OrientedAcrossRanks(
  vtkPolyData* input, vtkPolyData* work, vtkMultiProcessController* controller)
{
  namespace slm = shadinglab::mesh;
  int mine = slm::InconsistentlyOriented(work) ? 1 : 0, any = 0;
  controller->AllReduce(&mine, &any, 1, vtkCommunicator::MAX_OP);
  if (!any)
  {
    return nullptr;
  }
  const int rank = controller->GetLocalProcessId();
  const vtkIdType count = input->GetNumberOfPolys();
  std::vector<uint8_t> flips(static_cast<size_t>(count), 0);
  vtkSmartPointer<vtkPolyData> whole = GatherWithOwner(input, controller);
  if (rank == 0)
  {
    slm::FlatPolygons all;
    slm::FlatPolygonsFromPolyData(whole, all);
    const std::vector<int64_t> same =
      slm::CoincidentPointRepresentatives(all.points, all.numberOfPoints);
    std::vector<int64_t> connected(all.connectivity,
      all.connectivity + (all.numberOfPolygons > 0 ? all.offsets[all.numberOfPolygons] : 0));
    for (int64_t& v : connected)
    {
      v = same[static_cast<size_t>(v)];
    }
    slm::MeshView view = all;
    view.connectivity = connected.data();
    const std::vector<uint8_t> turn = slm::ConsistentOrientationFlips(view);
    // The gathered polygons are every rank's in rank order, each in its
    // own order (vtkAppendPolyData); kOwnerArray says whose.
    auto* owner = vtkIntArray::SafeDownCast(whole->GetCellData()->GetArray(kOwnerArray));
    const vtkIdType base = whole->GetNumberOfVerts() + whole->GetNumberOfLines();
    std::vector<std::vector<uint8_t>> perRank(
      static_cast<size_t>(controller->GetNumberOfProcesses()));
    for (int64_t f = 0; f < all.numberOfPolygons; ++f)
    {
      perRank[static_cast<size_t>(owner->GetValue(base + f))].push_back(turn[static_cast<size_t>(f)]);
    }
    for (int r = 1; r < controller->GetNumberOfProcesses(); ++r)
    {
      // A rank without polygons posts no receive: nothing is sent to it
      // (an unreceived message would be taken by its next call's receive).
      if (!perRank[r].empty())
      {
        controller->Send(perRank[r].data(), static_cast<vtkIdType>(perRank[r].size()), r, kFlipsTag);
      }
    }
    flips = perRank[0];
  }
  else if (count > 0)
  {
    controller->Receive(flips.data(), count, 0, kFlipsTag);
  }
  return slm::WithPolygonsTurned(input, flips);
}

} // namespace shadinglab::paraview
