// SPDX-License-Identifier: BSD-3-Clause
#include "PolyDataMesh.h"

#include "Geometry.h"

#include <vtkCellArray.h>

#include <cmath>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolygon.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>

namespace shadinglab::render
{

namespace
{

Mesh Convert(vtkPolyData* input, WorldFrame& frame, bool normalize);

/// Largest polygon handed to the renderers whole: the CPU renderer clips a
/// polygon at the near plane into at most one more vertex than it has, in a
/// fixed buffer of 64 (Raster.h kMaxPolygonVertices).
constexpr vtkIdType kMaxWholePolygon = 63;

/// True when the polygon turns the same way at every corner (collinear
/// corners allowed), measured against its Newell normal.
bool IsConvex(vtkPoints* points, vtkIdList* ids)
{
  const vtkIdType n = ids->GetNumberOfIds();
  auto at = [&](vtkIdType k) {
    double p[3];
    points->GetPoint(ids->GetId(k % n), p);
    return Vec3<double>(p[0], p[1], p[2]);
  };
  const Vec3<double> normal = mesh::NewellAreaVector<double>(n, at);
  for (vtkIdType k = 0; k < n; ++k)
  {
    const Vec3<double> a = at(k), b = at(k + 1), c = at(k + 2);
    if (Dot(Cross(b - a, c - b), normal) < 0)
    {
      return false;
    }
  }
  return true;
}

} // namespace

Mesh MeshFromPolyData(vtkPolyData* input)
{
  WorldFrame identity;
  return Convert(input, identity, false);
}

Mesh MeshFromPolyData(vtkPolyData* input, WorldFrame& frame)
{
  return Convert(input, frame, true);
}

namespace
{

Mesh Convert(vtkPolyData* input, WorldFrame& frame, bool normalize)
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
  frame = WorldFrame();
  if (normalize && np > 0)
  {
    double b[6];
    pd->GetBounds(b);
    const Vec3<double> lo(b[0], b[2], b[4]), hi(b[1], b[3], b[5]);
    const double radius = 0.5 * Length(hi - lo);
    frame.center = (lo + hi) * 0.5;
    // A mesh of one point has no extent: keep its scale.
    frame.scale = radius > 0 && std::isfinite(radius) ? radius : 1.0;
  }
  mesh.points.resize(static_cast<size_t>(3 * np));
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    const Vec3<double> local = frame.ToLocal(Vec3<double>(p[0], p[1], p[2]));
    mesh.points[3 * i] = static_cast<float>(local.x);
    mesh.points[3 * i + 1] = static_cast<float>(local.y);
    mesh.points[3 * i + 2] = static_cast<float>(local.z);
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
  // Polygons the renderers cannot take whole (concave ones, which a fan or
  // a scanline pairing of one span would fill wrongly, and ones with more
  // than kMaxWholePolygon vertices) are triangulated by ear cutting; the
  // triangles keep their polygon's cell normal. `polygonOf` maps back.
  std::vector<vtkIdType> polygonOf;
  polygonOf.reserve(static_cast<size_t>(polys->GetNumberOfCells()));
  vtkNew<vtkIdList> ids;
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> triangles;
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    polys->GetCellAtId(c, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    if (n > 3 && (n > kMaxWholePolygon || !IsConvex(pd->GetPoints(), ids)))
    {
      polygon->Initialize(static_cast<int>(n), ids->GetPointer(0), pd->GetPoints());
      triangles->Reset();
      if (polygon->Triangulate(triangles) && triangles->GetNumberOfIds() >= 3)
      {
        for (vtkIdType t = 0; t + 2 < triangles->GetNumberOfIds(); t += 3)
        {
          for (int k = 0; k < 3; ++k)
          {
            mesh.connectivity.push_back(ids->GetId(triangles->GetId(t + k)));
          }
          mesh.offsets.push_back(static_cast<int64_t>(mesh.connectivity.size()));
          polygonOf.push_back(c);
        }
        continue;
      }
    }
    for (vtkIdType k = 0; k < n; ++k)
    {
      mesh.connectivity.push_back(ids->GetId(k));
    }
    mesh.offsets.push_back(static_cast<int64_t>(mesh.connectivity.size()));
    polygonOf.push_back(c);
  }
  // Cell normals apply to polygons only when the polydata has no verts or
  // lines before them in cell order.
  vtkDataArray* cn = pd->GetCellData()->GetNormals();
  if (cn && cn->GetNumberOfComponents() == 3 && pd->GetNumberOfVerts() == 0 &&
    pd->GetNumberOfLines() == 0 && cn->GetNumberOfTuples() == polys->GetNumberOfCells())
  {
    mesh.faceNormals.resize(3 * polygonOf.size());
    for (size_t i = 0; i < polygonOf.size(); ++i)
    {
      const double* v = cn->GetTuple3(polygonOf[i]);
      for (int c = 0; c < 3; ++c)
      {
        mesh.faceNormals[3 * i + c] = static_cast<float>(v[c]);
      }
    }
  }
  return mesh;
}

} // namespace

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
