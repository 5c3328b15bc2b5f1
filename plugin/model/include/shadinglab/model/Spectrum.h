// SPDX-License-Identifier: BSD-3-Clause
// Wavelength: optical constants as functions of wavelength (measured data in
// refractiveindex.info's format), the CIE 1931 observer under an illuminant,
// and Fresnel per wavelength reduced to linear sRGB (docs/model.md
// section 7).
#pragma once

#include "shadinglab/model/Constants.h"
#include "shadinglab/model/Shading.h"
#include "shadinglab/model/Vec3.h"

#include <functional>
#include <string>
#include <vector>

namespace shadinglab
{

/// The visible range of the CIE tables: 380 to 780 nm in rows of 5 nm.
constexpr double kVisibleMinNm = 380.0;
constexpr double kVisibleMaxNm = 780.0;
constexpr int kCieRows = 81;

/**
 * A material's complex index n + i k as a function of wavelength: one
 * refractiveindex.info file (the format of datasets/optical). Three of its
 * data types are read: "tabulated nk", "tabulated n" (k = 0) and
 * "formula 2" (Sellmeier, n^2 - 1 = sum B_i l^2 / (l^2 - C_i), l in um),
 * the latter optionally with a "tabulated k". Linear between rows.
 */
struct Dispersion
{
  std::string name; ///< the file or preset it came from
  std::vector<double> nmN, n; ///< tabulated n (empty with a formula)
  std::vector<double> nmK, k; ///< tabulated k (empty: k = 0)
  bool sellmeier = false;
  double coefficients[6] = {}; ///< B1 C1 B2 C2 B3 C3 (C in um^2)
  double minNm = 0, maxNm = 0; ///< where n is defined

  /// n and k at `nm`; false outside [minNm, maxNm]. k outside its own table
  /// is its nearest row's (a dielectric's k is tabulated over less than
  /// its n).
  bool Evaluate(double nm, double& nOut, double& kOut) const;
};

/// Parses a refractiveindex.info YAML file's text. Returns "" or a one-line
/// error ("formula 3 is not supported: ...", "no data rows", a row that is
/// not three numbers, wavelengths not increasing, n <= 0, k < 0, the data
/// not covering 380-780 nm).
std::string ParseDispersion(const std::string& text, const std::string& name, Dispersion& out);

/// The measured data behind a preset (gold, silver, copper, aluminium, glass,
/// water), or nullptr (plastic, custom).
const Dispersion* PresetDispersion(const std::string& preset);
/// The presets that have measured data, in the order of MaterialPresets().
const std::vector<std::string>& PresetDispersionNames();

/**
 * The weights that turn a reflectance spectrum sampled at `wavelength[i]`
 * into linear sRGB under illuminant D65 (docs/model.md eq. 7.1-7.2):
 *   RGB = sum_i weight[i] R(wavelength[i]),
 *   weight[i] = M_sRGB sum_{rows j of group i} S_j (xbar_j, ybar_j, zbar_j) / sum_j S_j ybar_j.
 * The 81 rows of 5 nm are split into `count` contiguous groups of (nearly)
 * equal size; a group is sampled at its rows' mean wavelength. count = 81
 * is the 5 nm reference itself. A perfect reflector gives (1, 1, 1) to 2e-4.
 */
struct SpectralBasis
{
  std::vector<double> wavelength;
  std::vector<Vec3<double>> weight;
};
const SpectralBasis& SpectralBasisD65(int count = kSpectralSamples);

/// Linear sRGB of the reflectance spectrum R(nm) under D65 with `count`
/// samples (eq. 7.2; 81: the 5 nm reference).
Vec3<double> SpectrumToLinearSRGB(const std::function<double(double)>& R, int count);

/// CIE XYZ (D65 white Y = 1) of linear sRGB, and CIELAB relative to D65.
Vec3<double> LinearSRGBToXYZ(const Vec3<double>& rgb);
Vec3<double> XYZToLab(const Vec3<double>& xyz);

/// CIEDE2000 colour difference of two linear sRGB colours (Sharma, Wu &
/// Dalal 2005, Color Res. Appl. 30(1); docs/model.md eq. 7.4).
double DeltaE2000(const Vec3<double>& rgbA, const Vec3<double>& rgbB);
/// The same between two CIELAB colours (L*, a*, b*).
double DeltaE2000Lab(const Vec3<double>& lab1, const Vec3<double>& lab2);

/// Fills material.spectral* from the dispersion (eq. 7.3): eta and k at the
/// basis's wavelengths and its weights. Returns "" or a one-line error.
std::string SetSpectral(Material<double>& material, const Dispersion& dispersion);

/// The three-sample RGB material of a dispersion, as the accuracy study
/// compares them: "sampled" at 650/550/450 nm, "band" (n and k averaged over
/// 590-780, 490-590, 380-490 nm), "fitted" (per channel, the constant n, k
/// whose F matches the spectral colour's channel at normal incidence and
/// 60 degrees, least squares on a grid).
enum class RgbChoice
{
  Sampled,
  Band,
  Fitted
};
void RgbFromDispersion(const Dispersion& dispersion, RgbChoice choice, Vec3<double>& eta,
  Vec3<double>& k);

} // namespace shadinglab
