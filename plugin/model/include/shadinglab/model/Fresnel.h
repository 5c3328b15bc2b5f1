// SPDX-License-Identifier: BSD-3-Clause
// Fresnel reflectance: the F term of Cook-Torrance (docs/model.md eq. 1.8-1.9).
#pragma once

#include "shadinglab/model/Lanes.h"
#include "shadinglab/model/Vec3.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace shadinglab
{

/**
 * Unpolarized Fresnel reflectance of a smooth dielectric interface.
 *
 * Cook & Torrance 1982, "A Reflectance Model for Computer Graphics", eq. for F;
 * docs/model.md eq. 1.8:
 *   F = 1/2 sin^2(ti - tt)/sin^2(ti + tt) (1 + cos^2(ti + tt)/cos^2(ti - tt)),
 *   sin(tt) = sin(ti) / eta.
 *
 * Deliberate deviation in *evaluation*, not in value: the slide's form is 0/0
 * at normal incidence (ti = tt = 0). It equals (Rs + Rp)/2 with the Fresnel
 * amplitude ratios written in cosines (Born & Wolf, Principles of Optics,
 * sec. 1.5.2):
 *   rs = (cos ti - eta cos tt) / (cos ti + eta cos tt)
 *   rp = (eta cos ti - cos tt) / (eta cos ti + cos tt)
 * which is finite everywhere and tends to ((eta-1)/(eta+1))^2 at ti = 0.
 * The test suite checks the two forms agree away from the singularity.
 *
 * @param cosTheta_i cos of the incidence angle, L.H; clamped to [0, 1].
 * @param eta relative index eta_t / eta_i (> 0). eta < 1 (leaving glass) has
 *   total internal reflection beyond the critical angle: F = 1 there.
 * @remark eta == 1 is an invisible interface: F = 0 exactly (the cosine form
 *   would be 0/0 at grazing incidence).
 */
template <typename T>
SL_INLINE T F_Dielectric(T cosTheta_i, T eta)
{
  const auto invisible = eta == T(1);
  if (AllOf(invisible))
  {
    return T(0);
  }
  cosTheta_i = Clamp(cosTheta_i, T(0), T(1));
  const T sin2Theta_i = Max(T(0), T(1) - cosTheta_i * cosTheta_i);
  const T sin2Theta_t = sin2Theta_i / (eta * eta);
  // Handle total internal reflection case
  const auto totalInternal = sin2Theta_t >= T(1);
  if (AllOf(totalInternal))
  {
    return Select(invisible, T(0), T(1));
  }
  const T cosTheta_t = Sqrt(T(1) - sin2Theta_t);
  const T rs = (cosTheta_i - eta * cosTheta_t) / (cosTheta_i + eta * cosTheta_t);
  const T rp = (eta * cosTheta_i - cosTheta_t) / (eta * cosTheta_i + cosTheta_t);
  return Select(invisible, T(0), Select(totalInternal, T(1), T(0.5) * (rs * rs + rp * rp)));
}

/// s- and p-polarized reflectances (Rs, Rp) of a dielectric; F = (Rs+Rp)/2.
/// Used to locate Brewster's angle, where Rp = 0.
template <typename T>
void F_DielectricPolarized(T cosTheta_i, T eta, T& Rs, T& Rp)
{
  cosTheta_i = std::clamp(cosTheta_i, T(0), T(1));
  const T sin2Theta_t = std::max(T(0), T(1) - cosTheta_i * cosTheta_i) / (eta * eta);
  if (sin2Theta_t >= T(1))
  {
    Rs = Rp = T(1);
    return;
  }
  const T cosTheta_t = std::sqrt(T(1) - sin2Theta_t);
  const T rs = (cosTheta_i - eta * cosTheta_t) / (cosTheta_i + eta * cosTheta_t);
  const T rp = (eta * cosTheta_i - cosTheta_t) / (eta * cosTheta_i + cosTheta_t);
  Rs = rs * rs;
  Rp = rp * rp;
}

/**
 * Unpolarized Fresnel reflectance of a conductor with complex index
 * eta + i k (exact; Born & Wolf sec. 14.2; pbrt-v4 FrComplex).
 *
 * Cook & Torrance derived a real eta for metals from the measured
 * normal-incidence reflectance and used the dielectric formula; that
 * underestimates a metal's reflectance towards grazing. This is the
 * complex-index formula they approximated. With k = 0 it equals
 * F_Dielectric (including total internal reflection for eta < 1, which the
 * complex square root handles by itself).
 *
 * @param cosTheta_i L.H, clamped to [0, 1].
 * @param eta real part of the relative index (> 0).
 * @param k extinction coefficient (>= 0).
 */
template <typename T>
SL_INLINE T F_Conductor(T cosTheta_i, T eta, T k)
{
  using C = ComplexOf<T>;
  const auto dielectric = k == T(0);
  if (AllOf(dielectric))
  {
    return F_Dielectric(cosTheta_i, eta);
  }
  cosTheta_i = Clamp(cosTheta_i, T(0), T(1));
  const C n(eta, k);
  const T sin2Theta_i = Max(T(0), T(1) - cosTheta_i * cosTheta_i);
  const C sin2Theta_t = C(sin2Theta_i) / (n * n);
  const C cosTheta_t = ComplexSqrt<T>(C(T(1)) - sin2Theta_t);
  // k > 0 makes |n cos_i| + |cos_t| > 0 for every cos_i in [0, 1]: the
  // denominators cannot vanish. (k = 0 lanes of a batch, which only a
  // batch of mixed materials could have, are exact here too.)
  const C rs = (C(cosTheta_i) - n * cosTheta_t) / (C(cosTheta_i) + n * cosTheta_t);
  const C rp = (n * C(cosTheta_i) - cosTheta_t) / (n * C(cosTheta_i) + cosTheta_t);
  return T(0.5) * (ComplexNorm<T>(rs) + ComplexNorm<T>(rp));
}

/// Normal-incidence reflectance of a conductor: ((n-1)^2 + k^2)/((n+1)^2 + k^2).
template <typename T>
T F0_Conductor(T eta, T k)
{
  return ((eta - T(1)) * (eta - T(1)) + k * k) / ((eta + T(1)) * (eta + T(1)) + k * k);
}

/// Per-channel Fresnel (RGB): conductor when any k > 0, dielectric otherwise.
template <typename T>
SL_INLINE Vec3<T> F_RGB(T cosTheta_i, const Vec3<T>& eta, const Vec3<T>& k)
{
  return { F_Conductor(cosTheta_i, eta.x, k.x), F_Conductor(cosTheta_i, eta.y, k.y),
    F_Conductor(cosTheta_i, eta.z, k.z) };
}

} // namespace shadinglab
