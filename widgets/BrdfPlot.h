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

/// How the lobes' radius is drawn. Lobes differ by orders of magnitude
/// (a microfacet lobe peaks near 0.3/sr where Phong's n = 32 peaks at 3.3),
/// so the default draws each to its own peak, which the legend gives.
enum class BrdfScale
{
  PerLobe,  ///< each lobe / its peak: every shape shows, the legend gives the peak
  Absolute, ///< f_r itself (1/sr), one linear axis
  Log       ///< log10 f_r over four decades below the largest peak
};

class BrdfPlot : public QWidget
{
  Q_OBJECT
public:
  explicit BrdfPlot(QWidget* parent = nullptr);
  void SetLobes(const std::vector<BrdfLobe>& lobes, double thetaL);
  /// Only the specular term (kd = 0), which is what differs between models.
  void SetSpecularOnly(bool on);
  void SetScale(BrdfScale scale);
  BrdfScale GetScale() const { return this->Scale; }
  /// Each lobe's largest radius as drawn (1 for every lobe per lobe), and
  /// the radial axis's end: what a reader sees of each lobe.
  const std::vector<double>& DrawnPeaks() const { return this->Peaks; }
  double RadialMax() const { return this->RadialEnd; }

private:
  void Redraw();
  QtCharts::QChartView* View;
  std::vector<BrdfLobe> Lobes;
  double ThetaL = 45.0;
  bool SpecularOnly = true;
  BrdfScale Scale = BrdfScale::PerLobe;
  std::vector<double> Peaks;
  double RadialEnd = 1.0;
};

} // namespace shadinglab::widgets
