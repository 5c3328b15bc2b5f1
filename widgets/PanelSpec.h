// SPDX-License-Identifier: BSD-3-Clause
// What one panel of the comparison shows, and the view state all panels
// share. Plain data: the explorer's scenes are lists of PanelSpecs.
#pragma once

#include "shadinglab/model/Shading.h"
#include "shadinglab/render/ColorMap.h"
#include "shadinglab/render/Options.h"
#include "shadinglab/render/Renderer.h"
#include "shadinglab/render/Settings.h"

#include <vtkCamera.h>   // complete types for the smart pointers below
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>


namespace shadinglab::widgets
{

struct PanelSpec
{
  std::string title; ///< what the panel shows, in a teacher's words
  /// The mesh drawn (prepared: with the normals the panel should use). Panels
  /// may share one mesh or show different ones (repair, subdivision, normal
  /// weightings) under the one camera.
  vtkSmartPointer<vtkPolyData> mesh;
  /// Auto: at every render, the cheapest of flat, Gouraud and Phong
  /// predicted to keep the mean error under maxError (1/255) for this mesh,
  /// view and material, chosen by the panel's renderer.
  render::ShadingMode mode = render::ShadingMode::Phong;
  double maxError = 1.0;
  Material<double> material;
  /// GPU by default; a GPU panel without OpenGL >= 3.2 becomes a CPU panel
  /// and says so in its title.
  render::Backend backend = render::Backend::GPU;
  render::InterpolationSpace interpolation = render::InterpolationSpace::Perspective;
  /// Direct: quads and polygons scan-converted whole (CPU only: the GPU
  /// triangulates), the lecture's polygon scan conversion.
  render::PolygonHandling polygons = render::PolygonHandling::Triangulate;
  /// The lecture's incremental scan (CPU only: the GPU interpolates in its
  /// rasterizer), in float or double.
  render::ScanConversion scan = render::ScanConversion::Plane;
  render::ScanPrecision scanPrecision = render::ScanPrecision::Float;
  /// >= 0: the panel displays the per-pixel error |I - I_ref| of its image
  /// against panel `errorReference` as a heat map instead of its image.
  int errorReference = -1;
  /// The heat map's full scale, in linear intensity (or CIEDE2000 units).
  double errorScale = 16.0 / 255.0;
  /// The heat map shows the CIEDE2000 colour difference (docs/model.md
  /// eq. 7.4) instead of the luminance difference.
  bool colourDifference = false;
  /// >= 0: an analyser at this angle from the image's x axis in front of
  /// the panel's camera (RenderOptions::polarizer, docs/model.md eq. 8.3).
  double polarizer = -1.0;
  /// >= 0: a linear polarizer at this angle in front of the lights
  /// (RenderOptions::lightPolarizer, docs/model.md eq. 8.6).
  double lightPolarizer = -1.0;
  /// The panel shows the degree of linear polarization a polarization
  /// camera measures (eq. 8.5, render/Stokes.h) in viridis instead of its
  /// image (drawn by the CPU renderer: it needs linear frames).
  bool dolpImage = false;
};

/// What all panels share: one camera (rotate, zoom or pan in any panel moves
/// all) and one light given in the camera's frame (render::CameraLight).
struct ViewState
{
  vtkSmartPointer<vtkCamera> camera;
  double lightAzimuth = -25.0;  ///< degrees toward the camera's right
  double lightElevation = 25.0; ///< degrees toward the camera's up
  double lightIntensity = 1.0;  ///< I_L of the one light (eq. 1.1)
  /// 0: the light is directional; > 0: a point light this far from the
  /// camera's focal point, in the same direction.
  double lightDistance = 0.0;
  /// dw of the one light (eq. 1.1, steradians), as the settings table's default.
  double lightSolidAngle = render::Settings().lightSolidAngle;
  /// A mesh scene: vtkLightKit's five lights (render::LightKit) scaled by
  /// lightIntensity, the key light at lightAzimuth and lightElevation;
  /// otherwise the lecture's one light.
  bool lightKit = false;
  Vec3<float> background{ 0.32f, 0.34f, 0.43f };
  /// Linear intensity to pixel, as the settings table's default (every
  /// panel, both backends; profiles and error maps read display values).
  render::DisplayTransform display = render::RenderOptions().display;
  /// Colour by data, every panel: the array as --color-by spells it ("":
  /// the material's colour) and the map over the array's range.
  std::string colorBy;
  render::ColorMap colorMap;
  /// Highlights on a surface coloured by data (render::MaterialForData):
  /// Auto leaves them off, as on every front end.
  render::Highlights highlights = render::Highlights::Auto;
  /// Left-drag draws the profile line instead of rotating.
  bool profileTool = false;
};

/// The render options of a panel of `spec` at width x height.
render::RenderOptions PanelOptions(const PanelSpec& spec, const ViewState& view, int width,
  int height);

/// The scene's lighting for `camera`: one directional light from the view
/// state's direction, or the light kit with its key light there; ambient
/// intensity 1 (the material's ambient sets Ra).
Lighting<double> ViewLighting(const ViewState& view, const render::Camera& camera);

} // namespace shadinglab::widgets
