// SPDX-License-Identifier: BSD-3-Clause
// Named material presets with cited optical constants (their measured
// spectra: Spectrum.h).
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

/// The preset whose parameters m has, exactly (its spectral samples aside:
/// a preset with Fresnel per wavelength is still that preset), or nullptr.
const MaterialPreset* PresetMatching(const Material<double>& m);

} // namespace shadinglab

namespace shadinglab
{

/**
 * The material as one line of `key=value` pairs separated by ';' (the form
 * a ParaView property or a settings file stores), e.g.
 * "model=cook-torrance;kd=0;ks=1;ambient=0.05,0.05,0.05;diffuse=1,1,1;
 *  specular=1,1,1;shininess=32;m=0.2,0.6;w=0.4,0.6;eta=1.5,1.5,1.5;k=0,0,0;
 *  variant=1982". Values are written with 17 significant digits, so
 * ParseMaterial(SerializeMaterial(m)) == m exactly.
 */
std::string SerializeMaterial(const Material<double>& material);

/// "lambert", "phong", "blinn-phong" or "cook-torrance".
const char* ReflectanceModelName(ReflectanceModel model);
bool ParseReflectanceModel(const std::string& name, ReflectanceModel& model);

/// Parses SerializeMaterial's format (keys in any order, missing keys keep
/// the defaults). Returns an empty string on success, else a one-line error.
std::string ParseMaterial(const std::string& text, Material<double>& material);

} // namespace shadinglab
