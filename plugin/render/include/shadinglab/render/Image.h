// SPDX-License-Identifier: BSD-3-Clause
// The image both backends return, and its supersampling resolve.
#pragma once

#include "shadinglab/render/Options.h"

#include <cstdint>
#include <vector>

namespace shadinglab::render
{

/// Rec. 709 / sRGB luminance of linear RGB (the weights of BT.709).
template <typename T>
T Luminance(const Vec3<T>& rgb)
{
  return T(0.2126) * rgb.x + T(0.7152) * rgb.y + T(0.0722) * rgb.z;
}

/// Linear RGB image, row 0 at the top.
struct Image
{
  int width = 0;
  int height = 0;
  std::vector<float> rgb;         ///< 3 per pixel, linear
  std::vector<uint8_t> covered;   ///< 1 where a surface was drawn
  std::vector<uint16_t> coverage; ///< per-pixel polygon count (countCoverage only)

  /// 8-bit RGB after the display transform. NaN never occurs (tested) but
  /// would map to 0.
  std::vector<uint8_t> ToRGB8(DisplayTransform transform) const;
};

/**
 * Box-filters a full-resolution linear RGB frame (row 0 at the top) by
 * `factor` per axis into `out` (the supersampling resolve of both renderers).
 * A pixel is covered when any of its samples is.
 */
void DownsampleBox(const std::vector<float>& rgb, const std::vector<uint8_t>& covered, int width,
  int height, int factor, Image& out);

} // namespace shadinglab::render
