// SPDX-License-Identifier: BSD-3-Clause
// Polar plot of BRDF lobes in the plane of incidence, in the spirit of
// Disney's BRDF Explorer: the radius is the BRDF (1/sr, luminance) seen at
// viewing angle theta_v for light at theta_l, the normal points up, the
// incident direction is drawn as a line. The lobes are the model library's
// EvaluateBrdf, the function both renderers shade with. Qt Charts.
#pragma once

#include "shadinglab/model/Shading.h"

#include <QColor>
#include <QWidget>

#include <string>
#include <vector>

#include "QtCompat.h" // QtCharts:: in Qt 5 and 6

namespace shadinglab::widgets
{

struct BrdfLobe
{
  std::string name;
  Material<double> material;
  QColor color;
};

/// f_r luminance for light at thetaL and viewer at thetaV (degrees from the
/// normal, in the plane of incidence; thetaV > 0 on the mirror side).
double BrdfInPlane(const Material<double>& material, double thetaL, double thetaV);

/// The lobes the explorer compares by default: Phong, Blinn-Phong,
/// Cook-Torrance 1982 and Walter 2007 and a two-lobe Beckmann mixture, at
/// matched widths (Phong n, Beckmann m = sqrt(2 / (n + 2))).
std::vector<BrdfLobe> DefaultLobes(double shininess, double roughness);

class BrdfPlot : public QWidget
{
  Q_OBJECT
public:
  explicit BrdfPlot(QWidget* parent = nullptr);
  void SetLobes(const std::vector<BrdfLobe>& lobes, double thetaL);
  /// Only the specular term (kd = 0), which is what differs between models.
  void SetSpecularOnly(bool on);

private:
  void Redraw();
  QtCharts::QChartView* View;
  std::vector<BrdfLobe> Lobes;
  double ThetaL = 45.0;
  bool SpecularOnly = true;
};

} // namespace shadinglab::widgets
