// SPDX-License-Identifier: BSD-3-Clause
// Whether two polydata hold the same mesh bit for bit: points (type and
// bits), every cell array's cells, every point and cell data array (name,
// type, components, bits). Shared by FastReadersTest and the corpus check.
#pragma once

#include <vtkAbstractArray.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cstring>
#include <string>

namespace shadinglab::test
{

/// "" when `a` and `b` are the same array bit for bit, else what differs.
inline std::string ArrayDifference(vtkDataArray* a, vtkDataArray* b, const std::string& what)
{
  if (!a || !b)
  {
    return a == b ? "" : what + ": present in one only";
  }
  if (a->GetDataType() != b->GetDataType() || a->GetNumberOfComponents() != b->GetNumberOfComponents() ||
    a->GetNumberOfTuples() != b->GetNumberOfTuples())
  {
    return what + ": type, components or tuples differ (" + a->GetDataTypeAsString() + " " +
      std::to_string(a->GetNumberOfTuples()) + "x" + std::to_string(a->GetNumberOfComponents()) + " vs " +
      b->GetDataTypeAsString() + " " + std::to_string(b->GetNumberOfTuples()) + "x" +
      std::to_string(b->GetNumberOfComponents()) + ")";
  }
  const size_t bytes = static_cast<size_t>(a->GetNumberOfValues()) * static_cast<size_t>(a->GetDataTypeSize());
  if (bytes > 0 && std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0), bytes) != 0)
  {
    return what + ": values differ";
  }
  return "";
}

inline std::string AttributesDifference(vtkDataSetAttributes* a, vtkDataSetAttributes* b, const std::string& what)
{
  if (a->GetNumberOfArrays() != b->GetNumberOfArrays())
  {
    return what + ": " + std::to_string(a->GetNumberOfArrays()) + " arrays vs " +
      std::to_string(b->GetNumberOfArrays());
  }
  for (int i = 0; i < a->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* x = a->GetArray(i);
    const char* name = x ? x->GetName() : nullptr;
    vtkDataArray* y = name ? b->GetArray(name) : b->GetArray(i);
    const std::string d = ArrayDifference(x, y, what + " array '" + (name ? name : "?") + "'");
    if (!d.empty())
    {
      return d;
    }
  }
  const bool sameScalars = (a->GetScalars() == nullptr) == (b->GetScalars() == nullptr);
  const bool sameNormals = (a->GetNormals() == nullptr) == (b->GetNormals() == nullptr);
  return sameScalars && sameNormals ? "" : what + ": active scalars or normals differ";
}

inline std::string CellsDifference(vtkCellArray* a, vtkCellArray* b, const std::string& what)
{
  if (a->GetNumberOfCells() != b->GetNumberOfCells())
  {
    return what + ": " + std::to_string(a->GetNumberOfCells()) + " cells vs " +
      std::to_string(b->GetNumberOfCells());
  }
  vtkNew<vtkIdList> x, y;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellAtId(c, x);
    b->GetCellAtId(c, y);
    bool same = x->GetNumberOfIds() == y->GetNumberOfIds();
    for (vtkIdType k = 0; same && k < x->GetNumberOfIds(); ++k)
    {
      same = x->GetId(k) == y->GetId(k);
    }
    if (!same)
    {
      return what + ": cell " + std::to_string(c) + " differs";
    }
  }
  return "";
}

/// "" when the two meshes are the same bit for bit, else the first
/// difference found.
inline std::string MeshDifference(vtkPolyData* a, vtkPolyData* b)
{
  std::string d = ArrayDifference(a->GetPoints() ? a->GetPoints()->GetData() : nullptr,
    b->GetPoints() ? b->GetPoints()->GetData() : nullptr, "points");
  const char* names[] = { "verts", "lines", "polys", "strips" };
  vtkCellArray* as[] = { a->GetVerts(), a->GetLines(), a->GetPolys(), a->GetStrips() };
  vtkCellArray* bs[] = { b->GetVerts(), b->GetLines(), b->GetPolys(), b->GetStrips() };
  for (int i = 0; i < 4 && d.empty(); ++i)
  {
    d = CellsDifference(as[i], bs[i], names[i]);
  }
  if (d.empty())
  {
    d = AttributesDifference(a->GetPointData(), b->GetPointData(), "point data");
  }
  if (d.empty())
  {
    d = AttributesDifference(a->GetCellData(), b->GetCellData(), "cell data");
  }
  return d;
}

} // namespace shadinglab::test
