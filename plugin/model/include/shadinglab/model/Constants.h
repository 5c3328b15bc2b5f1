// SPDX-License-Identifier: BSD-3-Clause
// Named numerical guards of the shading model. Each value is derived where it
// is defined. The GLSL twin gets them as SL_* #defines generated from this
// header at build time (plugin/gl/GenerateGlslDefines.cpp): one source.
#pragma once

namespace shadinglab
{

template <typename T>
constexpr T kPi = T(3.14159265358979323846264338327950288);
template <typename T>
constexpr T kInvPi = T(0.318309886183790671537767526745028724);

/// Smallest N.L and N.V used in a BRDF denominator. 1e-4 is 89.994 degrees
/// from the normal (Filament's MIN_N_DOT_V). Below it the projected area of
/// a facet is under 1e-4 of its area, so the radiance it returns carries no
/// visible weight, while the product NoL*NoV >= 1e-8 stays far above float's
/// smallest normal (1.2e-38): Rs cannot overflow.
template <typename T>
constexpr T kMinCosTheta = T(1e-4);

/// Smallest RMS microfacet slope m. At m = 1e-3 the Beckmann lobe is 0.06
/// degrees wide, narrower than one pixel of a 4k display at 90 degrees field
/// of view, so smaller m is visually a mirror; the peak D = 1/m^2 = 1e6 then
/// keeps Rs <= 1e6 / (pi * kMinCosTheta^2) ~ 3e13, finite in float.
template <typename T>
constexpr T kMinRoughness = T(1e-3);

/// Largest RMS slope m. m = 1e3 means facets at 89.94 degrees on average:
/// no physical surface; D(alpha) * m^2 is then constant to 1e-6 over the
/// visible hemisphere, so a larger m changes nothing but risks m^2 overflow.
template <typename T>
constexpr T kMaxRoughness = T(1e3);

/// Beckmann D is 0 when cos^4(alpha) is below this (pbrt-v4 uses the same
/// 1e-16). There cos(alpha) < 1e-4, tan^2(alpha) > 1e8 and
/// exp(-tan^2/m^2) < exp(-100) even at kMaxRoughness: the lobe is below
/// 1e-43 of its peak, while the division by cos^4 would risk 0/0.
template <typename T>
constexpr T kMinCos4Alpha = T(1e-16);

/// |L + V| below this has no direction: L and V are within 1e-6 rad of
/// opposite, which with both above the surface only happens at grazing
/// incidence, where N.L * N.V ~ 0 and every reflected term vanishes. The
/// half vector then falls back to N. 1e-6 is ~8 float ulps of 1.
template <typename T>
constexpr T kMinHalfVectorLength = T(1e-6);

/// V.H below this makes G's ratios 2(N.H)(N.x)/(V.H) tend to infinity, so
/// G = min(1, ...) = 1 is the limit; the guard avoids 0/0 when N.H = 0 too.
/// 1e-7 is below float's epsilon (1.19e-7) relative to V.H <= 1.
template <typename T>
constexpr T kMinVoH = T(1e-7);

/// Squared length of an interpolated normal below which it has no direction
/// (vertex normals that cancel, e.g. opposite normals across a fold). 1e-12
/// is the square of 1e-6, ~8 float ulps of a unit component.
template <typename T>
constexpr T kMinNormalLengthSq = T(1e-12);

/// Screen-space triangle area (pixels^2) below which the affine normal
/// field N = A x + B y + C of Fast Phong is not solvable; such a triangle
/// covers no pixel centre, so a constant normal (the vertex average) is used.
template <typename T>
constexpr T kMinScreenArea = T(1e-9);

/// Largest Phong/Blinn exponent accepted. At n = 1e4 the lobe cos^n is
/// 0.67 degrees wide at half maximum, a mirror at any display resolution;
/// the cap keeps the normalization (n + 8) / (8 pi) ~ 400 modest and rejects
/// absurd input rather than silently producing a black picture.
template <typename T>
constexpr T kMaxShininess = T(1e4);

/// Floor of a denominator that is positive by construction but may
/// underflow (a point light's attenuation sum, cos^2 of a half angle, a
/// squared length): 1e-30 lies 8 orders above float's smallest normal
/// (1.2e-38), so x / 1e-30 for any x <= 1 stays below 1e30 < FLT_MAX and no
/// Inf can reach a pixel.
template <typename T>
constexpr T kTinyDenominator = T(1e-30);

/// What an ideal linear polarizer passes of unpolarized light (the Stokes
/// row (1, cos 2 theta, sin 2 theta, 0) / 2, docs/model.md eq. 8.3): half,
/// whatever its angle. The analyser passes half of unpolarized diffuse
/// light; a polarizer in front of a lamp passes half of its intensity.
template <typename T>
constexpr T kPolarizerTransmittance = T(0.5);

/// Floor of 1 - F0 in the tinted Fresnel term (docs/model.md eq. 9.4):
/// real metals reflect at most ~0.98 at normal incidence (silver), so the
/// floor only ever acts on a perfect mirror (F0 = 1, where F = F0 at every
/// angle and the rise is 0 anyway); it keeps 0 / 0 from any pixel.
template <typename T>
constexpr T kMinFresnelGap = T(1e-6);

/// Maximum number of Beckmann lobes in a mixture D = sum_k w_k D(m_k) and of
/// lights in one evaluation; fixed so the GPU uniform arrays match.
constexpr int kMaxLobes = 4;
constexpr int kMaxLights = 8;

/// Wavelength samples of spectral Fresnel (docs/model.md eq. 7.2): the
/// visible range's 81 rows of 5 nm in 16 contiguous groups. Measured against
/// all 81 rows (SpectrumTest prints it): the worst CIEDE2000 over the
/// presets and incidence angles 0-89 degrees is 0.31 (copper) with 16
/// samples, 0.53 with 12 (copper) and 0.93 with 8 (gold): 16 keeps every
/// preset under half a just-noticeable difference (1) for 16 F evaluations
/// a light. Fixed so the GPU uniform arrays match.
constexpr int kSpectralSamples = 16;

} // namespace shadinglab
