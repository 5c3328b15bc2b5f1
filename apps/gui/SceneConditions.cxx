// SPDX-License-Identifier: BSD-3-Clause
// Two scenes on what shading assumes of the mesh: `creases` (averaged vertex
// normals that do not represent the surface) and `flat-conditions` (the
// lecture's three conditions under which flat shading is exact); and
// `scanline`, the lecture's scan conversion pixel by pixel.
#include "SceneParts.h"

#include "AnalyticMeshes.h"

#include <vtkCleanPolyData.h>
#include <vtkCubeSource.h>
#include <vtkLinearSubdivisionFilter.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <cmath>

namespace shadinglab::gui
{

using render::ShadingMode;
using widgets::PanelSpec;

namespace
{

/// The cube's side: its circumscribed sphere is the unit sphere, the
/// sphere panel's surface (2 / sqrt(3)).
constexpr double kCubeSide = 1.1547005383792515;
/// The view's margin around the unit sphere's apparent size.
constexpr double kViewMargin = 1.15;

/// A cube of side `side` with one point per corner (no normals): the mesh
/// whose averaged vertex normals round it off.
PolyPtr SharedCornerCube(double side)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(side);
  cube->SetYLength(side);
  cube->SetZLength(side);
  vtkNew<vtkCleanPolyData> weld; // the source's 24 points (a normal each) to 8
  weld->SetInputConnection(cube->GetOutputPort());
  weld->Update();
  PolyPtr out = PolyPtr::New();
  out->DeepCopy(weld->GetOutput());
  out->GetPointData()->SetNormals(nullptr);
  return out;
}

/// `levels` linear subdivisions: more vertices on the same facets.
PolyPtr Subdivided(vtkPolyData* mesh, int levels)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(mesh);
  vtkNew<vtkLinearSubdivisionFilter> subdivide;
  subdivide->SetInputConnection(triangles->GetOutputPort());
  subdivide->SetNumberOfSubdivisions(levels);
  subdivide->Update();
  PolyPtr out = PolyPtr::New();
  out->DeepCopy(subdivide->GetOutput());
  return out;
}

} // namespace

PolyPtr ConditionsMesh(bool sphere)
{
  if (sphere)
  {
    return WithExactNormals(Adopt(datasets::MakeUVSphere(16, 8)));
  }
  // The source's own 24 points carry the face normals: exact for a cube.
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(kCubeSide);
  cube->SetYLength(kCubeSide);
  cube->SetZLength(kCubeSide);
  cube->Update();
  PolyPtr out = PolyPtr::New();
  out->DeepCopy(cube->GetOutput());
  return out;
}

render::Camera ConditionsCamera(double distance)
{
  render::Camera camera;
  const Vec3<double> direction = NormalizeOr(Vec3<double>(0.55, 0.45, 1.0), Vec3<double>(0, 0, 1));
  camera.focalPoint = Vec3<double>(0, 0, 0);
  camera.position = direction * distance;
  camera.viewUp = Vec3<double>(0, 1, 0);
  // The unit sphere subtends 2 asin(1/d); the margin around it.
  camera.viewAngle =
    std::min(120.0, 2.0 * std::asin(1.0 / distance) * kViewMargin * 180.0 / kPi<double>);
  camera.nearClip = std::max(1e-3, distance - 2.0);
  camera.farClip = distance + 2.0;
  return camera;
}

Scene Creases(const SceneOptions& o)
{
  Scene s;
  s.title = "Unrepresentative vertex normals";
  PolyPtr corrugated = Adopt(datasets::MakeCorrugatedPlane(6, 4, 0.12));
  PolyPtr cube = SharedCornerCube(1.0);
  const auto w = o.preparation.weighting;
  const auto b = render::Backend::CPU;
  // The corrugation, lit from the side, needs a stronger highlight to show
  // its slopes; the cube keeps the scenes' plastic (at 0.15 its rounded
  // highlight clipped to white across ~10 px of the profile).
  const Material<double> cubeMaterial = Plastic();
  Material<double> m = cubeMaterial;
  m.ks = 0.15;
  s.panels = {
    Panel("Corrugation, averaged normals: shaded flat", WithNormals(corrugated, w, 180.0),
      ShadingMode::Phong, m, b),
    Panel("Creases split at 30 deg: the facets return", WithNormals(corrugated, w, 30.0),
      ShadingMode::Phong, m, b),
    Panel("More vertices (2 subdivisions), averaged",
      WithNormals(Subdivided(corrugated, 2), w, 180.0), ShadingMode::Phong, m, b),
    Panel("Cube, averaged normals: rounded off", WithNormals(cube, w, 180.0),
      ShadingMode::Phong, cubeMaterial, b),
    Panel("Cube, creases split at 30 deg", WithNormals(cube, w, 30.0), ShadingMode::Phong,
      cubeMaterial, b),
  };
  // Looking down on the corrugation at 45 degrees, across its ridges.
  s.azimuth = 10;
  s.elevation = -45;
  s.zoom = 1.1;
  s.lightAzimuth = -50;
  s.lightElevation = 30;
  // Inside the outer slopes (their end normals are theirs) at any panel
  // aspect the docks leave (1.0 to 1.5 wide per tall).
  s.line = { 0.32, 0.45, 0.68, 0.45 };
  s.explanation =
    "A vertex normal averages the normals of the faces around it. On this corrugation "
    "every vertex sits on a ridge or in a valley, between two faces that lean equally "
    "the other way: every averaged normal points straight up, and Gouraud or Phong "
    "shading renders the corrugated surface as a flat plane (the profile is level). "
    "Splitting the vertices where faces meet at more than the crease angle gives each "
    "face its own normals back; adding vertices on the slopes gives normals that "
    "represent them, and leaves the smoothing to the ridges. The cube shows the other "
    "face of the same averaging: its corners' normals point along the diagonals and "
    "smooth shading rounds a box into a blob, with creases across faces that have none.";
  s.formula = "N<sub>v</sub> = normalize(&Sigma;<sub>f</sub> N<sub>f</sub>) = (0, 0, 1) when "
              "the faces around v lean symmetrically &nbsp; (eq. 2.2)";
  return s;
}

