// SPDX-License-Identifier: BSD-3-Clause
// The optics scenes: polarization (an analyser the user turns in front of a
// glass and a gold sphere) and spectral (RGB against measured spectra).
// docs/model.md sections 7 and 8.
#include "SceneParts.h"

#include "AnalyticMeshes.h"
#include "shadinglab/model/Fresnel.h"
#include "shadinglab/model/Materials.h"
#include "shadinglab/model/Spectrum.h"

#include <cmath>

namespace shadinglab::gui
{

using render::ShadingMode;

namespace
{

Material<double> Spectral(const char* preset)
{
  Material<double> m = Preset(preset);
  SetSpectral(m, *PresetDispersion(preset));
  return m;
}

/// Glass with a weak diffuse substrate, so that the sphere is visible where
/// the highlight is not; rough enough for a wide highlight near Brewster.
Material<double> RoughGlass()
{
  Material<double> m = Spectral("glass");
  m.kd = 0.15;
  m.ks = 0.85;
  m.lobes[0].m = 0.35;
  m.ambient = { 0.0, 0.0, 0.0 };
  return m;
}

} // namespace

Scene Polarization(const SceneOptions& o)
{
  Scene s;
  s.title = "Polarization: a polarizer in front of the camera";
  PolyPtr sphere = WithExactNormals(Adopt(datasets::MakeUVSphere(96, 48)));
  const Material<double> glass = RoughGlass();
  Material<double> gold = Spectral("gold");
  gold.lobes[0].m = 0.35;
  // Gold reflects ~10x what glass does: scaled down to glass's brightness
  // (and below 1: at 0.12 its highlight saturated 132 pixels).
  gold.ks = 0.09;
  auto through = [&](const char* title, const Material<double>& m, double deg) {
    widgets::PanelSpec p = Panel(title, sphere, ShadingMode::Phong, m, o.backend);
    p.polarizer = deg;
    p.lightPolarizer = o.lightPolarizer;
    return p;
  };
  widgets::PanelSpec plain =
    Panel("Glass (N-BK7), no polarizer", sphere, ShadingMode::Phong, glass, o.backend);
  plain.lightPolarizer = o.lightPolarizer;
  widgets::PanelSpec dolp = through("Glass: degree of linear polarization", glass, -1.0);
  dolp.dolpImage = true;
  const double theta = o.polarizer, crossed = std::fmod(o.polarizer + 90.0, 180.0);
  char a[96], b[96], c[96];
  std::snprintf(a, sizeof a, "Glass through a polarizer at %.0f deg", theta);
  std::snprintf(b, sizeof b, "Glass through a polarizer at %.0f deg", crossed);
  std::snprintf(c, sizeof c, "Gold through a polarizer at %.0f deg", theta);
  s.panels = { plain, through(a, glass, theta), through(b, glass, crossed), through(c, gold, theta),
    dolp };
  // The light from the left, nearly at right angles to the view: the
  // highlight's facets see it near Brewster's angle (56.6 degrees), where
  // glass reflects only s-polarized light, vertical in the image.
  s.lightAzimuth = -80;
  s.lightElevation = 5;
  s.lightIntensity = 1.5; // (2.5 saturated 6% of the glass sphere)
  s.plot = PlotKind::Parameter;
  s.explanation =
    "Light reflected by glass at Brewster's angle (tan \u03b8B = \u03b7, 56.6\u00b0 for "
    "N-BK7) is polarized perpendicular to the plane of incidence: Rp = 0. The light comes "
    "from the left, so that polarization is vertical in the image: a polarizer at 90\u00b0 "
    "passes the glass's highlight, the crossed one at 0\u00b0 nearly removes it (turn it "
    "with 'polarization: polarizer'). Diffuse light is unpolarized and passes by half. "
    "Gold, a conductor, reflects both polarizations strongly, so its highlight changes "
    "little. The last panel is what a polarization camera measures: the degree of linear "
    "polarization, highest where the highlight's facets see the light near Brewster's angle. "
    "With 'polarization: light polarizer' the light itself is polarized: a polarizer crossed "
    "with it removes the highlights (cross-polarized photography), and gold turns the "
    "light elliptical. The plot: Rs, Rp and the degree of linear polarization against the "
    "angle of incidence; the marker is Brewster's angle.";
  s.formula = "I(&theta;) = (S<sub>0</sub> + S<sub>1</sub> cos 2&theta; + S<sub>2</sub> sin "
              "2&theta;)/2; specular S = (A, B, 0, 0), A = (R<sub>s</sub>+R<sub>p</sub>)/2, "
              "B = (R<sub>s</sub>-R<sub>p</sub>)/2 &nbsp; (eq. 8.1-8.4)";
  return s;
}

Scene SpectralScene(const SceneOptions& o)
{
  Scene s;
  s.title = "Wavelength: RGB metals against their measured spectra";
  PolyPtr sphere = WithExactNormals(Adopt(datasets::MakeUVSphere(96, 48)));
  auto panel = [&](const char* title, const Material<double>& m) {
    return Panel(title, sphere, ShadingMode::Phong, m, o.backend);
  };
  // The RGB preset's n, k are fitted to the spectrum's colour (the closest
  // of three RGB choices); sampled at 650/550/450 nm is the usual choice.
  Material<double> goldSampled = Preset("gold");
  RgbFromDispersion(*PresetDispersion("gold"), RgbChoice::Sampled, goldSampled.eta, goldSampled.k);
  widgets::PanelSpec heat = panel("CIEDE2000: sampled RGB gold against spectral", goldSampled);
  heat.errorReference = 1;
  heat.colourDifference = true;
  heat.errorScale = 8.0;
  s.panels = { panel("Gold, RGB sampled at 650/550/450 nm", goldSampled),
    panel("Gold, spectral (16 wavelengths)", Spectral("gold")), heat,
    panel("Copper, RGB sampled", [] {
      Material<double> m = Preset("copper");
      RgbFromDispersion(*PresetDispersion("copper"), RgbChoice::Sampled, m.eta, m.k);
      return m;
    }()),
    panel("Copper, spectral (16 wavelengths)", Spectral("copper")) };
  s.lightAzimuth = -40;
  s.lightElevation = 20;
  // A dim light keeps the metals below white, so their colours show.
  s.lightIntensity = 0.07; // (0.08 saturated 45 pixels of spectral gold)
  s.plot = PlotKind::Parameter;
  s.explanation =
    "Fresnel's F depends on wavelength: a metal's n and k are functions of \u03bb. With "
    "three samples (the usual 650/550/450 nm) gold comes out too yellow: its colour is "
    "the integral of its reflectance spectrum under the light (D65) against the eye's "
    "colour-matching functions, and a spectrum with a steep edge near 520 nm is badly "
    "represented by three values. The heat map is the CIEDE2000 colour difference "
    "between the first two panels (1: just noticeable). The plot: gold's and copper's n, "
    "k and normal-incidence reflectance R against wavelength (Johnson & Christy 1972).";
  s.formula = "RGB = &Sigma;<sub>g</sub> w<sub>g</sub> F(&theta;; n(&lambda;<sub>g</sub>), "
              "k(&lambda;<sub>g</sub>)), w<sub>g</sub> = M &Sigma; S x&#772;y&#772;z&#772; / "
              "&Sigma; S y&#772; &nbsp; (eq. 7.1-7.3)";
  return s;
}

Study PolarizationStudy()
{
  Study study;
  study.title = "Glass (N-BK7, 550 nm) and gold: reflectances and polarization";
  study.xTitle = "angle of incidence (degrees)";
  study.yTitle = "R and DoLP";
  double n = 0, k = 0;
  PresetDispersion("glass")->Evaluate(550.0, n, k);
  study.marker = std::atan(n) * 180.0 / kPi<double>;
  study.markerLabel = "Brewster's angle";
  double gn = 0, gk = 0;
  PresetDispersion("gold")->Evaluate(550.0, gn, gk);
  Study::Series rs{ "glass Rs", {}, {} }, rp{ "glass Rp", {}, {} }, dolp{ "glass DoLP", {}, {} };
  Study::Series goldDolp{ "gold DoLP (550 nm)", {}, {} };
  for (int deg = 0; deg <= 89; ++deg)
  {
    const double c = std::cos(deg * kPi<double> / 180.0);
    double Rs = 0, Rp = 0;
    F_ConductorSP(c, n, k, Rs, Rp);
    rs.x.push_back(deg);
    rs.y.push_back(Rs);
    rp.x.push_back(deg);
    rp.y.push_back(Rp);
    dolp.x.push_back(deg);
    dolp.y.push_back(Rs + Rp > 0 ? (Rs - Rp) / (Rs + Rp) : 0.0);
    F_ConductorSP(c, gn, gk, Rs, Rp);
    goldDolp.x.push_back(deg);
    goldDolp.y.push_back(Rs + Rp > 0 ? (Rs - Rp) / (Rs + Rp) : 0.0);
  }
  study.series = { rs, rp, dolp, goldDolp };
  return study;
}

Study SpectralStudy()
{
  Study study;
  study.title = "Gold and copper: n, k and normal-incidence reflectance R against wavelength";
  study.xTitle = "wavelength (nm)";
  study.yTitle = "n, k / 4, R";
  for (const char* metal : { "gold", "copper" })
  {
    const Dispersion& d = *PresetDispersion(metal);
    Study::Series n{ std::string(metal) + " n", {}, {} }, k{ std::string(metal) + " k / 4", {}, {} },
      R{ std::string(metal) + " R", {}, {} };
    for (double nm = kVisibleMinNm; nm <= kVisibleMaxNm; nm += 5.0)
    {
      double nv = 0, kv = 0;
      d.Evaluate(nm, nv, kv);
      n.x.push_back(nm);
      n.y.push_back(nv);
      k.x.push_back(nm);
      k.y.push_back(kv / 4.0);
      R.x.push_back(nm);
      R.y.push_back(F0_Conductor(nv, kv));
    }
    study.series.push_back(n);
    study.series.push_back(k);
    study.series.push_back(R);
  }
  return study;
}

} // namespace shadinglab::gui
