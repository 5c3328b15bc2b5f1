// SPDX-License-Identifier: BSD-3-Clause
// One look for every chart of the explorer: white background that prints,
// titled axes, legend at the bottom, no animation (plots follow sliders).
#pragma once

#include <QString>

#include "QtCompat.h" // QtCharts:: in Qt 5 and 6

namespace shadinglab::widgets
{

/// Applies the common style and sets the chart's title.
void StyleChart(QtCharts::QChart* chart, const QString& title);
/// A value axis with a title and a readable label format.
QtCharts::QValueAxis* MakeAxis(const QString& title, const QString& format = "%.2g");

} // namespace shadinglab::widgets
