// SPDX-License-Identifier: BSD-3-Clause
// The explorer under Xvfb (label gl): the shared camera, re-rendering only
// what changed, every scene drawn, and the numbers its plots show against
// the lecture's formulas.
#include "AnalyticMeshes.h"
#include "BrdfPlot.h"
#include "ColorLegend.h"
#include "ComparisonWidget.h"
#include "CpuPanel.h"
#include "MainWindow.h"
#include "MaterialEditor.h"
#include "shadinglab/model/Spectrum.h"
#include "ShadingPanel.h"

#include "VtkCamera.h"

#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QMimeData>
#include <QMouseEvent>
#include <QSlider>
#include <QSurfaceFormat>
#include <QTest>
#include <QUrl>
#include <QVTKOpenGLNativeWidget.h>

#include <cmath>
#include <set>

using namespace shadinglab;

namespace
{

/// One step of 8-bit display: the tolerance the issue states for profiles.
constexpr double kOne255 = 1.0 / 255.0;

/// Lets Qt show new widgets and deliver queued events.
void Settle(int passes = 5)
{
  for (int i = 0; i < passes; ++i)
  {
    QApplication::processEvents();
  }
}

/// A window on scene `name` with all panels on `backend` (and the user's
/// mesh `input`, when given), drawn.
std::unique_ptr<gui::MainWindow> Open(
  const std::string& name, render::Backend backend, vtkPolyData* input = nullptr)
{
  gui::SceneOptions options;
  options.backend = backend;
  options.input = input;
  auto window = std::make_unique<gui::MainWindow>(options);
  window->resize(1500, 950);
  window->show();
  Settle();
  std::string error;
  if (!window->LoadScene(name, error))
  {
    qFatal("LoadScene(%s): %s", name.c_str(), error.c_str());
  }
  Settle();
  window->RefreshNow();
  return window;
}

/// Display coordinates (pixel x, y with y down, pixel centres at +0.5) of a
/// world point, as the renderers project it for an image of w x h.
void Project(vtkCamera* camera, const double p[3], int w, int h, double& x, double& y)
{
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(
    static_cast<double>(w) / h, -1, 1);
  double in[4] = { p[0], p[1], p[2], 1.0 }, out[4];
  m->MultiplyPoint(in, out);
  x = (out[0] / out[3] + 1.0) * 0.5 * w;
  y = (1.0 - out[1] / out[3]) * 0.5 * h;
}

void SendDrag(QWidget* target, QPoint from, QPoint to, Qt::MouseButton button)
{
  QMouseEvent press(QEvent::MouseButtonPress, from, target->mapToGlobal(from), button, button,
    Qt::NoModifier);
  QApplication::sendEvent(target, &press);
  for (int i = 1; i <= 5; ++i)
  {
    const QPoint p = from + (to - from) * i / 5;
    QMouseEvent move(
      QEvent::MouseMove, p, target->mapToGlobal(p), Qt::NoButton, button, Qt::NoModifier);
    QApplication::sendEvent(target, &move);
  }
  QMouseEvent release(
    QEvent::MouseButtonRelease, to, target->mapToGlobal(to), button, Qt::NoButton, Qt::NoModifier);
  QApplication::sendEvent(target, &release);
}

/// The widget inside a panel that draws (ImageView or QVTKOpenGLNativeWidget).
QWidget* ViewOf(widgets::ShadingPanel* panel)
{
  QWidget* best = nullptr;
  for (QWidget* child : panel->findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly))
  {
    if (!best || child->height() > best->height())
    {
      best = child;
    }
  }
  return best;
}

} // namespace

class ExplorerGLTest : public QObject
{
  Q_OBJECT
private slots:
  void CameraLinkMovesAllPanels();
  void MaterialSliderRerendersOnePanel();
  void EveryScreenshotIsDrawn();
  void MachBandsProfiles();
  void PerspectiveProfiles();
  void MoonProfiles();
  void MetalHighlightsKeepTheirColour();
  void DroppedMeshIsShown();
  void AutoPanelFollowsItsBudget();
  void OrientationDependsOnRotation();
  void LommelSeeligerOnGpuMatchesCpu();
  void UserMeshIsFramedWhateverItsPlaceAndSize();
  void ColourByDataOnBothBackends();
  void MaterialEditorShowsTheModelsParameters();
  void FlatConditionsErrorVanishesForTheCubeOnly();
  void PolarizationSceneShowsBrewster();
  void SpectralSceneShowsTheColourDifference();
  void CreasesAveragedCorrugationShadesFlat();
  void ScanlineInspectorShowsTheRenderersNumbers();
};

