// SPDX-License-Identifier: BSD-3-Clause
// The explorer's material scenes: the Moon, metals, Lommel-Seeliger on
// both backends, polarization and spectral Fresnel.
#include "ExplorerGLTest.h"
#include "ExplorerTestUtil.h"
#include "MeshIO.h"
#include "BrdfPlot.h"
#include "AnalyticMeshes.h"
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <QComboBox>

#include <QApplication>
#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QWheelEvent>
#include <QtTest/QtTest>

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

// The mouse wheel over the Controls dock scrolls the dock; a slider under
// the pointer changes only once it has the focus (issue: scrolling changed
// whatever passed under the pointer).
void ExplorerGLTest::WheelChangesAControlOnlyWithItsFocus()
{
  auto window = Open("modes", render::Backend::CPU);
  window->resize(1280, 720); // the dock must scroll
  Settle();
  auto* slider = window->Materials()->findChild<QSlider*>("shininess n");
  QVERIFY(slider);
  auto* scroll = qobject_cast<QScrollArea*>(window->findChild<QDockWidget*>()->widget());
  const auto docks = window->findChildren<QDockWidget*>();
  for (QDockWidget* dock : docks)
  {
    if (dock->windowTitle() == "Controls")
    {
      scroll = qobject_cast<QScrollArea*>(dock->widget());
    }
  }
  QVERIFY(scroll && scroll->verticalScrollBar()->maximum() > 0);
  slider->clearFocus();
  window->setFocus();
  Settle();
  const int before = slider->value();
  const int scrolled = scroll->verticalScrollBar()->value();
  auto wheel = [&](QWidget* target) {
    const QPoint at(target->width() / 2, target->height() / 2);
    QWheelEvent event(QPointF(at), QPointF(target->mapToGlobal(at)), QPoint(), QPoint(0, -120),
      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(target, &event);
    Settle();
  };
  wheel(slider);
  QCOMPARE(slider->value(), before);
  QVERIFY2(scroll->verticalScrollBar()->value() > scrolled,
    qPrintable(QString("dock at %1, was %2").arg(scroll->verticalScrollBar()->value()).arg(scrolled)));
  window->activateWindow();
  QVERIFY(QTest::qWaitForWindowActive(window.get()));
  slider->setFocus();
  Settle();
  QVERIFY(slider->hasFocus());
  wheel(slider);
  QVERIFY(slider->value() != before);
}

// One control never resets another: changing a scene's own option (the
// polarizer) rebuilds the scene but keeps the light and the camera the user
// set; a scene without panels leaves no panel controls of the previous one;
// File > Open lists every format the reader takes; the docks fold away and
// leave the panels most of a 1280 x 720 window.
void ExplorerGLTest::ControlsKeepEachOtherAndFold()
{
  auto window = Open("polarization", render::Backend::CPU);
  window->resize(1280, 720);
  Settle();
  auto* azimuth = window->findChild<QSlider*>("lightAzimuth");
  QVERIFY(azimuth);
  azimuth->setValue(37);
  Settle();
  window->Comparison()->View().camera->Azimuth(20);
  const double* moved = window->Comparison()->View().camera->GetPosition();
  const double movedX = moved[0];
  auto* polarizer = window->findChild<QDoubleSpinBox*>("polarizer");
  QVERIFY(polarizer);
  polarizer->setValue(45);
  emit polarizer->editingFinished();
  Settle();
  QCOMPARE(window->Comparison()->View().lightAzimuth, 37.0);
  QCOMPARE(azimuth->value(), 37);
  QVERIFY(std::abs(window->Comparison()->View().camera->GetPosition()[0] - movedX) < 1e-6);

  std::string error;
  QVERIFY(window->LoadScene("scanline", error));
  Settle();
  QVERIFY(!window->Materials()->isEnabled());
  QVERIFY(window->LoadScene("modes", error));
  Settle();
  QVERIFY(window->Materials()->isEnabled());

  const QString filter = gui::MainWindow::MeshFileFilter();
  for (const std::string& ext : ReadableExtensions())
  {
    QVERIFY2(filter.contains(QString("*.%1 ").arg(QString::fromStdString(ext))) ||
        filter.contains(QString("*.%1)").arg(QString::fromStdString(ext))),
      qPrintable(filter + " lacks " + QString::fromStdString(ext)));
  }

  window->resize(1280, 720);
  Settle();
  const int panels = window->Comparison()->width();
  QVERIFY2(panels >= 700, qPrintable(QString("panels get %1 px of 1280").arg(panels)));
  QDockWidget* controls = nullptr;
  for (QDockWidget* dock : window->findChildren<QDockWidget*>())
  {
    controls = dock->windowTitle() == "Controls" ? dock : controls;
  }
  QVERIFY(controls);
  controls->toggleViewAction()->trigger();
  Settle();
  QVERIFY(!controls->isVisible());
  QVERIFY(window->Comparison()->width() > panels + 200);
}

// The brdf scene shows every lobe at a glance: by default each lobe is
// drawn to its own peak (the legend gives it); on one linear axis the
// microfacet lobes shrink to a fraction of Phong's, which the log scale
// brings back within the axis' decades.
void ExplorerGLTest::BrdfPlotShowsEveryLobe()
{
  auto window = Open("brdf", render::Backend::CPU);
  auto* plot = window->findChild<widgets::BrdfPlot*>();
  QVERIFY(plot);
  QCOMPARE(plot->GetScale(), widgets::BrdfScale::PerLobe);
  QVERIFY(plot->DrawnPeaks().size() >= 4);
  for (double peak : plot->DrawnPeaks())
  {
    QVERIFY2(std::abs(peak - 1.0) < 1e-9, qPrintable(QString::number(peak)));
  }
  plot->SetScale(widgets::BrdfScale::Absolute);
  const auto absolute = plot->DrawnPeaks();
  const double smallest = *std::min_element(absolute.begin(), absolute.end());
  QVERIFY2(smallest < 0.1 * plot->RadialMax(),
    qPrintable(QString("%1 of %2: the problem the default solves").arg(smallest).arg(plot->RadialMax())));
  plot->SetScale(widgets::BrdfScale::Log);
  for (double peak : plot->DrawnPeaks())
  {
    QVERIFY2(peak > 0.5 * plot->RadialMax(), qPrintable(QString("%1 of %2").arg(peak).arg(plot->RadialMax())));
  }
}

// The spectral scene's CIEDE2000 map is computed from float frames: the
// same picture whether the panel it compares with is drawn by OpenGL (an
// 8-bit framebuffer, whose steps made speckle and rings) or by the CPU.
void ExplorerGLTest::SpectralErrorMapIsFromFloatFrames()
{
  auto heat = [](render::Backend backend, QImage& picture, bool& ok) {
    auto window = Open("spectral", backend);
    window->resize(1280, 720);
    Settle();
    window->RefreshNow();
    widgets::ShadingPanel* panel = window->Comparison()->Panel(2);
    ok = panel->Spec().errorReference >= 0 && window->Comparison()->Panel(0)->Backend() == backend;
    picture = panel->grab().toImage();
  };
  QImage fromGpu, fromCpu;
  bool gpuOk = false, cpuOk = false;
  heat(render::Backend::GPU, fromGpu, gpuOk);
  heat(render::Backend::CPU, fromCpu, cpuOk);
  QVERIFY2(gpuOk && cpuOk, "panel 3 is the error map of panel 1, drawn on each backend");
  QVERIFY(!fromGpu.isNull() && fromGpu.size() == fromCpu.size());
  int differing = 0, lit = 0;
  for (int y = 0; y < fromGpu.height(); ++y)
  {
    for (int x = 0; x < fromGpu.width(); ++x)
    {
      differing += fromGpu.pixel(x, y) != fromCpu.pixel(x, y);
      lit += qRed(fromCpu.pixel(x, y)) > 120;
    }
  }
  QVERIFY2(lit > 500, qPrintable(QString("%1 bright pixels in the map").arg(lit)));
  QCOMPARE(differing, 0);
}

// The Colour by data box's Highlights: Auto (the default) keeps a surface
// coloured by data true to its map; On adds the highlights back, on both
// backends alike.
void ExplorerGLTest::HighlightsOnDataFollowTheirControl()
{
  const vtkSmartPointer<vtkPolyData> torus = TorusWithHeight();
  for (const render::Backend backend : { render::Backend::CPU, render::Backend::GPU })
  {
    auto window = Open("modes", backend, torus);
    QVERIFY(window->ApplyColorBy("POINTS:Height").empty());
    window->RefreshNow();
    const render::Image plain = window->Comparison()->Panel(2)->Snapshot(); // Phong
    auto* box = window->findChild<QComboBox*>("highlights");
    QVERIFY(box);
    QCOMPARE(box->currentText(), QString("Auto"));
    box->setCurrentIndex(box->findText("On"));
    emit box->activated(box->currentIndex());
    window->RefreshNow();
    const render::Image shiny = window->Comparison()->Panel(2)->Snapshot();
    int whiter = 0;
    for (size_t p = 0; p < plain.covered.size(); ++p)
    {
      if (plain.covered[p] && shiny.covered[p])
      {
        const float gain = (shiny.rgb[3 * p] + shiny.rgb[3 * p + 1] + shiny.rgb[3 * p + 2]) -
          (plain.rgb[3 * p] + plain.rgb[3 * p + 1] + plain.rgb[3 * p + 2]);
        whiter += gain > 0.15f;
      }
    }
    QVERIFY2(whiter > 50, qPrintable(QString("%1 pixels brighter with highlights on (%2)")
                                       .arg(whiter)
                                       .arg(backend == render::Backend::GPU ? "GPU" : "CPU")));
  }
}
