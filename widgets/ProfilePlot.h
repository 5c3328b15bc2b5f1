// SPDX-License-Identifier: BSD-3-Clause
// The intensity profile along the comparison's line, one curve per panel,
// with its derivative below and, on request, the "perceived" profile of a
// lateral-inhibition model (Profile.h). Qt Charts.
#pragma once

#include "Profile.h"

#include <QColor>
#include <QWidget>

#include <string>
#include <vector>

class QLabel;

#include "QtCompat.h" // QtCharts:: in Qt 5 and 6

namespace shadinglab::widgets
{

struct ProfileCurve
{
  std::string name;
  QColor color;
  Profile profile;
};

class ProfilePlot : public QWidget
{
  Q_OBJECT
public:
  explicit ProfilePlot(QWidget* parent = nullptr);
  void SetCurves(const std::vector<ProfileCurve>& curves);
  /// Draws the perceived (centre-surround filtered) profile dashed.
  void SetShowPerceived(bool show);
  /// Writes distance and, per curve, intensity, derivative and perceived
  /// values as CSV (one row per sample; curves of different lengths are
  /// padded with empty cells).
  std::string ToCsv() const;

private:
  void Redraw();
  QtCharts::QChartView* IntensityView;
  QtCharts::QChartView* DerivativeView;
  QLabel* Legend; ///< each curve's colour and full name, wrapped
  std::vector<ProfileCurve> Curves;
  bool ShowPerceived = false;
};

} // namespace shadinglab::widgets
