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
//   SL_ANALYSER     1: a linear polarizer in front of the camera (eq. 8.3-8.4)
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
// cos 2 theta, sin 2 theta of the analyser's axis from the image's x axis
// (view coordinates: x right, y up).
uniform vec2 slAnalyser;
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
  f *= 0.5; // unpolarized: half passes the analyser
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
  f *= 0.5; // no Fresnel term: unpolarized, half passes the analyser
#endif
  return above ? f : vec3(0.0);
#else
  vec3 diffuse = diffuseColor * (slKd * Fd_Lambert());
  vec3 H = HalfVector(L, V, N);
  float NoH = dot(N, H);
  float VoH = max(dot(V, H), 0.0);
  float D = D_BeckmannMixture(NoH, slLobeWeight, slLobeM, SL_LOBE_COUNT);
  float G = G_CookTorrance(NoH, NoV, NoL, VoH);
#if SL_SPECTRAL
  vec3 F = F_Spectral(VoH, slSpectralEta, slSpectralK, slSpectralWeight);
#elif SL_CONDUCTOR
  vec3 F = F_RGB(VoH, slEta, slK);
#else
  vec3 F = vec3(F_Dielectric(VoH, slEta.x), F_Dielectric(VoH, slEta.y), F_Dielectric(VoH, slEta.z));
#endif
  float DG = Fs_CookTorrance(1.0, D, G, NoL, NoV, slJacobian);
#if SL_ANALYSER
  // Through the analyser (eq. 8.4; EvaluateBrdf in Shading.h): the
  // specular Stokes vector (A, B, 0, 0) in the frame of s = L x V, at
  // angle phi from the image's x axis; the diffuse term passes by half.
  vec3 A, B;
#if SL_SPECTRAL
  F_Spectral_SP(VoH, slSpectralEta, slSpectralK, slSpectralWeight, A, B);
#else
  F_RGB_SP(VoH, slEta, slK, A, B);
#endif
  vec3 sAxis = cross(L, V);
  float r2 = dot(sAxis.xy, sAxis.xy);
  bool oblique = r2 > SL_TINY_DENOMINATOR;
  float inv = 1.0 / max(r2, SL_TINY_DENOMINATOR);
  float cos2Phi = oblique ? (sAxis.x * sAxis.x - sAxis.y * sAxis.y) * inv : 1.0;
  float sin2Phi = oblique ? 2.0 * sAxis.x * sAxis.y * inv : 0.0;
  float cos2Delta = slAnalyser.x * cos2Phi + slAnalyser.y * sin2Phi;
  F = 0.5 * (A + B * cos2Delta);
  diffuse *= 0.5;
#endif
  vec3 f = diffuse + F * (slKs * DG);
  return above ? f : vec3(0.0);
#endif
}

vec3 Shade(vec3 diffuseColor, vec3 P, vec3 N, vec3 V)
{
#if SL_ANALYSER
  vec3 result = 0.5 * slAmbient; // unpolarized ambient light
#else
  vec3 result = slAmbient;
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
