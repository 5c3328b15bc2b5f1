// SPDX-License-Identifier: BSD-3-Clause
// The mouse wheel over a scrolled panel of controls scrolls the panel: it
// changes a slider, spin box or combo box only when that control has the
// keyboard focus (clicked or tabbed to). Without it, scrolling the
// explorer's Controls dock changed whatever control passed under the pointer.
#pragma once

#include <QObject>

class QScrollArea;

namespace shadinglab::widgets
{

class WheelGuard : public QObject
{
  Q_OBJECT
public:
  /// Guards every control inside `area`, those made later too (the
  /// material editor rebuilds its sliders): an application event filter.
  explicit WheelGuard(QScrollArea* area);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  QScrollArea* Area;
};

} // namespace shadinglab::widgets
