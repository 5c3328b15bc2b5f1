// SPDX-License-Identifier: BSD-3-Clause
// Wavelength (docs/model.md section 7): the measured data as the presets
// read it, the CIE/D65 reduction to linear sRGB, CIEDE2000, and the sample
// count's error against the 5 nm reference.
#include "shadinglab/model/Fresnel.h"
#include "shadinglab/model/Materials.h"
#include "shadinglab/model/Spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sl = shadinglab;

namespace
{

std::string ReadText(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The "wavelength_um n k" rows of a tabulated-nk file, read independently
/// of ParseDispersion: every line of three numbers.
std::vector<std::array<double, 3>> Rows(const std::string& text)
{
  std::vector<std::array<double, 3>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
  {
    std::istringstream l(line);
    std::array<double, 3> r{};
    std::string extra;
    if (l >> r[0] >> r[1] >> r[2] && !(l >> extra))
    {
      rows.push_back(r);
    }
  }
  return rows;
}

const std::string kOptical = std::string(SHADINGLAB_SOURCE_DIR) + "/datasets/optical/";

/// Worst CIEDE2000, over incidence 0-89 degrees, of `count` samples against
/// the 81-row reference for one dispersion.
double WorstDeltaE(const sl::Dispersion& d, int count)
{
  double worst = 0.0;
  for (double deg : { 0.0, 15.0, 30.0, 45.0, 60.0, 70.0, 75.0, 80.0, 85.0, 89.0 })
  {
    const double c = std::cos(deg * sl::kPi<double> / 180.0);
    auto R = [&](double nm) {
      double n = 0, k = 0;
      d.Evaluate(nm, n, k);
      return sl::F_Conductor(c, n, k);
    };
    worst = std::max(worst,
      sl::DeltaE2000(sl::SpectrumToLinearSRGB(R, sl::kCieRows), sl::SpectrumToLinearSRGB(R, count)));
  }
  return worst;
}

} // namespace

// The presets read the files' rows exactly, at every tabulated wavelength
// in the visible range.
TEST(SpectrumTest, PresetsAreTheirTabulatedData)
{
  const std::pair<const char*, const char*> files[] = { { "gold", "Au_Johnson.yml" },
    { "silver", "Ag_Johnson.yml" }, { "copper", "Cu_Johnson.yml" },
    { "aluminium", "Al_Rakic.yml" }, { "water", "H2O_Hale.yml" } };
  for (const auto& [preset, file] : files)
  {
    const sl::Dispersion* d = sl::PresetDispersion(preset);
    ASSERT_NE(d, nullptr) << preset;
    int checked = 0;
    for (const auto& r : Rows(ReadText(kOptical + file)))
    {
      const double nm = r[0] * 1000.0;
      if (nm < sl::kVisibleMinNm || nm > sl::kVisibleMaxNm)
      {
        continue;
      }
      double n = 0, k = 0;
      ASSERT_TRUE(d->Evaluate(nm, n, k)) << preset << " " << nm;
      EXPECT_DOUBLE_EQ(n, r[1]) << preset << " at " << nm << " nm";
      EXPECT_DOUBLE_EQ(k, r[2]) << preset << " at " << nm << " nm";
      ++checked;
    }
    EXPECT_GE(checked, 9) << preset;
    // Between rows: linear.
    double n = 0, k = 0;
    ASSERT_TRUE(d->Evaluate(500.0, n, k));
    EXPECT_TRUE(n > 0 && std::isfinite(n) && k >= 0);
  }
  // N-BK7's Sellmeier formula: n_d = 1.5168 at 587.56 nm, n_F = 1.5224 at
  // 486.13 nm, n_C = 1.5143 at 656.27 nm (SCHOTT's data sheet, 4 decimals).
  const sl::Dispersion* glass = sl::PresetDispersion("glass");
  ASSERT_NE(glass, nullptr);
  const std::pair<double, double> lines[] = { { 587.56, 1.5168 }, { 486.13, 1.5224 },
    { 656.27, 1.5143 } };
  for (const auto& [nm, expected] : lines)
  {
    double n = 0, k = 0;
    ASSERT_TRUE(glass->Evaluate(nm, n, k));
    EXPECT_NEAR(n, expected, 5e-5) << nm;
    EXPECT_LT(k, 1e-6);
  }
  EXPECT_EQ(sl::PresetDispersion("plastic"), nullptr);
  EXPECT_EQ(sl::PresetDispersion("aluminum"), sl::PresetDispersion("aluminium"));
}

// The metal presets' RGB n and k are RgbFromDispersion's fit to their
// spectra (to the 4 digits Materials.cpp writes).
TEST(SpectrumTest, MetalPresetsAreTheFitToTheirSpectra)
{
  for (const char* preset : { "gold", "copper", "silver", "aluminium" })
  {
    sl::Vec3d eta, k;
    sl::RgbFromDispersion(*sl::PresetDispersion(preset), sl::RgbChoice::Fitted, eta, k);
    const sl::Material<double>& m = sl::FindMaterialPreset(preset)->material;
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(m.eta[c], eta[c], 1e-3 * eta[c]) << preset << " channel " << c;
      EXPECT_NEAR(m.k[c], k[c], 1e-3 * k[c]) << preset << " channel " << c;
    }
  }
}

