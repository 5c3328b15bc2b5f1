// SPDX-License-Identifier: BSD-3-Clause
// The illumination model (docs/model.md eq. 1.1), shared by every shading mode:
//
//   I_r = Ra Ia + sum_j I_Lj (N.Lj) dw_j (kd Rd + ks Rs)
//
// with Rd = rho / pi (Lambert, rho the diffuse colour) and Rs the specular
// BRDF of the chosen model (Phong, Blinn-Phong or Cook-Torrance). The
// modes (flat, Gouraud, Phong, fast Phong) differ only in *where* this is
// evaluated; they all call Shade().
#pragma once

#include "shadinglab/model/Brdf.h"
#include "shadinglab/model/Constants.h"
#include "shadinglab/model/Fresnel.h"
#include "shadinglab/model/Vec3.h"

#include <cmath>
#include <string>
#include <string_view>

namespace shadinglab
{

/// What is evaluated: the reflectance model (docs/model.md section 1).
/// Where it is evaluated (flat, Gouraud, Phong, fast Phong) is a separate
/// choice, render::ShadingMode.
enum class ReflectanceModel
{
  Lambert,
  Phong,
  BlinnPhong,
  CookTorrance,
  LommelSeeliger, ///< the full moon's diffuse law (eq. 1.12): no specular term
};

/// One row of the reflectance models' name table: the one list the CLI,
/// the material format, the VTK classes and the GLSL #defines read.
struct ReflectanceModelRow
{
  ReflectanceModel value;
  const char* name;  ///< command-line / material-format name
  const char* label; ///< for people
  const char* glsl;  ///< GLSL #define suffix (SL_MODEL_<glsl>)
  /// The material parameters the model reads, by their keys in the
  /// settings table (space-separated): what a material editor shows for it.
  /// A new model declares its own here.
  const char* parameters;
};

inline constexpr ReflectanceModelRow kReflectanceModels[] = {
  { ReflectanceModel::Lambert, "lambert", "Lambert", "LAMBERT", "ambient kd albedo" },
  { ReflectanceModel::Phong, "phong", "Phong", "PHONG", "ambient kd ks shininess albedo specular" },
  { ReflectanceModel::BlinnPhong, "blinn-phong", "Blinn-Phong", "BLINN_PHONG",
    "ambient kd ks shininess albedo specular" },
  // F colours the specular term: no specular colour (eq. 1.5-1.8).
  { ReflectanceModel::CookTorrance, "cook-torrance", "Cook-Torrance", "COOK_TORRANCE",
    "ambient kd ks m w eta k variant spectral albedo" },
  { ReflectanceModel::LommelSeeliger, "lommel-seeliger", "Lommel-Seeliger", "LOMMEL_SEELIGER",
    "ambient kd albedo" },
};

/// Whether `model` reads the material parameter `key` (its row's
/// `parameters`).
inline bool ModelUsesParameter(ReflectanceModel model, std::string_view key)
{
  for (const ReflectanceModelRow& row : kReflectanceModels)
  {
    if (row.value != model)
    {
      continue;
    }
    std::string_view rest = row.parameters;
    while (!rest.empty())
    {
      const size_t space = rest.find(' ');
      if (rest.substr(0, space) == key)
      {
        return true;
      }
      rest = space == std::string_view::npos ? std::string_view() : rest.substr(space + 1);
    }
  }
  return false;
}

/// Material parameters of the illumination model. Plain data, so it can be
/// cast between float and double and uploaded to GLSL uniforms unchanged.
template <typename T>
struct Material
{
  ReflectanceModel model = ReflectanceModel::BlinnPhong;
  /// Ambient reflectance Ra (eq. 1.1).
  Vec3<T> ambient{ T(0.05), T(0.05), T(0.05) };
  /// Diffuse colour rho (albedo), Rd = rho / pi; per-vertex colours replace it.
  Vec3<T> diffuseColor{ T(1), T(1), T(1) };
  /// Specular colour for Phong and Blinn-Phong (Cook-Torrance takes its
  /// colour from the Fresnel term instead).
  Vec3<T> specularColor{ T(1), T(1), T(1) };
  T kd = T(0.7);
  T ks = T(0.3);
  /// Exponent n of (R.V)^n and (N.H)^n.
  T shininess = T(32);

