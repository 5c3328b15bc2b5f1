// SPDX-License-Identifier: BSD-3-Clause
// The explorer's artifact scenes: the numbers their plots show (Mach bands,
// perspective, orientation, flat conditions, creases, the scanline
// inspector) against the lecture's formulas.
#include "ExplorerGLTest.h"
#include "ExplorerTestUtil.h"
#include "ProfilePlot.h"

void ExplorerGLTest::MachBandsProfiles()
{
  auto window = Open("mach-bands", render::Backend::CPU);
  widgets::ComparisonWidget* view = window->Comparison();
  vtkCamera* camera = view->View().camera;
  const std::vector<widgets::Profile> profiles = view->Profiles();
  QCOMPARE(static_cast<int>(profiles.size()), 3);
  const render::Image image = view->Panel(1)->Snapshot();
  const widgets::PanelSpec& spec = view->Panel(1)->Spec();
  QCOMPARE(spec.mode, render::ShadingMode::Gouraud);
  // The vertex intensities: each vertical edge of the cylinder (two points
  // with one normal) projects to one screen x, with one Lambert intensity.
  const render::Camera cam = render::CameraFromVtk(camera);
  Lighting<double> lighting = widgets::ViewLighting(view->View(), cam);
  const Vec3<double> toEye = NormalizeOr(cam.position - cam.focalPoint, Vec3<double>(0, 0, 1));
  std::vector<std::pair<double, double>> edges; // screen x, intensity
  vtkPolyData* mesh = spec.mesh;
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  QVERIFY(normals);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3], n[3];
    mesh->GetPoint(i, p);
    normals->GetTuple(i, n);
    if (p[1] < 0.5 || std::abs(n[1]) > 1e-6)
    {
      continue; // one point per edge (the top ring), side normals only
    }
    const Vec3<double> N(n[0], n[1], n[2]);
    if (Dot(N, toEye) <= 0)
    {
      continue;
    }
    double x, y;
    Project(camera, p, image.width, image.height, x, y);
    const Vec3<double> I = Shade(spec.material, lighting, spec.material.diffuseColor,
      Vec3<double>(p[0], p[1], p[2]), N, toEye);
    edges.push_back({ x, widgets::Luminance(std::array<float, 3>{ float(I.x), float(I.y),
                                              float(I.z) }.data()) });
  }
  std::sort(edges.begin(), edges.end());
  QVERIFY2(edges.size() >= 3, "fewer than 3 front-facing edges");
  const widgets::Profile& gouraud = profiles[1];
  int checked = 0;
  double worst = 0;
  for (size_t s = 0; s < gouraud.intensity.size(); ++s)
  {
    const double x = gouraud.pixelX[s];
    for (size_t e = 0; e + 1 < edges.size(); ++e)
    {
      const double x0 = edges[e].first, x1 = edges[e + 1].first;
      // Within a face, one pixel clear of its edges.
      if (gouraud.covered[s] && x > x0 + 1 && x < x1 - 1)
      {
        const double t = (x - x0) / (x1 - x0);
        const double expected = edges[e].second + t * (edges[e + 1].second - edges[e].second);
        worst = std::max(worst, std::abs(gouraud.intensity[s] - expected));
        ++checked;
      }
    }
  }
  QVERIFY2(checked > 100, qPrintable(QString("only %1 samples inside faces").arg(checked)));
  QVERIFY2(worst <= kOne255, qPrintable(QString("Gouraud off the linear interpolation of its "
                                                "vertex intensities by %1/255")
                                          .arg(worst * 255)));
  // Flat: piecewise constant, one level per face, adjacent faces differ.
  const widgets::Profile& flat = profiles[0];
  std::vector<double> levels;
  for (size_t e = 0; e + 1 < edges.size(); ++e)
  {
    double lo = 1e9, hi = -1e9;
    for (size_t s = 0; s < flat.intensity.size(); ++s)
    {
      if (flat.covered[s] && flat.pixelX[s] > edges[e].first + 1 &&
        flat.pixelX[s] < edges[e + 1].first - 1)
      {
        lo = std::min(lo, flat.intensity[s]);
        hi = std::max(hi, flat.intensity[s]);
      }
    }
    if (hi >= lo)
    {
      QVERIFY2(hi - lo < 1e-5, qPrintable(QString("flat face %1 varies by %2").arg(e).arg(hi - lo)));
      levels.push_back(lo);
    }
  }
  QVERIFY(levels.size() >= 3);
  for (size_t i = 1; i < levels.size(); ++i)
  {
    QVERIFY(std::abs(levels[i] - levels[i - 1]) > 10 * kOne255);
  }
  // The derivative of Gouraud's profile is a step function: its jumps sit
  // at the edges, which is where the perceived profile over/undershoots.
  const std::vector<double> perceived = widgets::PerceivedProfile(gouraud);
  double bump = 0;
  for (size_t s = 0; s < perceived.size(); ++s)
  {
    if (gouraud.covered[s])
    {
      bump = std::max(bump, std::abs(perceived[s] - gouraud.intensity[s]));
    }
  }
  QVERIFY2(bump > 2 * kOne255, "no Mach band in the perceived Gouraud profile");
  // ...and the plot shows them at a glance: the second chart plots
  // perceived - actual on an axis where Gouraud's bands take a fifth or
  // more of its half-height (flat's steps clipped, the title says so).
  window->RefreshNow();
  const widgets::ProfilePlot* plot = window->Profile();
  QVERIFY2(plot->SecondTitle().contains("Mach bands"), qPrintable(plot->SecondTitle()));
  QVERIFY2(plot->SecondTitle().contains("Flat"), qPrintable(plot->SecondTitle()));
  QVERIFY2(bump > 0.2 * plot->SecondAxisSpan(),
    qPrintable(QString("Gouraud's bands %1 on an axis of +-%2").arg(bump).arg(plot->SecondAxisSpan())));
}