void ExplorerGLTest::CameraLinkMovesAllPanels()
{
  // A CPU and a GPU panel: a drag in either moves the one camera and
  // re-renders the other panel.
  auto window = Open("mach-bands", render::Backend::CPU);
  widgets::ComparisonWidget* view = window->Comparison();
  widgets::PanelSpec gpu = view->Panel(1)->Spec();
  gpu.backend = render::Backend::GPU;
  std::vector<widgets::PanelSpec> specs = { view->Panel(0)->Spec(), gpu };
  view->SetPanels(specs);
  view->ResetCamera(0, 0, 1.6, true);
  Settle();
  view->RenderAll();
  Settle();
  QCOMPARE(view->Panel(1)->Backend(), render::Backend::GPU);
  vtkCamera* camera = view->View().camera;

  for (int source = 0; source < 2; ++source)
  {
    double before[3];
    camera->GetPosition(before);
    const int other = 1 - source;
    const int otherRenders = view->Panel(other)->RenderCount();
    QWidget* target = ViewOf(view->Panel(source));
    QVERIFY(target);
    const QPoint c = target->rect().center();
    SendDrag(target, c, c + QPoint(60, 20), Qt::LeftButton);
    Settle();
    double after[3];
    camera->GetPosition(after);
    const double moved = std::hypot(after[0] - before[0], after[1] - before[1], after[2] - before[2]);
    QVERIFY2(moved > 1e-3, qPrintable(QString("drag in panel %1 moved nothing").arg(source)));
    QVERIFY2(view->Panel(other)->RenderCount() > otherRenders,
      qPrintable(QString("panel %1 not re-rendered after a drag in %2").arg(other).arg(source)));
    // Both panels now show the same camera: their silhouettes coincide.
    // (The grid may make them a pixel apart in size: compare each pixel of
    // one with the nearest of the other.)
    const render::Image a = view->Panel(0)->Snapshot(), b = view->Panel(1)->Snapshot();
    QVERIFY(std::abs(a.width - b.width) <= 1 && std::abs(a.height - b.height) <= 1);
    long differ = 0, covered = 0;
    for (int y = 0; y < a.height; ++y)
    {
      for (int x = 0; x < a.width; ++x)
      {
        const int bx = std::min(b.width - 1, x * b.width / a.width);
        const int by = std::min(b.height - 1, y * b.height / a.height);
        const bool ca = a.covered[static_cast<size_t>(y) * a.width + x];
        differ += ca != bool(b.covered[static_cast<size_t>(by) * b.width + bx]);
        covered += ca;
      }
    }
    QVERIFY(covered > 1000);
    QVERIFY2(differ < covered / 50, qPrintable(QString("silhouettes differ in %1 of %2 pixels")
                                                  .arg(differ).arg(covered)));
  }
}

void ExplorerGLTest::MaterialSliderRerendersOnePanel()
{
  auto window = Open("modes", render::Backend::GPU);
  widgets::ComparisonWidget* view = window->Comparison();
  QCOMPARE(view->PanelCount(), 6); // the five modes and an auto panel
  view->SetCurrentPanel(2);
  Settle();
  std::vector<int> before;
  for (int i = 0; i < view->PanelCount(); ++i)
  {
    before.push_back(view->Panel(i)->RenderCount());
  }
  const render::Image old = view->Panel(2)->Snapshot();
  // The user's way: one step of the shininess slider.
  auto* slider = window->Materials()->findChild<QSlider*>("shininess n");
  QVERIFY(slider);
  slider->setValue(slider->value() / 2);
  Settle();
  for (int i = 0; i < view->PanelCount(); ++i)
  {
    const int expected = before[i] + (i == 2 ? 1 : 0);
    QVERIFY2(view->Panel(i)->RenderCount() == expected,
      qPrintable(QString("panel %1: %2 renders, expected %3")
                   .arg(i)
                   .arg(view->Panel(i)->RenderCount())
                   .arg(expected)));
  }
  QVERIFY(view->Panel(2)->Spec().material.shininess < 20.0); // was 60
  // And the picture changed (a broader highlight).
  const render::Image now = view->Panel(2)->Snapshot();
  double change = 0;
  for (size_t i = 0; i < now.rgb.size(); ++i)
  {
    change += std::abs(now.rgb[i] - old.rgb[i]);
  }
  QVERIFY(change > 10.0);
  // kd + ks <= 1 is enforced as kd moves.
  QVERIFY(window->Materials()->SetParameter("kd", 0.95));
  const Material<double> m = view->Panel(2)->Spec().material;
  QVERIFY(m.kd + m.ks <= 1.0 + 1e-12);
  QCOMPARE(m.kd, 0.95);
}

