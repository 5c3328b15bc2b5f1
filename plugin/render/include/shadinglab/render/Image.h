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

/// RGB image, row 0 at the top: linear (the CPU renderer), or display
/// values when the backend applied the display transform itself (the GL
/// renderer, whose 8-bit framebuffer would clip linear values above 1).
struct Image
{
  int width = 0;
  int height = 0;
  std::vector<float> rgb;         ///< 3 per pixel, linear unless displayApplied
  std::vector<uint8_t> covered;   ///< 1 where a surface was drawn
  std::vector<uint16_t> coverage; ///< per-pixel polygon count (countCoverage only)
  /// Per pixel, the drawn surface's normalized device depth z/w in [-1, 1]
  /// (OpenGL's convention; +inf where nothing was drawn), when
  /// RenderOptions::keepDepth asked for it (CPU, no supersampling).
  std::vector<float> depth;
  /// Per pixel RGBA8, when RenderOptions::displayBytes asked for them: the
  /// display values of covered pixels, alpha 255 there and 0 elsewhere
  /// (where `rgb` is then not written either).
  std::vector<uint8_t> displayBytes;

  /// `rgb` holds display values already, of `appliedDisplay`.
  bool displayApplied = false;
  DisplayTransform appliedDisplay = DisplayTransform::Clamp;

  /// 8-bit RGB after the display transform (ApplyDisplay). NaN never occurs
  /// (tested) but would map to 0. An image whose backend applied its
  /// display transform is only quantized; asking it for another transform
  /// throws std::logic_error (a caller's bug: render with that transform).
  std::vector<uint8_t> ToRGB8(DisplayTransform transform) const;
  /// The same for `count` pixels from pixel `first`, written to `out`
  /// (3 bytes a pixel): a caller's own buffer, row by row.
  void ToRGB8(DisplayTransform transform, size_t first, size_t count, uint8_t* out) const;
};

/**
 * Box-filters a full-resolution linear RGB frame (row 0 at the top) by
 * `factor` per axis into `out` (the supersampling resolve of both renderers).
 * A pixel is covered when any of its samples is.
 */
void DownsampleBox(const std::vector<float>& rgb, const std::vector<uint8_t>& covered, int width,
  int height, int factor, Image& out);

} // namespace shadinglab::render
