// SPDX-License-Identifier: BSD-3-Clause
// Angular error of vertex normals against the exact normal on analytic
// surfaces, one markdown table: our four weightings, VTK's
// vtkPolyDataNormals and vtkTriangleMeshPointNormals, and the limit normals
// of two levels of OpenSubdiv refinement (measured against the analytic
// normal at the limit position). Deterministic: no timing involved.
#include "AnalyticMeshes.h"
#include "vtkOpenSubdivRefine.h"
#include "vtkWeightedPolyDataNormals.h"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleMeshPointNormals.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace
{

using NormalAt = std::function<void(const double p[3], double n[3])>;

void Normalize(double n[3])
{
  const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  n[0] /= l, n[1] /= l, n[2] /= l;
}

double AngleDeg(const double* a, const double* b)
{
  const double c[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
           a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) *
    180.0 / 3.14159265358979323846;
}

void Report(const std::string& surface, const std::string& res, const std::string& method,
  vtkPolyData* mesh, vtkDataArray* normals, const NormalAt& exact)
{
  double sum = 0, worst = 0;
  const vtkIdType n = mesh->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], e[3], v[3];
    mesh->GetPoint(i, p);
    exact(p, e);
    normals->GetTuple(i, v);
    const double a = AngleDeg(v, e);
    sum += a;
    worst = std::max(worst, a);
  }
  std::printf("| %s | %s | %s | %.4f | %.4f |\n", surface.c_str(), res.c_str(), method.c_str(),
    sum / n, worst);
}

} // namespace

int main()
{
  struct Surface
  {
    std::string name;
    std::vector<std::pair<std::string, std::function<vtkPolyData*()>>> levels;
    NormalAt exact;
  };
  const double a = 1.5, b = 1.0, c = 0.7;
  std::vector<Surface> surfaces = {
    { "uv sphere",
      { { "16x8", [] { return shadinglab::datasets::MakeUVSphere(16, 8); } },
        { "64x32", [] { return shadinglab::datasets::MakeUVSphere(64, 32); } },
        { "256x128", [] { return shadinglab::datasets::MakeUVSphere(256, 128); } } },
      [](const double p[3], double n[3]) {
        n[0] = p[0], n[1] = p[1], n[2] = p[2];
        Normalize(n);
      } },
    { "icosphere",
      { { "L1", [] { return shadinglab::datasets::MakeIcosphere(1); } },
        { "L3", [] { return shadinglab::datasets::MakeIcosphere(3); } },
        { "L5", [] { return shadinglab::datasets::MakeIcosphere(5); } } },
      [](const double p[3], double n[3]) {
        n[0] = p[0], n[1] = p[1], n[2] = p[2];
        Normalize(n);
      } },
    { "torus",
      { { "24x12", [] { return shadinglab::datasets::MakeTorus(1.0, 0.4, 24, 12); } },
        { "96x48", [] { return shadinglab::datasets::MakeTorus(1.0, 0.4, 96, 48); } },
        { "384x192", [] { return shadinglab::datasets::MakeTorus(1.0, 0.4, 384, 192); } } },
      [](const double p[3], double n[3]) {
        const double rho = std::sqrt(p[0] * p[0] + p[1] * p[1]);
        n[0] = p[0] - p[0] / rho, n[1] = p[1] - p[1] / rho, n[2] = p[2];
        Normalize(n);
      } },
    { "ellipsoid",
      { { "16x8", [=] { return shadinglab::datasets::MakeEllipsoid(a, b, c, 16, 8); } },
        { "64x32", [=] { return shadinglab::datasets::MakeEllipsoid(a, b, c, 64, 32); } },
        { "256x128", [=] { return shadinglab::datasets::MakeEllipsoid(a, b, c, 256, 128); } } },
      [=](const double p[3], double n[3]) {
        n[0] = p[0] / (a * a), n[1] = p[1] / (b * b), n[2] = p[2] / (c * c);
        Normalize(n);
      } },
  };
  std::printf("| surface | resolution | method | mean error (deg) | max error (deg) |\n");
  std::printf("|---|---|---|---|---|\n");
  const char* weightNames[] = { "ours uniform", "ours area", "ours angle", "ours max" };
  for (const auto& s : surfaces)
  {
    for (const auto& [res, make] : s.levels)
    {
      vtkSmartPointer<vtkPolyData> mesh;
      mesh.TakeReference(make());
      for (int w = 0; w < 4; ++w)
      {
        vtkNew<vtkWeightedPolyDataNormals> f;
        f->SetInputData(mesh);
        f->SetWeighting(w);
        f->SplittingOff();
        f->Update();
        Report(s.name, res, weightNames[w], f->GetOutput(), f->GetOutput()->GetPointData()->GetNormals(), s.exact);
      }
      {
        vtkNew<vtkPolyDataNormals> f;
        f->SetInputData(mesh);
        f->SplittingOff();
        f->ConsistencyOff();
        f->Update();
        Report(s.name, res, "vtkPolyDataNormals", f->GetOutput(), f->GetOutput()->GetPointData()->GetNormals(), s.exact);
      }
      {
        vtkNew<vtkTriangleMeshPointNormals> f;
        f->SetInputData(mesh);
        f->Update();
        Report(s.name, res, "vtkTriangleMeshPointNormals", f->GetOutput(), f->GetOutput()->GetPointData()->GetNormals(), s.exact);
      }
      if (mesh->GetNumberOfPolys() <= 20000)
      {
        vtkNew<vtkOpenSubdivRefine> f;
        f->SetInputData(mesh);
        f->SetLevels(2);
        f->Update();
        Report(s.name, res, "Loop x2 limit normals", f->GetOutput(), f->GetOutput()->GetPointData()->GetNormals(), s.exact);
      }
    }
  }
  return 0;
}
