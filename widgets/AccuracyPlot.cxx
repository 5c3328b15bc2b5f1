// SPDX-License-Identifier: BSD-3-Clause
#include "AccuracyPlot.h"

#include "ChartStyle.h"
#include "ComparisonWidget.h" // PanelColor

#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QLogValueAxis>
#include <QtCharts/QValueAxis>
#include <QtCharts/QScatterSeries>

#include <QApplication>
#include <QGridLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>

using namespace QtCharts;

namespace shadinglab::widgets
{

namespace
{

/// Errors are drawn no lower than this (1/255): an exact match would be
/// -infinity on a log axis, and 1e-3 / 255 is below anything visible.
constexpr double kErrorFloor = 1e-3;

QChartView* MakeChart(const std::string& group, const std::vector<AccuracyPoint>& points)
{
  auto* chart = new QChart;
  StyleChart(chart, QString::fromStdString(group));
  auto* x = new QLogValueAxis;
  x->setTitleText("frame time (ms, log)");
  x->setLabelFormat("%g");
  x->setBase(10);
  x->setMinorTickCount(8); // 2..9 between decades: a log axis one can read
  auto* y = new QLogValueAxis;
  y->setTitleText("mean error (1/255, log)");
  y->setLabelFormat("%g");
  y->setBase(10);
  y->setMinorTickCount(8);
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  std::map<std::string, QScatterSeries*> series;
  const char* order[] = { "flat", "gouraud", "phong", "fast-phong" };
  double xlo = 1e300, xhi = 0, ylo = 1e300, yhi = 0;
  for (int i = 0; i < 4; ++i)
  {
    auto* s = new QScatterSeries;
    s->setName(order[i]);
    s->setColor(PanelColor(i));
    s->setBorderColor(PanelColor(i));
    s->setMarkerSize(7);
    series[order[i]] = s;
  }
  std::vector<const AccuracyPoint*> front;
  for (const AccuracyPoint& p : points)
  {
    const double e = std::max(p.error, kErrorFloor);
    auto it = series.find(p.mode);
    if (it != series.end())
    {
      it->second->append(p.milliseconds, e);
    }
    xlo = std::min(xlo, p.milliseconds);
    xhi = std::max(xhi, p.milliseconds);
    ylo = std::min(ylo, e);
    yhi = std::max(yhi, e);
    if (p.pareto)
    {
      front.push_back(&p);
    }
  }
  for (const char* name : order)
  {
    chart->addSeries(series[name]);
    series[name]->attachAxis(x);
    series[name]->attachAxis(y);
  }
  std::sort(front.begin(), front.end(),
    [](const AccuracyPoint* a, const AccuracyPoint* b) { return a->milliseconds < b->milliseconds; });
  auto* line = new QLineSeries;
  line->setName("Pareto front");
  line->setPen(QPen(Qt::black, 1.5, Qt::DashLine));
  for (const AccuracyPoint* p : front)
  {
    line->append(p->milliseconds, std::max(p->error, kErrorFloor));
  }
  chart->addSeries(line);
  line->attachAxis(x);
  line->attachAxis(y);
  if (xlo <= xhi)
  {
    x->setRange(std::pow(10.0, std::floor(std::log10(xlo))), std::pow(10.0, std::ceil(std::log10(xhi))));
    y->setRange(std::pow(10.0, std::floor(std::log10(ylo))), std::pow(10.0, std::ceil(std::log10(yhi))));
  }
  auto* view = new QChartView(chart);
  view->setRenderHint(QPainter::Antialiasing);
  return view;
}

} // namespace

namespace
{

/// A QApplication for the plot's lifetime when none exists (Qt's offscreen
/// platform without DISPLAY); nullptr when one does.
std::unique_ptr<QApplication> EnsureApplication()
{
  static int argc = 1;
  static char name[] = "shadinglab";
  static char* argv[] = { name, nullptr };
  if (QApplication::instance())
  {
    return nullptr;
  }
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    setenv("QT_QPA_PLATFORM", "offscreen", 1); // no X: Qt's raster, no window
  }
  return std::make_unique<QApplication>(argc, argv);
}

/// The charts under a bold title, `columns` a row, grabbed to a PNG.
std::string WritePage(const std::string& title, const std::vector<QChartView*>& charts,
  int columns, const std::string& path)
{
  QWidget page;
  page.setStyleSheet("background: white;");
  auto* layout = new QVBoxLayout(&page);
  auto* heading = new QLabel(QString::fromStdString(title));
  QFont font = heading->font();
  font.setPointSize(12);
  font.setBold(true);
  heading->setFont(font);
  heading->setAlignment(Qt::AlignCenter);
  layout->addWidget(heading);
  auto* grid = new QGridLayout;
  layout->addLayout(grid, 1);
  for (size_t i = 0; i < charts.size(); ++i)
  {
    grid->addWidget(charts[i], static_cast<int>(i) / columns, static_cast<int>(i) % columns);
  }
  const int rows = static_cast<int>((charts.size() + columns - 1) / columns);
  page.resize(columns * 700, 60 + rows * 480);
  page.ensurePolished();
  page.layout()->activate();
  if (!page.grab().save(QString::fromStdString(path)))
  {
    return "cannot write " + path;
  }
  return "";
}

QLogValueAxis* LogAxis(const std::string& title)
{
  auto* axis = new QLogValueAxis;
  axis->setTitleText(QString::fromStdString(title));
  axis->setLabelFormat("%g");
  axis->setBase(10);
  axis->setMinorTickCount(8);
  return axis;
}

/// Values are drawn no lower than this fraction of the panel's largest:
/// an exact zero would be -infinity on a log axis.
constexpr double kLogFloorFraction = 1e-16;

QChartView* MakeLogLogChart(const LogLogPanel& panel)
{
  auto* chart = new QChart;
  StyleChart(chart, QString::fromStdString(panel.title));
  QAbstractAxis* x = nullptr;
  QAbstractAxis* y = nullptr;
  if (panel.linear)
  {
    auto* lx = new QValueAxis;
    auto* ly = new QValueAxis;
    lx->setTitleText(QString::fromStdString(panel.xTitle));
    ly->setTitleText(QString::fromStdString(panel.yTitle));
    lx->setLabelFormat("%g");
    ly->setLabelFormat("%g");
    x = lx;
    y = ly;
  }
  else
  {
    x = LogAxis(panel.xTitle);
    y = LogAxis(panel.yTitle);
  }
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  double xlo = 1e300, xhi = 0, yhi = std::max(0.0, panel.referenceY);
  for (const LogLogLine& line : panel.lines)
  {
    for (size_t i = 0; i < line.x.size(); ++i)
    {
      xlo = std::min(xlo, line.x[i]);
      xhi = std::max(xhi, line.x[i]);
      yhi = std::max(yhi, line.y[i]);
    }
  }
  const double floor = panel.linear ? 0.0 : yhi * kLogFloorFraction;
  double ylo = yhi;
  auto add = [&](QLineSeries* series)
  {
    chart->addSeries(series);
    series->attachAxis(x);
    series->attachAxis(y);
  };
  for (const LogLogLine& line : panel.lines)
  {
    auto* series = new QLineSeries;
    series->setName(QString::fromStdString(line.name));
    series->setPen(QPen(PanelColor(line.color), 2, line.dashed ? Qt::DashLine : Qt::SolidLine));
    series->setPointsVisible(!line.dashed);
    for (size_t i = 0; i < line.x.size() && i < line.y.size(); ++i)
    {
      const double v = std::max(line.y[i], floor);
      ylo = std::min(ylo, v);
      series->append(line.x[i], v);
    }
    add(series);
  }
  if (panel.referenceY > 0 && xlo <= xhi)
  {
    auto* series = new QLineSeries;
    series->setName(QString::fromStdString(panel.referenceName));
    series->setPen(QPen(Qt::black, 1.5, Qt::DotLine));
    series->append(xlo, panel.referenceY);
    series->append(xhi, panel.referenceY);
    add(series);
  }
  if (panel.linear && xlo <= xhi)
  {
    x->setRange(xlo, xhi);
    y->setRange(0.0, yhi > 0 ? 1.1 * yhi : 1.0);
    static_cast<QValueAxis*>(x)->applyNiceNumbers();
    static_cast<QValueAxis*>(y)->applyNiceNumbers();
  }
  else if (xlo <= xhi && ylo > 0)
  {
    x->setRange(xlo, xhi);
    y->setRange(std::pow(10.0, std::floor(std::log10(ylo))), std::pow(10.0, std::ceil(std::log10(yhi))));
  }
  chart->legend()->setAlignment(Qt::AlignRight); // long names: a column beside the plot
  auto* view = new QChartView(chart);
  view->setRenderHint(QPainter::Antialiasing);
  return view;
}

} // namespace

std::string WriteLogLogPlot(const std::vector<LogLogPanel>& panels, const std::string& title,
  const std::string& path, int columns)
{
  const std::unique_ptr<QApplication> app = EnsureApplication();
  std::vector<QChartView*> charts;
  for (const LogLogPanel& panel : panels)
  {
    charts.push_back(MakeLogLogChart(panel));
  }
  return WritePage(title, charts, columns, path);
}

std::string WriteAccuracyPlot(const std::vector<std::string>& groups,
  const std::vector<std::vector<AccuracyPoint>>& points, const std::string& title,
  const std::string& path)
{
  const std::unique_ptr<QApplication> app = EnsureApplication();
  std::vector<QChartView*> charts;
  for (size_t i = 0; i < groups.size() && i < points.size(); ++i)
  {
    charts.push_back(MakeChart(groups[i], points[i]));
  }
  return WritePage(title, charts, groups.size() > 1 ? 2 : 1, path);
}

} // namespace shadinglab::widgets
