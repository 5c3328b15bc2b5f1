// SPDX-License-Identifier: BSD-3-Clause
#include "AnalyticMeshes.h"
#include "MetaballField.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace shadinglab::datasets
{

namespace
{

constexpr double kPi = 3.14159265358979323846;

using P3 = std::array<double, 3>;

P3 Normalized(const P3& v)
{
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / l, v[1] / l, v[2] / l };
}

/// Builds a polydata from points, exact normals (may be empty) and polygons.
vtkPolyData* Assemble(const std::vector<P3>& points, const std::vector<P3>& normals,
  const std::vector<std::vector<vtkIdType>>& polys)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  for (size_t i = 0; i < points.size(); ++i)
  {
    pts->SetPoint(static_cast<vtkIdType>(i), points[i].data());
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& p : polys)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(p.size()), p.data());
  }
  auto* mesh = vtkPolyData::New();
  mesh->SetPoints(pts);
  mesh->SetPolys(cells);
  if (!normals.empty())
  {
    vtkNew<vtkDoubleArray> n;
    n->SetName(kExactNormalArray);
    n->SetNumberOfComponents(3);
    n->SetNumberOfTuples(static_cast<vtkIdType>(normals.size()));
    for (size_t i = 0; i < normals.size(); ++i)
    {
      n->SetTuple(static_cast<vtkIdType>(i), normals[i].data());
    }
    mesh->GetPointData()->AddArray(n);
  }
  return mesh;
}

/// Triangulated (u, v) grid on a surface: u periodic with `nu` columns,
/// v from 0 to 1 with `nv` rows. With poles, the first and last rows
/// collapse to single vertices.
/// `flip` reverses the winding for parametrizations whose (du x dv) points
/// inwards (the spheres, with v running from the north pole down).
template <typename Surface>
vtkPolyData* ParametricGrid(
  int nu, int nv, bool periodicV, bool poles, bool flip, Surface surface)
{
  std::vector<P3> points, normals;
  std::vector<std::vector<vtkIdType>> polys;
  const int rows = periodicV ? nv : nv + 1;
  auto index = [&](int i, int j) -> vtkIdType {
    i = ((i % nu) + nu) % nu;
    if (periodicV)
    {
      j = ((j % nv) + nv) % nv;
    }
    if (poles)
    {
      if (j == 0)
      {
        return 0;
      }
      if (j == nv)
      {
        return 1 + static_cast<vtkIdType>(nu) * (nv - 1);
      }
      return 1 + static_cast<vtkIdType>(j - 1) * nu + i;
    }
    return static_cast<vtkIdType>(j) * nu + i;
  };
  for (int j = 0; j < rows; ++j)
  {
    const double v = static_cast<double>(j) / nv;
    if (poles && (j == 0 || j == nv))
    {
      P3 p, n;
      surface(0.0, v, p, n);
      points.push_back(p);
      normals.push_back(n);
      continue;
    }
    for (int i = 0; i < nu; ++i)
    {
      P3 p, n;
      surface(static_cast<double>(i) / nu, v, p, n);
      points.push_back(p);
      normals.push_back(n);
    }
  }
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      const vtkIdType a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1),
                      d = index(i, j + 1);
      auto add = [&](vtkIdType p0, vtkIdType p1, vtkIdType p2) {
        if (flip)
        {
          polys.push_back({ p0, p2, p1 });
        }
        else
        {
          polys.push_back({ p0, p1, p2 });
        }
      };
      if (poles && j == 0)
      {
        add(a, c, d);
      }
      else if (poles && j == nv - 1)
      {
        add(a, b, c);
      }
      else
      {
        add(a, b, c);
        add(a, c, d);
      }
    }
  }
  return Assemble(points, normals, polys);
}

} // namespace

vtkPolyData* MakeUVSphere(int slices, int stacks)
{
  // v = 0 is the north pole (z = 1); counter-clockwise seen from outside.
  return ParametricGrid(slices, stacks, false, true, true, [](double u, double v, P3& p, P3& n) {
    const double phi = 2 * kPi * u, theta = kPi * v;
    n = { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) };
    if (v == 0.0 || v == 1.0)
    {
      n = { 0.0, 0.0, v == 0.0 ? 1.0 : -1.0 };
    }
    p = n;
  });
}

