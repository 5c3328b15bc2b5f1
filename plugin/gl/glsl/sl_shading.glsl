// SPDX-License-Identifier: BSD-3-Clause
// The illumination model (docs/model.md eq. 1.1) (GLSL twin of Shading.h):
//   I_r = Ra Ia + sum_j I_Lj (N.Lj) dw_j (kd Rd + ks Rs).
// Variants are compile-time #defines set by vtkShadingLabPolyDataMapper, so
// a scene pays only for what it uses:
//   SL_MODEL        SL_MODEL_LAMBERT, _PHONG, _BLINN_PHONG, _COOK_TORRANCE or
//                   _LOMMEL_SEELIGER
//   SL_LIGHT_COUNT  number of lights (1..8)
//   SL_POINT_LIGHTS 1 when any light is positional
//   SL_SPECULAR     0 drops the specular term (ks = 0)
//   SL_LOBE_COUNT   Beckmann mixture size (1..4)
//   SL_CONDUCTOR    1 when any k > 0 (complex-index Fresnel)
//   SL_SPECTRAL     1: Fresnel per wavelength (eq. 7.3) instead of per channel
//   SL_ANALYSER     1: a polarizer in front of the camera (eq. 8.3-8.4)
//   SL_LIGHT_POLARIZER 1: a linear polarizer in front of the lights (eq. 8.6)
//   SL_HEADLIGHT    1 when the only light is a headlight: L = +z in view
//                   coordinates, a constant the compiler folds

// xyz; w = 0: unit direction to the light (normalized by the mapper), 1: position.
uniform vec4 slLightVectorVC[SL_MAX_LIGHTS];
uniform vec3 slLightIrradiance[SL_MAX_LIGHTS]; // I_L dw
uniform vec3 slLightAttenuation[SL_MAX_LIGHTS];
// Spot cone: xyz unit axis (from the light outwards), w = cos(cone half-angle),
// or w < -1.5 for no cone; exponent of the cos^e falloff.
uniform vec4 slLightSpot[SL_MAX_LIGHTS];
uniform float slLightSpotExponent[SL_MAX_LIGHTS];
uniform vec3 slAmbient;                        // Ra Ia
uniform vec3 slSpecularColor;
uniform float slKd;
uniform float slKs;
uniform float slShininess;
uniform float slLobeWeight[SL_MAX_LOBES];
uniform float slLobeM[SL_MAX_LOBES];
uniform vec3 slEta;
uniform vec3 slK;
#if SL_SPECTRAL
// Fresnel per wavelength (docs/model.md eq. 7.3): eta, k at the samples'
// wavelengths and their CIE/D65 weights to linear sRGB.
uniform float slSpectralEta[SL_SPECTRAL_SAMPLES];
uniform float slSpectralK[SL_SPECTRAL_SAMPLES];
uniform vec3 slSpectralWeight[SL_SPECTRAL_SAMPLES];
#endif
uniform float slJacobian;
#if SL_ANALYSER
// The analyser's row (Shading.h Analyser): cos 2 theta, sin 2 theta of its
// axis from the image's x axis (view coordinates: x right, y up), and 1
// for a circular analyser.
uniform vec3 slAnalyser;
#endif
#if SL_LIGHT_POLARIZER
// The lights' polarizer axis in view coordinates (cos psi, sin psi, 0); its
// fallback is the viewing axis (0, 0, 1). The mapper scales the lights'
// irradiance by kPolarizerTransmittance.
uniform vec3 slLightPolarizer;
#endif

// Direction to the light and its irradiance factor at P (view coordinates).
bool LightIncidence(int j, vec3 P, out vec3 L, out vec3 irradiance)
{
#if SL_HEADLIGHT
  L = vec3(0.0, 0.0, 1.0);
  irradiance = slLightIrradiance[0];
  return true;
#endif
  vec4 lv = slLightVectorVC[j];
#if SL_POINT_LIGHTS
  if (lv.w == 0.0)
#endif
  {
    L = lv.xyz;
    irradiance = slLightIrradiance[j];
    return true;
  }
#if SL_POINT_LIGHTS
  vec3 toLight = lv.xyz - P;
  float d = length(toLight);
  if (!(d > 0.0))
  {
    return false;
  }
  L = toLight / d;
  vec3 a = slLightAttenuation[j];
  irradiance = slLightIrradiance[j] / max(a.x + a.y * d + a.z * d * d, SL_TINY_DENOMINATOR);
  vec4 spot = slLightSpot[j];
  if (spot.w > -1.5)
  {
    // Spot cone (OpenGL 1.x / VTK): outside it no light, inside cos^e.
    float coneDot = -dot(L, spot.xyz);
    if (!(coneDot >= spot.w))
    {
      return false;
    }
    irradiance *= pow(coneDot, slLightSpotExponent[j]);
  }
  return true;
#endif
}

