// SPDX-License-Identifier: BSD-3-Clause
#include "ViewInteraction.h"

#include <vtkCamera.h>
#include <vtkMath.h>

#include <QMouseEvent>
#include <QPainter>

#include <cmath>

namespace shadinglab::widgets
{

ProfileOverlay::ProfileOverlay(QWidget* view)
  : QWidget(view)
{
  this->setAttribute(Qt::WA_TransparentForMouseEvents);
  this->setAttribute(Qt::WA_NoSystemBackground);
  this->setGeometry(view->rect());
  view->installEventFilter(this);
}

void ProfileOverlay::SetLine(const ProfileLine& line)
{
  this->Line = line;
  this->update();
}

void ProfileOverlay::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  const QPointF a(this->Line.x0 * this->width(), this->Line.y0 * this->height());
  const QPointF b(this->Line.x1 * this->width(), this->Line.y1 * this->height());
  // Dark under light: visible on any shade of the surface.
  painter.setPen(QPen(QColor(0, 0, 0, 160), 3));
  painter.drawLine(a, b);
  painter.setPen(QPen(QColor(255, 230, 0), 1, Qt::DashLine));
  painter.drawLine(a, b);
  painter.setBrush(QColor(255, 230, 0));
  painter.drawEllipse(a, 3, 3);
}

bool ProfileOverlay::eventFilter(QObject* watched, QEvent* event)
{
  auto* view = static_cast<QWidget*>(this->parent());
  if (watched != view)
  {
    return false;
  }
  if (event->type() == QEvent::Resize)
  {
    this->setGeometry(view->rect());
    this->raise();
    return false;
  }
  if (event->type() != QEvent::MouseButtonPress && event->type() != QEvent::MouseMove &&
    event->type() != QEvent::MouseButtonRelease)
  {
    return false;
  }
  auto* mouse = static_cast<QMouseEvent*>(event);
  const double w = std::max(1, view->width()), h = std::max(1, view->height());
  const double x = mouse->localPos().x() / w, y = mouse->localPos().y() / h;
  if (event->type() == QEvent::MouseButtonPress)
  {
    if (this->Pressed)
    {
      this->Pressed();
    }
    if (mouse->button() == Qt::LeftButton && this->DrawsLine && this->DrawsLine(mouse->modifiers()))
    {
      this->Dragging = true;
      this->Line = ProfileLine{ x, y, x, y };
      return true;
    }
    return false;
  }
  if (!this->Dragging)
  {
    return false;
  }
  this->Line.x1 = std::clamp(x, 0.0, 1.0);
  this->Line.y1 = std::clamp(y, 0.0, 1.0);
  if (event->type() == QEvent::MouseButtonRelease)
  {
    this->Dragging = false;
  }
  this->update();
  if (this->LineEdited && (this->Line.x1 != this->Line.x0 || this->Line.y1 != this->Line.y0))
  {
    this->LineEdited(this->Line);
  }
  return true;
}

void RotateCamera(vtkCamera* camera, double dx, double dy, int width, int height)
{
  // vtkInteractorStyleTrackballCamera::Rotate: 20 degrees per view size,
  // times its MotionFactor 10.
  const double motionFactor = 10.0;
  camera->Azimuth(-20.0 / std::max(1, width) * dx * motionFactor);
  camera->Elevation(-20.0 / std::max(1, height) * dy * motionFactor);
  camera->OrthogonalizeViewUp();
}

void DollyCamera(vtkCamera* camera, double factor)
{
  if (camera->GetParallelProjection())
  {
    camera->SetParallelScale(camera->GetParallelScale() / factor);
  }
  else
  {
    camera->Dolly(factor);
  }
}

void PanCamera(vtkCamera* camera, double dx, double dy, int height)
{
  // Move focal point and position by the world distance under the cursor
  // motion at the focal plane.
  double* fp = camera->GetFocalPoint();
  double* pos = camera->GetPosition();
  const double distance = std::sqrt(vtkMath::Distance2BetweenPoints(fp, pos));
  const double viewHeight = camera->GetParallelProjection()
    ? 2.0 * camera->GetParallelScale()
    : 2.0 * distance * std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0);
  const double scale = viewHeight / std::max(1, height);
  double up[3], right[3], forward[3];
  camera->GetViewUp(up);
  for (int i = 0; i < 3; ++i)
  {
    forward[i] = fp[i] - pos[i];
  }
  vtkMath::Cross(forward, up, right);
  vtkMath::Normalize(right);
  double shift[3], newFp[3], newPos[3];
  for (int i = 0; i < 3; ++i)
  {
    shift[i] = (-dx * right[i] + dy * up[i]) * scale;
    newFp[i] = fp[i] + shift[i];
    newPos[i] = pos[i] + shift[i];
  }
  camera->SetFocalPoint(newFp);
  camera->SetPosition(newPos);
}

} // namespace shadinglab::widgets
