// SPDX-License-Identifier: BSD-3-Clause
// The pieces the scenes are assembled from (Scenes.cxx, SceneConditions.cxx):
// the lecture's materials and one panel's spec.
#pragma once

#include "SceneMeshes.h"
#include "Scenes.h"

namespace shadinglab::gui
{

/// A white-ish Lambertian surface, no highlight, no ambient.
Material<double> Lambert(double kd = 0.9);
/// The lecture's plastic: a red diffuse colour under a white highlight.
Material<double> Plastic(ReflectanceModel model = ReflectanceModel::BlinnPhong);
/// A material preset by name (plugin/model's table).
Material<double> Preset(const char* name);
widgets::PanelSpec Panel(const std::string& title, const PolyPtr& mesh, render::ShadingMode mode,
  const Material<double>& material, render::Backend backend);

/// The scenes of SceneConditions.cxx.
Scene Creases(const SceneOptions& options);
Scene FlatConditions(const SceneOptions& options);
Scene Scanline(const SceneOptions& options);
/// The scenes of SceneOptics.cxx and their plots.
Scene Polarization(const SceneOptions& options);
Scene SpectralScene(const SceneOptions& options);
Study PolarizationStudy();
Study SpectralStudy();

/// flat-conditions: the unit cube or the sphere around it (radius
/// sqrt(3)/2), and the camera and light `distance` cube sides from the
/// centre, the view angle keeping the object's size on screen.
PolyPtr ConditionsMesh(bool sphere);
render::Camera ConditionsCamera(double distance);

} // namespace shadinglab::gui
