// SPDX-License-Identifier: BSD-3-Clause
// What both panel kinds share about the mouse: the profile line overlay and
// its drag, and (for views VTK's interactor does not drive) the trackball
// camera moves on the shared vtkCamera.
#pragma once

#include "Profile.h"

#include <QWidget>

#include <functional>

class vtkCamera;

namespace shadinglab::widgets
{

/// Draws the profile line over a view (transparent to the mouse) and turns
/// drags in the view it watches into new lines.
class ProfileOverlay : public QWidget
{
public:
  explicit ProfileOverlay(QWidget* view);
  void SetLine(const ProfileLine& line);
  /// Called with each new line while the user drags one.
  std::function<void(const ProfileLine&)> LineEdited;
  /// Whether a left drag in the view draws a line (else it is the view's).
  std::function<bool(Qt::KeyboardModifiers)> DrawsLine;
  /// Called on any mouse press in the view.
  std::function<void()> Pressed;

protected:
  void paintEvent(QPaintEvent* event) override;
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  ProfileLine Line;
  bool Dragging = false;
};

/// Trackball camera moves as vtkInteractorStyleTrackballCamera makes them.
void RotateCamera(vtkCamera* camera, double dx, double dy, int width, int height);
void DollyCamera(vtkCamera* camera, double factor);
void PanCamera(vtkCamera* camera, double dx, double dy, int height);

} // namespace shadinglab::widgets
