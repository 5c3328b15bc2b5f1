// SPDX-License-Identifier: BSD-3-Clause
// Colour by data: a scalar per vertex or per polygon (render::Mesh) mapped
// through one of ParaView's colour-map presets, as the ShadingLab Surface
// representation maps it in ParaView. The tables are ParaView's own lookup
// tables (256 discrete bins, 8-bit), extracted at build time by
// plugin/render/tools/ExtractColorMaps.py.
#pragma once

#include "shadinglab/model/Vec3.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace shadinglab::render
{

/// A preset's 256 colours over [rangeMin, rangeMax]; below and above the
/// range the end colours (ParaView's default), NaN the preset's NaN colour.
/// The colour is the diffuse colour rho of the shading equation (eq. 1.1).
struct ColorMap
{
  std::string label; ///< ParaView's name: "Cool to Warm"
  std::vector<Vec3<float>> colors;
  Vec3<float> nanColor{ 1, 1, 0 };
  double rangeMin = 0, rangeMax = 1;

  /// The bin of `s` (vtkLookupTable's indexing: floor((s - min) / (max -
  /// min) * bins), clamped), or the NaN colour. A range of zero width maps
  /// everything to the first bin.
  /// Always inlined: the CPU renderer maps every pixel's interpolated
  /// scalar, and GCC made it a call per pixel once the rasterizer grew
  /// (~5% of a Phong frame of ParaView's 1M sphere by Elevation).
  [[gnu::always_inline]] Vec3<float> Map(double s) const
  {
    if (std::isnan(s) || this->colors.empty())
    {
      return this->nanColor;
    }
    const int bins = static_cast<int>(this->colors.size());
    const double width = this->rangeMax - this->rangeMin;
    const double t = width > 0 ? (s - this->rangeMin) / width : 0.0;
    // Clamp in double first: a huge or infinite t does not fit an int. The
    // clamped t * bins is >= 0, where the int conversion's truncation is
    // floor: without std::floor, a libm call per pixel on baseline x86-64
    // (~6% of a CPU frame of ParaView's 1M sphere by Elevation).
    const int bin = static_cast<int>(std::clamp(t, 0.0, 1.0) * bins);
    return this->colors[static_cast<size_t>(std::min(bins - 1, bin))];
  }

  /// A range of zero width: every value maps to one colour (a constant
  /// field; MeshFromPolyData gives one also for a field constant up to
  /// rounding).
  bool IsConstant() const { return !(this->rangeMax > this->rangeMin); }

  /// A legend bar's colour at fraction t of its height (0: the minimum):
  /// the map's bin there, or for a constant field the one colour drawn (a
  /// ramp the picture does not use would misstate it).
  Vec3<float> LegendColor(double t) const;

  /// The value of tick k of `count` + 1 evenly spaced legend ticks (0: the
  /// range's minimum). A value within kLegendZeroFraction of the range's
  /// width from zero is 0: float data and rounding put a range's end at
  /// -2.6e-08 for a surface that starts at zero.
  double LegendTick(int k, int count) const;
};

/// 1e-6 of the range's width: far below the 4 significant digits a legend
/// prints, far above double rounding of a data range (1e-16 relative).
constexpr double kLegendZeroFraction = 1e-6;

/// The presets: ParaView's name, its name before ParaView 6.0 where it was
/// renamed ("" otherwise), and the command line's (kebab-case), e.g.
/// "Viridis", "Viridis (matplotlib)" and "viridis", in the order listed.
struct ColorMapName
{
  std::string label;
  std::string alias;
  std::string key;
};
const std::vector<ColorMapName>& ColorMapNames();

/// The preset named `name` (label, alias or key, any case) with range [0, 1];
/// false when there is none.
bool FindColorMap(const std::string& name, ColorMap& map);

/// The false colours of a polarization image (docs/model.md eq. 8.5): DoLP
/// in viridis over [0, 1], or the angle of polarization on a cyclic hue
/// wheel over [-90, 90] degrees (-90 and 90 are one axis and one colour;
/// Wilkie & Weidlich 2010 draw AoP as hue); NaN (no light) dark grey.
ColorMap DolpColorMap();
ColorMap AopColorMap();

} // namespace shadinglab::render
