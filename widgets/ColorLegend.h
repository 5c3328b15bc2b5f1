// SPDX-License-Identifier: BSD-3-Clause
// The explorer's colour legend: the array's name, the colour map's bar from
// its minimum (bottom) to its maximum, five ticks with their values, as
// the CLI draws it into its PNGs and ParaView shows its scalar bar.
#pragma once

#include "shadinglab/render/ColorMap.h"

#include <QWidget>

#include <string>

namespace shadinglab::widgets
{

class ColorLegend : public QWidget
{
  Q_OBJECT
public:
  explicit ColorLegend(QWidget* parent = nullptr);
  /// Shows `map` titled `title`; hidden when `map` is nullptr.
  void SetMap(const render::ColorMap* map, const std::string& title);
  QSize sizeHint() const override { return QSize(180, 220); }

protected:
  void paintEvent(QPaintEvent* event) override;

private:
  render::ColorMap Map;
  QString Title;
};

} // namespace shadinglab::widgets
