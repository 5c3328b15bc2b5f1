// Linear intensity to display value (docs/model.md, section 6): the GLSL
// twin of plugin/render/include/shadinglab/render/Display.h, same names.
// SL_DISPLAY is set by the mapper; the constants are generated from the C++.

// Khronos PBR Neutral tone mapping (Khronos Group 2024; eq. 6.1).
vec3 PbrNeutral(vec3 c)
{
  float x = min(c.r, min(c.g, c.b));
  float f = x < 2.0 * SL_NEUTRAL_F90 ? x - x * x / (4.0 * SL_NEUTRAL_F90) : SL_NEUTRAL_F90;
  c -= vec3(f);
  float p = max(c.r, max(c.g, c.b));
  if (!(p > SL_NEUTRAL_START_COMPRESSION))
  {
    return c;
  }
  float d = 1.0 - SL_NEUTRAL_START_COMPRESSION;
  float pn = 1.0 - d * d / (p + d - SL_NEUTRAL_START_COMPRESSION);
  float g = 1.0 / (SL_NEUTRAL_DESATURATION * (p - pn) + 1.0);
  return c * (pn / p * g) + vec3(pn) * (1.0 - g);
}

// IEC 61966-2-1 sRGB encoding of a linear value in [0, 1] (eq. 6.2).
float EncodeSRGB(float v)
{
  return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

// The display value in [0, 1] of a linear colour; NaN and negative
// channels become 0 (max(NaN, 0) is 0 on every GPU we met, and the clamp
// below catches what is left).
vec3 ApplyDisplay(vec3 c)
{
  c = max(c, vec3(0.0));
#if SL_DISPLAY == SL_DISPLAY_NEUTRAL
  c = PbrNeutral(c);
#endif
  c = clamp(c, 0.0, 1.0);
#if SL_DISPLAY == SL_DISPLAY_SRGB
  c = vec3(EncodeSRGB(c.r), EncodeSRGB(c.g), EncodeSRGB(c.b));
#endif
  return c;
}