void ExplorerGLTest::MaterialEditorShowsTheModelsParameters()
{
  // Each model declares the parameters it reads (ReflectanceModelRow::
  // parameters): the editor shows those and hides the rest, as Disney's
  // BRDF Explorer shows a BRDF's own parameters.
  widgets::MaterialEditor editor;
  auto shown = [&editor](const char* label) {
    auto* slider = editor.findChild<QSlider*>(label);
    return slider && slider->isVisibleTo(&editor);
  };
  Material<double> m;
  m.model = ReflectanceModel::Lambert;
  editor.SetMaterial(m);
  QVERIFY(shown("kd") && shown("albedo R") && shown("ambient"));
  QVERIFY(!shown("ks") && !shown("shininess n") && !shown("eta R") && !shown("m (lobe 1)"));
  m.model = ReflectanceModel::BlinnPhong;
  editor.SetMaterial(m);
  QVERIFY(shown("ks") && shown("shininess n") && shown("specular R"));
  QVERIFY(!shown("eta R") && !shown("k R") && !shown("m (lobe 1)"));
  m.model = ReflectanceModel::CookTorrance;
  m.lobeCount = 1;
  editor.SetMaterial(m);
  QVERIFY(shown("m (lobe 1)") && shown("eta R") && shown("k B") && shown("ks"));
  QVERIFY(!shown("shininess n") && !shown("specular R") && !shown("m (lobe 2)"));
  m.lobeCount = 2;
  m.lobes[0].weight = m.lobes[1].weight = 0.5;
  m.lobes[1].m = 0.5;
  editor.SetMaterial(m);
  QVERIFY(shown("m (lobe 2)") && shown("weight lobe 1"));
  // Fresnel per wavelength: the spectrum control (Cook-Torrance only)
  // fills the material's spectral samples, and the RGB eta and k, which F
  // no longer reads, are hidden; back to RGB shows them again.
  auto* spectrum = editor.findChildren<QComboBox*>().last();
  QVERIFY(spectrum->isVisibleTo(&editor));
  const int goldIndex = spectrum->findData(QString("gold"));
  QVERIFY(goldIndex > 0);
  int changed = 0;
  QObject::connect(&editor, &widgets::MaterialEditor::materialChanged,
    [&changed](const Material<double>&) { ++changed; });
  QMetaObject::invokeMethod(spectrum, "activated", Q_ARG(int, goldIndex));
  QCOMPARE(editor.GetMaterial().spectralCount, kSpectralSamples);
  QVERIFY(changed >= 1);
  QVERIFY(!shown("eta R") && !shown("k B") && shown("m (lobe 1)"));
  QMetaObject::invokeMethod(spectrum, "activated", Q_ARG(int, 0));
  QCOMPARE(editor.GetMaterial().spectralCount, 0);
  QVERIFY(shown("eta R") && shown("k B"));
  m.model = ReflectanceModel::LommelSeeliger;
  editor.SetMaterial(m);
  QVERIFY(shown("kd") && !shown("ks") && !shown("eta R") && !shown("m (lobe 2)"));
  QVERIFY(!spectrum->isVisibleTo(&editor));
}

void ExplorerGLTest::EveryScreenshotIsDrawn()
{
  for (const gui::SceneInfo& info : gui::SceneList())
  {
    auto window = Open(info.name, render::Backend::GPU);
    const QImage shot = window->grab().toImage();
    QVERIFY(shot.width() >= 1000);
    widgets::ComparisonWidget* view = window->Comparison();
    for (int i = 0; i < view->PanelCount(); ++i)
    {
      // Each panel drew its surface, lit: covered pixels that are not the
      // background (the full moon may be a single shade, and is).
      const render::Image image = view->Panel(i)->Snapshot();
      const Vec3<float> bg = view->View().background;
      long covered = 0, lit = 0;
      for (size_t p = 0; p < image.covered.size(); ++p)
      {
        if (image.covered[p])
        {
          ++covered;
          const float* c = &image.rgb[3 * p];
          lit += std::abs(c[0] - bg.x) + std::abs(c[1] - bg.y) + std::abs(c[2] - bg.z) >
            10 * kOne255;
        }
      }
      QVERIFY2(covered > 500 && lit > covered / 2,
        qPrintable(QString("%1 panel %2: %3 pixels covered, %4 unlike the background")
                     .arg(info.name)
                     .arg(i)
                     .arg(covered)
                     .arg(lit)));
      QVERIFY2(view->Panel(i)->Title().indexOf("error") < 0,
        qPrintable(view->Panel(i)->Title()));
    }
    if (std::string(info.name) == "brdf")
    {
      QVERIFY(window->PlotCsv().find("Cook-Torrance") != std::string::npos);
    }
    // The screenshot shows the panels: it is not one flat colour.
    std::set<QRgb> colours;
    for (int y = 0; y < shot.height(); y += 7)
    {
      for (int x = 0; x < shot.width(); x += 7)
      {
        colours.insert(shot.pixel(x, y));
      }
    }
    QVERIFY2(colours.size() > 50, info.name);
  }
}

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

