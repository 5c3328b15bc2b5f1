// SPDX-License-Identifier: BSD-3-Clause
// Everything a user sets for a surface, in one struct (Settings), and one
// table describing it (SettingsTable): key, label, type, range or choices,
// one-line documentation and the front ends that show it. The CLI's flags
// and --help, the explorer's ranges, the VTK mapper's settings and the
// ParaView XML (generated at build time by plugin/paraview/GenerateXml.cpp)
// all read this table, so a default, a range or a spelling cannot differ
// between front ends. A setting's default is the value Settings{} holds:
// it is written once, in the struct below.
//
// Adding a setting: a field below, one row in src/SettingsTable.cpp, and its use.
#pragma once

#include "shadinglab/model/Shading.h"
#include "shadinglab/model/Spectrum.h"
#include "shadinglab/render/Backend.h"
#include "shadinglab/render/DataColor.h"
#include "shadinglab/render/Options.h"
#include "shadinglab/render/Renderer.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace shadinglab::render
{

/// How vertex normals are made for a mesh without them (or always, with
/// `recompute`). The weighting's values are mesh::NormalWeighting's.
struct NormalSettings
{
  int weighting = 1;          ///< 0 uniform, 1 area, 2 angle, 3 Max
  /// Split creases where faces meet at more than this (degrees; 180:
  /// nowhere). 30 as ParaView's Generate Surface Normals: CAD parts keep
  /// their edges, smooth meshes (dihedral angles of a few degrees) are
  /// not split.
  double featureAngle = 30.0;
  bool recompute = false;     ///< replace the data's own normals too
};

/// How the front ends that read files (the CLI, the explorer) turn them
/// into surfaces; ParaView's own Surface properties do this there.
struct InputSettings
{
  /// Times each higher-order (quadratic) face is split: ParaView's
  /// Nonlinear Subdivision Level, default 1 there too.
  int nonlinearSubdivisionLevel = 1;
};

/// Colour by data in the front ends that read files (the CLI): which array,
/// through which of ParaView's colour maps, over which range. ParaView's
/// own colouring controls do this for the representation.
struct ColorBySettings
{
  std::string array;                    ///< "[POINTS:|CELLS:]NAME[:COMPONENT|Magnitude]"; "": none
  std::string colormap = "cool-to-warm"; ///< ParaView's default preset
  std::string range = "auto";           ///< "auto" (the data's) or "MIN,MAX"
};

/// What a vtkShadingLabPolyDataMapper shows (docs/model.md eq. 8.5): the
/// picture, or what a polarization camera measures, in false colour.
enum class PolarizationImage
{
  Intensity, ///< the picture
  Dolp,      ///< degree of linear polarization, viridis over [0, 1]
  Aop        ///< angle of polarization, a cyclic hue wheel over [-90, 90] deg
};

/// Every setting of a surface's shading: one struct, passed whole.
struct Settings
{
  /// Mode (Auto with its budget maxError), interpolation, polygons,
  /// expansion, display transform, spread, ssaa, threads, culling.
  RenderOptions render;
  /// Scales every light's intensity I_L (eq. 1.1): the CLI's lights, the
  /// explorer's light, the vtkLights a mapper draws with.
  double lightIntensity = 1.0;
  /// The solid angle dw every light subtends (eq. 1.1, in steradians): its
  /// irradiance is I_L dw. pi makes a unit white light on a white
  /// Lambertian surface facing it give exactly 1 (Light::solidAngle).
  double lightSolidAngle = kPi<double>;
  Material<double> material;
  std::string preset; ///< the preset `material` was started from ("" custom)
  /// Whether the specular lobe is drawn; Auto leaves it off a surface
  /// coloured by data (render::MaterialForData, docs/model.md section 9).
  Highlights highlights = Highlights::Auto;
  /// Fresnel per wavelength (docs/model.md section 7) from the measured
  /// data of `nk` or else of the preset; ApplySetting keeps
  /// material.spectral* in step (ResolveSpectral).
  bool spectral = false;
  /// A refractiveindex.info file given by the user (--nk): its path, and
  /// its data once a front end has read it (ReadNkFile).
  std::string nkFile;
  std::shared_ptr<const Dispersion> nk;
  NormalSettings normals;
  ColorBySettings color;
  InputSettings input;
  /// Who draws a vtkShadingLabPolyDataMapper's (and ParaView's ShadingLab
  /// Surface's) pixels: OpenGL shaders, or the CPU renderer handing its
  /// colour and depth to OpenGL (plugin/vtk/CpuBackend.h), or Auto
  /// (render/Backend.h's chooser).
  Backend backend = Backend::GPU;
  /// Measured on the CPU renderer's linear frames: anything but Intensity
  /// draws through the CPU backend.
  PolarizationImage polarizationImage = PolarizationImage::Intensity;
};

enum class SettingGroup
{
  Render,
  Material,
  Lights,
  Mesh
};

enum class SettingKind
{
  Choice,  ///< one of `choices`; its value is the choice's index
  Real,    ///< `count` reals in [min, max]
  Integer, ///< an integer in [min, max]
  Flag,    ///< on or off
  Text     ///< a name (from `choices` when it has any)
};

/// Which front end shows a setting (bit mask).
enum SettingFrontEnd : unsigned
{
  kCli = 1u,      ///< `shadinglab render` / `compare` flag --key
  kParaView = 2u, ///< property `property` of the ShadingLab Surface
  kMapper = 4u,   ///< read by vtkShadingLabPolyDataMapper
  kExplorer = 8u  ///< a control of the explorer
};

/// One choice of a Choice or Text setting.
struct SettingChoice
{
  std::string key;   ///< command-line spelling (kebab-case)
  std::string label; ///< display spelling (Title Case, as ParaView shows it)
};

/// A setting's value: numbers (a Choice's index, a Flag's 0/1) or text.
struct SettingValue
{
  std::vector<double> numbers;
  std::string text;
};

struct SettingRow
{
  std::string key;      ///< "max-error": the CLI flag --max-error
  std::string property; ///< "MaxError": the ParaView property
  std::string label;    ///< "Max Error (1/255)"
  SettingGroup group = SettingGroup::Render;
  SettingKind kind = SettingKind::Real;
  /// Real: how many values are given; the CLI accepts 1..maxCount and
  /// broadcasts a single value when `broadcast` (an RGB triple).
  int minCount = 1;
  int maxCount = 1;
  bool broadcast = false;
  /// Values of the ParaView property (0: maxCount); the ambient Ra is one
  /// grey value there.
  int paraviewCount = 0;
  double min = 0;
  double max = 0;
  std::vector<SettingChoice> choices;
  std::string doc; ///< one line, for --help, tooltips and the ParaView panel
  unsigned frontEnds = 0;
  /// The CLI's name for the value in --help ("E", "DEG", "R,G,B").
  std::string metavar;
  std::function<void(Settings&, const SettingValue&)> set;
  std::function<SettingValue(const Settings&)> get;
};

/// The table, in the order the front ends list the settings.
const std::vector<SettingRow>& SettingsTable();
/// The row with this key, or nullptr.
const SettingRow* FindSetting(const std::string& key);

/// Parses a typed value: a choice's key or label (any case), a comma list
/// of reals, an integer, or on/off. Returns "" or a one-line error that
/// names the setting with `prefix` ("--" on the command line).
std::string ParseSetting(
  const SettingRow& row, const std::string& text, SettingValue& value, const std::string& prefix);
/// Checks `value` against the row's count, range and choices, then sets it.
/// Returns "" or a one-line error.
std::string ApplySetting(
  Settings& settings, const SettingRow& row, const SettingValue& value, const std::string& prefix);
/// ParseSetting then ApplySetting, by key.
std::string ApplySettingText(Settings& settings, const std::string& key, const std::string& text,
  const std::string& prefix = "");

/// The value as a user would type it: a choice's key, "1.5,1.5,1.5", "on".
std::string FormatSetting(const SettingRow& row, const SettingValue& value);
/// The default (Settings{}'s value), formatted.
std::string DefaultText(const SettingRow& row);
/// "[0.01, 255]", "flat | gouraud | ...", for help and docs.
std::string RangeText(const SettingRow& row);

/// Fills or clears settings.material.spectral* from `spectral`, `nk` and
/// `preset` (ApplySetting calls it after every change). Returns "" or why
/// spectral Fresnel has no data (no preset with measured data, no --nk).
std::string ResolveSpectral(Settings& settings);

/// ValidateMaterial, and whether `spectral` has the data it needs: the one
/// check every front end makes before drawing. "" or a one-line error.
std::string ValidateSettings(const Settings& settings);

/// Reads and parses settings.nkFile into settings.nk (and resolves).
/// Returns "" or a one-line error naming the file.
std::string ReadNkFile(Settings& settings);

/// Whether every setting of the table has the same value in `a` and `b`.
bool SameSettings(const Settings& a, const Settings& b);

/// The --help lines of every row shown on the command line in `group`.
std::string CliHelp(SettingGroup group);

/// The material's lobe weights as relative weights: scaled to sum to 1 over
/// the used lobes (the one policy of every front end); a zero sum is left
/// for ValidateMaterial to report.
void NormalizeLobeWeights(Material<double>& material);

} // namespace shadinglab::render
