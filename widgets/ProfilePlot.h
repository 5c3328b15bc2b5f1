// SPDX-License-Identifier: BSD-3-Clause
// The intensity profile along the comparison's line, one curve per panel,
// with its derivative beside it and, on request, the "perceived" profile of
// a lateral-inhibition model (Profile.h), whose difference from the
// intensity (the Mach bands the eye adds) then replaces the derivative, on
// its own axis: bands of a few thousandths stay visible next to a flat
// staircase's steps. Qt Charts.
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
  /// The second chart: its title, and the half-height of its y axis (the
  /// derivative's, or the bands' with the perceived profile shown).
  QString SecondTitle() const;
  double SecondAxisSpan() const { return this->SecondSpan; }

private:
  void Redraw();
  QtCharts::QChartView* IntensityView;
  QtCharts::QChartView* DerivativeView;
  QLabel* Legend; ///< each curve's colour and full name, wrapped
  std::vector<ProfileCurve> Curves;
  bool ShowPerceived = false;
  double SecondSpan = 0.0;
};

} // namespace shadinglab::widgets