void ExplorerGLTest::MoonProfiles()
{
  auto window = Open("moon", render::Backend::CPU);
  widgets::ComparisonWidget* view = window->Comparison();
  vtkCamera* camera = view->View().camera;
  const std::vector<widgets::Profile> profiles = view->Profiles();
  const render::Image image = view->Panel(0)->Snapshot();
  const double centre[3] = { 0, 0, 0 };
  double cx, cy;
  Project(camera, centre, image.width, image.height, cx, cy);
  // Parallel projection: the unit sphere's radius in pixels.
  const double radius = image.height / (2.0 * camera->GetParallelScale());
  const double kd = view->Panel(0)->Spec().material.kd;
  double worstLambert = 0, lo = 1e9, hi = -1e9;
  int checked = 0;
  for (size_t s = 0; s < profiles[0].intensity.size(); ++s)
  {
    const double r = std::hypot(profiles[0].pixelX[s] - cx, profiles[0].pixelY[s] - cy) / radius;
    if (r > 0.9 || !profiles[0].covered[s])
    {
      continue; // the limb: facets of the tessellation
    }
    // Light from the viewer: I = kd rho (N.L) with N.L = cos(theta) = sqrt(1 - r^2).
    worstLambert =
      std::max(worstLambert, std::abs(profiles[0].intensity[s] - kd * std::sqrt(1 - r * r)));
    lo = std::min(lo, profiles[1].intensity[s]);
    hi = std::max(hi, profiles[1].intensity[s]);
    ++checked;
  }
  QVERIFY(checked > 100);
  QVERIFY2(worstLambert <= kOne255,
    qPrintable(QString("Lambert off the cosine law by %1/255").arg(worstLambert * 255)));
  QVERIFY2(hi - lo <= kOne255,
    qPrintable(QString("Lommel-Seeliger disk varies by %1/255").arg((hi - lo) * 255)));
  QVERIFY(std::abs(lo - kd) < kOne255); // equal to Lambert's centre (eq. 1.12)
}

void ExplorerGLTest::MetalHighlightsKeepTheirColour()
{
  // The scene's dim light reaches the panels: the metals' highlights stay
  // below 1 in every channel (a clamped highlight is white, its Fresnel
  // colour lost), and gold's is yellower (more green per red) than copper's.
  auto window = Open("metal", render::Backend::CPU);
  widgets::ComparisonWidget* view = window->Comparison();
  QCOMPARE(view->PanelCount(), 4);
  double greenPerRed[2] = { 0, 0 };
  for (int p = 0; p < 2; ++p)
  {
    const render::Image image = view->Panel(p)->Snapshot();
    size_t brightest = 0;
    double best = -1;
    for (size_t i = 0; i < image.covered.size(); ++i)
    {
      const float* c = &image.rgb[3 * i];
      if (image.covered[i] && c[0] + c[1] + c[2] > best)
      {
        best = c[0] + c[1] + c[2];
        brightest = i;
      }
    }
    const float* c = &image.rgb[3 * brightest];
    QVERIFY2(c[0] < 1.0f && c[1] < 1.0f && c[2] < 1.0f && c[0] > 0.2f,
      qPrintable(QString("panel %1 highlight %2 %3 %4").arg(p).arg(c[0]).arg(c[1]).arg(c[2])));
    greenPerRed[p] = c[1] / c[0];
  }
  QVERIFY2(greenPerRed[0] > greenPerRed[1] + 0.05,
    qPrintable(QString("gold G/R %1, copper %2").arg(greenPerRed[0]).arg(greenPerRed[1])));
}

