// SPDX-License-Identifier: BSD-3-Clause
#include "ChartStyle.h"

#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QValueAxis>

namespace shadinglab::widgets
{

void StyleChart(QtCharts::QChart* chart, const QString& title)
{
  chart->setTitle(title);
  QFont font = chart->titleFont();
  font.setBold(true);
  font.setPointSize(10);
  chart->setTitleFont(font);
  chart->setAnimationOptions(QtCharts::QChart::NoAnimation);
  chart->setBackgroundBrush(Qt::white);
  chart->setMargins(QMargins(4, 4, 4, 4));
  chart->legend()->setAlignment(Qt::AlignBottom);
  chart->legend()->setShowToolTips(true);
  QFont legendFont = chart->legend()->font();
  legendFont.setPointSize(8);
  chart->legend()->setFont(legendFont);
}

QtCharts::QValueAxis* MakeAxis(const QString& title, const QString& format)
{
  auto* axis = new QtCharts::QValueAxis;
  axis->setTitleText(title);
  axis->setLabelFormat(format);
  QFont font = axis->titleFont();
  font.setPointSize(9);
  axis->setTitleFont(font);
  return axis;
}

} // namespace shadinglab::widgets
