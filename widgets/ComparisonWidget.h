// SPDX-License-Identifier: BSD-3-Clause
// N panels side by side (1 to 6) under one camera and one light: rotating,
// zooming or panning in any panel moves all. Only what changed is redrawn:
// a camera or light move re-renders every panel; a panel's new settings
// re-render that panel (and the heat maps that compare against it).
#pragma once

#include "PanelSpec.h"
#include "Profile.h"

#include <QWidget>

#include <vector>

class QGridLayout;

namespace shadinglab::widgets
{

class ShadingPanel;

/// The curve colours of panels 0..5 (Okabe & Ito's colour-blind-safe set,
/// which also stays apart in greyscale print).
QColor PanelColor(int index);

class ComparisonWidget : public QWidget
{
  Q_OBJECT
public:
  static constexpr int kMaxPanels = 6;

  explicit ComparisonWidget(QWidget* parent = nullptr);
  ~ComparisonWidget() override;

  /// Replaces the panels (at most kMaxPanels; more is std::invalid_argument).
  void SetPanels(const std::vector<PanelSpec>& specs);
  int PanelCount() const { return static_cast<int>(this->Panels.size()); }
  ShadingPanel* Panel(int index) const { return this->Panels.at(index); }

  /// One panel's new settings: re-renders that panel and its heat maps.
  void SetPanelSpec(int index, const PanelSpec& spec);

  ViewState& View() { return this->State; }
  /// Fits the camera to the panels' meshes as vtkRenderer::ResetCamera
  /// (view along -z), then azimuth, elevation (degrees) and zoom.
  /// Panels not laid out yet are fitted again at their first render.
  void ResetCamera(double azimuth, double elevation, double zoom, bool parallel);
  /// A given camera (world coordinates; the clipping range is fitted).
  void SetCamera(const render::Camera& camera);
  /// The light in the camera's frame: re-renders every panel.
  void SetLight(double azimuth, double elevation);
  /// The light's intensity I_L (the light-intensity setting); redraws all.
  void SetLightIntensity(double intensity);
  /// dw of the light, steradians (eq. 1.1).
  void SetLightSolidAngle(double solidAngle);
  /**
   * Colours every panel by the array `colorBy` ([POINTS:|CELLS:]NAME[:C],
   * "" for none) through the colour map `map`, over the array's range on
   * the first panel's mesh. Returns "" or a one-line error (and changes
   * nothing).
   */
  std::string SetColorBy(const std::string& colorBy, const std::string& map);
  void SetProfileTool(bool on) { this->State.profileTool = on; }

  void RenderAll();

  void SetProfileLine(const ProfileLine& line);
  const ProfileLine& GetProfileLine() const { return this->Line; }
  /// The profile of every shaded panel (heat maps excluded) along the line.
  std::vector<Profile> Profiles() const;
  /// The panel index of each entry of Profiles().
  std::vector<int> ProfilePanels() const;

  /// The panel the user last clicked into (material edits go there).
  int CurrentPanel() const { return this->Current; }
  void SetCurrentPanel(int index);

signals:
  /// After any re-render (plots re-read their numbers).
  void rendered();
  void profileLineChanged();
  void currentPanelChanged(int index);

private:
  void OnCameraMoved(ShadingPanel* source);
  /// Every panel but `alreadyDrawn` (may be null), heat maps last.
  void RenderPanels(const ShadingPanel* alreadyDrawn);
  void RenderPanelAndDependents(int index);

  bool FitCamera();

  struct CameraFit
  {
    double azimuth = 0, elevation = 0, zoom = 1;
    bool parallel = false;
    bool pending = false;
  } Fit;
  /// Event-loop passes to wait for new panels to be laid out before the
  /// camera is fitted to a guessed aspect: Qt shows new children on its
  /// next pass, so 1-2 suffice; 10 bounds the wait if a panel stays hidden.
  static constexpr int kMaxFitRetries = 10;
  int FitRetries = 0;
  ViewState State;
  std::vector<ShadingPanel*> Panels;
  QGridLayout* Grid;
  ProfileLine Line;
  int Current = 0;
};

} // namespace shadinglab::widgets
