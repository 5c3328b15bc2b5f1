// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/Image.h"

#include <algorithm>
#include <cmath>

namespace shadinglab::render
{

namespace
{

/// IEC 61966-2-1 sRGB encoding of a linear value in [0, 1].
float EncodeSRGB(float v)
{
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

} // namespace

void DownsampleBox(const std::vector<float>& rgb, const std::vector<uint8_t>& covered, int width,
  int height, int factor, Image& out)
{
  out.width = width / factor;
  out.height = height / factor;
  out.rgb.assign(static_cast<size_t>(out.width) * out.height * 3, 0.0f);
  out.covered.assign(static_cast<size_t>(out.width) * out.height, 0);
  const float norm = 1.0f / static_cast<float>(factor * factor);
  for (int y = 0; y < out.height; ++y)
  {
    for (int x = 0; x < out.width; ++x)
    {
      float sum[3] = { 0, 0, 0 };
      uint8_t any = 0;
      for (int sy = 0; sy < factor; ++sy)
      {
        for (int sx = 0; sx < factor; ++sx)
        {
          const size_t i = static_cast<size_t>(y * factor + sy) * width + (x * factor + sx);
          for (int c = 0; c < 3; ++c)
          {
            sum[c] += rgb[3 * i + c];
          }
          any |= covered[i];
        }
      }
      const size_t o = static_cast<size_t>(y) * out.width + x;
      for (int c = 0; c < 3; ++c)
      {
        out.rgb[3 * o + c] = sum[c] * norm;
      }
      out.covered[o] = any;
    }
  }
}

std::vector<uint8_t> Image::ToRGB8(DisplayTransform transform) const
{
  std::vector<uint8_t> out(this->rgb.size());
  for (size_t i = 0; i < this->rgb.size(); ++i)
  {
    float v = this->rgb[i];
    v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
    if (transform == DisplayTransform::SRGB)
    {
      v = EncodeSRGB(v);
    }
    out[i] = static_cast<uint8_t>(std::lround(v * 255.0f));
  }
  return out;
}

} // namespace shadinglab::render