Scene FlatConditions(const SceneOptions& o)
{
  Scene s;
  s.title = "When is flat shading exact?";
  const double d = o.distance;
  const auto b = render::Backend::CPU;
  Material<double> m = Plastic();
  PolyPtr cube = ConditionsMesh(false), sphere = ConditionsMesh(true);
  PanelSpec cubeExact = Panel("Cube, lit per pixel (exact)", cube, ShadingMode::Phong, m, b);
  PanelSpec cubeFlat = Panel("Cube, flat", cube, ShadingMode::Flat, m, b);
  PanelSpec cubeError = Panel("Cube: |flat - exact|", cube, ShadingMode::Flat, m, b);
  cubeError.errorReference = 0;
  PanelSpec sphereExact =
    Panel("Sphere, lit per pixel (exact normals)", sphere, ShadingMode::Phong, m, b);
  PanelSpec sphereFlat = Panel("Sphere, flat", sphere, ShadingMode::Flat, m, b);
  PanelSpec sphereError = Panel("Sphere: |flat - exact|", sphere, ShadingMode::Flat, m, b);
  sphereError.errorReference = 3;
  for (PanelSpec* e : { &cubeError, &sphereError })
  {
    e->errorScale = 32.0 / 255.0;
  }
  s.panels = { cubeExact, cubeFlat, cubeError, sphereExact, sphereFlat, sphereError };
  s.explicitCamera = true;
  s.camera = ConditionsCamera(d);
  s.lightDistance = d;
  s.lightAzimuth = -25;
  s.lightElevation = 25;
  s.plot = PlotKind::Parameter;
  s.explanation =
    "Flat shading lights each polygon once. That is exact only when (1) the object is a "
    "polyhedron, not an approximation of a curved surface; (2) the light is far away, "
    "so N.L is constant over a face; (3) the viewer is far away, so V.R is constant "
    "over a face. Here the camera and a point light stand at the same distance from "
    "the object (set it under Plot). Near, the cube's faces vary across in the exact "
    "image and flat shading errs; far, the cube's error vanishes, while the sphere's "
    "stays: its facets are not its surface. The plot measures the mean error against "
    "the distance.";
  s.formula = "I<sub>face</sub> = I(P<sub>0</sub>, N<sub>f</sub>, L(P<sub>0</sub>), "
              "V(P<sub>0</sub>)) = I(P) for all P of the face iff N, L and V are constant "
              "on it &nbsp; (eq. 2.1)";
  return s;
}

Scene Scanline(const SceneOptions&)
{
  Scene s;
  s.title = "The scan line, pixel by pixel";
  s.plot = PlotKind::Scanline;
  s.explanation =
    "One triangle, magnified until its pixels are squares, drawn by the CPU renderer. "
    "Click or drag to pick the scan line and a pixel. Along each edge the value at the "
    "scan line is interpolated in y (x4, x5 and their I or N); along the span it is "
    "interpolated in x. The lecture does both by forward differences: one addition per "
    "row and per pixel. Beside the per-row values stand those of the incremental scan, "
    "stepped in float or double: identical to the eye here, they drift apart over long "
    "spans and edges (docs/model.md eq. 2.12, docs/incremental-scan.md). In Phong mode "
    "the arrows are the interpolated normals before renormalization. Every number is "
    "the renderer's own, read back from its trace of that row.";
  s.formula = "I<sub>p</sub> = (x<sub>5</sub> - x<sub>p</sub>)/(x<sub>5</sub> - x<sub>4</sub>) "
              "I<sub>4</sub> + (x<sub>p</sub> - x<sub>4</sub>)/(x<sub>5</sub> - x<sub>4</sub>) "
              "I<sub>5</sub>; &nbsp; I<sub>p+1</sub> = I<sub>p</sub> + (I<sub>5</sub> - "
              "I<sub>4</sub>)/(x<sub>5</sub> - x<sub>4</sub>) &nbsp; (eq. 2.3-2.4, 2.10-2.11)";
  return s;
}

} // namespace shadinglab::gui
