// SPDX-License-Identifier: BSD-3-Clause
// Spectral Fresnel on the command line (docs/model.md section 7):
// `brdf --spectral --term F` prints the linear sRGB of the metal's
// reflectance spectrum, `--nk FILE.yml` reads a refractiveindex.info file,
// and every bad file or missing data source is one line and exit 2.
#include "CliTestUtil.h"

#include "shadinglab/model/Fresnel.h"
#include "shadinglab/model/Spectrum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using shadinglab::testing::RunCli;
namespace sl = shadinglab;

namespace
{
const std::string kData = std::string(SHADINGLAB_SOURCE_DIR) + "/datasets/";

/// The r, g, b columns of brdf's CSV's only data row.
std::vector<double> LastRgb(const std::string& csv)
{
  std::istringstream in(csv);
  std::string line, last;
  while (std::getline(in, line))
  {
    if (!line.empty())
    {
      last = line;
    }
  }
  std::vector<double> v;
  std::istringstream row(last);
  std::string cell;
  while (std::getline(row, cell, ','))
  {
    v.push_back(std::stod(cell));
  }
  return v.size() >= 6 ? std::vector<double>(v.end() - 3, v.end()) : std::vector<double>();
}

std::string Write(const std::string& name, const std::string& text)
{
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}
} // namespace

// At normal incidence, brdf --spectral --term F is the metal's
// normal-incidence reflectance spectrum as linear sRGB (eq. 7.2-7.3), from
// the preset and from the same data read with --nk.
TEST(SpectralCliTest, NormalIncidenceIsTheSpectrumsColour)
{
  const sl::Dispersion* gold = sl::PresetDispersion("gold");
  ASSERT_NE(gold, nullptr);
  const sl::Vec3d expected = sl::SpectrumToLinearSRGB(
    [&](double nm) {
      double n = 0, k = 0;
      gold->Evaluate(nm, n, k);
      return sl::F0_Conductor(n, k);
    },
    sl::kSpectralSamples);
  const std::string angles = " --term F --theta-l 0 --theta-v 0 --phi 0";
  for (const std::string& source :
    { std::string("--material gold"), "--nk " + kData + "optical/Au_Johnson.yml" })
  {
    const auto r = RunCli("brdf " + source + " --spectral" + angles);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::vector<double> rgb = LastRgb(r.out);
    ASSERT_EQ(rgb.size(), 3u) << r.out;
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(rgb[c], expected[c], 1e-8) << source;
    }
  }
  // Without --spectral the preset's three samples: a different gold.
  const auto rgb = RunCli("brdf --material gold" + angles);
  ASSERT_EQ(rgb.status, 0);
  const std::vector<double> three = LastRgb(rgb.out);
  ASSERT_EQ(three.size(), 3u);
  EXPECT_GT(std::abs(three[0] - expected[0]) + std::abs(three[2] - expected[2]), 0.01);
}

// Empty, truncated, binary, out-of-range and unsupported files, and a
// mesh given as optical data: one line naming the file, exit 2.
TEST(SpectralCliTest, BadOpticalDataIsOneLineAndExitTwo)
{
  const std::string brdf = "brdf --spectral --term F --theta-l 0 ";
  const std::pair<std::string, std::string> files[] = {
    { Write("sl_empty.yml", ""), "no DATA block" },
    { Write("sl_formula5.yml", "DATA:\n  - type: formula 5\n    coefficients: 1 2 3\n"),
      "not supported" },
    { Write("sl_truncated.yml", "DATA:\n  - type: tabulated nk\n    data: |\n        0.3 1.5 0\n"
                                "        0.8 1."),
      "numbers" },
    { Write("sl_ir.yml", "DATA:\n  - type: tabulated nk\n    data: |\n        1.0 1.5 0\n"
                         "        2.0 1.5 0\n"),
      "not the visible" },
    { Write("sl_binary.yml", std::string("DATA:\0\x01\x02", 8)), "binary" },
    { kData + "torus_48x24.vtp", "" },
    { "/nonexistent/x.yml", "cannot open" },
  };
  for (const auto& [path, expected] : files)
  {
    const auto r = RunCli(brdf + "--nk " + path);
    EXPECT_EQ(r.status, 2) << path << ": " << r.err;
    EXPECT_NE(r.err.find("--nk " + path), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  // --spectral with a material that has no measured data.
  const auto none = RunCli(brdf + "--material plastic");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("needs measured optical data"), std::string::npos) << none.err;
  EXPECT_EQ(std::count(none.err.begin(), none.err.end(), '\n'), 1) << none.err;
}

// render --spectral draws on the CPU and is a different picture from the
// RGB preset; --spectral without data refuses before reading the mesh.
TEST(SpectralCliTest, RenderSpectralGold)
{
  const std::string dir = ::testing::TempDir();
  const std::string common = "render " + kData +
    "icosphere_4.vtp --backend cpu --material gold --size 96x96 ";
  ASSERT_EQ(RunCli(common + "--spectral --out " + dir + "/sl_spec.png").status, 0);
  ASSERT_EQ(RunCli(common + "--out " + dir + "/sl_rgb.png").status, 0);
  std::ifstream a(dir + "/sl_spec.png", std::ios::binary), b(dir + "/sl_rgb.png", std::ios::binary);
  const std::string pa((std::istreambuf_iterator<char>(a)), {}), pb((std::istreambuf_iterator<char>(b)), {});
  EXPECT_FALSE(pa.empty());
  EXPECT_NE(pa, pb);
  const auto bad = RunCli("render " + kData + "icosphere_4.vtp --backend cpu --spectral --out " +
    dir + "/sl_bad.png");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("needs measured optical data"), std::string::npos) << bad.err;
}