void ExplorerGLTest::PerspectiveProfiles()
{
  auto window = Open("perspective", render::Backend::CPU);
  widgets::ComparisonWidget* view = window->Comparison();
  vtkCamera* camera = view->View().camera;
  const std::vector<widgets::Profile> profiles = view->Profiles();
  QCOMPARE(static_cast<int>(profiles.size()), 2);
  const render::Image image = view->Panel(0)->Snapshot();
  const render::Camera cam = render::CameraFromVtk(camera);
  const Lighting<double> lighting = widgets::ViewLighting(view->View(), cam);
  const double NoL = lighting.lights[0].vector.y; // the floor faces +y
  // The floor's colour is its depth fraction t = -z / 8 (black near, white
  // far): cast the ray of each profile pixel onto y = 0.
  vtkMatrix4x4* m =
    camera->GetCompositeProjectionTransformMatrix(double(image.width) / image.height, -1, 1);
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(m, inverse);
  const widgets::Profile& correct = profiles[0];
  double worst = 0;
  int checked = 0;
  for (size_t s = 0; s < correct.intensity.size(); ++s)
  {
    if (!correct.covered[s])
    {
      continue;
    }
    const double ndcX = 2.0 * correct.pixelX[s] / image.width - 1.0;
    const double ndcY = 1.0 - 2.0 * correct.pixelY[s] / image.height;
    double nearP[4] = { ndcX, ndcY, -1, 1 }, farP[4] = { ndcX, ndcY, 1, 1 }, a[4], b[4];
    inverse->MultiplyPoint(nearP, a);
    inverse->MultiplyPoint(farP, b);
    for (int k = 0; k < 3; ++k)
    {
      a[k] /= a[3];
      b[k] /= b[3];
    }
    const double u = a[1] / (a[1] - b[1]);
    const double z = a[2] + u * (b[2] - a[2]);
    const double t = std::clamp(-z / 8.0, 0.0, 1.0);
    // Colours are 8-bit in the mesh: 0 and 255, so rho = t exactly.
    worst = std::max(worst, std::abs(correct.intensity[s] - t * NoL));
    ++checked;
  }
  QVERIFY(checked > 100);
  QVERIFY2(worst <= kOne255, qPrintable(QString("perspective-correct profile off the ray-cast "
                                                "depth by %1/255").arg(worst * 255)));
  // Screen-space: linear in screen distance within each triangle, so its
  // profile has at most a kink where the line crosses the quad's diagonal,
  // and it is brighter than the perspective-correct one (the far half of
  // the ramp squeezed into few pixels).
  const widgets::Profile& screen = profiles[1];
  int kinks = 0;
  double brighter = 0;
  for (size_t s = 2; s < screen.intensity.size(); ++s)
  {
    if (screen.covered[s] && screen.covered[s - 1] && screen.covered[s - 2])
    {
      const double second =
        screen.intensity[s] - 2 * screen.intensity[s - 1] + screen.intensity[s - 2];
      kinks += std::abs(second) > 2 * kOne255;
      brighter += screen.intensity[s] - correct.intensity[s];
    }
  }
  QVERIFY2(kinks <= 3, qPrintable(QString("screen-space profile not piecewise linear: %1 kinks")
                                    .arg(kinks)));
  QVERIFY(brighter > 0);
}