  // Cook-Torrance (docs/model.md eq. 1.5-1.10).
  BeckmannLobe<T> lobes[kMaxLobes] = {};
  int lobeCount = 1;
  /// Relative index of refraction per RGB channel.
  Vec3<T> eta{ T(1.5), T(1.5), T(1.5) };
  /// Extinction coefficient per channel; any k > 0 selects the conductor
  /// Fresnel (complex index eta + i k).
  Vec3<T> k{ T(0), T(0), T(0) };
  SpecularVariant variant = SpecularVariant::CookTorrance1982;
  /// A conductor coloured by data (render::MaterialForData): the per-point
  /// colour rho becomes the Fresnel term's F0 and tints the ambient term
  /// (glTF 2.0's metallic convention; docs/model.md eq. 9.4).
  bool albedoTintsFresnel = false;

  /// Fresnel per wavelength (docs/model.md eq. 7.3): with spectralCount > 0
  /// F = sum_i spectralWeight[i] F(cos, spectralEta[i], spectralK[i])
  /// replaces the RGB eta and k. Filled by SetSpectral (Spectrum.h) from
  /// measured data; 0 is the three-sample RGB material.
  int spectralCount = 0;
  T spectralEta[kSpectralSamples] = {};
  T spectralK[kSpectralSamples] = {};
  Vec3<T> spectralWeight[kSpectralSamples] = {};

  template <typename U>
  Material<U> Cast() const
  {
    Material<U> out;
    out.model = model;
    out.ambient = Vec3<U>(ambient);
    out.diffuseColor = Vec3<U>(diffuseColor);
    out.specularColor = Vec3<U>(specularColor);
    out.kd = static_cast<U>(kd);
    out.ks = static_cast<U>(ks);
    out.shininess = static_cast<U>(shininess);
    for (int i = 0; i < kMaxLobes; ++i)
    {
      out.lobes[i].weight = static_cast<U>(lobes[i].weight);
      out.lobes[i].m = static_cast<U>(lobes[i].m);
    }
    out.lobeCount = lobeCount;
    out.eta = Vec3<U>(eta);
    out.k = Vec3<U>(k);
    out.variant = variant;
    out.albedoTintsFresnel = albedoTintsFresnel;
    // Only the samples in use: the wide kernel casts the material to
    // every lane once per pixel queue.
    out.spectralCount = spectralCount;
    for (int i = 0; i < spectralCount && i < kSpectralSamples; ++i)
    {
      out.spectralEta[i] = static_cast<U>(spectralEta[i]);
      out.spectralK[i] = static_cast<U>(spectralK[i]);
      out.spectralWeight[i] = Vec3<U>(spectralWeight[i]);
    }
    return out;
  }

  bool IsConductor() const { return k.x > T(0) || k.y > T(0) || k.z > T(0); }

  /// Fresnel's Mueller matrix entries A, B, C, D at cos(theta_i) = L.H
  /// (docs/model.md eq. 8.2), per wavelength when spectral.
  SL_INLINE void FresnelMueller(T cosTheta_i, Vec3<T>& A, Vec3<T>& B, Vec3<T>& C, Vec3<T>& D) const
  {
    if (spectralCount > 0)
    {
      F_Spectral_Mueller(cosTheta_i, spectralEta, spectralK, spectralWeight, spectralCount, A, B, C, D);
    }
    else
    {
      F_RGB_Mueller(cosTheta_i, eta, k, A, B, C, D);
    }
  }

  /// A = (Rs + Rp) / 2 and B = (Rs - Rp) / 2 alone (C, D folded away).
  SL_INLINE void FresnelSP(T cosTheta_i, Vec3<T>& A, Vec3<T>& B) const
  {
    Vec3<T> C, D;
    FresnelMueller(cosTheta_i, A, B, C, D);
  }

