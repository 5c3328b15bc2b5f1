// SPDX-License-Identifier: BSD-3-Clause
// What `shadinglab render` gives without flags: no clipped highlights on
// any shipped dataset or a CAD-like part, and a mesh without normals split
// at 30-degree creases as ParaView's Generate Surface Normals does.
#include "CliTestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

using shadinglab::testing::PerTestTempPath;
using shadinglab::testing::RunCli;

namespace
{
const std::string kData = std::string(SHADINGLAB_SOURCE_DIR) + "/datasets/";
/// The bound: at most 0.5 % of covered pixels at 255 in a channel.
constexpr double kMaxClippedFraction = 0.005;

/// A hexagonal prism (a nut's outside: flat faces meeting at 60 and 90
/// degrees), written as OBJ without normals.
std::string WriteHexPrism()
{
  const std::string path = PerTestTempPath("shadinglab_hex_prism", ".obj");
  std::ofstream f(path);
  for (int z = 0; z < 2; ++z)
  {
    for (int i = 0; i < 6; ++i)
    {
      const double a = i * M_PI / 3.0;
      f << "v " << std::cos(a) << " " << std::sin(a) << " " << (z ? 0.8 : -0.8) << "\n";
    }
  }
  for (int i = 0; i < 6; ++i)
  {
    const int j = (i + 1) % 6;
    f << "f " << i + 1 << " " << j + 1 << " " << j + 7 << " " << i + 7 << "\n";
  }
  f << "f 6 5 4 3 2 1\nf 7 8 9 10 11 12\n";
  return path;
}

/// A number field of the --stats JSON line.
long long StatsField(const std::string& json, const std::string& key)
{
  const size_t at = json.find("\"" + key + "\":");
  return at == std::string::npos ? -1 : std::stoll(json.substr(at + key.size() + 3));
}

std::string ReadBytes(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}
} // namespace

TEST(DefaultsTest, NoShippedDatasetOrCadPartClipsByDefault)
{
  std::vector<std::string> inputs = { WriteHexPrism() };
  for (const auto& entry : std::filesystem::directory_iterator(kData))
  {
    const std::string ext = entry.path().extension().string();
    if (ext == ".vtp" || ext == ".vtk" || ext == ".stl" || ext == ".ply" || ext == ".obj" ||
      ext == ".off")
    {
      inputs.push_back(entry.path().string());
    }
  }
  ASSERT_GE(inputs.size(), 20u);
  const std::string out = ::testing::TempDir() + "/shadinglab_defaults.png";
  long long covered = 0;
  for (const std::string& input : inputs)
  {
    const auto r = RunCli("render " + input + " --backend cpu --size 320x240 --stats --out " + out);
    ASSERT_EQ(r.status, 0) << input << ": " << r.err;
    const long long n = StatsField(r.out, "pixels_covered"), at255 = StatsField(r.out, "pixels_at_255");
    ASSERT_GE(at255, 0) << r.out;
    EXPECT_LE(at255, kMaxClippedFraction * n) << input << ": " << at255 << " of " << n;
    covered += n;
  }
  EXPECT_GT(covered, 0);
  // The measure can fail: under Clamp the default material saturates a
  // sixth of the torus.
  const auto r = RunCli("render " + kData + "torus_48x24.vtp --backend cpu --size 320x240 "
                        "--display clamp --stats --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_GT(StatsField(r.out, "pixels_at_255"), 0.1 * StatsField(r.out, "pixels_covered")) << r.out;
}

TEST(DefaultsTest, MeshWithoutNormalsIsSplitAtThirtyDegrees)
{
  const std::string prism = WriteHexPrism();
  const std::string dir = ::testing::TempDir();
  const std::string common = " --backend cpu --size 160x120 --elevation 30 --azimuth 20 --out ";
  const auto byDefault = RunCli("render " + prism + common + dir + "/sl_default.png");
  ASSERT_EQ(byDefault.status, 0) << byDefault.err;
  EXPECT_NE(byDefault.err.find("split where faces meet at more than 30 degrees"), std::string::npos)
    << byDefault.err;
  const auto at30 = RunCli("render " + prism + common + dir + "/sl_30.png --feature-angle 30");
  const auto at180 = RunCli("render " + prism + common + dir + "/sl_180.png --feature-angle 180");
  ASSERT_EQ(at30.status, 0) << at30.err;
  ASSERT_EQ(at180.status, 0) << at180.err;
  EXPECT_EQ(ReadBytes(dir + "/sl_default.png"), ReadBytes(dir + "/sl_30.png"));
  EXPECT_NE(ReadBytes(dir + "/sl_default.png"), ReadBytes(dir + "/sl_180.png"));
  // Flat shading uses no vertex normals: none are made, none announced.
  const auto flat = RunCli("render " + prism + common + dir + "/sl_flat.png --mode flat");
  ASSERT_EQ(flat.status, 0) << flat.err;
  EXPECT_EQ(flat.err.find("normals"), std::string::npos) << flat.err;
}