void ExplorerGLTest::DroppedMeshIsShown()
{
  // A file dropped on the window becomes the mesh of the scenes that show
  // the user's mesh (modes): every panel draws its 8-sided cylinder.
  auto window = Open("modes", render::Backend::CPU);
  const QString path = QString(SHADINGLAB_SOURCE_DIR) + "/datasets/cylinder_8.stl";
  QMimeData mime;
  mime.setUrls({ QUrl::fromLocalFile(path) });
  QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(window.get(), &enter);
  QVERIFY(enter.isAccepted());
  QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(window.get(), &drop);
  Settle();
  window->RefreshNow();
  widgets::ComparisonWidget* view = window->Comparison();
  QVERIFY(view->PanelCount() >= 2);
  for (int p = 0; p < view->PanelCount(); ++p)
  {
    const vtkIdType polys = view->Panel(p)->Spec().mesh->GetNumberOfPolys();
    // The STL's 8 side quads as 16 triangles and two 8-gon caps as 6 each.
    QVERIFY2(polys == 28, qPrintable(QString("panel %1 has %2 polygons").arg(p).arg(polys)));
    QVERIFY(view->Panel(p)->Snapshot().covered.size() > 0);
  }
}

void ExplorerGLTest::AutoPanelFollowsItsBudget()
{
  // An auto panel draws a cheap mode (flat or Gouraud: on this 576-triangle
  // torus their predicted costs are within a few percent) under a generous
  // budget and Phong under a tight one, pixel for pixel as the fixed panel
  // of that mode, on both backends; its title names the choice.
  for (render::Backend backend : { render::Backend::CPU, render::Backend::GPU })
  {
    auto window = Open("modes", backend);
    widgets::ComparisonWidget* view = window->Comparison();
    QCOMPARE(view->PanelCount(), 6);
    widgets::ShadingPanel* autoPanel = view->Panel(5);
    QVERIFY(autoPanel->Spec().mode == render::ShadingMode::Auto);
    const double budgets[2] = { 255.0, 0.01 };
    for (int k = 0; k < 2; ++k)
    {
      widgets::PanelSpec spec = autoPanel->Spec();
      spec.maxError = budgets[k];
      spec.material = view->Panel(2)->Spec().material;
      autoPanel->SetSpec(spec);
      Settle();
      const render::ShadingMode drawn = autoPanel->DrawnMode();
      const bool expected = k == 0 ? drawn != render::ShadingMode::Phong
                                   : drawn == render::ShadingMode::Phong;
      QVERIFY2(expected && drawn != render::ShadingMode::FastPhong,
        qPrintable(QString("%1, budget %2: drew %3")
                     .arg(render::BackendName(backend))
                     .arg(budgets[k])
                     .arg(render::ShadingModeName(drawn))));
      QVERIFY(autoPanel->Title().contains(QString("auto: ") + render::ShadingModeName(drawn)));
      // Panel 2 (Phong, in the auto panel's column: views of one size) set
      // to the drawn mode draws the same picture.
      widgets::ShadingPanel* fixed = view->Panel(2);
      widgets::PanelSpec same = fixed->Spec();
      same.mode = drawn;
      fixed->SetSpec(same);
      Settle();
      const render::Image a = autoPanel->Snapshot(), b = fixed->Snapshot();
      QCOMPARE(a.width, b.width);
      QCOMPARE(a.height, b.height);
      QVERIFY(a.rgb == b.rgb);
    }
  }
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

void ExplorerGLTest::LommelSeeligerOnGpuMatchesCpu()
{
  // The new model on both backends: the moon scene's middle panel.
  auto gpu = Open("moon", render::Backend::GPU);
  auto cpu = Open("moon", render::Backend::CPU);
  QCOMPARE(gpu->Comparison()->Panel(1)->Backend(), render::Backend::GPU);
  const widgets::Profile g = gpu->Comparison()->Profiles()[1];
  const widgets::Profile c = cpu->Comparison()->Profiles()[1];
  QCOMPARE(g.intensity.size(), c.intensity.size());
  int both = 0;
  for (size_t s = 0; s < g.intensity.size(); ++s)
  {
    if (g.covered[s] && c.covered[s])
    {
      ++both;
      QVERIFY2(std::abs(g.intensity[s] - c.intensity[s]) <= 1.5 * kOne255,
        qPrintable(QString("sample %1: GPU %2, CPU %3").arg(s).arg(g.intensity[s]).arg(c.intensity[s])));
    }
  }
  QVERIFY(both > 100);
}

int main(int argc, char** argv)
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  ExplorerGLTest test;
  return QTest::qExec(&test, argc, argv);
}


