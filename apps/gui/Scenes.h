// SPDX-License-Identifier: BSD-3-Clause
// The lecture's scenes: for each, the panels, the camera and light, a short
// explanation with the formula it illustrates, and the plot that says what
// the pictures show in numbers.
#pragma once

#include "PanelSpec.h"
#include "Profile.h"

#include "MeshPreparation.h"
#include "MeshIO.h"

#include <string>
#include <vector>

namespace shadinglab::gui
{

enum class PlotKind
{
  None,
  Profile,  ///< intensity profile along the line (+ derivative)
  Brdf,     ///< polar BRDF lobes
  Parameter, ///< a measured quantity against a parameter (Study)
  Scanline   ///< the scanline inspector (widgets/ScanlineInspector.h), no panels
};

struct SceneInfo
{
  const char* name;
  const char* summary;
};

/// The scenes in lecture order.
const std::vector<SceneInfo>& SceneList();

/// flat-conditions' distance range (circumradii): from just outside the
/// object (1.5: the near plane stays in front of it) to where even a
/// shininess-60 highlight is constant over a face to 0.1/255.
inline constexpr double kMinConditionsDistance = 1.5;
inline constexpr double kMaxConditionsDistance = 1e4;

struct SceneOptions
{
  render::Backend backend = render::Backend::GPU;
  /// The user's mesh (already read; prepared by MakeScene) for the scenes
  /// that show one mesh (modes, silhouette, moon, metal); nullptr: the
  /// scene's own mesh.
  vtkPolyData* input = nullptr;
  /// Mesh preparation of the user's mesh (normal weighting, crease angle,
  /// subdivision, repair).
  mesh::PreparationOptions preparation;
  /// How files are read (File > Open and INPUT): the nonlinear subdivision.
  ReadOptions reading;
  /// orientation: rotation of the quad in the image plane (degrees).
  double rotation = 0.0;
  /// normals: "corrugated" or "isosurface".
  std::string variant = "corrugated";
  /// flat-conditions: the camera's and the light's distance from the
  /// object's centre, in circumradii.
  double distance = 3.0;
  /// polarization: the analyser's angle from the image's x axis (degrees).
  double polarizer = 0.0;
  /// polarization: the lights' polarizer angle (degrees; < 0: unpolarized).
  double lightPolarizer = -1.0;
};

struct Scene
{
  std::string name, title;
  std::string explanation; ///< HTML: what to look at and why
  std::string formula;     ///< HTML: the formula it illustrates
  std::vector<widgets::PanelSpec> panels;
  double azimuth = 0, elevation = 0, zoom = 1;
  bool parallel = false;
  /// Instead of fitting the bounds (azimuth, elevation, zoom): this camera.
  bool explicitCamera = false;
  render::Camera camera;
  double lightAzimuth = -25, lightElevation = 25, lightIntensity = 1;
  /// 0: a directional light; > 0: a point light this far from the focal
  /// point, in the light's direction.
  double lightDistance = 0;
  /// The user's mesh: vtkLightKit's lights as ParaView (render::LightKit);
  /// the lecture's scenes keep one light and say so in their explanation.
  bool lightKit = false;
  widgets::ProfileLine line;
  PlotKind plot = PlotKind::Profile;
  bool perceived = false;
  bool usesInput = false; ///< the user's mesh replaces the scene's mesh
  /// The lecture's scenes plot the intensity I itself: Clamp, the identity
  /// on [0, 1]. A user's mesh gets the settings' default (PBR Neutral, no
  /// clipping), as in the CLI and ParaView.
  render::DisplayTransform display = render::DisplayTransform::Clamp;
};

/// Builds scene `name`; throws std::invalid_argument for an unknown name or
/// a mesh the preparation cannot use (one line).
Scene MakeScene(const std::string& name, const SceneOptions& options);

/// The measured quantity of a Parameter scene, computed with the CPU
/// renderer at a fixed size (so it does not depend on the window).
struct Study
{
  std::string title, xTitle, yTitle;
  struct Series
  {
    std::string name;
    std::vector<double> x, y;
  };
  std::vector<Series> series;
  std::vector<std::string> categories; ///< labels of integer x values, or empty
  double marker = -1e300;              ///< the current parameter value
  std::string markerLabel = "current"; ///< the marker's legend entry
};
Study RunStudy(const Scene& scene, const SceneOptions& options);

} // namespace shadinglab::gui
