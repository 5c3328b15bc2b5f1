// SPDX-License-Identifier: BSD-3-Clause
#include "WheelGuard.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QScrollArea>
#include <QScrollBar>
#include <QWheelEvent>

namespace shadinglab::widgets
{

WheelGuard::WheelGuard(QScrollArea* area)
  : QObject(area)
  , Area(area)
{
  qApp->installEventFilter(this);
}

bool WheelGuard::eventFilter(QObject* watched, QEvent* event)
{
  if (event->type() != QEvent::Wheel)
  {
    return false;
  }
  auto* control = qobject_cast<QWidget*>(watched);
  // A spin box's line edit receives the wheel first: judge the spin box.
  if (control && qobject_cast<QAbstractSpinBox*>(control->parentWidget()))
  {
    control = control->parentWidget();
  }
  // (Scroll bars are sliders too, and scroll.)
  const bool guarded = control && !qobject_cast<QScrollBar*>(control) &&
    (qobject_cast<QAbstractSlider*>(control) || qobject_cast<QAbstractSpinBox*>(control) ||
      qobject_cast<QComboBox*>(control)) &&
    this->Area->isAncestorOf(control);
  if (!guarded || control->hasFocus())
  {
    return false;
  }
  // Not focused: the panel scrolls instead (a new event for its scroll bar:
  // Qt's delivery of the one under way must not be re-entered).
  const auto* wheel = static_cast<QWheelEvent*>(event);
  QScrollBar* bar = this->Area->verticalScrollBar();
  const QPointF global = wheel->globalPosition();
  QWheelEvent forwarded(bar->mapFromGlobal(global.toPoint()), global, wheel->pixelDelta(),
    wheel->angleDelta(), wheel->buttons(), wheel->modifiers(), wheel->phase(), wheel->inverted());
  QApplication::sendEvent(bar, &forwarded);
  return true;
}

} // namespace shadinglab::widgets