void ExplorerGLTest::OrientationDependsOnRotation()
{
  auto window = Open("orientation", render::Backend::CPU);
  const std::string csv = window->PlotCsv();
  // The study: polygon scan conversion gives 0.5 kd at 0 degrees and the
  // corner value near 45; triangulation one corner value throughout.
  double at0 = -1, at45 = -1;
  std::istringstream in(csv);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.rfind("\"polygon", 0) == 0)
    {
      const size_t a = line.find("\",") + 2, b = line.find(',', a);
      const double x = std::stod(line.substr(a, b - a)), y = std::stod(line.substr(b + 1));
      if (x == 0)
        at0 = y;
      if (x == 45)
        at45 = y;
    }
  }
  QVERIFY(at0 >= 0 && at45 >= 0);
  QVERIFY2(std::abs(at0 - 0.5 * (230 + 26) / 255.0) < 2 * kOne255, qPrintable(QString::number(at0)));
  QVERIFY2(std::abs(at0 - at45) > 0.2, qPrintable(QString("%1 vs %2").arg(at0).arg(at45)));
}

// The lecture's three conditions: flat shading's error on the cube (a
// polyhedron) falls as light and viewer recede and is zero for a
// directional light and a parallel view; the sphere's (not a polyhedron)
// stays above 3/255 at every distance (~5-6/255 with the scenes' unclipped
// plastic), thousands of times the far cube's.
void ExplorerGLTest::FlatConditionsErrorVanishesForTheCubeOnly()
{
  auto window = Open("flat-conditions", render::Backend::CPU);
  const std::string csv = window->PlotCsv();
  const auto cube = StudySeries(csv, "cube (a polyhedron)");
  const auto sphere = StudySeries(csv, "sphere (16 x 8 facets)");
  const auto cubeFar = StudySeries(csv, "cube, both at infinity");
  QVERIFY2(cube.size() >= 10 && sphere.size() == cube.size(), csv.c_str());
  QVERIFY2(cube.front().second > 3.0, qPrintable(QString::number(cube.front().second)));
  for (size_t i = 1; i < cube.size(); ++i)
  {
    QVERIFY2(cube[i].second < cube[i - 1].second, qPrintable(QString::number(cube[i].first)));
  }
  QVERIFY2(cube.back().second < 0.01, qPrintable(QString::number(cube.back().second)));
  QVERIFY(!cubeFar.empty());
  QCOMPARE(cubeFar.front().second, 0.0);
  for (const auto& [x, y] : sphere)
  {
    QVERIFY2(y > 3.0, qPrintable(QString("%1: %2").arg(x).arg(y)));
  }
  QVERIFY(sphere.back().second > 1000.0 * cube.back().second);
  // The heat maps show it too: the cube's error panel is not blank near.
  QCOMPARE(window->Comparison()->PanelCount(), 6);
}

