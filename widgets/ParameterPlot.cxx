// SPDX-License-Identifier: BSD-3-Clause
#include "ParameterPlot.h"

#include "ChartStyle.h"

#include <QtCharts/QCategoryAxis>
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

void ParameterPlot::SetSeries(const QString& title, const QString& xTitle, const QString& yTitle,
  const std::vector<ParameterSeries>& series, double marker, const std::vector<QString>& categories)
{
  this->Data = series;
  auto* chart = new QChart;
  StyleChart(chart, title);
  QValueAxis* x = nullptr;
  if (!categories.empty())
  {
    auto* cat = new QCategoryAxis;
    cat->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
    for (size_t i = 0; i < categories.size(); ++i)
    {
      cat->append(categories[i], static_cast<double>(i));
    }
    cat->setTitleText(xTitle);
    x = cat;
  }
  else
  {
    x = MakeAxis(xTitle, "%.3g");
  }
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
  const double pad = categories.empty() ? 0.0 : 0.5;
  x->setRange(xlo - pad, xhi + pad);
  // Plain integers for counts, three digits otherwise (no 4.94e+03).
  y->setLabelFormat(yhi >= 100.0 ? "%.0f" : "%.3g");
  y->setRange(ylo, yhi * 1.1);
  y->applyNiceNumbers();
  if (categories.empty())
  {
    x->applyNiceNumbers();
  }
  if (marker > -1e299)
  {
    auto* mark = new QLineSeries;
    mark->setName("current");
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