vtkPolyData* MakeEllipsoid(double a, double b, double c, int slices, int stacks)
{
  return ParametricGrid(slices, stacks, false, true, true, [=](double u, double v, P3& p, P3& n) {
    const double phi = 2 * kPi * u, theta = kPi * v;
    P3 s = { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) };
    if (v == 0.0 || v == 1.0)
    {
      s = { 0.0, 0.0, v == 0.0 ? 1.0 : -1.0 };
    }
    p = { a * s[0], b * s[1], c * s[2] };
    n = Normalized({ p[0] / (a * a), p[1] / (b * b), p[2] / (c * c) });
  });
}

vtkPolyData* MakeTorus(double R, double r, int major, int minor)
{
  return ParametricGrid(major, minor, true, false, false, [=](double u, double v, P3& p, P3& n) {
    const double phi = 2 * kPi * u, theta = 2 * kPi * v;
    n = { std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), std::sin(theta) };
    p = { (R + r * std::cos(theta)) * std::cos(phi), (R + r * std::cos(theta)) * std::sin(phi),
      r * std::sin(theta) };
  });
}

vtkPolyData* MakeIcosphere(int level)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<P3> points = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 },
    { 0, -1, t }, { 0, 1, t }, { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 },
    { -t, 0, -1 }, { -t, 0, 1 } };
  for (auto& p : points)
  {
    p = Normalized(p);
  }
  std::vector<std::array<vtkIdType, 3>> faces = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 },
    { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 },
    { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 },
    { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  for (int l = 0; l < level; ++l)
  {
    std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> midpoints;
    auto midpoint = [&](vtkIdType a, vtkIdType b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = midpoints.find(key);
      if (it != midpoints.end())
      {
        return it->second;
      }
      const P3& pa = points[a];
      const P3& pb = points[b];
      points.push_back(Normalized({ pa[0] + pb[0], pa[1] + pb[1], pa[2] + pb[2] }));
      const vtkIdType id = static_cast<vtkIdType>(points.size() - 1);
      midpoints[key] = id;
      return id;
    };
    std::vector<std::array<vtkIdType, 3>> next;
    next.reserve(faces.size() * 4);
    for (const auto& f : faces)
    {
      const vtkIdType a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      next.push_back({ f[0], a, c });
      next.push_back({ f[1], b, a });
      next.push_back({ f[2], c, b });
      next.push_back({ a, b, c });
    }
    faces.swap(next);
  }
  std::vector<std::vector<vtkIdType>> polys;
  polys.reserve(faces.size());
  for (const auto& f : faces)
  {
    polys.push_back({ f[0], f[1], f[2] });
  }
  return Assemble(points, points, polys);
}

vtkPolyData* MakeLowPolyCylinder(int sides)
{
  std::vector<P3> points;
  std::vector<std::vector<vtkIdType>> polys;
  for (int i = 0; i < sides; ++i)
  {
    const double a = 2 * kPi * i / sides;
    points.push_back({ std::cos(a), std::sin(a), -1.0 });
    points.push_back({ std::cos(a), std::sin(a), 1.0 });
  }
  std::vector<vtkIdType> top, bottom;
  for (int i = 0; i < sides; ++i)
  {
    const vtkIdType b0 = 2 * i, t0 = 2 * i + 1, b1 = 2 * ((i + 1) % sides),
                    t1 = 2 * ((i + 1) % sides) + 1;
    polys.push_back({ b0, b1, t1, t0 });
    top.push_back(t0);
    bottom.insert(bottom.begin(), b0);
  }
  polys.push_back(top);
  polys.push_back(bottom);
  return Assemble(points, {}, polys);
}

vtkPolyData* MakeCorrugatedPlane(int ridges, int depth, double amplitude)
{
  std::vector<P3> points;
  std::vector<std::vector<vtkIdType>> polys;
  const int nx = 2 * ridges + 1;
  for (int j = 0; j <= depth; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const double x = 2.0 * i / (nx - 1) - 1.0;
      const double y = 2.0 * j / depth - 1.0;
      points.push_back({ x, y, (i % 2 == 0) ? amplitude : -amplitude });
    }
  }
  for (int j = 0; j < depth; ++j)
  {
    for (int i = 0; i + 1 < nx; ++i)
    {
      const vtkIdType a = j * nx + i;
      polys.push_back({ a, a + 1, a + 1 + nx, a + nx });
    }
  }
  return Assemble(points, {}, polys);
}