// kd Rd + ks Rs of the cosine-lobe models from the cosines alone
// (Shading.h BrdfFromCosines; docs/model.md eq. 1.3-1.4): exact shading and
// fast Phong both call it. RoV = R.V, NoH = N.H.
vec3 BrdfFromCosines(vec3 diffuseColor, float NoH, float RoV)
{
  vec3 diffuse = diffuseColor * (slKd * Fd_Lambert());
#if SL_MODEL == SL_MODEL_PHONG && SL_SPECULAR
  return diffuse + slSpecularColor * (slKs * Fs_Phong(RoV, slShininess));
#elif SL_MODEL == SL_MODEL_BLINN_PHONG && SL_SPECULAR
  return diffuse + slSpecularColor * (slKs * Fs_BlinnPhong(NoH, slShininess));
#else
  return diffuse;
#endif
}

#if SL_MODEL == SL_MODEL_COOK_TORRANCE && (SL_ANALYSER || SL_LIGHT_POLARIZER)
// The Fresnel term through the polarizers (Shading.h F_Polarized;
// docs/model.md eq. 8.2-8.6): the light's Stokes vector in the frame of
// s = L x V, times Fresnel's Mueller matrix, into the image's frame,
// through the analyser (or its S0 without one).
vec3 F_Polarized(float cosTheta_i, vec3 L, vec3 V)
{
  vec3 A, B, C, D;
#if SL_SPECTRAL
  F_Spectral_Mueller(cosTheta_i, slSpectralEta, slSpectralK, slSpectralWeight, A, B, C, D);
#else
  F_RGB_Mueller(cosTheta_i, slEta, slK, A, B, C, D);
#endif
  vec3 s = cross(L, V);
  bool oblique = dot(s, s) > SL_TINY_DENOMINATOR;
  float S1 = 0.0, S2 = 0.0;
#if SL_LIGHT_POLARIZER
  vec3 e = slLightPolarizer - L * dot(slLightPolarizer, L);
  vec3 f0 = vec3(0.0, 0.0, 1.0);
  e = dot(e, e) > SL_TINY_DENOMINATOR ? e : f0 - L * dot(f0, L);
  s = oblique ? s : e;
  float ex = dot(e, s), ey = dot(e, cross(s, L));
  float invE = 1.0 / max(ex * ex + ey * ey, SL_TINY_DENOMINATOR);
  S1 = (ex * ex - ey * ey) * invE;
  S2 = 2.0 * ex * ey * invE;
#else
  s = oblique ? s : vec3(1.0, 0.0, 0.0);
#endif
  vec3 out0 = A + B * S1, out1 = B + A * S1, out2 = C * S2, out3 = D * -S2;
#if SL_ANALYSER
  float r2 = dot(s.xy, s.xy);
  bool seen = r2 > SL_TINY_DENOMINATOR;
  float inv = 1.0 / max(r2, SL_TINY_DENOMINATOR);
  float cos2Phi = seen ? (s.x * s.x - s.y * s.y) * inv : 1.0;
  float sin2Phi = seen ? 2.0 * s.x * s.y * inv : 0.0;
  vec3 image1 = out1 * cos2Phi - out2 * sin2Phi;
  vec3 image2 = out1 * sin2Phi + out2 * cos2Phi;
  return (out0 + image1 * slAnalyser.x + image2 * slAnalyser.y + out3 * slAnalyser.z) *
    SL_POLARIZER_TRANSMITTANCE;
#else
  return out0;
#endif
}
#endif

