// SPDX-License-Identifier: BSD-3-Clause
#include "MeshArrays.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace shadinglab::mesh
{

FlatPolygons FlatPolygonsFromPolyData(vtkPolyData* input)
{
  FlatPolygons out;
  const vtkIdType np = input->GetNumberOfPoints();
  out.points.resize(static_cast<size_t>(3 * np));
  for (vtkIdType i = 0; i < np; ++i)
  {
    input->GetPoint(i, &out.points[3 * i]);
  }
  vtkNew<vtkIdList> ids;
  vtkCellArray* polys = input->GetPolys();
  out.offsets.reserve(static_cast<size_t>(polys->GetNumberOfCells() + 1));
  out.connectivity.reserve(static_cast<size_t>(polys->GetNumberOfConnectivityIds()));
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    polys->GetCellAtId(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      out.connectivity.push_back(ids->GetId(k));
    }
    out.offsets.push_back(static_cast<int64_t>(out.connectivity.size()));
  }
  return out;
}

std::vector<int64_t> LineSegments(vtkPolyData* input)
{
  std::vector<int64_t> segments;
  vtkNew<vtkIdList> ids;
  vtkCellArray* lines = input->GetLines();
  for (vtkIdType c = 0; c < lines->GetNumberOfCells(); ++c)
  {
    lines->GetCellAtId(c, ids);
    for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      segments.push_back(ids->GetId(k));
      segments.push_back(ids->GetId(k + 1));
    }
  }
  return segments;
}

} // namespace shadinglab::mesh
