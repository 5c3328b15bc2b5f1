// SPDX-License-Identifier: BSD-3-Clause
// A measured quantity against a parameter (the orientation scene's centre
// intensity against rotation, silhouette error against subdivision level,
// normal error against weighting), as lines with markers. Qt Charts.
#pragma once

#include <QColor>
#include <QString>
#include <QWidget>

#include <vector>

#include "QtCompat.h" // QtCharts:: in Qt 5 and 6

namespace shadinglab::widgets
{

struct ParameterSeries
{
  QString name;
  QColor color;
  std::vector<double> x, y;
};

class ParameterPlot : public QWidget
{
  Q_OBJECT
public:
  explicit ParameterPlot(QWidget* parent = nullptr);
  /// Replaces the plot. `marker` >= xmin draws a vertical line there (the
  /// parameter's current value, or what `markerLabel` names in the legend).
  /// With `categories`, a bar chart: the series' x are category indices,
  /// one bar per series in each group.
  void SetSeries(const QString& title, const QString& xTitle, const QString& yTitle,
    const std::vector<ParameterSeries>& series, double marker = -1e300,
    const std::vector<QString>& categories = {}, const QString& markerLabel = "current");
  const std::vector<ParameterSeries>& Series() const { return this->Data; }

private:
  QtCharts::QChartView* View;
  std::vector<ParameterSeries> Data;
};

} // namespace shadinglab::widgets