#if SL_MODEL == SL_MODEL_COOK_TORRANCE && SL_SPECULAR
// F at cos(theta_i) (Shading.h Material::Fresnel).
vec3 SlFresnel(float cosTheta_i)
{
#if SL_SPECTRAL
  return F_Spectral(cosTheta_i, slSpectralEta, slSpectralK, slSpectralWeight);
#elif SL_CONDUCTOR
  return F_RGB(cosTheta_i, slEta, slK);
#else
  return vec3(F_Dielectric(cosTheta_i, slEta.x), F_Dielectric(cosTheta_i, slEta.y),
    F_Dielectric(cosTheta_i, slEta.z));
#endif
}
#endif

// kd Rd + ks Rs for one pair of directions (Shading.h EvaluateBrdf;
// docs/model.md eq. 1.2).
vec3 EvaluateBrdf(vec3 diffuseColor, vec3 N, vec3 L, vec3 V)
{
  float NoL = dot(N, L);
  float NoV = dot(N, V);
  bool above = NoL > 0.0 && NoV > 0.0;
#if SL_MODEL == SL_MODEL_LOMMEL_SEELIGER
  vec3 f = diffuseColor * (slKd * Fd_LommelSeeliger(NoL, NoV));
#if SL_ANALYSER
  f *= SL_POLARIZER_TRANSMITTANCE; // unpolarized: half passes the analyser
#endif
  return above ? f : vec3(0.0);
#elif SL_MODEL != SL_MODEL_COOK_TORRANCE || !SL_SPECULAR
#if SL_MODEL == SL_MODEL_PHONG
  float RoV = dot(N * (2.0 * NoL) - L, V);
  float NoH = 0.0;
#elif SL_MODEL == SL_MODEL_BLINN_PHONG
  float RoV = 0.0;
  float NoH = dot(N, HalfVector(L, V, N));
#else
  float RoV = 0.0, NoH = 0.0;
#endif
  vec3 f = BrdfFromCosines(diffuseColor, NoH, RoV);
#if SL_ANALYSER
  f *= SL_POLARIZER_TRANSMITTANCE; // no Fresnel term: depolarized, half passes
#endif
  return above ? f : vec3(0.0);
#else
  vec3 diffuse = diffuseColor * (slKd * Fd_Lambert());
  vec3 H = HalfVector(L, V, N);
  float NoH = dot(N, H);
  float VoH = max(dot(V, H), 0.0);
  float D = D_BeckmannMixture(NoH, slLobeWeight, slLobeM, SL_LOBE_COUNT);
  float G = G_CookTorrance(NoH, NoV, NoL, VoH);
  vec3 F = SlFresnel(VoH);
#if SL_TINT
  // The data colour as F0 (eq. 9.4, Shading.h F_Tinted).
  vec3 Ft = F_Tinted(F, SlFresnel(1.0), diffuseColor);
#endif
  float DG = Fs_CookTorrance(1.0, D, G, NoL, NoV, slJacobian);
#if SL_ANALYSER || SL_LIGHT_POLARIZER
  // Polarized (eq. 8.2-8.6; EvaluateBrdf in Shading.h); diffuse reflection
  // depolarizes: half of it passes an analyser.
#if SL_TINT
  F = F_Polarized(VoH, L, V) * Ft / max(F, vec3(SL_TINY_DENOMINATOR));
#else
  F = F_Polarized(VoH, L, V);
#endif
#elif SL_TINT
  F = Ft;
#endif
#if SL_ANALYSER
  diffuse *= SL_POLARIZER_TRANSMITTANCE;
#endif
  vec3 f = diffuse + F * (slKs * DG);
  return above ? f : vec3(0.0);
#endif
}

vec3 Shade(vec3 diffuseColor, vec3 P, vec3 N, vec3 V)
{
#if SL_ANALYSER
  vec3 result = SL_POLARIZER_TRANSMITTANCE * slAmbient; // unpolarized ambient light
#else
  vec3 result = slAmbient;
#endif
#if SL_TINT
  result *= diffuseColor; // eq. 9.4: the surroundings in the data colour
#endif
  for (int j = 0; j < SL_LIGHT_COUNT; ++j)
  {
    vec3 L, irradiance;
    if (!LightIncidence(j, P, L, irradiance))
    {
      continue;
    }
    // EvaluateBrdf is 0 below the horizon; max() keeps this branch-free.
    float NoL = max(dot(N, L), 0.0);
    result += irradiance * EvaluateBrdf(diffuseColor, N, L, V) * NoL;
  }
  return result;
}
