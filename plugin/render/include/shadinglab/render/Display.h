// SPDX-License-Identifier: BSD-3-Clause
// Linear intensity to display value (docs/model.md, section 6): the C++
// half of a twin whose GLSL half is plugin/gl/glsl/sl_display.glsl (same
// function names; the constants reach the GLSL as generated #defines).
#pragma once

#include "shadinglab/model/Vec3.h"
#include "shadinglab/render/Options.h"

#include <algorithm>
#include <cstdint>
#include <cmath>

namespace shadinglab::render
{

/// PBR Neutral's F90: the Fresnel reflectance at normal incidence of an
/// IOR-1.5 dielectric, subtracted as the toe's black offset (Khronos).
inline constexpr float kNeutralF90 = 0.04f;
/// PBR Neutral's K_s: compression starts where the largest channel reaches
/// 0.8 - F90 (below it the curve is c - F90: identity up to the offset).
inline constexpr float kNeutralStartCompression = 0.8f - kNeutralF90;
/// PBR Neutral's K_d: how fast compressed highlights desaturate towards white.
inline constexpr float kNeutralDesaturation = 0.15f;

/// Khronos PBR Neutral tone mapping (Khronos Group 2024, "PBR Neutral
/// Specification"; docs/model.md eq. 6.1). Input: non-negative linear
/// Rec. 709; output: linear Rec. 709 in [0, 1), reaching 1 only as the
/// input goes to infinity (an 8-bit 255 needs a peak above ~29).
inline Vec3<float> PbrNeutral(Vec3<float> c)
{
  const float x = std::min(c.x, std::min(c.y, c.z));
  const float f = x < 2.0f * kNeutralF90 ? x - x * x / (4.0f * kNeutralF90) : kNeutralF90;
  c = c - Vec3<float>(f, f, f);
  const float p = std::max(c.x, std::max(c.y, c.z));
  if (!(p > kNeutralStartCompression))
  {
    return c;
  }
  const float d = 1.0f - kNeutralStartCompression;
  const float pn = 1.0f - d * d / (p + d - kNeutralStartCompression);
  const float g = 1.0f / (kNeutralDesaturation * (p - pn) + 1.0f);
  return c * (pn / p * g) + Vec3<float>(pn, pn, pn) * (1.0f - g);
}

/// IEC 61966-2-1 sRGB encoding of a linear value in [0, 1] (eq. 6.2).
inline float EncodeSRGB(float v)
{
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

/// The display value in [0, 1] of a linear colour. A NaN, infinite or
/// negative channel becomes 0 (no renderer produces one: tested).
inline Vec3<float> ApplyDisplay(DisplayTransform transform, Vec3<float> c)
{
  auto sane = [](float v) { return std::isfinite(v) ? std::max(v, 0.0f) : 0.0f; };
  c = Vec3<float>(sane(c.x), sane(c.y), sane(c.z));
  if (transform == DisplayTransform::Neutral)
  {
    c = PbrNeutral(c);
  }
  auto unit = [](float v) { return std::clamp(v, 0.0f, 1.0f); };
  c = Vec3<float>(unit(c.x), unit(c.y), unit(c.z));
  if (transform == DisplayTransform::SRGB)
  {
    c = Vec3<float>(EncodeSRGB(c.x), EncodeSRGB(c.y), EncodeSRGB(c.z));
  }
  return c;
}

/// A display value in [0, 1] (ApplyDisplay's) as an 8-bit level: v * 255
/// rounded half away from zero, as std::lround, without its library call
/// (the hand-over converts a million pixels a frame). Exact: v * 255 is a
/// float below 256, and adding 0.5 to it in double loses no bit.
inline uint8_t ToByte(float v)
{
  return static_cast<uint8_t>(static_cast<double>(v * 255.0f) + 0.5);
}

/// Pixels [first, last) of linear RGB (three floats a pixel) as RGBA8
/// display bytes, four a pixel: ApplyDisplay, then ToByte, alpha 255 where
/// `covered` and 0 elsewhere (an uncovered pixel's colour bytes are left as
/// they are: whoever reads them blends by alpha). Returns the number of
/// covered pixels. What the CPU renderer hands to OpenGL
/// (RenderOptions::displayBytes), as Image::ToRGB8 rounds. Always inlined:
/// called once a band, GCC kept it a call, which cost a Phong frame of
/// ParaView's 1M sphere ~1% (BM_CpuParaViewSphere).
[[gnu::always_inline]] inline size_t ToDisplayBytes(DisplayTransform transform, const float* rgb, const uint8_t* covered,
  size_t first, size_t last, uint8_t* rgba)
{
  size_t count = 0;
  for (size_t i = first; i < last; ++i)
  {
    uint8_t* out = rgba + 4 * i;
    if (!covered[i])
    {
      out[3] = 0;
      continue;
    }
    ++count;
    const Vec3<float> c = ApplyDisplay(transform, Vec3<float>(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]));
    out[0] = ToByte(c.x);
    out[1] = ToByte(c.y);
    out[2] = ToByte(c.z);
    out[3] = 255;
  }
  return count;
}

const char* DisplayTransformName(DisplayTransform transform);

} // namespace shadinglab::render