void ExplorerGLTest::UserMeshIsFramedWhateverItsPlaceAndSize()
{
  // The user's mesh far from the origin, tiny and huge: each scene that
  // shows it centres it, fills the panel as its own mesh does, and its
  // profile line crosses it (the plots show data).
  struct Placement
  {
    const char* what;
    double scale, offset[3];
  };
  const Placement placements[] = { { "far from the origin", 1.0, { 1000, -500, 2000 } },
    { "tiny", 1e-4, { 0.003, 0, 0 } }, { "huge", 1e4, { -3e4, 2e4, 0 } } };
  for (const Placement& placement : placements)
  {
    vtkSmartPointer<vtkPolyData> torus;
    torus.TakeReference(datasets::MakeTorus(1.0, 0.45, 48, 24));
    vtkNew<vtkTransform> transform;
    transform->Translate(placement.offset);
    transform->Scale(placement.scale, placement.scale, placement.scale);
    vtkNew<vtkTransformPolyDataFilter> move;
    move->SetInputData(torus);
    move->SetTransform(transform);
    move->Update();
    for (const char* scene : { "modes", "moon" })
    {
      auto window = Open(scene, render::Backend::CPU, move->GetOutput());
      widgets::ComparisonWidget* view = window->Comparison();
      const render::Image image = view->Panel(0)->Snapshot();
      int x0 = image.width, x1 = -1, y0 = image.height, y1 = -1;
      for (int y = 0; y < image.height; ++y)
      {
        for (int x = 0; x < image.width; ++x)
        {
          if (image.covered[static_cast<size_t>(y) * image.width + x])
          {
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
          }
        }
      }
      const QString where = QString("%1 in %2: covered x %3..%4, y %5..%6 of %7 x %8")
                              .arg(placement.what).arg(scene).arg(x0).arg(x1).arg(y0).arg(y1)
                              .arg(image.width).arg(image.height);
      QVERIFY2(x1 > x0 && y1 > y0, qPrintable(where));
      // Centred within a tenth of the panel, and filling at least half of
      // its smaller side.
      QVERIFY2(std::abs((x0 + x1) / 2.0 - image.width / 2.0) < 0.1 * image.width, qPrintable(where));
      QVERIFY2(std::abs((y0 + y1) / 2.0 - image.height / 2.0) < 0.1 * image.height, qPrintable(where));
      QVERIFY2(std::max(x1 - x0, y1 - y0) > 0.5 * std::min(image.width, image.height), qPrintable(where));
      const widgets::Profile profile = view->Profiles()[0];
      int covered = 0;
      for (uint8_t c : profile.covered)
      {
        covered += c;
      }
      QVERIFY2(covered > static_cast<int>(profile.covered.size()) / 5,
        qPrintable(where + QString(": the profile crosses %1 of %2 samples").arg(covered).arg(profile.covered.size())));
    }
  }
}

