// SPDX-License-Identifier: BSD-3-Clause
// One panel of the comparison: a title saying what it shows, and a view
// drawn by one backend of the renderer interface (GpuPanel: a
// QVTKOpenGLNativeWidget with vtkShadingLabPolyDataMapper; CpuPanel: the
// software renderer's image). All panels share the ViewState's camera.
#pragma once

#include "PanelSpec.h"
#include "Profile.h"

#include <QWidget>

class QLabel;

namespace shadinglab::widgets
{

class ProfileOverlay;

class ShadingPanel : public QWidget
{
  Q_OBJECT
public:
  /**
   * A panel for `spec` on its backend: a GPU panel when OpenGL >= 3.2
   * answers (checked once per process), else a CPU panel whose title says
   * why. Heat-map panels (errorReference >= 0) are CPU panels.
   */
  static ShadingPanel* Create(const PanelSpec& spec, ViewState* view, QWidget* parent);

  const PanelSpec& Spec() const { return this->SpecValue; }
  /// New settings (mode, model, material, mesh, ...): re-renders this panel.
  void SetSpec(const PanelSpec& spec);
  /// The panel whose image a heat-map panel compares against.
  void SetReference(ShadingPanel* reference) { this->Reference = reference; }
  ShadingPanel* GetReference() const { return this->Reference; }

  /// Re-renders now (a no-op while the view has no size or no GL context).
  void Render();
  /// The last rendered image (linear, before any heat map), read back from
  /// the framebuffer on the GPU.
  virtual render::Image Snapshot() = 0;
  virtual render::Backend Backend() const = 0;

  /// Renders the backend actually made (a GPU panel counts frames VTK drew,
  /// including those Qt asked for on expose).
  int RenderCount() const { return this->Renders; }
  double LastRenderMilliseconds() const { return this->LastMilliseconds; }
  /// The title as shown (with the backend, and why when it fell back).
  QString Title() const;
  /// Auto mode: the mode the last render drew (the spec's mode otherwise).
  render::ShadingMode DrawnMode() const { return this->Drawn; }
  /// A colour swatch in the title that matches the panel's plot curves.
  void SetCurveColor(const QColor& color);

  void SetProfileLine(const ProfileLine& line);
  const ProfileLine& GetProfileLine() const { return this->Line; }
  void SetSelected(bool selected);

signals:
  /// The user moved the shared camera in this panel.
  void cameraMoved(ShadingPanel* source);
  /// The user dragged a new profile line in this panel.
  void profileLineEdited(const ProfileLine& line);
  /// The user clicked into the panel (to edit its material).
  void activated(ShadingPanel* source);

protected:
  ShadingPanel(const PanelSpec& spec, ViewState* view, QWidget* parent);
  /// Draws with the backend; returns false when nothing could be drawn yet.
  virtual bool RenderView() = 0;
  virtual void OnSpecChanged() {}
  virtual void OnProfileLineChanged() {}
  /// The profile line's overlay on `view`: draws the line, turns left drags
  /// (with the profile tool or Ctrl) into new lines, reports presses.
  ProfileOverlay* InstallOverlay(QWidget* view);
  /// Puts the view widget under the title.
  void SetViewWidget(QWidget* view);
  /// Counts one frame drawn, taking `milliseconds`.
  void CountRender(double milliseconds);
  void UpdateTitle();
  /// After a render: the mode drawn and, in auto mode, the title names it
  /// and its tooltip gives the reasons `why` (cleared otherwise).
  void NoteDrawnMode(render::ShadingMode drawn, const std::string& why);

  PanelSpec SpecValue;
  ViewState* View;
  ShadingPanel* Reference = nullptr;
  ProfileLine Line;
  QString Note; ///< e.g. why a GPU panel fell back to the CPU
  QString Error; ///< the last render's one-line error, shown in the title

private:
  QLabel* TitleLabel;
  QColor CurveColor;
  int Renders = 0;
  double LastMilliseconds = 0;
  bool Selected = false;
  render::ShadingMode Drawn;
  QString AutoNote; ///< "(auto: gouraud)" after an auto-mode render
};

} // namespace shadinglab::widgets
