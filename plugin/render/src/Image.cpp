// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/Image.h"

#include "shadinglab/render/Display.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace shadinglab::render
{


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

const char* DisplayTransformName(DisplayTransform transform)
{
  for (const auto& row : kDisplayTransforms)
  {
    if (row.value == transform)
    {
      return row.name;
    }
  }
  return "?";
}

std::vector<uint8_t> Image::ToRGB8(DisplayTransform transform) const
{
  std::vector<uint8_t> out(this->rgb.size());
  this->ToRGB8(transform, 0, this->rgb.size() / 3, out.data());
  return out;
}

void Image::ToRGB8(DisplayTransform transform, size_t first, size_t count, uint8_t* out) const
{
  if (this->displayApplied && transform != this->appliedDisplay)
  {
    throw std::logic_error(std::string("the image went through display '") +
      DisplayTransformName(this->appliedDisplay) + "' already, not '" +
      DisplayTransformName(transform) + "'");
  }
  for (size_t i = first; i < first + count; ++i)
  {
    Vec3<float> c(this->rgb[3 * i], this->rgb[3 * i + 1], this->rgb[3 * i + 2]);
    c = this->displayApplied ? ApplyDisplay(DisplayTransform::Clamp, c) : ApplyDisplay(transform, c);
    out[3 * (i - first)] = ToByte(c.x);
    out[3 * (i - first) + 1] = ToByte(c.y);
    out[3 * (i - first) + 2] = ToByte(c.z);
  }
}

} // namespace shadinglab::render