#include "ExplorerGLTest.moc"
#include "ScanlineInspector.h"
void ExplorerGLTest::ColourByDataOnBothBackends()
{
  // A user's torus with a point array (its height): coloured through
  // Cool to Warm on every panel, the GPU panel as the CPU panel, the legend
  // shown; an array the mesh lacks is one line and changes nothing.
  vtkSmartPointer<vtkPolyData> torus;
  torus.TakeReference(datasets::MakeTorus(1.0, 0.45, 48, 24));
  vtkNew<vtkFloatArray> height;
  height->SetName("Height");
  for (vtkIdType i = 0; i < torus->GetNumberOfPoints(); ++i)
  {
    height->InsertNextValue(static_cast<float>(torus->GetPoint(i)[1]));
  }
  torus->GetPointData()->AddArray(height);
  render::Image phong[2];
  for (const render::Backend backend : { render::Backend::CPU, render::Backend::GPU })
  {
    auto window = Open("modes", backend, torus);
    QVERIFY(!window->ApplyColorBy("POINTS:Pressure").empty());
    QVERIFY(window->Comparison()->View().colorBy.empty());
    QVERIFY2(window->ApplyColorBy("POINTS:Height").empty(), "colour by Height");
    window->RefreshNow();
    widgets::ComparisonWidget* view = window->Comparison();
    QCOMPARE(view->View().colorMap.label, std::string("Cool to Warm"));
    QVERIFY(std::abs(view->View().colorMap.rangeMax - 1.45) < 1e-3);
    const render::Image image = view->Panel(2)->Snapshot(); // Phong
    double spread = 0;
    int covered = 0;
    for (size_t p = 0; p < image.covered.size(); ++p)
    {
      if (image.covered[p])
      {
        spread += std::abs(image.rgb[3 * p] - image.rgb[3 * p + 2]);
        ++covered;
      }
    }
    QVERIFY2(covered > 1000 && spread / covered > 0.08,
      qPrintable(QString("mean |R - B| %1 over %2 pixels").arg(spread / std::max(covered, 1)).arg(covered)));
    phong[backend == render::Backend::GPU] = image;
    auto* legend = window->findChild<widgets::ColorLegend*>();
    QVERIFY(legend && legend->isVisible());
  }
  // The two backends' Phong panels: the same colours (display values).
  const render::Image& a = phong[0];
  const render::Image& b = phong[1];
  QCOMPARE(a.width, b.width);
  double sum = 0;
  int both = 0;
  for (size_t p = 0; p < a.covered.size(); ++p)
  {
    if (a.covered[p] && b.covered[p])
    {
      for (int c = 0; c < 3; ++c)
      {
        sum += std::abs(a.rgb[3 * p + c] - b.rgb[3 * p + c]);
      }
      ++both;
    }
  }
  const double mean255 = 255.0 * sum / (3.0 * std::max(both, 1));
  QVERIFY2(both > 1000 && mean255 < 1.5, qPrintable(QString("GPU vs CPU mean %1/255 over %2 pixels").arg(mean255).arg(both)));
}



namespace
{

/// The study's series `name` from the plot's CSV (x, y pairs).
std::vector<std::pair<double, double>> StudySeries(const std::string& csv, const std::string& name)
{
  std::vector<std::pair<double, double>> out;
  std::istringstream in(csv);
  std::string line;
  const std::string prefix = "\"" + name + "\",";
  while (std::getline(in, line))
  {
    if (line.rfind(prefix, 0) == 0)
    {
      const size_t a = prefix.size(), b = line.find(',', a);
      out.emplace_back(std::stod(line.substr(a, b - a)), std::stod(line.substr(b + 1)));
    }
  }
  return out;
}

/// The sample standard deviation of a profile's covered samples.
double CoveredSpread(const widgets::Profile& p)
{
  double sum = 0, sum2 = 0;
  int n = 0;
  for (size_t s = 0; s < p.intensity.size(); ++s)
  {
    if (p.covered[s])
    {
      sum += p.intensity[s];
      sum2 += p.intensity[s] * p.intensity[s];
      ++n;
    }
  }
  return n > 1 ? std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1))) : 0.0;
}

} // namespace

// The lecture's three conditions: flat shading's error on the cube (a
// polyhedron) falls as light and viewer recede and is zero for a
// directional light and a parallel view; the sphere's (not a polyhedron)
// stays above 10/255 at every distance.
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
    QVERIFY2(y > 10.0, qPrintable(QString("%1: %2").arg(x).arg(y)));
  }
  // The heat maps show it too: the cube's error panel is not blank near.
  QCOMPARE(window->Comparison()->PanelCount(), 6);
}

namespace
{
/// Mean luminance of a panel's covered pixels (display values).
double MeanLuminance(const render::Image& image)
{
  double sum = 0;
  long n = 0;
  for (size_t p = 0; p < image.covered.size(); ++p)
  {
    if (image.covered[p])
    {
      sum += render::Luminance(Vec3<double>(image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]));
      ++n;
    }
  }
  return n ? sum / n : 0.0;
}
} // namespace