  /// F at cos(theta_i) = L.H: per wavelength when spectral, else per channel.
  SL_INLINE Vec3<T> Fresnel(T cosTheta_i) const
  {
    return spectralCount > 0
      ? F_Spectral(cosTheta_i, spectralEta, spectralK, spectralWeight, spectralCount)
      : F_RGB(cosTheta_i, eta, k);
  }
};

/**
 * glTF 2.0's metallic convention on the exact Fresnel term (docs/model.md
 * eq. 9.4; Khronos glTF 2.0 specification, appendix B, "metal_brdf"):
 * F_t = c + (1 - c) w, w = clamp((F - F0) / max(1 - F0, kMinFresnelGap),
 * 0, 1), per channel: the data colour c at normal incidence, rising to
 * white at grazing as the metal's own F rises from its F0.
 */
template <typename T>
SL_INLINE Vec3<T> F_Tinted(const Vec3<T>& F, const Vec3<T>& F0, const Vec3<T>& c)
{
  auto rise = [](const T& f, const T& f0) {
    return Min(Max((f - f0) / Max(T(1) - f0, T(kMinFresnelGap<ScalarOf<T>>)), T(0)), T(1));
  };
  const Vec3<T> w(rise(F.x, F0.x), rise(F.y, F0.y), rise(F.z, F0.z));
  return c + (Vec3<T>(T(1), T(1), T(1)) - c) * w;
}

/**
 * Checks a material against the model's domain. Returns an empty string when
 * valid, else a one-line description of the first problem (kd + ks > 1,
 * negative or non-finite values, eta <= 0, mixture weights not summing to 1,
 * shininess out of [0, kMaxShininess], ...).
 */
std::string ValidateMaterial(const Material<double>& material);

enum class LightType
{
  Directional,
  Point,
};

/// A light of docs/model.md eq. 1.1 and 1.11: intensity I_L over a solid angle dw.
template <typename T>
struct Light
{
  LightType type = LightType::Directional;
  /// Directional: unit direction *towards* the light. Point: position.
  Vec3<T> vector{ T(0), T(0), T(1) };
  Vec3<T> intensity{ T(1), T(1), T(1) };
  /// Solid angle dw. The default pi makes a unit white light on a white
  /// Lambertian surface (kd = 1) facing it give intensity 1: I_L dw Rd = 1,
  /// the scale of the classic (unnormalized) Phong model.
  T solidAngle = T(kPi<ScalarOf<T>>);
  /// Point lights: I_L / (c0 + c1 d + c2 d^2) (OpenGL's fixed-function form).
  /// (1, 0, 0) disables attenuation.
  Vec3<T> attenuation{ T(1), T(0), T(0) };
  /// Point lights as spot lights, OpenGL's and VTK's convention: a cone of
  /// half-angle coneAngle degrees around spotDirection (from the light
  /// outwards) with falloff cos^coneExponent; coneAngle > 90 is no cone.
  Vec3<T> spotDirection{ T(0), T(0), T(-1) };
  T coneAngle = T(180);
  T coneExponent = T(1);

  template <typename U>
  Light<U> Cast() const
  {
    Light<U> out;
    out.type = type;
    out.vector = Vec3<U>(vector);
    out.intensity = Vec3<U>(intensity);
    out.solidAngle = static_cast<U>(solidAngle);
    out.attenuation = Vec3<U>(attenuation);
    out.spotDirection = Vec3<U>(spotDirection);
    out.coneAngle = static_cast<U>(coneAngle);
    out.coneExponent = static_cast<U>(coneExponent);
    return out;
  }
};

/**
 * The analyser in front of the camera (docs/model.md eq. 8.3): what passes
 * of a Stokes vector S in the image's frame is
 *   (S0 + w1 S1 + w2 S2 + w3 S3) / 2,
 * (w1, w2, w3) = (cos 2 theta, sin 2 theta, 0) for a linear polarizer whose
 * axis is at theta from the image's x axis, (0, 0, 1) for a circular one
 * (a quarter-wave plate before it: right-handed light passes, eq. 8.5).
 */
template <typename T>
struct Analyser
{
  bool on = false;
  T cos2Theta = T(1), sin2Theta = T(0), circular = T(0);
  /// The image's x and y axes in the space the shading is done in.
  Vec3<T> right{ T(1), T(0), T(0) }, up{ T(0), T(1), T(0) };

