// SPDX-License-Identifier: BSD-3-Clause
// Named material presets with cited optical constants, and the spectral to
// RGB reduction of Fresnel reflectance.
#pragma once

#include "shadinglab/model/Shading.h"

#include <string>
#include <vector>

namespace shadinglab
{

/// A preset: name, the material, and where its numbers come from.
struct MaterialPreset
{
  std::string name;
  std::string source;
  Material<double> material;
};

/// All presets: plastic, glass, gold, copper, silver, aluminium.
const std::vector<MaterialPreset>& MaterialPresets();

/// The preset with this name, or nullptr.
const MaterialPreset* FindMaterialPreset(const std::string& name);

/// One sample of a spectral refractive index: wavelength (nm), eta, k.
struct SpectralIndexSample
{
  double wavelength = 550.0;
  double eta = 1.5;
  double k = 0.0;
};

/**
 * Fresnel reflectance of a spectrally sampled material reduced to RGB.
 * Each sample's F(cosTheta_i) is averaged into the band it falls in: blue
 * [380, 490) nm, green [490, 590) nm, red [590, 780] nm, a box-filter
 * approximation of the sRGB primaries' dominant ranges (deliberately simple:
 * no colour-matching functions, documented in README). A band with no sample
 * takes the nearest sample's value. Samples outside [380, 780] nm are ignored.
 * Returns false (and leaves rgb untouched) when no sample is in range.
 */
bool F_SpectralToRGB(
  double cosTheta_i, const std::vector<SpectralIndexSample>& samples, Vec3<double>& rgb);

} // namespace shadinglab
