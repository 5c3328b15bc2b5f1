// SPDX-License-Identifier: BSD-3-Clause
// What a polarization camera measures (docs/model.md eq. 8.5): the Stokes
// image of a scene, from frames through four linear analysers and a
// circular one. The CLI's render --output and the explorer's DoLP panel.
#pragma once

#include "shadinglab/render/Renderer.h"

#include <cstdint>
#include <vector>

namespace shadinglab::render
{

/// Below this S0 (linear luminance) a pixel carries no light to speak of:
/// its DoLP and AoP are NaN rather than noise over nothing. 1e-6 is 1/3900
/// of the smallest non-zero 8-bit step (1/255), far under anything visible.
inline constexpr double kMinStokesS0 = 1e-6;

struct StokesImage
{
  int width = 0, height = 0;
  /// S0..S3 per pixel and channel (linear RGB, rows top-down).
  std::vector<float> s[4];
  /// Degree and angle (degrees from the image's x axis, in [-90, 90]) of
  /// linear polarization of the luminances; NaN where no light arrives.
  std::vector<float> dolp, aop;
  std::vector<uint8_t> covered;
  /// The frames' depth, when options.keepDepth asked for it.
  std::vector<float> depth;
  /// DoLP averaged over the pixels that have one.
  double meanDolp = 0.0;
};

/**
 * Renders `scene` through analysers at 0, 45, 90 and 135 degrees and a
 * circular one: S0 = I0 + I90, S1 = I0 - I90, S2 = I45 - I135,
 * S3 = 2 I_R - S0. `options.polarizer` is ignored (the analysers are
 * this function's). `stats` receives the first frame's. Needs linear
 * frames (the CPU renderer): throws std::invalid_argument with a one-line
 * message otherwise.
 */
StokesImage MeasureStokes(Renderer& renderer, const Scene& scene, const RenderOptions& options,
  RenderStats* stats = nullptr);

/// What a false-colour polarization picture shows.
enum class StokesQuantity
{
  Dolp, ///< degree of linear polarization, DolpColorMap() (ColorMap.h)
  Aop   ///< angle of polarization, AopColorMap()
};

/// The false colour of every pixel (linear RGB in [0, 1], three floats a
/// pixel, rows top-down): the quantity through its colour map where the
/// surface is (NaN, no light: the map's NaN colour), `background` elsewhere.
/// The CLI's PNG, the explorer's DoLP panel and ParaView's image use it.
std::vector<float> FalseColour(
  const StokesImage& stokes, StokesQuantity quantity, const Vec3<float>& background);

} // namespace shadinglab::render