// A perfect reflector under D65 is white, (1, 1, 1), for every sample
// count: the weights of each count sum to the white point.
TEST(SpectrumTest, PerfectReflectorIsWhite)
{
  for (int count : { 3, 8, sl::kSpectralSamples, sl::kCieRows })
  {
    const sl::Vec3d rgb = sl::SpectrumToLinearSRGB([](double) { return 1.0; }, count);
    EXPECT_NEAR(rgb.x, 1.0, 2e-4) << count;
    EXPECT_NEAR(rgb.y, 1.0, 2e-4) << count;
    EXPECT_NEAR(rgb.z, 1.0, 2e-4) << count;
    const sl::Vec3d half = sl::SpectrumToLinearSRGB([](double) { return 0.5; }, count);
    EXPECT_NEAR(half.y, 0.5 * rgb.y, 1e-12);
  }
  // The basis covers 380-780 nm in increasing order.
  const sl::SpectralBasis& basis = sl::SpectralBasisD65();
  ASSERT_EQ(static_cast<int>(basis.wavelength.size()), sl::kSpectralSamples);
  EXPECT_GT(basis.wavelength.front(), 380.0);
  EXPECT_LT(basis.wavelength.back(), 780.0);
  for (size_t i = 1; i < basis.wavelength.size(); ++i)
  {
    EXPECT_GT(basis.wavelength[i], basis.wavelength[i - 1]);
  }
}

// CIEDE2000 against Sharma, Wu & Dalal's published test pairs (Table 1).
TEST(SpectrumTest, DeltaE2000MatchesSharmasTestData)
{
  struct Pair
  {
    sl::Vec3d a, b;
    double dE;
  };
  const Pair pairs[] = {
    { { 50.0, 2.6772, -79.7751 }, { 50.0, 0.0, -82.7485 }, 2.0425 },
    { { 50.0, 0.0, 0.0 }, { 50.0, -1.0, 2.0 }, 2.3669 },
    { { 50.0, 2.5, 0.0 }, { 73.0, 25.0, -18.0 }, 27.1492 },
    { { 60.2574, -34.0099, 36.2677 }, { 60.4626, -34.1751, 39.4387 }, 1.2644 },
    { { 2.0776, 0.0795, -1.1350 }, { 0.9033, -0.0636, -0.5514 }, 0.9082 },
  };
  for (const Pair& p : pairs)
  {
    EXPECT_NEAR(sl::DeltaE2000Lab(p.a, p.b), p.dE, 1e-4);
    EXPECT_NEAR(sl::DeltaE2000Lab(p.b, p.a), p.dE, 1e-4);
  }
  EXPECT_EQ(sl::DeltaE2000({ 0.3, 0.5, 0.7 }, { 0.3, 0.5, 0.7 }), 0.0);
  // White in Lab is (100, 0, 0).
  const sl::Vec3d white = sl::XYZToLab(sl::LinearSRGBToXYZ({ 1, 1, 1 }));
  EXPECT_NEAR(white.x, 100.0, 1e-9);
  EXPECT_NEAR(white.y, 0.0, 1e-9);
}

// Spectral F at normal incidence is the linear sRGB of the normal-incidence
// reflectance spectrum; 16 samples are within half a just-noticeable
// difference (CIEDE2000 < 0.5) of the 5 nm reference at every angle for
// every preset, and 8 are not (what kSpectralSamples' comment claims).
TEST(SpectrumTest, SixteenSamplesAreWithinAJndOfTheReference)
{
  double worst16 = 0.0, worst8 = 0.0;
  for (const char* preset : { "gold", "silver", "copper", "aluminium", "glass", "water" })
  {
    const sl::Dispersion* d = sl::PresetDispersion(preset);
    ASSERT_NE(d, nullptr);
    sl::Material<double> m = sl::FindMaterialPreset(preset)->material;
    ASSERT_EQ(sl::SetSpectral(m, *d), "");
    ASSERT_EQ(m.spectralCount, sl::kSpectralSamples);
    auto R0 = [&](double nm) {
      double n = 0, k = 0;
      d->Evaluate(nm, n, k);
      return sl::F0_Conductor(n, k);
    };
    const sl::Vec3d F = m.Fresnel(1.0);
    const sl::Vec3d sampled = sl::SpectrumToLinearSRGB(R0, sl::kSpectralSamples);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(F[c], sampled[c], 1e-12) << preset;
    }
    const double dE = sl::DeltaE2000(F, sl::SpectrumToLinearSRGB(R0, sl::kCieRows));
    EXPECT_LT(dE, 0.5) << preset;
    const double w16 = WorstDeltaE(*d, sl::kSpectralSamples), w8 = WorstDeltaE(*d, 8);
    std::printf("%-10s normal incidence F (%.4f, %.4f, %.4f), dE2000 against 81 samples, "
                "worst: 16 samples %.3f, 12: %.3f, 8: %.3f\n",
      preset, F.x, F.y, F.z, w16, WorstDeltaE(*d, 12), w8);
    worst16 = std::max(worst16, w16);
    worst8 = std::max(worst8, w8);
  }
  EXPECT_LT(worst16, 0.5);
  EXPECT_GT(worst8, 0.5);
}