vtkPolyData* MakeQuadStrip(int quads)
{
  std::vector<P3> points, normals;
  std::vector<std::vector<vtkIdType>> polys;
  for (int i = 0; i <= quads; ++i)
  {
    const double a = kPi * i / quads;
    const P3 n = { -std::cos(a), 0.0, std::sin(a) };
    for (double y : { -0.25, 0.25 })
    {
      points.push_back({ -std::cos(a), y, std::sin(a) });
      normals.push_back(n);
    }
  }
  for (int i = 0; i < quads; ++i)
  {
    const vtkIdType a = 2 * i;
    polys.push_back({ a, a + 2, a + 3, a + 1 });
  }
  return Assemble(points, normals, polys);
}

vtkPolyData* MakeTJunctionPatch(int coarse)
{
  // Height field z = 0.3 cos(pi x / 2) cos(pi y / 2) over [-1, 1]^2: the left
  // half meshed with coarse quads, the right half with quads of half the
  // size. The column x = 0 belongs to both; its fine vertices at odd rows lie
  // in the middle of coarse edges.
  auto height = [](double x, double y) { return 0.3 * std::cos(kPi * x / 2) * std::cos(kPi * y / 2); };
  auto normal = [](double x, double y) {
    const double dzdx = -0.3 * kPi / 2 * std::sin(kPi * x / 2) * std::cos(kPi * y / 2);
    const double dzdy = -0.3 * kPi / 2 * std::cos(kPi * x / 2) * std::sin(kPi * y / 2);
    return Normalized({ -dzdx, -dzdy, 1.0 });
  };
  std::vector<P3> points, normals;
  std::vector<std::vector<vtkIdType>> polys;
  std::map<std::pair<int, int>, vtkIdType> ids; // keyed on the fine lattice
  const int fine = 2 * coarse;
  auto id = [&](int fi, int fj) {
    const auto key = std::make_pair(fi, fj);
    const auto it = ids.find(key);
    if (it != ids.end())
    {
      return it->second;
    }
    const double x = -1.0 + 2.0 * fi / (2 * fine), y = -1.0 + 2.0 * fj / fine;
    double z = height(x, y);
    if (fi == fine && fj % 2 == 1)
    {
      // A T-junction vertex sits exactly on the coarse edge (the midpoint
      // of its ends), as adaptive refinement leaves it: the geometry is
      // watertight, the interpolated shading is not.
      const double y0 = -1.0 + 2.0 * (fj - 1) / fine, y1 = -1.0 + 2.0 * (fj + 1) / fine;
      z = 0.5 * (height(x, y0) + height(x, y1));
    }
    points.push_back({ x, y, z });
    normals.push_back(normal(x, y));
    ids[key] = static_cast<vtkIdType>(points.size() - 1);
    return ids[key];
  };
  // Left half: coarse cells span 2 fine steps; fine lattice x index 0..fine.
  for (int j = 0; j < fine; j += 2)
  {
    for (int i = 0; i < fine; i += 2)
    {
      polys.push_back({ id(i, j), id(i + 2, j), id(i + 2, j + 2), id(i, j + 2) });
    }
  }
  // Right half: fine cells, x index fine..2*fine.
  for (int j = 0; j < fine; ++j)
  {
    for (int i = fine; i < 2 * fine; ++i)
    {
      polys.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return Assemble(points, normals, polys);
}

namespace
{
/// The blobs' field (MetaballField.h) on this file's point type.
double Field(const P3& p, P3* gradient)
{
  return MetaballField(p, gradient);
}
constexpr double kIsoValue = kMetaballIsoValue;
} // namespace

vtkPolyData* MakeMetaballIsosurface(int n)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, n);
  const double lo = -1.0, step = 2.0 / (n - 1);
  image->SetOrigin(lo, lo, lo);
  image->SetSpacing(step, step, step);
  vtkNew<vtkDoubleArray> values;
  values->SetName("Density");
  values->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const P3 p = { lo + i * step, lo + j * step, lo + k * step };
        values->SetValue((static_cast<vtkIdType>(k) * n + j) * n + i, Field(p, nullptr));
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetValue(0, kIsoValue);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  auto* mesh = vtkPolyData::New();
  mesh->ShallowCopy(contour->GetOutput());
  // Exact normal: minus the normalized field gradient at each vertex.
  vtkNew<vtkDoubleArray> exact;
  exact->SetName(kExactNormalArray);
  exact->SetNumberOfComponents(3);
  exact->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    P3 p, g;
    mesh->GetPoint(i, p.data());
    Field(p, &g);
    const P3 nrm = Normalized({ -g[0], -g[1], -g[2] });
    exact->SetTuple(i, nrm.data());
  }
  mesh->GetPointData()->AddArray(exact);
  return mesh;
}

