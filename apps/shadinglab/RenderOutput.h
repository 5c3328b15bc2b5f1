// SPDX-License-Identifier: BSD-3-Clause
// Writing what the render commands make: PNG files and panel labels.
#pragma once

#include "shadinglab/render/ColorMap.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadinglab::cli
{

/// Writes an 8-bit RGB image (row 0 at the top) as PNG. Throws UsageError
/// with one line when the file cannot be written.
void WritePng(int width, int height, const std::vector<uint8_t>& rgb8, const std::string& path);

/// Draws `text` into the RGB8 canvas at (x, y) (top-left origin), white on
/// the canvas colour, using VTK's FreeType text rendering (no GL needed).
void DrawLabel(std::vector<uint8_t>& canvas, int canvasWidth, int canvasHeight, int x, int y,
  const std::string& text, int fontSize = 15);

/// Draws a vertical colour legend at the right edge of the canvas (over a
/// darkened box, as ParaView's scalar bar sits over the view): `title`
/// above, the map's bins from its minimum (bottom) to maximum, five ticks
/// with their values. Sized from the canvas height (15 px text at 768).
void DrawColorLegend(std::vector<uint8_t>& canvas, int canvasWidth, int canvasHeight,
  const render::ColorMap& map, const std::string& title);

} // namespace shadinglab::cli
