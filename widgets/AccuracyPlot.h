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

/// One panel per group (e.g. per shape) in a grid; returns "" or a one-line
/// error. Creates a QApplication if none exists (offscreen without DISPLAY).
std::string WriteAccuracyPlot(const std::vector<std::string>& groups,
  const std::vector<std::vector<AccuracyPoint>>& points, const std::string& title,
  const std::string& path);

} // namespace shadinglab::widgets
