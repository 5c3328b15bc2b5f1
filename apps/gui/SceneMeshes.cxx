// SPDX-License-Identifier: BSD-3-Clause
#include "SceneMeshes.h"

#include "AnalyticMeshes.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <stdexcept>

namespace shadinglab::gui
{

namespace
{
constexpr double kPiD = 3.14159265358979323846;
}

PolyPtr Adopt(vtkPolyData* mesh)
{
  PolyPtr out;
  out.TakeReference(mesh);
  return out;
}

PolyPtr WithExactNormals(vtkPolyData* mesh)
{
  auto out = PolyPtr::New();
  out->DeepCopy(mesh);
  vtkDataArray* exact = out->GetPointData()->GetArray(datasets::kExactNormalArray);
  if (!exact)
  {
    throw std::invalid_argument("mesh has no exact normals");
  }
  out->GetPointData()->SetNormals(exact);
  return out;
}

PolyPtr WithNormals(vtkPolyData* mesh, mesh::NormalWeighting weighting, double featureAngle)
{
  mesh::PreparationOptions options;
  options.repair = false;
  options.weighting = weighting;
  options.featureAngle = featureAngle;
  return Prepared(mesh, options);
}

PolyPtr Prepared(vtkPolyData* mesh, const mesh::PreparationOptions& options)
{
  mesh::PreparationReport report;
  return mesh::PrepareMesh(mesh, options, report);
}

PolyPtr Rotated(vtkPolyData* mesh, int axis, double degrees)
{
  vtkNew<vtkTransform> transform;
  transform->RotateWXYZ(degrees, axis == 0, axis == 1, axis == 2);
  vtkNew<vtkTransformPolyDataFilter> filter;
  filter->SetTransform(transform);
  filter->SetInputData(mesh);
  filter->Update();
  PolyPtr out = filter->GetOutput();
  return out;
}

PolyPtr OrientationQuad(double degrees)
{
  auto out = PolyPtr::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetName("Normals");
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  colors->SetName("Colors");
  const double a = degrees * kPiD / 180.0;
  const double corners[4][2] = { { 1, 1 }, { -1, 1 }, { -1, -1 }, { 1, -1 } };
  const unsigned char shades[4] = { 230, 26, 230, 26 }; // 0.9 and 0.1 of 255
  for (int i = 0; i < 4; ++i)
  {
    const double x = corners[i][0], y = corners[i][1];
    points->InsertNextPoint(
      x * std::cos(a) - y * std::sin(a), x * std::sin(a) + y * std::cos(a), 0.0);
    normals->InsertNextTuple3(0, 0, 1);
    const unsigned char c[3] = { shades[i], shades[i], shades[i] };
    colors->InsertNextTypedTuple(c);
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  polys->InsertNextCell(4, ids);
  out->SetPoints(points);
  out->SetPolys(polys);
  out->GetPointData()->SetNormals(normals);
  out->GetPointData()->SetScalars(colors);
  return out;
}

PolyPtr CorrugatedSurface(int n)
{
  auto out = PolyPtr::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> exact;
  exact->SetNumberOfComponents(3);
  exact->SetName(datasets::kExactNormalArray);
  const double amplitude = 0.12, k = 2.0 * kPiD;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      // Uneven columns: spacing grows from left to right by a factor ~3.
      const double u = static_cast<double>(i) / n;
      const double x = -1.0 + 2.0 * (0.5 * u + 0.5 * u * u);
      const double y = -1.0 + 2.0 * j / n;
      points->InsertNextPoint(x, y, amplitude * std::sin(k * x));
      const double dzdx = amplitude * k * std::cos(k * x);
      const double len = std::sqrt(1.0 + dzdx * dzdx);
      exact->InsertNextTuple3(-dzdx / len, 0.0, 1.0 / len);
    }
  }
  vtkNew<vtkCellArray> polys;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      // Diagonals flip by a fixed pattern (every third cell and odd rows).
      if ((i * 7 + j * 3) % 3 == 0 || j % 2 == 1)
      {
        const vtkIdType t1[3] = { a, b, c }, t2[3] = { a, c, d };
        polys->InsertNextCell(3, t1);
        polys->InsertNextCell(3, t2);
      }
      else
      {
        const vtkIdType t1[3] = { a, b, d }, t2[3] = { b, c, d };
        polys->InsertNextCell(3, t1);
        polys->InsertNextCell(3, t2);
      }
    }
  }
  out->SetPoints(points);
  out->SetPolys(polys);
  out->GetPointData()->AddArray(exact);
  return out;
}

PolyPtr CrackedTJunctions(vtkPolyData* patch)
{
  auto out = PolyPtr::New();
  out->DeepCopy(patch);
  // T vertices are the points of column x = 0 used by fine cells only: they
  // lie on coarse edges at the mean height of the edge's ends; lift them to
  // the surface height, 0.3 cos(pi x / 2) cos(pi y / 2) (AnalyticMeshes).
  vtkPoints* points = out->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    if (std::abs(p[0]) > 1e-12)
    {
      continue;
    }
    const double surface = 0.3 * std::cos(kPiD * p[0] / 2) * std::cos(kPiD * p[1] / 2);
    if (std::abs(surface - p[2]) > 1e-9)
    {
      p[2] = surface;
      points->SetPoint(i, p);
    }
  }
  return out;
}

} // namespace shadinglab::gui