vtkPolyData* MakeRecedingPlane(double depth)
{
  auto* mesh = Assemble({ { -0.5, 0.0, 0.0 }, { 0.5, 0.0, 0.0 }, { 0.5, 0.0, -depth }, { -0.5, 0.0, -depth } },
    { { 0, 1, 0 }, { 0, 1, 0 }, { 0, 1, 0 }, { 0, 1, 0 } }, { { 0, 1, 2, 3 } });
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  for (unsigned char c : { 0, 0, 255, 255 })
  {
    const unsigned char rgb[3] = { c, c, c };
    colors->InsertNextTypedTuple(rgb);
  }
  mesh->GetPointData()->SetScalars(colors);
  return mesh;
}

vtkPolyData* MakeTerrain(int n)
{
  auto height = [](double x, double y, double& dx, double& dy) {
    // Two hills, a valley and a ripple: smooth, with an analytic gradient.
    double z = 0;
    dx = dy = 0;
    const double hills[3][4] = { { -0.4, -0.3, 0.35, 0.45 }, { 0.45, 0.35, 0.25, 0.3 },
      { 0.1, -0.5, -0.2, 0.35 } };
    for (const auto& h : hills)
    {
      const double ex = x - h[0], ey = y - h[1], s2 = h[3] * h[3];
      const double e = h[2] * std::exp(-(ex * ex + ey * ey) / s2);
      z += e;
      dx += -2 * ex / s2 * e;
      dy += -2 * ey / s2 * e;
    }
    z += 0.03 * std::sin(6 * x) * std::cos(5 * y);
    dx += 0.18 * std::cos(6 * x) * std::cos(5 * y);
    dy += -0.15 * std::sin(6 * x) * std::sin(5 * y);
    return z;
  };
  std::vector<P3> points, normals;
  std::vector<std::vector<vtkIdType>> polys;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double x = -1.0 + 2.0 * i / (n - 1), y = -1.0 + 2.0 * j / (n - 1);
      double dx, dy;
      const double z = height(x, y, dx, dy);
      points.push_back({ x, y, z });
      normals.push_back(Normalized({ -dx, -dy, 1.0 }));
    }
  }
  for (int j = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i)
    {
      const vtkIdType a = j * n + i;
      polys.push_back({ a, a + 1, a + 1 + n });
      polys.push_back({ a, a + 1 + n, a + n });
    }
  }
  auto* mesh = Assemble(points, normals, polys);
  vtkNew<vtkFloatArray> elevation;
  elevation->SetName("Elevation");
  elevation->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    elevation->SetValue(i, static_cast<float>(points[static_cast<size_t>(i)][2]));
  }
  mesh->GetPointData()->AddArray(elevation);
  return mesh;
}

vtkPolyData* MakeNoisyDecimatedSphere(int level, double noise, double keep)
{
  vtkSmartPointer<vtkPolyData> sphere;
  sphere.TakeReference(MakeIcosphere(level));
  vtkPoints* points = sphere->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    // A smooth bumpy field plus a hash-based jitter: deterministic on every
    // machine (no std random distribution, whose output is unspecified).
    const double bumps = std::sin(5.0 * p[0]) * std::sin(4.0 * p[1] + 1.0) * std::cos(3.0 * p[2]);
    const double hash = std::fmod(std::sin(12.9898 * i + 78.233) * 43758.5453, 1.0);
    const double r = 1.0 + noise * (0.7 * bumps + 0.3 * hash);
    points->SetPoint(i, p[0] * r, p[1] * r, p[2] * r);
  }
  sphere->GetPointData()->RemoveArray(kExactNormalArray);
  vtkNew<vtkQuadricDecimation> decimate;
  decimate->SetInputData(sphere);
  decimate->SetTargetReduction(1.0 - keep);
  decimate->VolumePreservationOn();
  decimate->Update();
  vtkPolyData* out = vtkPolyData::New();
  out->ShallowCopy(decimate->GetOutput());
  return out;
}

} // namespace shadinglab::datasets
