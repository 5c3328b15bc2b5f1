// SPDX-License-Identifier: BSD-3-Clause
#include "ParameterPlot.h"

#include "ChartStyle.h"

#include <QtCharts/QBarCategoryAxis>
#include <QtCharts/QBarSeries>
#include <QtCharts/QBarSet>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QScatterSeries>
#include <QtCharts/QValueAxis>

#include <QVBoxLayout>

#include <algorithm>

using namespace QtCharts;

namespace shadinglab::widgets
{

ParameterPlot::ParameterPlot(QWidget* parent)
  : QWidget(parent)
  , View(new QChartView(this))
{
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  this->View->setRenderHint(QPainter::Antialiasing);
  this->View->setMinimumHeight(200);
  layout->addWidget(this->View);
}

namespace
{

/// A categorical comparison (normal weightings, say): grouped bars, one
/// set per series, one group per category; a series' x are category
/// indices.
QChart* MakeBarChart(const QString& title, const QString& xTitle, const QString& yTitle,
  const std::vector<ParameterSeries>& series, const std::vector<QString>& categories)
{
  auto* chart = new QChart;
  StyleChart(chart, title);
  auto* bars = new QBarSeries;
  double yhi = 1e-6;
  for (const ParameterSeries& s : series)
  {
    auto* set = new QBarSet(s.name);
    set->setColor(s.color);
    set->setBorderColor(s.color);
    std::vector<double> values(categories.size(), 0.0);
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
    {
      const auto c = static_cast<size_t>(s.x[i] + 0.5);
      if (c < values.size())
      {
        values[c] = s.y[i];
        yhi = std::max(yhi, s.y[i]);
      }
    }
    for (double v : values)
    {
      set->append(v);
    }
    bars->append(set);
  }
  chart->addSeries(bars);
  auto* x = new QBarCategoryAxis;
  for (const QString& c : categories)
  {
    x->append(c);
  }
  x->setTitleText(xTitle);
  QValueAxis* y = MakeAxis(yTitle, yhi >= 100.0 ? "%.0f" : "%.3g");
  y->setRange(0.0, yhi * 1.1);
  y->applyNiceNumbers();
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  bars->attachAxis(x);
  bars->attachAxis(y);
  return chart;
}

} // namespace

void ParameterPlot::SetSeries(const QString& title, const QString& xTitle, const QString& yTitle,
  const std::vector<ParameterSeries>& series, double marker, const std::vector<QString>& categories,
  const QString& markerLabel)
{
  this->Data = series;
  if (!categories.empty())
  {
    QChart* old = this->View->chart();
    this->View->setChart(MakeBarChart(title, xTitle, yTitle, series, categories));
    delete old;
    return;
  }
  auto* chart = new QChart;
  StyleChart(chart, title);
  QValueAxis* x = MakeAxis(xTitle, "%.3g");
  QValueAxis* y = MakeAxis(yTitle, "%.3g");
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  double xlo = 1e300, xhi = -1e300, ylo = 0.0, yhi = 1e-6;
  for (const ParameterSeries& s : series)
  {
    auto* line = new QLineSeries;
    auto* dots = new QScatterSeries;
    line->setName(s.name);
    line->setPen(QPen(s.color, 2));
    dots->setColor(s.color);
    dots->setBorderColor(s.color);
    dots->setMarkerSize(6);
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
    {
      line->append(s.x[i], s.y[i]);
      dots->append(s.x[i], s.y[i]);
      xlo = std::min(xlo, s.x[i]);
      xhi = std::max(xhi, s.x[i]);
      ylo = std::min(ylo, s.y[i]);
      yhi = std::max(yhi, s.y[i]);
    }
    for (QAbstractSeries* a : { static_cast<QAbstractSeries*>(line), static_cast<QAbstractSeries*>(dots) })
    {
      chart->addSeries(a);
      a->attachAxis(x);
      a->attachAxis(y);
    }
    chart->legend()->markers(dots).front()->setVisible(false);
  }
  if (xlo > xhi)
  {
    xlo = 0;
    xhi = 1;
  }
  if (xhi == xlo)
  {
    xhi = xlo + 1;
  }
  x->setRange(xlo, xhi);
  // Plain integers for counts, three digits otherwise (no 4.94e+03).
  y->setLabelFormat(yhi >= 100.0 ? "%.0f" : "%.3g");
  y->setRange(ylo, yhi * 1.1);
  y->applyNiceNumbers();
  x->applyNiceNumbers();
  if (marker > -1e299)
  {
    auto* mark = new QLineSeries;
    mark->setName(markerLabel);
    mark->setPen(QPen(Qt::black, 1, Qt::DashLine));
    mark->append(marker, ylo);
    mark->append(marker, yhi * 1.1);
    chart->addSeries(mark);
    mark->attachAxis(x);
    mark->attachAxis(y);
  }
  QChart* old = this->View->chart();
  this->View->setChart(chart);
  delete old;
}

} // namespace shadinglab::widgets