// Gold's colour: red above green above blue at normal incidence, and the
// spectral and the three-sample RGB gold differ visibly (the study's
// point); a material with the same n, k at every wavelength is grey.
TEST(SpectrumTest, GoldIsGoldAndFlatSpectraAreGrey)
{
  sl::Material<double> gold = sl::FindMaterialPreset("gold")->material;
  ASSERT_EQ(sl::SetSpectral(gold, *sl::PresetDispersion("gold")), "");
  const sl::Vec3d F = gold.Fresnel(1.0);
  EXPECT_GT(F.x, F.y);
  EXPECT_GT(F.y, F.z);
  sl::Vec3d eta, k;
  sl::RgbFromDispersion(*sl::PresetDispersion("gold"), sl::RgbChoice::Sampled, eta, k);
  EXPECT_GT(sl::DeltaE2000(F, sl::F_RGB(1.0, eta, k)), 2.0);

  sl::Dispersion flat;
  ASSERT_EQ(sl::ParseDispersion("DATA:\n  - type: tabulated nk\n    data: |\n        0.3 1.5 0\n"
                                "        0.8 1.5 0\n",
              "flat", flat),
    "");
  sl::Material<double> m;
  ASSERT_EQ(sl::SetSpectral(m, flat), "");
  for (double c : { 1.0, 0.5, 0.1 })
  {
    const sl::Vec3d g = m.Fresnel(c);
    const double expected = sl::F_Dielectric(c, 1.5);
    EXPECT_NEAR(g.x, expected, 3e-4 * expected + 1e-12);
    EXPECT_NEAR(g.y, expected, 3e-4 * expected + 1e-12);
    EXPECT_NEAR(g.z, expected, 3e-4 * expected + 1e-12);
  }
}

// The three data types read, and a one-line error naming the problem for
// everything else.
TEST(SpectrumTest, ParseDispersionReadsThreeTypesAndRejectsTheRest)
{
  sl::Dispersion d;
  EXPECT_EQ(sl::ParseDispersion(ReadText(kOptical + "N-BK7_Schott.yml"), "bk7", d), "");
  EXPECT_TRUE(d.sellmeier);
  EXPECT_EQ(sl::ParseDispersion("DATA:\n  - type: tabulated n\n    data: |\n        0.35 1.40\n"
                                "        0.80 1.38\n",
              "n only", d),
    "");
  double n = 0, k = 1;
  ASSERT_TRUE(d.Evaluate(575.0, n, k));
  EXPECT_NEAR(n, 1.39, 1e-12);
  EXPECT_EQ(k, 0.0);

  const std::pair<const char*, const char*> bad[] = {
    { "", "no DATA block" },
    { "REFERENCES: x\n", "no DATA block" },
    { "DATA:\n  - type: formula 3\n    coefficients: 0 1 2\n", "not supported" },
    { "DATA:\n  - type: tabulated nk\n    data: |\n        0.3 1.5\n        0.8 1.5 0\n",
      "has 2 numbers" },
    { "DATA:\n  - type: tabulated nk\n    data: |\n        0.3 1.5 x\n        0.8 1.5 0\n",
      "not numbers" },
    { "DATA:\n  - type: tabulated nk\n    data: |\n        0.8 1.5 0\n        0.3 1.5 0\n",
      "do not increase" },
    { "DATA:\n  - type: tabulated nk\n    data: |\n        0.5 1.5 0\n        0.6 1.5 0\n",
      "not the visible" },
    { "DATA:\n  - type: tabulated nk\n    data: |\n        0.3 -1 0\n        0.8 1.5 0\n",
      "n <= 0" },
    { "DATA:\n  - type: tabulated nk\n    data: |\n        0.3 1.5 -2\n        0.8 1.5 0\n",
      "k < 0" },
    { "DATA:\n  - type: tabulated nk\n    data: |\n        0.3 nan 0\n        0.8 1.5 0\n",
      "not numbers" },
    { "DATA:\n  - type: formula 2\n    coefficients: 0 1\n", "7 coefficients" },
    // A Sellmeier pole inside the visible range (C = 0.25 um^2: 500 nm).
    { "DATA:\n  - type: formula 2\n    wavelength_range: 0.3 2.5\n"
      "    coefficients: 0 1 0.25 0 0 0 0\n",
      "not a positive number" },
  };
  for (const auto& [text, expected] : bad)
  {
    const std::string problem = sl::ParseDispersion(text, "f.yml", d);
    EXPECT_NE(problem.find(expected), std::string::npos) << "'" << text << "': " << problem;
    EXPECT_EQ(problem.find('\n'), std::string::npos) << problem;
    EXPECT_EQ(problem.rfind("f.yml", 0), 0u) << problem;
  }
}
