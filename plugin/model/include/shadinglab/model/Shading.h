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

  /// A = (Rs + Rp) / 2 and B = (Rs - Rp) / 2 at cos(theta_i) = L.H
  /// (docs/model.md eq. 8.2), per wavelength when spectral.
  SL_INLINE void FresnelSP(T cosTheta_i, Vec3<T>& A, Vec3<T>& B) const
  {
    if (spectralCount > 0)
    {
      F_Spectral_SP(cosTheta_i, spectralEta, spectralK, spectralWeight, spectralCount, A, B);
    }
    else
    {
      F_RGB_SP(cosTheta_i, eta, k, A, B);
    }
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
 * A linear polarizer in front of the camera, the analyser (docs/model.md
 * eq. 8.3): what passes of a Stokes vector S in the image's frame is
 * (S0 + S1 cos 2 theta + S2 sin 2 theta) / 2, theta its transmission axis
 * from the image's x axis. Lights are unpolarized, diffuse reflection
 * depolarizes: only the Fresnel term carries polarization.
 */
template <typename T>
struct Analyser
{
  bool on = false;
  T cos2Theta = T(1), sin2Theta = T(0);
  /// The image's x and y axes in the space the shading is done in.
  Vec3<T> right{ T(1), T(0), T(0) }, up{ T(0), T(1), T(0) };

  template <typename U>
  Analyser<U> Cast() const
  {
    Analyser<U> out;
    out.on = on;
    out.cos2Theta = static_cast<U>(cos2Theta);
    out.sin2Theta = static_cast<U>(sin2Theta);
    out.right = Vec3<U>(right);
    out.up = Vec3<U>(up);
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
 * kd Rd + ks Rs for one pair of directions: the BRDF (1/sr) of
 * docs/model.md eq. 1.2.
 * N, L, V unit, pointing away from the surface.
 */
template <typename T>
SL_INLINE Vec3<T> EvaluateBrdf(
  const Material<T>& material, const Vec3<T>& diffuseColor, const Vec3<T>& N, const Vec3<T>& L,
  const Vec3<T>& V, const Analyser<T>* analyser = nullptr)
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
      if (analyser && analyser->on)
      {
        // Through the analyser (eq. 8.4): the specular reflection of
        // unpolarized light is (A, B, 0, 0) in the microfacet's s/p frame,
        // s = L x V (L, V and H lie in its plane of incidence) at angle phi
        // from the image's x axis; (A + B cos 2(theta - phi)) / 2 passes.
        // The diffuse term is unpolarized: half passes.
        Vec3<T> A, B;
        material.FresnelSP(VoH, A, B);
        const Vec3<T> sAxis = Cross(L, V);
        const T c = Dot(sAxis, analyser->right), d = Dot(sAxis, analyser->up);
        const T r2 = c * c + d * d;
        // L parallel to V: normal incidence on the facet, Rs = Rp (B = 0).
        const auto oblique = r2 > T(kTinyDenominator<ScalarOf<T>>);
        const T inv = T(1) / Max(r2, T(kTinyDenominator<ScalarOf<T>>));
        const T cos2Phi = Select(oblique, (c * c - d * d) * inv, T(1));
        const T sin2Phi = Select(oblique, T(2) * c * d * inv, T(0));
        const T cos2Delta = analyser->cos2Theta * cos2Phi + analyser->sin2Theta * sin2Phi;
        F = (A + B * cos2Delta) * T(0.5);
        const T DG = Fs_CookTorrance(T(1), D, G, NoL, NoV, material.variant);
        f = diffuse * T(0.5) + F * (material.ks * DG);
        break;
      }
      F = material.Fresnel(VoH);
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
    // No Fresnel term: these models reflect unpolarized light unpolarized.
    f *= T(0.5);
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
  // The ambient light is unpolarized: half passes an analyser.
  Vec3<T> result = material.ambient * lighting.ambientIntensity * T(analyser ? 0.5 : 1.0);
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
      lit, irradiance * EvaluateBrdf(material, diffuseColor, N, L, V, analyser) * NoL, Vec3<T>());
  }
  return result;
}

} // namespace shadinglab
