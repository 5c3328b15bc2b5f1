// SPDX-License-Identifier: BSD-3-Clause
// The explorer window under Xvfb: the shared camera, re-rendering only
// what changed, every scene drawn, user meshes, colour by data, auto panels.
#include "ExplorerGLTest.h"
#include "ExplorerTestUtil.h"

#include <QLayout>

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
  // A hidden parameter leaves no gap: kd's row is followed by albedo R's at
  // the pitch of albedo R to G (Qt 5's QFormLayout kept hidden rows' height).
  editor.resize(editor.sizeHint());
  editor.layout()->activate();
  auto top = [&editor](const char* label) {
    return editor.findChild<QSlider*>(label)->parentWidget()->geometry().top();
  };
  const int pitch = top("albedo G") - top("albedo R");
  QVERIFY(pitch > 0);
  QCOMPARE(top("albedo R") - top("kd"), pitch);
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
  // The preset box names the preset a material is ("(custom)" when it is
  // none): a scene's gold, spectral or not, says "gold"; an edit makes it
  // custom, and editing it back makes it gold again.
  auto* preset = editor.findChildren<QComboBox*>().first();
  QCOMPARE(preset->currentText(), QString("(custom)"));
  Material<double> gold = FindMaterialPreset("gold")->material;
  editor.SetMaterial(gold);
  QCOMPARE(preset->currentText(), QString("gold"));
  QVERIFY(SetSpectral(gold, *PresetDispersion("gold")).empty());
  editor.SetMaterial(gold);
  QCOMPARE(preset->currentText(), QString("gold"));
  const double m1 = gold.lobes[0].m;
  QVERIFY(editor.SetParameter("m (lobe 1)", 0.5));
  QCOMPARE(preset->currentText(), QString("(custom)"));
  QVERIFY(editor.SetParameter("m (lobe 1)", m1));
  QCOMPARE(preset->currentText(), QString("gold"));
  QMetaObject::invokeMethod(preset, "activated", Q_ARG(int, preset->findText("copper")));
  QCOMPARE(preset->currentText(), QString("copper"));
  QCOMPARE(editor.GetMaterial().k.x, FindMaterialPreset("copper")->material.k.x);
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
      long covered = 0, lit = 0, white = 0;
      for (size_t p = 0; p < image.covered.size(); ++p)
      {
        if (image.covered[p])
        {
          ++covered;
          const float* c = &image.rgb[3 * p];
          lit += std::abs(c[0] - bg.x) + std::abs(c[1] - bg.y) + std::abs(c[2] - bg.z) >
            10 * kOne255;
          white += std::max({ c[0], c[1], c[2] }) >= 1.0f - 0.5f * kOne255;
        }
      }
      // The lecture's scenes plot I itself (clamped to [0, 1]): no shaded
      // pixel saturates, or a highlight's shape is cut off flat (false
      // colour, the heat maps and the DoLP image, is exempt).
      const widgets::PanelSpec& spec = view->Panel(i)->Spec();
      if (spec.errorReference < 0 && !spec.dolpImage)
      {
        QVERIFY2(white == 0,
          qPrintable(QString("%1 panel %2: %3 of %4 covered pixels saturated")
                       .arg(info.name)
                       .arg(i)
                       .arg(white)
                       .arg(covered)));
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

void ExplorerGLTest::ColourByDataOnBothBackends()
{
  // A user's torus with a point array (its height): coloured through
  // Cool to Warm on every panel, the GPU panel as the CPU panel, the legend
  // shown; an array the mesh lacks is one line and changes nothing.
  const vtkSmartPointer<vtkPolyData> torus = TorusWithHeight();
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

int main(int argc, char** argv)
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  ExplorerGLTest test;
  return QTest::qExec(&test, argc, argv);
}
