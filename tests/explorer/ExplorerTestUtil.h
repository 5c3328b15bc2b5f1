// SPDX-License-Identifier: BSD-3-Clause
// What the explorer's tests share: the includes, opening a window on a
// scene, projecting a world point, dragging, finding a panel's view.
#pragma once

#include "AnalyticMeshes.h"
#include "BrdfPlot.h"
#include "ColorLegend.h"
#include "ComparisonWidget.h"
#include "CpuPanel.h"
#include "MainWindow.h"
#include "MaterialEditor.h"
#include "shadinglab/model/Materials.h"
#include "shadinglab/model/Spectrum.h"
#include "ScanlineInspector.h"
#include "ShadingPanel.h"
#include <vtkNew.h>

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
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace shadinglab;

namespace shadinglab::explorertest
{

/// One step of 8-bit display: the tolerance the issue states for profiles.
inline constexpr double kOne255 = 1.0 / 255.0;

/// A user's torus (R 1, r 0.45, 48 x 24) with a point array "Height" (y).
inline vtkSmartPointer<vtkPolyData> TorusWithHeight()
{
  vtkSmartPointer<vtkPolyData> torus;
  torus.TakeReference(datasets::MakeTorus(1.0, 0.45, 48, 24));
  vtkNew<vtkFloatArray> height;
  height->SetName("Height");
  for (vtkIdType i = 0; i < torus->GetNumberOfPoints(); ++i)
  {
    height->InsertNextValue(static_cast<float>(torus->GetPoint(i)[1]));
  }
  torus->GetPointData()->AddArray(height);
  return torus;
}

/// Lets Qt show new widgets and deliver queued events.
inline void Settle(int passes = 5)
{
  for (int i = 0; i < passes; ++i)
  {
    QApplication::processEvents();
  }
}

/// A window on scene `name` with all panels on `backend` (and the user's
/// mesh `input`, when given), drawn.
inline std::unique_ptr<gui::MainWindow> Open(
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
inline void Project(vtkCamera* camera, const double p[3], int w, int h, double& x, double& y)
{
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(
    static_cast<double>(w) / h, -1, 1);
  double in[4] = { p[0], p[1], p[2], 1.0 }, out[4];
  m->MultiplyPoint(in, out);
  x = (out[0] / out[3] + 1.0) * 0.5 * w;
  y = (1.0 - out[1] / out[3]) * 0.5 * h;
}

inline void SendDrag(QWidget* target, QPoint from, QPoint to, Qt::MouseButton button)
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
inline QWidget* ViewOf(widgets::ShadingPanel* panel)
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

/// Mean luminance of a panel's covered pixels (display values).
inline double MeanLuminance(const render::Image& image)
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

/// The study's series `name` from the plot's CSV (x, y pairs).
inline std::vector<std::pair<double, double>> StudySeries(const std::string& csv, const std::string& name)
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
inline double CoveredSpread(const widgets::Profile& p)
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

} // namespace shadinglab::explorertest

using namespace shadinglab::explorertest;