// The glass's highlight, near Brewster's angle and s-polarized (vertical in
// the image), passes a polarizer at 90 degrees and is removed by the crossed
// one at 0; the plot's DoLP peaks at 1 at its marker, Brewster's angle.
void ExplorerGLTest::PolarizationSceneShowsBrewster()
{
  auto window = Open("polarization", render::Backend::CPU);
  widgets::ComparisonWidget* view = window->Comparison();
  QCOMPARE(view->PanelCount(), 5);
  // --polarizer 0 by default: panel 2 at 0 degrees, panel 3 crossed (90).
  const double none = MeanLuminance(view->Panel(0)->Snapshot());
  const double at0 = MeanLuminance(view->Panel(1)->Snapshot());
  const double at90 = MeanLuminance(view->Panel(2)->Snapshot());
  QVERIFY2(at90 > 1.5 * at0, qPrintable(QString("%1 vs %2").arg(at90).arg(at0)));
  QVERIFY(none > at90 && none > at0);
  // The DoLP panel: what a polarization camera measures. Its most
  // polarized pixels are the highlight's, s-polarized: vertical (AoP +-90).
  auto* dolpPanel = dynamic_cast<widgets::CpuPanel*>(view->Panel(4));
  QVERIFY(dolpPanel);
  auto dolpSummary = [](const render::StokesImage& stokes) {
    double peak = 0.0, peakAop = 0.0;
    for (size_t p = 0; p < stokes.dolp.size(); ++p)
    {
      if (!std::isnan(stokes.dolp[p]) && stokes.dolp[p] > peak)
      {
        peak = stokes.dolp[p];
        peakAop = stokes.aop[p];
      }
    }
    return std::make_pair(peak, peakAop);
  };
  const auto [dolpPeak, peakAop] = dolpSummary(dolpPanel->LastStokes());
  QVERIFY2(dolpPeak > 0.4 && dolpPeak <= 1.0 && std::abs(std::abs(peakAop) - 90.0) < 15.0,
    qPrintable(QString("DoLP %1 at AoP %2").arg(dolpPeak).arg(peakAop)));
  // A polarizer in front of the light along the image's x axis: the light
  // meets the highlight's facets p-polarized near Brewster's angle, where
  // glass hardly reflects it: the highlight fades in every panel, and the
  // DoLP panel measures another light: its most polarized pixels are where
  // facets tilted out of the horizontal plane reflect the light's s part
  // (their polarization tilted too, no longer vertical).
  auto* lightPolarizer = window->findChild<QDoubleSpinBox*>("lightPolarizer");
  QVERIFY(lightPolarizer);
  lightPolarizer->setValue(0.0);
  emit lightPolarizer->editingFinished();
  Settle();
  window->RefreshNow();
  const double polarizedLight = MeanLuminance(view->Panel(0)->Snapshot());
  QVERIFY2(polarizedLight < 0.75 * none,
    qPrintable(QString("%1 vs %2").arg(polarizedLight).arg(none)));
  // The scene was rebuilt with new panels: the DoLP panel is another one.
  dolpPanel = dynamic_cast<widgets::CpuPanel*>(view->Panel(4));
  QVERIFY(dolpPanel);
  const auto [peakP, peakAopP] = dolpSummary(dolpPanel->LastStokes());
  QVERIFY2(std::abs(std::abs(peakAopP) - 90.0) > 20.0 && std::abs(peakP - dolpPeak) > 0.02,
    qPrintable(QString("DoLP %1 at AoP %2").arg(peakP).arg(peakAopP)));
  const std::string csv = window->PlotCsv();
  const auto dolp = StudySeries(csv, "glass DoLP");
  QVERIFY2(dolp.size() == 90, csv.c_str());
  auto peak = std::max_element(dolp.begin(), dolp.end(),
    [](const auto& a, const auto& b) { return a.second < b.second; });
  QVERIFY2(std::abs(peak->first - 57.0) <= 1.0 && peak->second > 0.999,
    qPrintable(QString("%1: %2").arg(peak->first).arg(peak->second)));
}

// Gold with three RGB samples against its spectrum: a visible colour
// difference (the heat map's CIEDE2000 well above 1 where the highlight is).
void ExplorerGLTest::SpectralSceneShowsTheColourDifference()
{
  auto window = Open("spectral", render::Backend::CPU);
  widgets::ComparisonWidget* view = window->Comparison();
  QCOMPARE(view->PanelCount(), 5);
  const render::Image rgb = view->Panel(0)->Snapshot(), spectral = view->Panel(1)->Snapshot();
  double worst = 0;
  for (size_t p = 0; p < rgb.covered.size(); ++p)
  {
    if (rgb.covered[p] && spectral.covered[p])
    {
      worst = std::max(worst,
        DeltaE2000(Vec3<double>(rgb.rgb[3 * p], rgb.rgb[3 * p + 1], rgb.rgb[3 * p + 2]),
          Vec3<double>(spectral.rgb[3 * p], spectral.rgb[3 * p + 1], spectral.rgb[3 * p + 2])));
    }
  }
  QVERIFY2(worst > 2.0, qPrintable(QString::number(worst)));
  const auto n = StudySeries(window->PlotCsv(), "gold n");
  QCOMPARE(static_cast<int>(n.size()), 81);
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