  /// The analyser whose axis is `degrees` from the image's x axis (linear),
  /// or the circular one (the angle unused), in the image's own frame.
  static Analyser At(double degrees, bool isCircular)
  {
    const double twoTheta = 2.0 * degrees * kPi<double> / 180.0;
    Analyser a;
    a.on = true;
    a.cos2Theta = isCircular ? T(0) : static_cast<T>(std::cos(twoTheta));
    a.sin2Theta = isCircular ? T(0) : static_cast<T>(std::sin(twoTheta));
    a.circular = isCircular ? T(1) : T(0);
    return a;
  }

  template <typename U>
  Analyser<U> Cast() const
  {
    Analyser<U> out;
    out.on = on;
    out.cos2Theta = static_cast<U>(cos2Theta);
    out.sin2Theta = static_cast<U>(sin2Theta);
    out.circular = static_cast<U>(circular);
    out.right = Vec3<U>(right);
    out.up = Vec3<U>(up);
    return out;
  }
};

/**
 * A linear polarizer in front of every light (docs/model.md eq. 8.6): its
 * transmission axis is `axis` (cos psi right + sin psi up: psi from the
 * image's x axis, as the camera sees it) projected perpendicular to the
 * light's direction; where the light shines along that axis, `fallback`
 * (the camera's viewing axis, perpendicular to it) projected instead.
 * It passes kPolarizerTransmittance of the lamp's unpolarized light: the
 * renderers scale the lights' intensity by it (off: lights unpolarized).
 */
template <typename T>
struct LightPolarizer
{
  bool on = false;
  Vec3<T> axis{ T(1), T(0), T(0) }, fallback{ T(0), T(0), T(1) };

  template <typename U>
  LightPolarizer<U> Cast() const
  {
    LightPolarizer<U> out;
    out.on = on;
    out.axis = Vec3<U>(axis);
    out.fallback = Vec3<U>(fallback);
    return out;
  }
};

/// The lights and ambient intensity Ia of one scene.
template <typename T>
struct Lighting
{
  Light<T> lights[kMaxLights] = {};
  int lightCount = 1;
  Vec3<T> ambientIntensity{ T(1), T(1), T(1) };
  /// The analyser in front of the camera (off: the eye sees S0).
  Analyser<T> analyser;
  /// A polarizer in front of the lights (off: unpolarized lights).
  LightPolarizer<T> lightPolarizer;

