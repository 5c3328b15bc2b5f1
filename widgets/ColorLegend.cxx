// SPDX-License-Identifier: BSD-3-Clause
#include "ColorLegend.h"

#include <QPainter>

#include <algorithm>

namespace shadinglab::widgets
{

ColorLegend::ColorLegend(QWidget* parent)
  : QWidget(parent)
{
  this->setMinimumSize(140, 160);
  this->hide();
}

void ColorLegend::SetMap(const render::ColorMap* map, const std::string& title)
{
  if (!map || map->colors.empty())
  {
    this->hide();
    return;
  }
  this->Map = *map;
  this->Title = QString::fromStdString(title);
  this->show();
  this->update();
}

void ColorLegend::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  painter.fillRect(this->rect(), QColor(40, 42, 50));
  painter.setPen(Qt::white);
  const QFontMetrics metrics = painter.fontMetrics();
  const int line = metrics.height();
  painter.drawText(8, 4 + metrics.ascent(), this->Title);
  const int top = 10 + line, bottom = this->height() - line / 2 - 6;
  const int barX = 10, barW = 18, barH = std::max(10, bottom - top);
  for (int y = 0; y < barH; ++y)
  {
    // The maximum at the top (a constant field: its one colour).
    const Vec3<float> c = this->Map.LegendColor(1.0 - (y + 0.5) / barH);
    painter.setPen(QColor::fromRgbF(c.x, c.y, c.z));
    painter.drawLine(barX, top + y, barX + barW - 1, top + y);
  }
  painter.setPen(Qt::white);
  for (int k = 0; k <= 4; ++k)
  {
    if (this->Map.IsConstant() && k != 2)
    {
      continue; // one value: one tick, at the middle
    }
    const int y = top + (barH - 1) * (4 - k) / 4;
    painter.drawLine(barX + barW, y, barX + barW + 4, y);
    const double value = this->Map.LegendTick(k, 4);
    painter.drawText(barX + barW + 8, y + metrics.ascent() / 2 - 1, QString::number(value, 'g', 4));
  }
}

} // namespace shadinglab::widgets
