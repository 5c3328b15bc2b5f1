// SPDX-License-Identifier: BSD-3-Clause
// Fresnel reflectance: the F term of Cook-Torrance (docs/model.md eq. 1.8-1.9).
#pragma once

#include "shadinglab/model/Constants.h"
#include "shadinglab/model/Lanes.h"
#include "shadinglab/model/Vec3.h"

#include <algorithm>
#include <cmath>

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
 * eta + i k (exact; Born & Wolf, Principles of Optics, sec. 14.2).
 *
 * Cook & Torrance derived a real eta for metals from the measured
 * normal-incidence reflectance and used the dielectric formula; that
 * underestimates a metal's reflectance towards grazing. This is the
 * complex-index formula they approximated, docs/model.md eq. 1.9, in real
 * arithmetic (Born & Wolf's a and b, where n cos(theta_t) = a + i b):
 *   a^2 + b^2 = sqrt((eta^2 - k^2 - sin^2 ti)^2 + 4 eta^2 k^2)
 *   a^2       = ((a^2 + b^2) + (eta^2 - k^2 - sin^2 ti)) / 2
 *             = 2 eta^2 k^2 / ((a^2 + b^2) - (eta^2 - k^2 - sin^2 ti))
 *   Rs = (a^2 + b^2 - 2 a cos ti + cos^2 ti) / (a^2 + b^2 + 2 a cos ti + cos^2 ti)
 *   Rp = Rs (cos^2 ti (a^2 + b^2) - 2 a cos ti sin^2 ti + sin^4 ti)
 *          / (cos^2 ti (a^2 + b^2) + 2 a cos ti sin^2 ti + sin^4 ti)
 *   F  = (Rs + Rp) / 2
 * Two square roots and two divisions, against a complex square root and two
 * complex divisions (3.5x fewer cycles on 8 AVX2 lanes); equal to the
 * complex form to rounding (FresnelTest holds it to 1e-12 in double). With
 * k = 0 it is F_Dielectric, total internal reflection for eta < 1
 * included (a = 0 there: Rs = Rp = 1).
 *
 * F_ConductorMueller gives Rs and Rp themselves (the polarized
 * reflectances, docs/model.md eq. 8.1) and the phase terms of Fresnel's
 * Mueller matrix; F_ConductorSP Rs and Rp alone; F_Conductor their mean.
 *
 * @param cosTheta_i L.H, clamped to [0, 1].
 * @param eta real part of the relative index (> 0).
 * @param k extinction coefficient (>= 0).
 *
 * With n cos(theta_t) = u = a + i b, rs = (cos ti - u) / (cos ti + u) and
 * rp = -rs (u cos ti - sin^2 ti) / (u cos ti + sin^2 ti) (Born & Wolf sec.
 * 1.5.2 and 14.2, rp in the frames of eq. 8.6: it is -rs at normal
 * incidence, as both waves' second axes then point opposite ways). Then
 * (docs/model.md eq. 8.2)
 *   C + i D = rs rp* = -Rs ((cos^2 ti (a^2 + b^2) - sin^4 ti) - 2 i b cos ti sin^2 ti)
 *                      / (cos^2 ti (a^2 + b^2) + 2 a cos ti sin^2 ti + sin^4 ti)
 * real (D = 0) for a dielectric outside total internal reflection; D is the
 * phase between s and p that turns linear polarization elliptical (a metal,
 * or glass from inside beyond the critical angle: Fresnel's rhomb).
 * C^2 + D^2 = Rs Rp.
 */
template <typename T>
SL_INLINE void F_ConductorMueller(T cosTheta_i, T eta, T k, T& Rs, T& Rp, T& C, T& D)
{
  cosTheta_i = Clamp(cosTheta_i, T(0), T(1));
  const T cos2Theta_i = cosTheta_i * cosTheta_i;
  const T sin2Theta_i = Max(T(0), T(1) - cos2Theta_i);
  const T t0 = eta * eta - k * k - sin2Theta_i;
  const T etaK = eta * k;
  const T a2plusb2 = Sqrt(t0 * t0 + T(4) * etaK * etaK);
  // a^2 = (a^2 + b^2 + t0) / 2 cancels where t0 < 0 (eta < 1, little
  // absorption); there the same value is 2 eta^2 k^2 / (a^2 + b^2 - t0).
  // Both denominators are >= a^2 + b^2 > 0. b likewise: (a^2 + b^2 - t0) / 2
  // where t0 < 0, else eta k / a (2 a b = 2 eta k).
  const T sum = a2plusb2 + Abs(t0);
  const auto positive = t0 >= T(0);
  const T a = Sqrt(Select(positive, T(0.5) * sum, T(2) * etaK * etaK / Max(sum, T(kTinyDenominator<ScalarOf<T>>))));
  const T b = Select(positive, etaK / Max(a, T(kTinyDenominator<ScalarOf<T>>)), Sqrt(T(0.5) * sum));
  const T t1 = a2plusb2 + cos2Theta_i;
  const T t2 = T(2) * cosTheta_i * a;
  // t1 + t2 >= a^2 + b^2 >= 2 eta k > 0 for a conductor. It vanishes only
  // for k = 0 at eta = 1 and grazing incidence, where t1 - t2 = 0 too and
  // the limit is Rs = 0.
  Rs = (t1 - t2) / Max(t1 + t2, T(kTinyDenominator<ScalarOf<T>>));
  // t3 + t4 > 0: cos ti and sin ti are never both 0.
  const T t3 = cos2Theta_i * a2plusb2 + sin2Theta_i * sin2Theta_i;
  const T t4 = t2 * sin2Theta_i;
  const T invP = T(1) / (t3 + t4);
  Rp = Rs * (t3 - t4) * invP;
  C = -Rs * (cos2Theta_i * a2plusb2 - sin2Theta_i * sin2Theta_i) * invP;
  D = Rs * (T(2) * b * cosTheta_i * sin2Theta_i) * invP;
}

/// Rs and Rp of F_ConductorMueller (the phase terms unused are folded away).
template <typename T>
SL_INLINE void F_ConductorSP(T cosTheta_i, T eta, T k, T& Rs, T& Rp)
{
  T C, D;
  F_ConductorMueller(cosTheta_i, eta, k, Rs, Rp, C, D);
}

/// F = (Rs + Rp) / 2 of F_ConductorSP; a dielectric (k = 0) through
/// F_Dielectric, which also handles the invisible interface eta = 1.
template <typename T>
SL_INLINE T F_Conductor(T cosTheta_i, T eta, T k)
{
  const auto dielectric = k == T(0);
  if (AllOf(dielectric))
  {
    return F_Dielectric(cosTheta_i, eta);
  }
  T Rs, Rp;
  F_ConductorSP(cosTheta_i, eta, k, Rs, Rp);
  return T(0.5) * (Rs + Rp);
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

/**
 * Fresnel per wavelength reduced to linear sRGB (docs/model.md eq. 7.3):
 *   F_rgb = sum_i w_i F(cos theta_i; eta(lambda_i), k(lambda_i)),
 * w_i the CIE 1931 observer under D65 over sample i's 5 nm rows, through
 * the XYZ to linear sRGB matrix (eq. 7.2; SpectralBasisD65 in Spectrum.h).
 * The lecture: "F depends on wavelength ... eta_lambda".
 */
template <typename T>
SL_INLINE Vec3<T> F_Spectral(T cosTheta_i, const T* eta, const T* k, const Vec3<T>* weight, int count)
{
  Vec3<T> F;
  for (int i = 0; i < count; ++i)
  {
    F += weight[i] * F_Conductor(cosTheta_i, eta[i], k[i]);
  }
  return F;
}

/**
 * Fresnel's Mueller matrix per channel (per wavelength when spectral,
 * weighted as F_Spectral; docs/model.md eq. 8.2): A = (Rs + Rp) / 2 = F,
 * B = (Rs - Rp) / 2, C + i D = rs rp*, in the frame whose first axis is s,
 * perpendicular to the plane of incidence:
 *   | A B 0 0 |
 *   | B A 0 0 |
 *   | 0 0 C D |
 *   | 0 0 -D C |
 * Unpolarized light reflects as (A, B, 0, 0). The weights are linear, so
 * the spectral entries are the weighted sums of each wavelength's.
 */
template <typename T>
SL_INLINE void F_RGB_Mueller(T cosTheta_i, const Vec3<T>& eta, const Vec3<T>& k, Vec3<T>& A,
  Vec3<T>& B, Vec3<T>& C, Vec3<T>& D)
{
  for (int c = 0; c < 3; ++c)
  {
    T Rs, Rp;
    F_ConductorMueller(cosTheta_i, eta[c], k[c], Rs, Rp, C[c], D[c]);
    A[c] = T(0.5) * (Rs + Rp);
    B[c] = T(0.5) * (Rs - Rp);
  }
}

template <typename T>
SL_INLINE void F_Spectral_Mueller(T cosTheta_i, const T* eta, const T* k, const Vec3<T>* weight,
  int count, Vec3<T>& A, Vec3<T>& B, Vec3<T>& C, Vec3<T>& D)
{
  A = B = C = D = Vec3<T>();
  for (int i = 0; i < count; ++i)
  {
    T Rs, Rp, Ci, Di;
    F_ConductorMueller(cosTheta_i, eta[i], k[i], Rs, Rp, Ci, Di);
    A += weight[i] * (T(0.5) * (Rs + Rp));
    B += weight[i] * (T(0.5) * (Rs - Rp));
    C += weight[i] * Ci;
    D += weight[i] * Di;
  }
}

} // namespace shadinglab
