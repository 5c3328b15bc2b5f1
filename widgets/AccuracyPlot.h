// SPDX-License-Identifier: BSD-3-Clause
// The accuracy study's plot: frame time against mean error on log-log
// axes, one colour per shading mode, the Pareto front drawn through its
// points. Qt Charts, rendered to a PNG without a display (Qt's offscreen
// platform) so `shadinglab accuracy` works anywhere.
#pragma once

#include <string>
#include <vector>

namespace shadinglab::widgets
{

struct AccuracyPoint
{
  std::string mode;   ///< series (colour): flat, gouraud, phong, fast-phong
  double milliseconds; ///< x
  double error;        ///< y (mean, 1/255)
  bool pareto;
};

/// A line of a log-log panel (WriteLogLogPlot).
struct LogLogLine
{
  std::string name;
  std::vector<double> x, y; ///< y <= 0 is drawn at the panel's floor
  int color = 0;            ///< PanelColor index
  bool dashed = false;      ///< e.g. a bound beside its measurement
};

struct LogLogPanel
{
  std::string title, xTitle, yTitle;
  std::vector<LogLogLine> lines;
  /// A horizontal reference line (e.g. 1/255, the visible step) when > 0.
  double referenceY = 0;
  std::string referenceName;
  /// Linear axes instead (x from its smallest value, y from 0): for
  /// quantities such as an angle and a colour difference.
  bool linear = false;
};

/// Panels of lines on log-log axes, side by side, to a PNG; "" or a
/// one-line error. As WriteAccuracyPlot, without a display if need be.
std::string WriteLogLogPlot(const std::vector<LogLogPanel>& panels, const std::string& title,
  const std::string& path, int columns = 1);

/// One panel per group (e.g. per shape) in a grid; returns "" or a one-line
/// error. Creates a QApplication if none exists (offscreen without DISPLAY).
std::string WriteAccuracyPlot(const std::vector<std::string>& groups,
  const std::vector<std::vector<AccuracyPoint>>& points, const std::string& title,
  const std::string& path);

} // namespace shadinglab::widgets
