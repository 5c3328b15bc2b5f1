// SPDX-License-Identifier: BSD-3-Clause
// A filter whose result depends on the whole mesh (mesh repair: the weld
// tolerance is relative to the whole bounding box, a T-junction may straddle
// a partition boundary, and each closed component is oriented outward as a
// whole) runs on distributed data by gathering: every rank's polygons go to
// rank 0, tagged with their owner; rank 0 runs the filter once on the whole
// mesh, exactly as on one rank; each rank gets back its own polygons (with
// the points they use; partition-boundary points on every rank that uses
// them, as RedistributeDataSet hands them out). Memory on rank 0 is the
// whole mesh: a once-per-pipeline preparation step, not a per-frame one.
// Collective: every rank must call Gather and then Scatter.
#pragma once

#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <vector>

namespace shadinglab::paraview
{

/// Cell array naming each gathered polygon's owning rank.
constexpr const char* kOwnerArray = "ShadingLabOwner";
/// Message tag of the scattered pieces.
constexpr int kScatterTag = 48213;

/// Rank 0: every rank's polygons appended in rank order, kOwnerArray set;
/// other ranks: nullptr. `input` is not modified.
inline vtkSmartPointer<vtkPolyData> GatherWithOwner(
  vtkPolyData* input, vtkMultiProcessController* controller)
{
  vtkNew<vtkPolyData> mine;
  mine->ShallowCopy(input); // its own attribute objects: the input keeps its arrays
  vtkNew<vtkIntArray> owner;
  owner->SetName(kOwnerArray);
  owner->SetNumberOfTuples(mine->GetNumberOfCells());
  owner->FillValue(controller->GetLocalProcessId());
  mine->GetCellData()->AddArray(owner);
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->Gather(mine, pieces, 0);
  if (controller->GetLocalProcessId() != 0)
  {
    return nullptr;
  }
  vtkNew<vtkAppendPolyData> append;
  for (const auto& piece : pieces)
  {
    if (auto* poly = vtkPolyData::SafeDownCast(piece))
    {
      append->AddInputData(poly);
    }
  }
  append->Update();
  vtkSmartPointer<vtkPolyData> whole = append->GetOutput();
  return whole;
}

/// The polygons of `mesh` owned by `rank`, with the points they use.
inline vtkSmartPointer<vtkPolyData> OwnedPart(vtkPolyData* mesh, int rank)
{
  auto part = vtkSmartPointer<vtkPolyData>::New();
  auto* owner = vtkIntArray::SafeDownCast(mesh->GetCellData()->GetArray(kOwnerArray));
  vtkCellArray* polys = mesh->GetPolys();
  if (!owner || !polys)
  {
    return part;
  }
  // Polygons follow vertices and lines in the cell numbering.
  const vtkIdType base = mesh->GetNumberOfVerts() + mesh->GetNumberOfLines();
  std::vector<vtkIdType> map(static_cast<size_t>(mesh->GetNumberOfPoints()), -1);
  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints()->GetDataType());
  vtkNew<vtkCellArray> cells;
  vtkPointData* outPD = part->GetPointData();
  vtkCellData* outCD = part->GetCellData();
  outPD->CopyAllocate(mesh->GetPointData());
  outCD->CopyAllocate(mesh->GetCellData());
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    if (owner->GetValue(base + c) != rank)
    {
      continue;
    }
    polys->GetCellAtId(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      vtkIdType& local = map[ids->GetId(k)];
      if (local < 0)
      {
        local = points->InsertNextPoint(mesh->GetPoint(ids->GetId(k)));
        outPD->CopyData(mesh->GetPointData(), ids->GetId(k), local);
      }
      ids->SetId(k, local);
    }
    const vtkIdType out = cells->InsertNextCell(ids);
    outCD->CopyData(mesh->GetCellData(), base + c, out);
  }
  part->SetPoints(points);
  part->SetPolys(cells);
  outCD->RemoveArray(kOwnerArray);
  return part;
}

/// Rank 0 sends each rank its part of `whole` (which only rank 0 has) and
/// keeps its own in `output`; the others receive theirs into `output`.
/// `ok` (rank 0's) is broadcast first: when false no rank waits for data.
inline bool ScatterByOwner(
  vtkPolyData* whole, bool ok, vtkMultiProcessController* controller, vtkPolyData* output)
{
  int status = ok ? 1 : 0;
  controller->Broadcast(&status, 1, 0);
  if (!status)
  {
    return false;
  }
  const int rank = controller->GetLocalProcessId();
  if (rank == 0)
  {
    for (int r = 1; r < controller->GetNumberOfProcesses(); ++r)
    {
      vtkSmartPointer<vtkPolyData> part = OwnedPart(whole, r);
      controller->Send(part, r, kScatterTag);
    }
    output->ShallowCopy(OwnedPart(whole, 0));
    return true;
  }
  return controller->Receive(output, 0, kScatterTag) != 0;
}

} // namespace shadinglab::paraview
