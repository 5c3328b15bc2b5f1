// SPDX-License-Identifier: BSD-3-Clause
// How true a picture coloured by data is to its colour map (docs/model.md
// eq. 9.3): the share of covered pixels whose colour is not the map's
// colour at the pixel's value times a brightness s >= 0.
#pragma once

#include "shadinglab/render/Image.h"
#include "shadinglab/render/Renderer.h"
#include "shadinglab/render/Scene.h"

#include <cstdint>

namespace shadinglab::render
{

/// How far (linear, any channel) a pixel may be from s x map(value) and
/// still be true to the map: 2/255, twice an 8-bit step, so float rounding
/// and supersampled edges where two bins mix never count, while a white
/// highlight or a grey ambient term (Ra Ia = 0.05 by default) always does.
inline constexpr double kFidelityTolerance = 2.0 / 255.0;
/// Shade below which a pixel is taken as unlit (its value cannot be read
/// back from the ramp, eq. 9.3); it must then be black within the tolerance.
inline constexpr double kFidelityUnlit = 1e-4;

struct FidelityResult
{
  int64_t covered = 0;    ///< pixels drawn
  int64_t unfaithful = 0; ///< of those, not s x map(value)
  double Fraction() const
  {
    return covered > 0 ? static_cast<double>(unfaithful) / static_cast<double>(covered) : 0.0;
  }
};

/**
 * Compares `picture` (linear) with W, the same view drawn with a white map
 * and without highlights or ambient (render::MaterialForData, Off), and Q,
 * drawn so with a grey ramp over the map's bins: the pixel's value is
 * t = Q / W, and a pixel is true to the map when |P - s map(t)| <=
 * kFidelityTolerance in every channel for the best s >= 0 (eq. 9.3): any
 * brightness, no other hue. Light colours cancel: map(t) is taken under
 * W's hue.
 */
FidelityResult CompareWithMap(
  const Image& picture, const Image& white, const Image& ramp, const ColorMap& map);

/**
 * Draws `scene` (coloured by data: scene.colorMap set) as given, then W and
 * Q (CompareWithMap) with the same renderer, camera and lights, in linear
 * frames (the CPU renderer). Throws std::invalid_argument without a colour
 * map, and what Render throws.
 */
FidelityResult MeasureColorFidelity(
  Renderer& renderer, const Scene& scene, RenderOptions options);

} // namespace shadinglab::render
