// SPDX-License-Identifier: BSD-3-Clause
#include "PolyDataMesh.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>

namespace shadinglab::render
{

Mesh MeshFromPolyData(vtkPolyData* input)
{
  vtkSmartPointer<vtkPolyData> pd = input;
  if (input->GetNumberOfStrips() > 0)
  {
    vtkNew<vtkTriangleFilter> tri;
    tri->SetInputData(input);
    tri->PassLinesOff();
    tri->PassVertsOff();
    tri->Update();
    pd = tri->GetOutput();
  }
  Mesh mesh;
  const vtkIdType np = pd->GetNumberOfPoints();
  mesh.points.resize(static_cast<size_t>(3 * np));
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    for (int c = 0; c < 3; ++c)
    {
      mesh.points[3 * i + c] = static_cast<float>(p[c]);
    }
  }
  if (vtkDataArray* n = pd->GetPointData()->GetNormals())
  {
    if (n->GetNumberOfComponents() == 3 && n->GetNumberOfTuples() == np)
    {
      mesh.normals.resize(static_cast<size_t>(3 * np));
      for (vtkIdType i = 0; i < np; ++i)
      {
        const double* v = n->GetTuple3(i);
        for (int c = 0; c < 3; ++c)
        {
          mesh.normals[3 * i + c] = static_cast<float>(v[c]);
        }
      }
    }
  }
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(pd->GetPointData()->GetScalars());
  if (scalars && (scalars->GetNumberOfComponents() == 3 || scalars->GetNumberOfComponents() == 4) &&
    scalars->GetNumberOfTuples() == np)
  {
    mesh.colors.resize(static_cast<size_t>(3 * np));
    for (vtkIdType i = 0; i < np; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        mesh.colors[3 * i + c] = scalars->GetTypedComponent(i, c) / 255.0f;
      }
    }
  }
  vtkCellArray* polys = pd->GetPolys();
  mesh.offsets.reserve(static_cast<size_t>(polys->GetNumberOfCells() + 1));
  mesh.offsets.push_back(0);
  mesh.connectivity.reserve(static_cast<size_t>(polys->GetNumberOfConnectivityIds()));
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    polys->GetCellAtId(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      mesh.connectivity.push_back(ids->GetId(k));
    }
    mesh.offsets.push_back(static_cast<int64_t>(mesh.connectivity.size()));
  }
  // Cell normals apply to polygons only when the polydata has no verts or
  // lines before them in cell order.
  vtkDataArray* cn = pd->GetCellData()->GetNormals();
  if (cn && cn->GetNumberOfComponents() == 3 && pd->GetNumberOfVerts() == 0 &&
    pd->GetNumberOfLines() == 0 && cn->GetNumberOfTuples() == polys->GetNumberOfCells())
  {
    mesh.faceNormals.resize(static_cast<size_t>(3 * cn->GetNumberOfTuples()));
    for (vtkIdType i = 0; i < cn->GetNumberOfTuples(); ++i)
    {
      const double* v = cn->GetTuple3(i);
      for (int c = 0; c < 3; ++c)
      {
        mesh.faceNormals[3 * i + c] = static_cast<float>(v[c]);
      }
    }
  }
  return mesh;
}

namespace
{

vtkSmartPointer<vtkFloatArray> FloatArray(const std::vector<float>& values, const char* name)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / 3));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  return array;
}

} // namespace

vtkPolyData* PolyDataFromMesh(const Mesh& mesh)
{
  vtkPolyData* pd = vtkPolyData::New();
  vtkNew<vtkPoints> points;
  points->SetData(FloatArray(mesh.points, "Points"));
  pd->SetPoints(points);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(mesh.offsets.size()));
  std::copy(mesh.offsets.begin(), mesh.offsets.end(), offsets->GetPointer(0));
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(mesh.connectivity.size()));
  std::copy(mesh.connectivity.begin(), mesh.connectivity.end(), connectivity->GetPointer(0));
  vtkNew<vtkCellArray> polys;
  if (mesh.offsets.empty())
  {
    offsets->InsertNextValue(0);
  }
  polys->SetData(offsets, connectivity);
  pd->SetPolys(polys);
  if (!mesh.normals.empty())
  {
    pd->GetPointData()->SetNormals(FloatArray(mesh.normals, "Normals"));
  }
  if (!mesh.colors.empty())
  {
    pd->GetPointData()->SetScalars(FloatArray(mesh.colors, "Colors"));
  }
  if (!mesh.faceNormals.empty())
  {
    pd->GetCellData()->SetNormals(FloatArray(mesh.faceNormals, "Normals"));
  }
  return pd;
}

} // namespace shadinglab::render
