// SPDX-License-Identifier: BSD-3-Clause
// BRDF terms, one family per prefix (Filament's convention): Fd_ diffuse,
// Fs_ specular lobes, D_ microfacet distributions, G_ geometric attenuation.
// The GLSL twin is plugin/gl/glsl/sl_brdf.glsl: same names, same guards.
//
// Every direction is a unit vector pointing away from the surface; dot
// products are named NoL, NoV, NoH, VoH, RoV.
#pragma once

#include "shadinglab/model/Constants.h"
#include "shadinglab/model/Vec3.h"

#include <algorithm>
#include <cmath>

namespace shadinglab
{

/// Lambert 1760; docs/model.md eq. 1.2: Rd = 1/pi, the BRDF of a perfectly
/// diffuse surface with albedo 1.
template <typename T>
constexpr T Fd_Lambert()
{
  return T(kInvPi<ScalarOf<T>>);
}

/**
 * Lommel-Seeliger (Seeliger 1888; Hapke 1981, eq. 19), docs/model.md
 * eq. 1.12: single scattering in a dark, porous regolith, whose radiance
 * goes as N.L / (N.L + N.V). Scaled by 2 so that it equals Lambert at
 * normal incidence and view (the two disks match at their centres):
 *   Rd = (2 / pi) / (N.L + N.V).
 * The denominator is floored at kMinCosTheta (both cosines are > 0 where
 * the model is evaluated; the floor only keeps a grazing pair finite).
 */
template <typename T>
SL_INLINE T Fd_LommelSeeliger(T NoL, T NoV)
{
  using S = ScalarOf<T>;
  return T(2) * kInvPi<S> / Max(NoL + NoV, T(kMinCosTheta<S>));
}

/// Clamp of the RMS slope m to [kMinRoughness, kMaxRoughness] (see there).
template <typename T>
SL_INLINE T ClampRoughness(T m)
{
  using S = ScalarOf<T>;
  return Clamp(m, T(kMinRoughness<S>), T(kMaxRoughness<S>));
}

/**
 * Phong 1975, "Illumination for Computer Generated Pictures": specular
 * intensity (R.V)^n. Returned as a BRDF with the energy normalization
 * (n + 2) / (2 pi) of Lewis 1994, "Making Shaders More Physically
 * Plausible", so that a lobe of any n reflects at most ks of the light.
 * Deviation from the 1975 paper (no normalization) stated here on purpose:
 * one shading equation I = Ra Ia + sum I_L (N.L) dw f serves all models.
 */
/// x^n by std::pow (per lane for a batch): the default power of the cosine
/// lobes below. Fast Phong passes a table lookup instead (Bishop & Weimer
/// 1986, section 4).
struct StdPow
{
  template <typename T>
  SL_INLINE T operator()(T x, T n) const
  {
    return Pow(x, n);
  }
};

template <typename T, typename Power = StdPow>
SL_INLINE T Fs_Phong(T RoV, T shininess, Power power = {})
{
  using S = ScalarOf<T>;
  const auto lit = RoV > T(0);
  if (!AnyOf(lit))
  {
    return T(0);
  }
  return Select(lit,
    (shininess + T(2)) * (S(0.5) * kInvPi<S>)*power(Min(RoV, T(1)), shininess), T(0));
}

/**
 * Blinn 1977, "Models of Light Reflection for Computer Synthesized
 * Pictures": (N.H)^n, normalized by (n + 8) / (8 pi) (Akenine-Moller et al.,
 * Real-Time Rendering 3rd ed., eq. 7.49), see Fs_Phong for why.
 */
template <typename T, typename Power = StdPow>
SL_INLINE T Fs_BlinnPhong(T NoH, T shininess, Power power = {})
{
  using S = ScalarOf<T>;
  const auto lit = NoH > T(0);
  if (!AnyOf(lit))
  {
    return T(0);
  }
  return Select(lit,
    (shininess + T(8)) * (S(0.125) * kInvPi<S>)*power(Min(NoH, T(1)), shininess), T(0));
}

/**
 * Beckmann distribution as in Cook & Torrance 1982, eq. (the lecture's
 * docs/model.md eq. 1.6):  D = exp(-(tan(a)/m)^2) / (m^2 cos^4(a)),  a = acos(N.H).
 * Without the 1/pi that Rs carries: (1/pi) D cos(a) integrates to 1 over the
 * hemisphere (tested).
 * @param NoH cos(a); <= 0 means no facet faces H: D = 0.
 * @param m RMS slope, clamped to [kMinRoughness, kMaxRoughness].
 */
template <typename T>
SL_INLINE T D_Beckmann(T NoH, T m)
{
  using S = ScalarOf<T>;
  const auto facing = NoH > T(0);
  if (!AnyOf(facing))
  {
    return T(0);
  }
  NoH = Min(NoH, T(1));
  m = ClampRoughness(m);
  const T cos2Alpha = NoH * NoH;
  const T cos4Alpha = cos2Alpha * cos2Alpha;
  const auto inLobe = facing && !(cos4Alpha < T(kMinCos4Alpha<S>));
  if (!AnyOf(inLobe))
  {
    return T(0);
  }
  const T tan2Alpha = (T(1) - cos2Alpha) / cos2Alpha;
  const T m2 = m * m;
  return Select(inLobe, Exp(-tan2Alpha / m2) / (m2 * cos4Alpha), T(0));
}

/// One lobe of a Beckmann mixture: weight w_k and RMS slope m_k.
template <typename T>
struct BeckmannLobe
{
  T weight = T(1);
  T m = T(0.3);
};

/**
 * Mixture of Beckmann distributions, Cook & Torrance 1982 (docs/model.md eq. 1.7):
 *   D = sum_k w_k D(m_k).
 * The weights should sum to 1 for the mixture to stay normalized; the
 * Material validation enforces it.
 */
template <typename T>
SL_INLINE T D_BeckmannMixture(T NoH, const BeckmannLobe<T>* lobes, int count)
{
  T D = T(0);
  for (int k = 0; k < count; ++k)
  {
    D += lobes[k].weight * D_Beckmann(NoH, lobes[k].m);
  }
  return D;
}

/**
 * Geometric attenuation of V-groove microfacets, Torrance & Sparrow 1967 as
 * used by Cook & Torrance 1982 (docs/model.md eq. 1.10):
 *   G = min(1, 2(N.H)(N.L)/(V.H), 2(N.H)(N.V)/(V.H)).
 * V.H -> 0 sends both ratios to +infinity: G = 1 is the limit.
 */
template <typename T>
SL_INLINE T G_CookTorrance(T NoH, T NoV, T NoL, T VoH)
{
  using S = ScalarOf<T>;
  const auto visible = NoL > T(0) && NoV > T(0) && NoH > T(0);
  if (!AnyOf(visible))
  {
    return T(0);
  }
  const auto grazing = VoH < T(kMinVoH<S>);
  if (AllOf(grazing))
  {
    return Select(visible, T(1), T(0));
  }
  const T Gs = T(2) * NoH * NoL / VoH;
  const T Gm = T(2) * NoH * NoV / VoH;
  return Select(visible, Select(grazing, T(1), Min(T(1), Min(Gs, Gm))), T(0));
}

/// Which specular denominator Cook-Torrance uses.
enum class SpecularVariant
{
  /// Cook & Torrance 1982 / docs/model.md eq. 1.5: Rs = (1/pi) F D G / ((N.L)(N.V)).
  CookTorrance1982,
  /// Walter et al. 2007, "Microfacet Models for Refraction through Rough
  /// Surfaces", eq. 20: f = F D_n G / (4 (N.L)(N.V)) with the normalized
  /// D_n = D/pi. The 4 comes from the Jacobian of the half-vector map,
  /// dw_h/dw_o = 1/(4 V.H); the 1982 form is 4x brighter and reflects more
  /// than it receives for smooth surfaces (see the white-furnace test).
  Walter2007,
};

/**
 * Specular BRDF Rs of Cook & Torrance (docs/model.md eq. 1.5) or of Walter et al. 2007,
 * from its terms. NoL, NoV <= 0 (light or viewer below the surface): 0.
 * Denominators are clamped to kMinCosTheta.
 */
template <typename T>
SL_INLINE T Fs_CookTorrance(T F, T D, T G, T NoL, T NoV, SpecularVariant variant)
{
  using S = ScalarOf<T>;
  const auto lit = NoL > T(0) && NoV > T(0);
  if (!AnyOf(lit))
  {
    return T(0);
  }
  const T denominator = Max(NoL, T(kMinCosTheta<S>)) * Max(NoV, T(kMinCosTheta<S>));
  const S jacobian = variant == SpecularVariant::Walter2007 ? S(4) : S(1);
  return Select(lit, F * D * G * kInvPi<S> / (jacobian * denominator), T(0));
}

/**
 * H = normalize(L + V), the half vector (Blinn 1977). When L = -V it has no
 * direction; see kMinHalfVectorLength for why N is then the right fallback.
 */
template <typename T>
SL_INLINE Vec3<T> HalfVector(const Vec3<T>& L, const Vec3<T>& V, const Vec3<T>& N)
{
  using S = ScalarOf<T>;
  const Vec3<T> sum = L + V;
  const T lengthSq = Dot(sum, sum);
  const auto defined = lengthSq >= T(kMinHalfVectorLength<S> * kMinHalfVectorLength<S>);
  if (!AnyOf(defined))
  {
    return N;
  }
  return Select(defined, sum * (T(1) / Sqrt(lengthSq)), N);
}

} // namespace shadinglab
