// SPDX-License-Identifier: BSD-3-Clause
// The measured quantities behind the Parameter scenes, rendered with the
// CPU renderer at a fixed size so the numbers do not depend on the window.
#include "Scenes.h"

#include "SceneMeshes.h"
#include "SceneParts.h"

#include "CpuPanel.h"
#include "VtkCamera.h"
#include "shadinglab/cpu/SoftwareRenderer.h"

#include <vtkCamera.h>
#include <vtkPolyData.h>

#include <cmath>

namespace shadinglab::gui
{

namespace
{

/// The study's image side: odd, so one pixel sits on the view's centre.
constexpr int kStudySize = 129;
/// Largest mesh a study refines to: 4M faces take a few seconds to subdivide
/// and render on the CPU, the most a click on a scene should cost.
constexpr double kStudyMaxFaces = 4e6;
/// flat-conditions at infinity: half the parallel view's height, the unit
/// sphere with ConditionsCamera's margin.
constexpr double kViewMarginOfLimit = 1.15;

widgets::ViewState StudyView(const Scene& scene, const std::vector<widgets::PanelSpec>& panels)
{
  double bounds[6] = { 1e300, -1e300, 1e300, -1e300, 1e300, -1e300 };
  for (const widgets::PanelSpec& spec : panels)
  {
    const double* b = spec.mesh->GetBounds();
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], b[2 * a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], b[2 * a + 1]);
    }
  }
  widgets::ViewState view;
  view.camera = vtkSmartPointer<vtkCamera>::New();
  render::ApplyToVtkCamera(scene.explicitCamera
      ? scene.camera
      : render::FitCamera(bounds, scene.azimuth, scene.elevation, scene.zoom, 1.0, scene.parallel),
    view.camera);
  view.lightAzimuth = scene.lightAzimuth;
  view.lightElevation = scene.lightElevation;
  view.lightIntensity = scene.lightIntensity;
  view.lightDistance = scene.lightDistance;
  view.lightKit = scene.lightKit;
  view.display = scene.display;
  return view;
}

Study OrientationStudy(const Scene& scene, const SceneOptions& options)
{
  Study study;
  study.title = "Intensity at the square's centre against its rotation";
  study.xTitle = "rotation in the image plane (degrees)";
  study.yTitle = "centre luminance (linear)";
  study.marker = options.rotation;
  cpu::SoftwareRenderer renderer;
  Study::Series polygon{ "polygon scan conversion (eq. 2.3)", {}, {} };
  Study::Series triangles{ "two triangles", {}, {} };
  Study::Series bilinear{ "bilinear (rotation invariant)", {}, {} };
  for (int degrees = 0; degrees <= 90; degrees += 3)
  {
    widgets::PanelSpec spec = scene.panels[0];
    spec.mesh = OrientationQuad(degrees);
    const widgets::ViewState view = StudyView(scene, { spec });
    for (auto handling : { render::PolygonHandling::Direct, render::PolygonHandling::Triangulate })
    {
      spec.polygons = handling;
      widgets::CpuMeshCache cache;
      const render::Image& image =
        widgets::RenderOnCpu(renderer, cache, spec, view, kStudySize, kStudySize);
      const size_t centre = static_cast<size_t>(kStudySize / 2) * kStudySize + kStudySize / 2;
      Study::Series& series =
        handling == render::PolygonHandling::Direct ? polygon : triangles;
      series.x.push_back(degrees);
      series.y.push_back(widgets::Luminance(&image.rgb[3 * centre]));
    }
    // Bilinear interpolation of the corner values 0.9, 0.1, 0.9, 0.1 at the
    // centre: their mean, times kd.
    bilinear.x.push_back(degrees);
    bilinear.y.push_back(scene.panels[0].material.kd * 0.5 * (230 + 26) / 255.0);
  }
  study.series = { polygon, triangles, bilinear };
  return study;
}

Study SilhouetteStudy(const Scene& scene, const SceneOptions& options)
{
  Study study;
  study.title = "Silhouette error against subdivision level";
  study.xTitle = "subdivision level";
  cpu::SoftwareRenderer renderer;
  // Level 5 is the reference, unless the mesh would pass kStudyMaxFaces.
  int kLevels = 5;
  while (kLevels > 2 && scene.panels[0].mesh->GetNumberOfPolys() * std::pow(4.0, kLevels) >
      kStudyMaxFaces)
  {
    --kLevels;
  }
  study.yTitle = "pixels unlike level " + std::to_string(kLevels);
  std::vector<widgets::PanelSpec> specs;
  for (int level = 0; level <= kLevels; ++level)
  {
    widgets::PanelSpec spec = scene.panels[0];
    mesh::PreparationOptions p = options.preparation;
    p.repair = false;
    p.featureAngle = options.input ? p.featureAngle : 180.0; // as the scene
    p.subdivisionLevels = level;
    spec.mesh = Prepared(scene.panels[0].mesh, p);
    specs.push_back(spec);
  }
  const widgets::ViewState view = StudyView(scene, specs);
  constexpr int kSize = 256;
  std::vector<std::vector<uint8_t>> coverage;
  for (const widgets::PanelSpec& spec : specs)
  {
    widgets::CpuMeshCache cache;
    coverage.push_back(widgets::RenderOnCpu(renderer, cache, spec, view, kSize, kSize).covered);
  }
  Study::Series series{ "coverage differences, 256 x 256 view", {}, {} };
  for (int level = 0; level < kLevels; ++level)
  {
    double differ = 0;
    for (size_t i = 0; i < coverage[level].size(); ++i)
    {
      differ += coverage[level][i] != coverage[kLevels][i];
    }
    series.x.push_back(level);
    series.y.push_back(differ);
  }
  study.series = { series };
  return study;
}

