// SPDX-License-Identifier: BSD-3-Clause
// Small geometric helpers shared by the mesh tests.
#pragma once

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

namespace shadinglab::testing
{

/// Signed volume by the divergence theorem (polygons fan-triangulated):
/// positive for a closed surface oriented outwards.
inline double SignedVolume(vtkPolyData* mesh)
{
  double volume = 0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfPolys(); ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, ids);
    double p0[3];
    mesh->GetPoint(ids->GetId(0), p0);
    for (vtkIdType k = 1; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      double p1[3], p2[3];
      mesh->GetPoint(ids->GetId(k), p1);
      mesh->GetPoint(ids->GetId(k + 1), p2);
      volume += (p0[0] * (p1[1] * p2[2] - p1[2] * p2[1]) - p0[1] * (p1[0] * p2[2] - p1[2] * p2[0]) +
                  p0[2] * (p1[0] * p2[1] - p1[1] * p2[0])) /
        6.0;
    }
  }
  return volume;
}

} // namespace shadinglab::testing
