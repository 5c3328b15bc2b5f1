// SPDX-License-Identifier: BSD-3-Clause
// The settings table: one row a setting (Settings.h says what reads it).
// Adding a setting means adding its row here; Settings.cpp parses, applies
// and prints any row.
#include "shadinglab/render/Settings.h"

#include "SettingsText.h"

#include "shadinglab/render/ColorMap.h"

#include "shadinglab/model/Materials.h"

#include <cctype>
#include <string>
#include <vector>

namespace shadinglab::render
{

namespace
{

using settings_text::Lower;
using settings_text::RoundTripNumber;

SettingValue Number(double v)
{
  return { { v }, {} };
}

SettingValue Text(const std::string& text)
{
  return { {}, text };
}

SettingValue Triple(const Vec3<double>& v)
{
  return { { v.x, v.y, v.z }, {} };
}

Vec3<double> TripleOf(const SettingValue& v)
{
  // One value is broadcast to the three channels (rows with `broadcast`).
  return v.numbers.size() == 1 ? Vec3<double>(v.numbers[0], v.numbers[0], v.numbers[0])
                               : Vec3<double>(v.numbers[0], v.numbers[1], v.numbers[2]);
}

template <typename Row, size_t N>
std::vector<SettingChoice> ChoicesOf(const Row (&table)[N])
{
  std::vector<SettingChoice> out;
  for (const auto& row : table)
  {
    out.push_back({ row.name, row.label });
  }
  return out;
}

std::string TitleCase(std::string name)
{
  if (!name.empty())
  {
    name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
  }
  return name;
}

SettingRow Row(const char* key, const char* property, const char* label, SettingGroup group,
  SettingKind kind)
{
  SettingRow row;
  row.key = key;
  row.property = property;
  row.label = label;
  row.group = group;
  row.kind = kind;
  return row;
}

// The mode row's choice indices are the enum's values: the drawn modes in
// order, then Auto.
static_assert(static_cast<int>(ShadingMode::Auto) == kShadingModeCount);

/// The rows of where and how the model is evaluated, and how the image is made.
void RenderRows(std::vector<SettingRow>& t)
{
  using G = SettingGroup;
  using K = SettingKind;
  {
    SettingRow r = Row("mode", "ShadingMode", "Shading Mode", G::Render, K::Choice);
    r.choices = ChoicesOf(kShadingModes);
    r.choices.push_back({ "auto", "Auto" });
    r.doc = "where the reflectance model is evaluated (docs/model.md section 2): once per "
            "polygon, at the vertices, per pixel, by Bishop & Weimer's quadratic, or auto: the "
            "cheapest of flat, gouraud and phong predicted to keep the mean error under "
            "max-error (eq. 4.1-4.5)";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "M";
    // The choices' indices are the enum's values (Auto last).
    r.set = [](Settings& s, const SettingValue& v) {
      s.render.mode = static_cast<ShadingMode>(static_cast<int>(v.numbers[0]));
    };
    r.get = [](const Settings& s) { return Number(static_cast<int>(s.render.mode)); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("max-error", "MaxError", "Max Error (1/255)", G::Render, K::Real);
    r.min = kMinMaxError;
    r.max = kMaxMaxError;
    r.doc = "auto mode: the mean error allowed against exact shading, in 1/255 of the display "
            "range";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "E";
    r.set = [](Settings& s, const SettingValue& v) { s.render.maxError = v.numbers[0]; };
    r.get = [](const Settings& s) { return Number(s.render.maxError); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("interp", "InterpolationSpace", "Interpolation Space", G::Render, K::Choice);
    r.choices = ChoicesOf(kInterpolationSpaces);
    r.doc = "perspective-correct interpolation, or linear in screen space as the lecture (shows "
            "its perspective distortion, docs/model.md eq. 3.1)";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "I";
    r.set = [](Settings& s, const SettingValue& v) {
      s.render.interpolation = kInterpolationSpaces[static_cast<int>(v.numbers[0])].value;
    };
    r.get = [](const Settings& s) { return Number(static_cast<int>(s.render.interpolation)); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("polygons", "PolygonHandling", "Polygons", G::Render, K::Choice);
    r.choices = { { "triangulate", "Triangulate" }, { "direct", "Direct" } };
    r.doc = "polygons of more than three vertices triangulated (a fan, concave ones ear-clipped), "
            "or scan-converted whole by the even-odd rule (shows orientation dependence, eq. 3.2; CPU)";
    r.frontEnds = kCli;
    r.metavar = "P";
    r.set = [](Settings& s, const SettingValue& v) {
      s.render.polygons = static_cast<PolygonHandling>(static_cast<int>(v.numbers[0]));
    };
    r.get = [](const Settings& s) { return Number(static_cast<int>(s.render.polygons)); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("backend", "Backend", "Backend", G::Render, K::Choice);
    r.choices = { { "gpu", "GPU" }, { "cpu", "CPU" }, { "auto", "Auto" } };
    r.doc = "who draws the mapper's pixels: the GLSL shaders, the CPU renderer handing colour "
            "and depth to OpenGL (no GPU needed), or auto: CPU where OpenGL is a software "
            "rasterizer and the mesh has " + std::to_string(kAutoCpuMinPolygons) +
      " polygons or more";
    r.frontEnds = kParaView | kMapper;
    r.metavar = "B";
    r.set = [](Settings& s, const SettingValue& v) {
      s.backend = static_cast<Backend>(static_cast<int>(v.numbers[0]));
    };
    r.get = [](const Settings& s) { return Number(static_cast<int>(s.backend)); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("polarization-image", "PolarizationImage", "Polarization Image", G::Render,
      K::Choice);
    r.choices = { { "intensity", "Intensity" }, { "dolp", "DoLP" }, { "aop", "AoP" } };
    r.doc = "what the surface shows: the picture, or what a polarization camera measures through "
            "analysers at 0/45/90/135 degrees: the degree of linear polarization (viridis, 0 to "
            "1) or its angle from the image's x axis (a cyclic hue wheel, -90 to 90 degrees); "
            "dark grey where no light arrives (eq. 8.5; drawn by the CPU backend; the command "
            "line's render --output)";
    r.frontEnds = kParaView | kMapper;
    r.metavar = "I";
    r.set = [](Settings& s, const SettingValue& v) {
      s.polarizationImage = static_cast<PolarizationImage>(static_cast<int>(v.numbers[0]));
    };
    r.get = [](const Settings& s) { return Number(static_cast<int>(s.polarizationImage)); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("scan", "ScanConversion", "Scan Conversion", G::Render, K::Choice);
    r.choices = ChoicesOf(kScanConversions);
    r.doc = "per-row spans (default), or the lecture's incremental DDA: edges stepped row to "
            "row, spans pixel to pixel, in screen space (eq. 2.10-2.11; CPU)";
    r.frontEnds = kCli | kExplorer;
    r.metavar = "S";
    r.set = [](Settings& s, const SettingValue& v) {
      s.render.scan = kScanConversions[static_cast<int>(v.numbers[0])].value;
    };
    r.get = [](const Settings& s) { return Number(static_cast<int>(s.render.scan)); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("scan-precision", "ScanPrecision", "Scan Precision", G::Render, K::Choice);
    r.choices = ChoicesOf(kScanPrecisions);
    r.doc = "the incremental scan's arithmetic: float (rounding error grows with the span, "
            "docs/model.md eq. 2.12) or double (CPU)";
    r.frontEnds = kCli | kExplorer;
    r.metavar = "P";
    r.set = [](Settings& s, const SettingValue& v) {
      s.render.scanPrecision = kScanPrecisions[static_cast<int>(v.numbers[0])].value;
    };
    r.get = [](const Settings& s) { return Number(static_cast<int>(s.render.scanPrecision)); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("expansion", "ExpansionPoint", "Fast Phong Expansion", G::Render, K::Choice);
    r.choices = { { "vertex", "Vertex" }, { "centroid", "Centroid" } };
    r.doc = "fast-phong Taylor point: the provoking vertex (both backends) or the centroid "
            "(lower error, eq. 2.7; CPU only)";
    r.frontEnds = kCli;
    r.metavar = "E";
    r.set = [](Settings& s, const SettingValue& v) {
      s.render.expansion = v.numbers[0] == 0 ? ExpansionPoint::Vertex : ExpansionPoint::Centroid;
    };
    r.get = [](const Settings& s) {
      return Number(s.render.expansion == ExpansionPoint::Vertex ? 0 : 1);
    };
    t.push_back(r);
  }
  {
    SettingRow r = Row("fast-phong-max-spread", "FastPhongMaxSpread", "Fast Phong Spread Limit",
      G::Render, K::Real);
    r.min = 0;
    r.max = 180;
    r.doc = "fast-phong evaluates a pixel exactly where its normal is more than this many "
            "degrees from the expansion point's (eq. 2.9); 180 shows the raw quadratic";
    r.frontEnds = kCli | kParaView | kMapper;
    r.metavar = "DEG";
    r.set = [](Settings& s, const SettingValue& v) { s.render.fastPhongMaxSpread = v.numbers[0]; };
    r.get = [](const Settings& s) { return Number(s.render.fastPhongMaxSpread); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("polarizer", "Polarizer", "Polarizer (deg, -1 none)", G::Render, K::Real);
    r.min = -1;
    r.max = 180;
    r.doc = "an analyser in front of the camera: a linear polarizer whose transmission axis is "
            "DEG from the image's x axis (counter-clockwise; Cook-Torrance's Fresnel term "
            "polarizes, diffuse light passes by half; docs/model.md section 8); -1: none";
    r.frontEnds = kCli | kParaView | kMapper;
    r.metavar = "DEG";
    r.set = [](Settings& s, const SettingValue& v) { s.render.polarizer = v.numbers[0]; };
    r.get = [](const Settings& s) { return Number(s.render.polarizer); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("light-polarizer", "LightPolarizer", "Light Polarizer (deg, -1 none)",
      G::Render, K::Real);
    r.min = -1;
    r.max = 180;
    r.doc = "a linear polarizer in front of every light, its transmission axis DEG from the "
            "image's x axis as the camera sees it; it passes half the light, and Cook-Torrance's "
            "Fresnel term keeps, rotates and (metals) turns its polarization elliptical "
            "(docs/model.md eq. 8.6); crossed with --polarizer it removes a headlight's "
            "highlights; -1: unpolarized lights";
    r.frontEnds = kCli | kParaView | kMapper;
    r.metavar = "DEG";
    r.set = [](Settings& s, const SettingValue& v) { s.render.lightPolarizer = v.numbers[0]; };
    r.get = [](const Settings& s) { return Number(s.render.lightPolarizer); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("fast-phong-as-is", "FastPhongAsIs", "Fast Phong As Is", G::Render, K::Flag);
    r.doc = "fast-phong with its quadratics even on triangles too small for them to pay (CPU; "
            "default: exact Phong there, said on stderr)";
    r.frontEnds = kCli;
    r.set = [](Settings& s, const SettingValue& v) { s.render.fastPhongFallback = v.numbers[0] == 0; };
    r.get = [](const Settings& s) { return Number(s.render.fastPhongFallback ? 0 : 1); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("ssaa", "Supersampling", "Supersampling", G::Render, K::Integer);
    r.min = 1;
    r.max = kMaxSupersampling;
    r.doc = "supersampling N x N per pixel (box filter)";
    r.frontEnds = kCli;
    r.metavar = "N";
    r.set = [](Settings& s, const SettingValue& v) { s.render.ssaa = static_cast<int>(v.numbers[0]); };
    r.get = [](const Settings& s) { return Number(s.render.ssaa); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("threads", "Threads", "Threads", G::Render, K::Integer);
    r.min = 0;
    r.max = 256;
    r.doc = "worker threads of the CPU renderer; 0: all cores";
    r.frontEnds = kCli;
    r.metavar = "N";
    r.set = [](Settings& s, const SettingValue& v) { s.render.threads = static_cast<int>(v.numbers[0]); };
    r.get = [](const Settings& s) { return Number(s.render.threads); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("cull", "CullBackFaces", "Cull Back Faces", G::Render, K::Flag);
    r.doc = "cull back faces";
    r.frontEnds = kCli;
    r.set = [](Settings& s, const SettingValue& v) { s.render.cullBackFaces = v.numbers[0] != 0; };
    r.get = [](const Settings& s) { return Number(s.render.cullBackFaces ? 1 : 0); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("display", "DisplayTransform", "Display", G::Render, K::Choice);
    r.choices = ChoicesOf(kDisplayTransforms);
    r.doc = "linear intensity to pixel: clamped to [0, 1], clamped then sRGB-encoded, or "
            "Khronos PBR Neutral (highlights compressed, never clipped)";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "D";
    r.set = [](Settings& s, const SettingValue& v) {
      s.render.display = kDisplayTransforms[static_cast<int>(v.numbers[0])].value;
    };
    r.get = [](const Settings& s) { return Number(static_cast<int>(s.render.display)); };
    t.push_back(r);
  }
}

/// The rows of colour by data.
void ColorRows(std::vector<SettingRow>& t)
{
  using G = SettingGroup;
  using K = SettingKind;
  {
    SettingRow r = Row("color-by", "ColorBy", "Color By", G::Render, K::Text);
    r.doc = "colour by a point or cell array (a component, or the magnitude of a vector): it "
            "gives the diffuse colour, mapped per pixel after interpolation";
    r.frontEnds = kCli;
    r.metavar = "[POINTS:|CELLS:]NAME[:C|Magnitude]";
    r.set = [](Settings& s, const SettingValue& v) { s.color.array = v.text; };
    r.get = [](const Settings& s) { return Text(s.color.array); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("colormap", "Colormap", "Color Map", G::Render, K::Text);
    for (const ColorMapName& name : ColorMapNames())
    {
      r.choices.push_back(
        { name.key, name.alias.empty() ? name.label : name.label + ", formerly " + name.alias });
    }
    r.doc = "the colour map of --color-by: ParaView's preset of that name";
    r.frontEnds = kCli;
    r.metavar = "NAME";
    r.set = [](Settings& s, const SettingValue& v) { s.color.colormap = v.text; };
    r.get = [](const Settings& s) { return Text(s.color.colormap); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("range", "ColorRange", "Color Range", G::Render, K::Text);
    r.doc = "the data range the colour map spans: auto (the array's finite values) or MIN,MAX";
    r.frontEnds = kCli;
    r.metavar = "MIN,MAX";
    r.set = [](Settings& s, const SettingValue& v) { s.color.range = v.text; };
    r.get = [](const Settings& s) { return Text(s.color.range); };
    t.push_back(r);
  }
}

/// The smallest solid angle a light may subtend: 1e-6 sr, about a
/// seventieth of the sun's 6.8e-5 sr (a point-like source; zero would be
/// no light at all, which the intensity says more plainly).
constexpr double kMinLightSolidAngle = 1e-6;

/// The rows of the lights.
void LightRows(std::vector<SettingRow>& t)
{
  using G = SettingGroup;
  using K = SettingKind;
  {
    SettingRow r = Row("light-intensity", "LightIntensity", "Light Intensity", G::Lights, K::Real);
    // 1e6 keeps I_L times any reflectance (<= 1/sr x pi) far inside float.
    r.min = 0;
    r.max = 1e6;
    r.doc = "scales the intensity I_L of every light (eq. 1.1)";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "I";
    r.set = [](Settings& s, const SettingValue& v) { s.lightIntensity = v.numbers[0]; };
    r.get = [](const Settings& s) { return Number(s.lightIntensity); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("light-solid-angle", "LightSolidAngle", "Light Solid Angle (sr)", G::Lights, K::Real);
    // Up to the whole sphere, 4 pi sr.
    r.min = kMinLightSolidAngle;
    r.max = 4 * kPi<double>;
    r.doc = "the solid angle dw each light subtends, in steradians: irradiance I_L dw (eq. 1.1); pi "
            "makes a unit light on a white Lambertian surface give 1";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "SR";
    r.set = [](Settings& s, const SettingValue& v) { s.lightSolidAngle = v.numbers[0]; };
    r.get = [](const Settings& s) { return Number(s.lightSolidAngle); };
    t.push_back(r);
  }
}

/// The rows of the material (docs/model.md section 1).
void MaterialRows(std::vector<SettingRow>& t)
{
  using G = SettingGroup;
  using K = SettingKind;
  {
    SettingRow r = Row("material", "MaterialPreset", "Material Preset", G::Material, K::Text);
    r.choices.push_back({ "custom", "Custom" });
    for (const auto& p : MaterialPresets())
    {
      r.choices.push_back({ p.name, TitleCase(p.name) });
    }
    r.doc = "a named material with cited optical constants (plugin/model/src/Materials.cpp) "
            "that replaces every material parameter; custom: the parameters";
    r.frontEnds = kCli | kParaView | kMapper;
    r.metavar = "PRESET";
    r.set = [](Settings& s, const SettingValue& v) {
      s.preset = v.text == "custom" ? std::string() : v.text;
      if (const MaterialPreset* preset = FindMaterialPreset(s.preset))
      {
        s.material = preset->material;
      }
    };
    r.get = [](const Settings& s) { return SettingValue{ {}, s.preset.empty() ? "custom" : s.preset }; };
    t.push_back(r);
  }
  {
    SettingRow r = Row("model", "ReflectanceModel", "Reflectance Model", G::Material, K::Choice);
    r.choices = ChoicesOf(kReflectanceModels);
    r.doc = "what is evaluated (docs/model.md section 1), independent of the shading mode";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "NAME";
    r.set = [](Settings& s, const SettingValue& v) {
      s.material.model = kReflectanceModels[static_cast<int>(v.numbers[0])].value;
    };
    r.get = [](const Settings& s) { return Number(static_cast<int>(s.material.model)); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("kd", "Kd", "Diffuse kd", G::Material, K::Real);
    r.min = 0;
    r.max = 1;
    r.doc = "diffuse weight kd of R = kd Rd + ks Rs (kd + ks <= 1)";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "X";
    r.set = [](Settings& s, const SettingValue& v) { s.material.kd = v.numbers[0]; };
    r.get = [](const Settings& s) { return Number(s.material.kd); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("ks", "Ks", "Specular ks", G::Material, K::Real);
    r.min = 0;
    r.max = 1;
    r.doc = "specular weight ks of R = kd Rd + ks Rs (kd + ks <= 1)";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "X";
    r.set = [](Settings& s, const SettingValue& v) { s.material.ks = v.numbers[0]; };
    r.get = [](const Settings& s) { return Number(s.material.ks); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("highlights", "Highlights", "Highlights", G::Material, K::Choice);
    r.choices = ChoicesOf(kHighlightModes);
    r.doc = "draw the specular lobe: auto leaves it off a surface coloured by data (white "
            "added to a colour map reads as data), on draws it always, off never";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "H";
    r.set = [](Settings& s, const SettingValue& v) {
      s.highlights = kHighlightModes[static_cast<int>(v.numbers[0])].value;
    };
    r.get = [](const Settings& s) { return Number(static_cast<int>(s.highlights)); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("shininess", "Shininess", "Shininess n", G::Material, K::Real);
    r.min = 0;
    r.max = 1e4;
    r.doc = "exponent n of the Phong (R.V)^n and Blinn-Phong (N.H)^n lobes, normalized by "
            "(n+2)/2pi and (n+8)/8pi";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "N";
    r.set = [](Settings& s, const SettingValue& v) { s.material.shininess = v.numbers[0]; };
    r.get = [](const Settings& s) { return Number(s.material.shininess); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("albedo", "Albedo", "Albedo rho", G::Material, K::Real);
    r.maxCount = 3;
    r.broadcast = true;
    r.min = 0;
    r.max = 1;
    r.doc = "diffuse colour rho, Rd = rho/pi (in ParaView and VTK the mapped colour is rho)";
    r.frontEnds = kCli;
    r.metavar = "R,G,B";
    r.set = [](Settings& s, const SettingValue& v) { s.material.diffuseColor = TripleOf(v); };
    r.get = [](const Settings& s) { return Triple(s.material.diffuseColor); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("ambient", "AmbientReflectance", "Ambient Ra", G::Material, K::Real);
    r.maxCount = 3;
    r.broadcast = true;
    r.min = 0;
    r.max = 1;
    r.paraviewCount = 1;
    r.doc = "ambient reflectance Ra of the term Ra Ia (eq. 1.1)";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "R,G,B";
    r.set = [](Settings& s, const SettingValue& v) { s.material.ambient = TripleOf(v); };
    r.get = [](const Settings& s) { return Triple(s.material.ambient); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("specular", "SpecularTint", "Specular Colour", G::Material, K::Real);
    r.maxCount = 3;
    r.broadcast = true;
    r.min = 0;
    r.max = 1;
    r.doc = "specular colour of the Phong and Blinn-Phong lobes (Cook-Torrance takes its "
            "colour from Fresnel)";
    r.frontEnds = kCli | kParaView | kMapper;
    r.metavar = "R,G,B";
    r.set = [](Settings& s, const SettingValue& v) { s.material.specularColor = TripleOf(v); };
    r.get = [](const Settings& s) { return Triple(s.material.specularColor); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("m", "BeckmannRoughness", "Roughness m", G::Material, K::Real);
    r.maxCount = kMaxLobes;
    // 0 marks an unused lobe; a used one must lie in [1e-3, 1e3]
    // (ValidateMaterial).
    r.min = 0;
    r.max = 1e3;
    r.doc = "Cook-Torrance RMS microfacet slopes m_k of the Beckmann mixture, one per lobe "
            "(the leading positive values are the lobes)";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "M[,M..]";
    r.set = [](Settings& s, const SettingValue& v) {
      Material<double>& m = s.material;
      m.lobeCount = 0;
      for (size_t k = 0; k < v.numbers.size() && v.numbers[k] > 0; ++k)
      {
        m.lobes[k].m = v.numbers[k];
        m.lobeCount = static_cast<int>(k) + 1;
      }
      if (m.lobeCount == 0)
      {
        m.lobeCount = 1;
        m.lobes[0].m = v.numbers[0]; // rejected by ValidateMaterial with its own message
      }
    };
    r.get = [](const Settings& s) {
      SettingValue v;
      for (int k = 0; k < kMaxLobes; ++k)
      {
        v.numbers.push_back(k < s.material.lobeCount ? s.material.lobes[k].m : 0.0);
      }
      return v;
    };
    t.push_back(r);
  }
  {
    SettingRow r = Row("w", "BeckmannWeights", "Lobe Weights w", G::Material, K::Real);
    r.maxCount = kMaxLobes;
    r.min = 0;
    r.max = 1;
    r.doc = "relative weights w_k of the Beckmann lobes, normalized to sum to 1 over the used "
            "lobes";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "W[,W..]";
    r.set = [](Settings& s, const SettingValue& v) {
      for (int k = 0; k < kMaxLobes; ++k)
      {
        s.material.lobes[k].weight = k < static_cast<int>(v.numbers.size()) ? v.numbers[k] : 0.0;
      }
    };
    r.get = [](const Settings& s) {
      SettingValue v;
      for (int k = 0; k < kMaxLobes; ++k)
      {
        v.numbers.push_back(k < s.material.lobeCount ? s.material.lobes[k].weight : 0.0);
      }
      return v;
    };
    t.push_back(r);
  }
  {
    SettingRow r = Row("eta", "Eta", "Index eta (RGB)", G::Material, K::Real);
    r.maxCount = 3;
    r.broadcast = true;
    // An index below 0.01 or above 100 is no material (ValidateMaterial).
    r.min = 0.01;
    r.max = 100;
    r.doc = "relative index of refraction per RGB channel, for the Fresnel term";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "E[,E,E]";
    r.set = [](Settings& s, const SettingValue& v) { s.material.eta = TripleOf(v); };
    r.get = [](const Settings& s) { return Triple(s.material.eta); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("k", "Extinction", "Extinction k (RGB)", G::Material, K::Real);
    r.maxCount = 3;
    r.broadcast = true;
    r.min = 0;
    r.max = 100;
    r.doc = "extinction coefficient per RGB channel; any k > 0 selects the conductor Fresnel "
            "with complex index eta + ik";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.metavar = "K[,K,K]";
    r.set = [](Settings& s, const SettingValue& v) { s.material.k = TripleOf(v); };
    r.get = [](const Settings& s) { return Triple(s.material.k); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("spectral", "Spectral", "Spectral Fresnel", G::Material, K::Flag);
    r.doc = "Cook-Torrance's F per wavelength from measured n and k (a preset's, or --nk's), "
            "integrated under D65 against the CIE 1931 observer to linear sRGB with " +
      std::to_string(kSpectralSamples) + " samples (docs/model.md section 7); replaces eta and k";
    r.frontEnds = kCli | kParaView | kMapper | kExplorer;
    r.set = [](Settings& s, const SettingValue& v) { s.spectral = v.numbers[0] != 0; };
    r.get = [](const Settings& s) { return Number(s.spectral ? 1 : 0); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("nk", "OpticalDataFile", "Optical Data File", G::Material, K::Text);
    r.doc = "a refractiveindex.info YAML file (tabulated nk, tabulated n, or Sellmeier "
            "formula 2) covering 380-780 nm: the material's n and k for --spectral (in "
            "ParaView: a file on the server; empty: the preset's data)";
    r.frontEnds = kCli | kParaView;
    r.metavar = "FILE.yml";
    r.set = [](Settings& s, const SettingValue& v) {
      s.nkFile = v.text;
      s.nk.reset();
    };
    r.get = [](const Settings& s) { return SettingValue{ {}, s.nkFile }; };
    t.push_back(r);
  }
  {
    SettingRow r = Row("variant", "SpecularVariant", "Specular Variant", G::Material, K::Choice);
    r.choices = { { "1982", "Cook-Torrance 1982" }, { "walter", "Walter 2007" } };
    r.doc = "Cook-Torrance denominator: (N.L)(N.V) as Cook & Torrance 1982 and the lecture, or "
            "4(N.L)(N.V) of Walter et al. 2007 (eq. 1.5)";
    r.frontEnds = kCli | kParaView | kMapper;
    r.metavar = "V";
    r.set = [](Settings& s, const SettingValue& v) {
      s.material.variant =
        v.numbers[0] == 0 ? SpecularVariant::CookTorrance1982 : SpecularVariant::Walter2007;
    };
    r.get = [](const Settings& s) {
      return Number(s.material.variant == SpecularVariant::CookTorrance1982 ? 0 : 1);
    };
    t.push_back(r);
  }
}

/// The rows of the normals made for a mesh without them.
void MeshRows(std::vector<SettingRow>& t)
{
  using G = SettingGroup;
  using K = SettingKind;
  {
    SettingRow r = Row("normal-weighting", "NormalWeighting", "Normal Weighting", G::Mesh, K::Choice);
    r.choices = { { "uniform", "Uniform" }, { "area", "Area" }, { "angle", "Angle" },
      { "max", "Max" } };
    r.doc = "weighting of the vertex normals made when the data has none (or always, with "
            "recompute-normals): uniform, area, angle (Thurmer & Wuthrich 1998) or Max (1999)";
    r.frontEnds = kParaView | kMapper;
    r.metavar = "W";
    r.set = [](Settings& s, const SettingValue& v) { s.normals.weighting = static_cast<int>(v.numbers[0]); };
    r.get = [](const Settings& s) { return Number(s.normals.weighting); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("feature-angle", "FeatureAngle", "Feature Angle", G::Mesh, K::Real);
    r.min = 0;
    r.max = 180;
    r.doc = "made normals are split where faces meet at more than this angle in degrees; 180 "
            "splits nowhere";
    r.frontEnds = kParaView | kMapper;
    r.metavar = "DEG";
    r.set = [](Settings& s, const SettingValue& v) { s.normals.featureAngle = v.numbers[0]; };
    r.get = [](const Settings& s) { return Number(s.normals.featureAngle); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("nonlinear-subdivision", "NonlinearSubdivisionLevel",
      "Nonlinear Subdivision Level", G::Mesh, K::Integer);
    // 4 as ParaView's property (mesh::kMaxNonlinearSubdivisionLevel):
    // 256 triangles per quadratic triangle.
    r.min = 0;
    r.max = 4;
    r.doc = "times each higher-order (quadratic) face of a file is split into linear ones, as "
            "ParaView's Surface does; 0 draws the corner nodes' faces";
    r.frontEnds = kCli | kExplorer;
    r.metavar = "N";
    r.set = [](Settings& s, const SettingValue& v) {
      s.input.nonlinearSubdivisionLevel = static_cast<int>(v.numbers[0]);
    };
    r.get = [](const Settings& s) { return Number(s.input.nonlinearSubdivisionLevel); };
    t.push_back(r);
  }
  {
    SettingRow r = Row("recompute-normals", "RecomputeNormals", "Recompute Normals", G::Mesh, K::Flag);
    r.doc = "make normals with the weighting and feature angle even when the data has normals";
    r.frontEnds = kParaView | kMapper;
    r.set = [](Settings& s, const SettingValue& v) { s.normals.recompute = v.numbers[0] != 0; };
    r.get = [](const Settings& s) { return Number(s.normals.recompute ? 1 : 0); };
    t.push_back(r);
  }
}

std::vector<SettingRow> MakeTable()
{
  std::vector<SettingRow> t;
  RenderRows(t);
  ColorRows(t);
  LightRows(t);
  MaterialRows(t);
  MeshRows(t);
  return t;
}

} // namespace

const std::vector<SettingRow>& SettingsTable()
{
  static const std::vector<SettingRow> table = MakeTable();
  return table;
}

} // namespace shadinglab::render