Study NormalsStudy(const Scene& scene)
{
  Study study;
  study.title = "Mean shading error of each weighting (Phong, 256 x 256)";
  study.xTitle = "vertex normal weighting";
  study.yTitle = "mean |I - I_exact| (1/255)";
  cpu::SoftwareRenderer renderer;
  const widgets::ViewState view = StudyView(scene, scene.panels);
  constexpr int kSize = 256;
  widgets::CpuMeshCache referenceCache;
  const render::Image reference =
    widgets::RenderOnCpu(renderer, referenceCache, scene.panels[0], view, kSize, kSize);
  Study::Series series{ "mean error", {}, {} };
  for (size_t p = 1; p < scene.panels.size(); ++p)
  {
    widgets::CpuMeshCache cache;
    const render::Image& image =
      widgets::RenderOnCpu(renderer, cache, scene.panels[p], view, kSize, kSize);
    double sum = 0;
    long count = 0;
    for (size_t i = 0; i < image.covered.size(); ++i)
    {
      if (image.covered[i] && reference.covered[i])
      {
        sum += std::abs(
          widgets::Luminance(&image.rgb[3 * i]) - widgets::Luminance(&reference.rgb[3 * i]));
        ++count;
      }
    }
    series.x.push_back(static_cast<double>(p - 1));
    series.y.push_back(count ? 255.0 * sum / count : 0.0);
    const std::string& title = scene.panels[p].title;
    study.categories.push_back(title.substr(0, title.find(" weights")));
  }
  study.series = { series };
  return study;
}

/// Mean |a - b| of the luminance, in 1/255, over the pixels both cover.
double MeanDifference255(const render::Image& a, const render::Image& b)
{
  double sum = 0;
  long count = 0;
  for (size_t i = 0; i < a.covered.size() && i < b.covered.size(); ++i)
  {
    if (a.covered[i] && b.covered[i])
    {
      sum += std::abs(widgets::Luminance(&a.rgb[3 * i]) - widgets::Luminance(&b.rgb[3 * i]));
      ++count;
    }
  }
  return count ? 255.0 * sum / count : 0.0;
}

/// flat-conditions: the mean error of flat shading against per-pixel
/// lighting (panels 1 against 0, 4 against 3) with the camera and the
/// point light at each distance; and the limit, a directional light and a
/// parallel view, drawn as a level line.
Study FlatConditionsStudy(const Scene& scene, const SceneOptions& options)
{
  Study study;
  study.title = "Flat shading's mean error against the distance of light and viewer";
  study.xTitle = "log10 of the distance (circumradii)";
  study.yTitle = "mean error (1/255)";
  study.marker = std::log10(options.distance);
  cpu::SoftwareRenderer renderer;
  const double distances[] = { 1.5, 2, 3, 5, 10, 20, 50, 100, 300, 1000, 3000, 10000 };
  Study::Series cube{ "cube (a polyhedron)", {}, {} }, sphere{ "sphere (16 x 8 facets)", {}, {} };
  auto error = [&](const widgets::ViewState& view, int exact, int flat)
  {
    widgets::CpuMeshCache a, b;
    const render::Image reference =
      widgets::RenderOnCpu(renderer, a, scene.panels[exact], view, kStudySize, kStudySize);
    return MeanDifference255(
      widgets::RenderOnCpu(renderer, b, scene.panels[flat], view, kStudySize, kStudySize),
      reference);
  };
  for (double d : distances)
  {
    Scene at = scene;
    at.camera = ConditionsCamera(d);
    at.lightDistance = d;
    const widgets::ViewState view = StudyView(at, at.panels);
    cube.x.push_back(std::log10(d));
    cube.y.push_back(error(view, 0, 1));
    sphere.x.push_back(std::log10(d));
    sphere.y.push_back(error(view, 3, 4));
  }
  // At infinity: parallel rays from the light and to the viewer.
  Scene limit = scene;
  limit.camera = ConditionsCamera(distances[0]);
  limit.camera.parallel = true;
  limit.camera.parallelScale = kViewMarginOfLimit;
  limit.lightDistance = 0;
  const widgets::ViewState view = StudyView(limit, limit.panels);
  const double cubeLimit = error(view, 0, 1), sphereLimit = error(view, 3, 4);
  Study::Series cubeFar{ "cube, both at infinity", {}, {} };
  Study::Series sphereFar{ "sphere, both at infinity", {}, {} };
  for (Study::Series* s : { &cubeFar, &sphereFar })
  {
    s->x = { cube.x.front(), cube.x.back() };
    const double v = s == &cubeFar ? cubeLimit : sphereLimit;
    s->y = { v, v };
  }
  study.series = { cube, sphere, cubeFar, sphereFar };
  return study;
}

} // namespace

Study RunStudy(const Scene& scene, const SceneOptions& options)
{
  if (scene.name == "orientation")
  {
    return OrientationStudy(scene, options);
  }
  if (scene.name == "silhouette")
  {
    return SilhouetteStudy(scene, options);
  }
  if (scene.name == "normals")
  {
    return NormalsStudy(scene);
  }
  if (scene.name == "flat-conditions")
  {
    return FlatConditionsStudy(scene, options);
  }
  if (scene.name == "polarization")
  {
    return PolarizationStudy();
  }
  if (scene.name == "spectral")
  {
    return SpectralStudy();
  }
  return {};
}

} // namespace shadinglab::gui