// The corrugation with averaged normals shades (nearly) flat across its
// ridges, the creased one does not; the cube with averaged normals shows a
// highlight where the creased one has flat faces.
void ExplorerGLTest::CreasesAveragedCorrugationShadesFlat()
{
  auto window = Open("creases", render::Backend::CPU);
  const std::vector<widgets::Profile> profiles = window->Comparison()->Profiles();
  QCOMPARE(profiles.size(), size_t(5));
  const double averaged = CoveredSpread(profiles[0]), creased = CoveredSpread(profiles[1]);
  const double refined = CoveredSpread(profiles[2]);
  QVERIFY2(creased > 4 * averaged, qPrintable(QString("%1 vs %2").arg(creased).arg(averaged)));
  QVERIFY2(refined > 2 * averaged, qPrintable(QString("%1 vs %2").arg(refined).arg(averaged)));
  double roundPeak = 0, boxPeak = 0;
  for (size_t s = 0; s < profiles[3].intensity.size(); ++s)
  {
    roundPeak = std::max(roundPeak, profiles[3].covered[s] ? profiles[3].intensity[s] : 0.0);
    boxPeak = std::max(boxPeak, profiles[4].covered[s] ? profiles[4].intensity[s] : 0.0);
  }
  QVERIFY2(roundPeak > 2 * boxPeak, qPrintable(QString("%1 vs %2").arg(roundPeak).arg(boxPeak)));
}

// The inspector's numbers are the renderer's: the selected pixel's value is
// the rendered image's pixel (Gouraud: the traced lit colour is what was
// written; Phong: the image), it lies on the line through the traced span
// ends (eq. 2.4), the equations print it, and the incremental scan's value
// stands beside it. Off the triangle there is no value.
void ExplorerGLTest::ScanlineInspectorShowsTheRenderersNumbers()
{
  auto window = Open("scanline", render::Backend::CPU);
  widgets::ScanlineInspector* inspector = window->Scanline();
  QVERIFY(inspector->isVisible());
  QVERIFY(window->Comparison()->PanelCount() == 0);
  for (const auto mode : { render::ShadingMode::Gouraud, render::ShadingMode::Phong })
  {
    inspector->SetMode(mode);
    inspector->Select(4, 6);
    for (bool incremental : { false, true })
    {
      const render::ScanTrace& trace = inspector->Trace(incremental);
      QCOMPARE(trace.row, 4);
      QCOMPARE(trace.spans.size(), size_t(1));
      const double value = inspector->SelectedValue(incremental);
      const render::Image& image = inspector->Rendered(incremental);
      const double pixel = image.rgb[3 * (4 * widgets::ScanlineInspector::kColumns + 6)];
      QVERIFY2(std::abs(value - pixel) < 1e-6, qPrintable(QString("%1 vs %2").arg(value).arg(pixel)));
      // Eq. 2.4 through the traced ends, slot by slot.
      const render::TracedSpan& span = trace.spans.front();
      const int slot = mode == render::ShadingMode::Phong ? trace.normalSlot : trace.intensitySlot;
      QVERIFY(slot >= 0);
      const double t = (6.5 - span.xLeft) / (span.xRight - span.xLeft);
      for (const render::TracedPixel& p : trace.pixels)
      {
        if (p.i == 6)
        {
          const double expected = span.left[slot] + t * (span.right[slot] - span.left[slot]);
          QVERIFY2(std::abs(p.attributes[slot] - expected) < 1e-5,
            qPrintable(QString("%1 vs %2").arg(p.attributes[slot]).arg(expected)));
        }
      }
    }
    QVERIFY(inspector->Equations().contains(QString::number(inspector->SelectedValue(false), 'f', 4)));
  }
  inspector->Select(0, 13);
  QVERIFY(std::isnan(inspector->SelectedValue(false)));
  QVERIFY(inspector->Equations().contains("misses") || inspector->Equations().contains("outside"));
  QVERIFY(window->PlotCsv().rfind("row,pixel,per_row,incremental", 0) == 0);
}