  template <typename U>
  Lighting<U> Cast() const
  {
    Lighting<U> out;
    for (int i = 0; i < kMaxLights; ++i)
    {
      out.lights[i] = lights[i].template Cast<U>();
    }
    out.lightCount = lightCount;
    out.ambientIntensity = Vec3<U>(ambientIntensity);
    out.analyser = analyser.template Cast<U>();
    out.lightPolarizer = lightPolarizer.template Cast<U>();
    return out;
  }
};

/// Direction to the light from P and the irradiance factor I_L dw
/// (attenuated for point lights). Returns false (per lane) when the light
/// is at P or P is outside a spot light's cone; L and irradiance are then
/// not to be used.
template <typename T>
SL_INLINE MaskOf<T> LightIncidence(const Light<T>& light, const Vec3<T>& P, Vec3<T>& L, Vec3<T>& irradiance)
{
  using S = ScalarOf<T>;
  if (light.type == LightType::Directional)
  {
    L = NormalizeOr(light.vector, Vec3<T>(T(0), T(0), T(1)));
    irradiance = light.intensity * light.solidAngle;
    return MaskOf<T>(true);
  }
  const Vec3<T> toLight = light.vector - P;
  const T d = Length(toLight);
  auto reached = d > T(0);
  if (!AnyOf(reached))
  {
    return reached;
  }
  L = toLight / d;
  const T attenuation =
    light.attenuation.x + light.attenuation.y * d + light.attenuation.z * d * d;
  // Validation keeps c0 > 0 or the other terms positive; a zero sum at d > 0
  // cannot happen, but guard anyway so no Inf reaches a pixel.
  irradiance = light.intensity * (light.solidAngle / Max(attenuation, T(kTinyDenominator<S>)));
  if (AnyOf(light.coneAngle <= T(90)))
  {
    // Spot cone (OpenGL 1.x / VTK): outside it no light, inside cos^e.
    // (The cone is one light's: the same in every lane.)
    const T coneDot = -Dot(L, NormalizeOr(light.spotDirection, Vec3<T>(T(0), T(0), T(-1))));
    reached = reached && coneDot >= Cos(light.coneAngle * kPi<S> / S(180));
    if (!AnyOf(reached))
    {
      return reached;
    }
    irradiance *= Pow(coneDot, light.coneExponent);
  }
  return reached;
}

/**
 * kd Rd + ks Rs of the models whose specular lobe is a power of one cosine
 * (Lambert; Phong 1975, docs/model.md eq. 1.3; Blinn 1977, eq. 1.4), from
 * the cosines alone: RoV = R.V = 2 (N.L)(N.V) - L.V and NoH = N.H. The one
 * place these BRDFs are written: EvaluateBrdf calls it with exact cosines,
 * fast Phong with its quadratics and a table power (eq. 2.6-2.8), and the
 * GLSL twin (sl_shading.glsl) has the same function. Cook-Torrance is not a
 * function of these cosines: it returns the diffuse term only for it.
 */
template <ReflectanceModel Model, typename T, typename Power = StdPow>
SL_INLINE Vec3<T> BrdfFromCosines(const Material<T>& material, const Vec3<T>& diffuseColor, T NoH,
  T RoV, Power power = {})
{
  const Vec3<T> diffuse = diffuseColor * (material.kd * Fd_Lambert<T>());
  if constexpr (Model == ReflectanceModel::Phong)
  {
    return diffuse +
      material.specularColor * (material.ks * Fs_Phong(RoV, material.shininess, power));
  }
  else if constexpr (Model == ReflectanceModel::BlinnPhong)
  {
    return diffuse +
      material.specularColor * (material.ks * Fs_BlinnPhong(NoH, material.shininess, power));
  }
  else
  {
    return diffuse;
  }
}

/// The same with the material's model chosen at run time.
template <typename T, typename Power = StdPow>
SL_INLINE Vec3<T> BrdfFromCosines(const Material<T>& material, const Vec3<T>& diffuseColor, T NoH,
  T RoV, Power power = {})
{
  switch (material.model)
  {
    case ReflectanceModel::Phong:
      return BrdfFromCosines<ReflectanceModel::Phong>(material, diffuseColor, NoH, RoV, power);
    case ReflectanceModel::BlinnPhong:
      return BrdfFromCosines<ReflectanceModel::BlinnPhong>(material, diffuseColor, NoH, RoV, power);
    case ReflectanceModel::Lambert:
    case ReflectanceModel::CookTorrance:
    case ReflectanceModel::LommelSeeliger:
      break;
  }
  return BrdfFromCosines<ReflectanceModel::Lambert>(material, diffuseColor, NoH, RoV, power);
}

/**
 * The Fresnel term as the camera sees it through the polarizers
 * (docs/model.md eq. 8.2-8.6): the light's Stokes vector in the frame of
 * the microfacet's plane of incidence (s = L x V; L, V and H lie in that
 * plane), (1, 0, 0, 0) when unpolarized, (1, cos 2 beta, sin 2 beta, 0)
 * through the light's polarizer at beta from s; times Fresnel's Mueller
 * matrix (A, B, C, D); rotated by phi, s's angle from the image's x axis,
 * into the image's frame; through the analyser, or its S0 without one.
 * Per unit light intensity passing the light's polarizer.
 */
template <typename T>
SL_INLINE Vec3<T> F_Polarized(const Material<T>& material, T cosTheta_i, const Vec3<T>& L,
  const Vec3<T>& V, const Analyser<T>* analyser, const LightPolarizer<T>* lightPolarizer)
{
  using S = ScalarOf<T>;
  const T tiny = T(kTinyDenominator<S>);
  Vec3<T> A, B, C, D;
  material.FresnelMueller(cosTheta_i, A, B, C, D);
  // L parallel to V: normal incidence on the facet, where any s
  // perpendicular to V gives the same picture (Rs = Rp, C = -Rs, D = 0).
  Vec3<T> s = Cross(L, V);
  const auto oblique = Dot(s, s) > tiny;
  // The light's Stokes vector in the incident wave's frame (s, s x L):
  // the ratios below do not need s to be unit.
  T S1 = T(0), S2 = T(0);
  if (lightPolarizer)
  {
    const Vec3<T>& e0 = lightPolarizer->axis;
    Vec3<T> e = e0 - L * Dot(e0, L);
    const Vec3<T>& f0 = lightPolarizer->fallback;
    e = Select(Dot(e, e) > tiny, e, f0 - L * Dot(f0, L));
    s = Select(oblique, s, e);
    const T ex = Dot(e, s), ey = Dot(e, Cross(s, L));
    const T inv = T(1) / Max(ex * ex + ey * ey, tiny);
    S1 = (ex * ex - ey * ey) * inv;
    S2 = T(2) * ex * ey * inv;
  }
  else
  {
    s = Select(oblique, s, analyser->right);
  }
  // Fresnel's Mueller matrix on (1, S1, S2, 0) (eq. 8.2).
  const Vec3<T> out0 = A + B * S1, out1 = B + A * S1, out2 = C * S2, out3 = D * (T(0) - S2);
  if (!analyser)
  {
    return out0;
  }
  // Into the image's frame (eq. 8.4): the reflected wave's frame
  // (s, V x s) is right-handed about V, as (right, up) is.
  const T c = Dot(s, analyser->right), d = Dot(s, analyser->up);
  const T r2 = c * c + d * d;
  const auto seen = r2 > tiny;
  const T inv = T(1) / Max(r2, tiny);
  const T cos2Phi = Select(seen, (c * c - d * d) * inv, T(1));
  const T sin2Phi = Select(seen, T(2) * c * d * inv, T(0));
  const Vec3<T> image1 = out1 * cos2Phi - out2 * sin2Phi;
  const Vec3<T> image2 = out1 * sin2Phi + out2 * cos2Phi;
  // The analyser's row (eq. 8.3).
  return (out0 + image1 * analyser->cos2Theta + image2 * analyser->sin2Theta +
           out3 * analyser->circular) *
    T(kPolarizerTransmittance<S>);
}

/**
 * kd Rd + ks Rs for one pair of directions: the BRDF (1/sr) of
 * docs/model.md eq. 1.2.
 * N, L, V unit, pointing away from the surface.
 */
template <typename T>
SL_INLINE Vec3<T> EvaluateBrdf(
  const Material<T>& material, const Vec3<T>& diffuseColor, const Vec3<T>& N, const Vec3<T>& L,
  const Vec3<T>& V, const Analyser<T>* analyser = nullptr,
  const LightPolarizer<T>* lightPolarizer = nullptr)
{
  const T NoL = Dot(N, L);
  const T NoV = Dot(N, V);
  const auto lit = NoL > T(0) && NoV > T(0);
  if (!AnyOf(lit))
  {
    return {};
  }
  Vec3<T> f;
  switch (material.model)
  {
    case ReflectanceModel::Lambert:
      f = BrdfFromCosines(material, diffuseColor, T(0), T(0));
      break;
    case ReflectanceModel::Phong:
      f = BrdfFromCosines(material, diffuseColor, T(0), Dot(Reflect(L, N), V));
      break;
    case ReflectanceModel::BlinnPhong:
      f = BrdfFromCosines(material, diffuseColor, Dot(N, HalfVector(L, V, N)), T(0));
      break;
    case ReflectanceModel::CookTorrance:
    {
      const Vec3<T> diffuse = diffuseColor * (material.kd * Fd_Lambert<T>());
      const Vec3<T> H = HalfVector(L, V, N);
      const T NoH = Dot(N, H);
      const T VoH = Max(Dot(V, H), T(0));
      const T D = D_BeckmannMixture(NoH, material.lobes, material.lobeCount);
      const T G = G_CookTorrance(NoH, NoV, NoL, VoH);
      // F is evaluated at theta_i = acos(L.H) (eq. 1.8); L.H = V.H.
      Vec3<T> F;
      if ((analyser && analyser->on) || (lightPolarizer && lightPolarizer->on))
      {
        // Polarized (eq. 8.2-8.6); diffuse reflection depolarizes: half of
        // it passes an analyser.
        const Analyser<T>* a = analyser && analyser->on ? analyser : nullptr;
        const T DG = Fs_CookTorrance(T(1), D, G, NoL, NoV, material.variant);
        Vec3<T> polarized =
          F_Polarized(material, VoH, L, V, a, lightPolarizer && lightPolarizer->on ? lightPolarizer : nullptr);
        if (material.albedoTintsFresnel)
        {
          // The tint scales what passes, channel by channel, as it scales F.
          const Vec3<T> F1 = material.Fresnel(VoH);
          const Vec3<T> Ft = F_Tinted(F1, material.Fresnel(T(1)), diffuseColor);
          const T tiny(kTinyDenominator<ScalarOf<T>>);
          polarized = Vec3<T>(polarized.x * Ft.x / Max(F1.x, tiny), polarized.y * Ft.y / Max(F1.y, tiny),
            polarized.z * Ft.z / Max(F1.z, tiny));
        }
        f = diffuse * T(a ? kPolarizerTransmittance<ScalarOf<T>> : 1) + polarized * (material.ks * DG);
        break;
      }
      F = material.Fresnel(VoH);
      if (material.albedoTintsFresnel)
      {
        F = F_Tinted(F, material.Fresnel(T(1)), diffuseColor);
      }
      const T DG = Fs_CookTorrance(T(1), D, G, NoL, NoV, material.variant);
      f = diffuse + F * (material.ks * DG);
      break;
    }
    case ReflectanceModel::LommelSeeliger:
      f = diffuseColor * (material.kd * Fd_LommelSeeliger(NoL, NoV));
      break;
  }
  if (analyser && analyser->on && material.model != ReflectanceModel::CookTorrance)
  {
    // No Fresnel term: these models depolarize (docs/model.md section 8).
    f *= T(kPolarizerTransmittance<ScalarOf<T>>);
  }
  return Select(lit, f, Vec3<T>());
}

/**
 * The illumination model (docs/model.md eq. 1.1) at one surface point:
 *   I_r = Ra Ia + sum_j I_Lj (N.Lj) dw_j (kd Rd + ks Rs).
 * @param P position (for point lights), N unit normal, V unit direction to
 *   the viewer. Returns linear RGB, finite for finite input.
 */
template <typename T>
SL_INLINE Vec3<T> Shade(
  const Material<T>& material, const Lighting<T>& lighting, const Vec3<T>& diffuseColor,
  const Vec3<T>& P, const Vec3<T>& N, const Vec3<T>& V)
{
  const Analyser<T>* analyser = lighting.analyser.on ? &lighting.analyser : nullptr;
  const LightPolarizer<T>* lightPolarizer =
    lighting.lightPolarizer.on ? &lighting.lightPolarizer : nullptr;
  // The ambient light is unpolarized: half passes an analyser.
  Vec3<T> result = material.ambient * lighting.ambientIntensity *
    T(analyser ? kPolarizerTransmittance<ScalarOf<T>> : ScalarOf<T>(1));
  if (material.albedoTintsFresnel)
  {
    result = result * diffuseColor; // eq. 9.4: the surroundings in the data colour
  }
  for (int j = 0; j < lighting.lightCount; ++j)
  {
    Vec3<T> L, irradiance;
    const auto reached = LightIncidence(lighting.lights[j], P, L, irradiance);
    if (!AnyOf(reached))
    {
      continue;
    }
    const T NoL = Dot(N, L);
    const auto lit = reached && NoL > T(0);
    if (!AnyOf(lit))
    {
      continue;
    }
    // Lanes the light does not reach add 0 (a single value never gets here).
    result += Select(
      lit, irradiance * EvaluateBrdf(material, diffuseColor, N, L, V, analyser, lightPolarizer) * NoL, Vec3<T>());
  }
  return result;
}

} // namespace shadinglab
