// SPDX-License-Identifier: BSD-3-Clause
// shadinglab brdf: CSV format, values, and error exits.
#include "CliTestUtil.h"
#include "MeshIO.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <tuple>
#include <vector>

using shadinglab::testing::CountLines;
using shadinglab::testing::RunCli;

namespace
{
std::vector<std::vector<double>> ParseCsv(const std::string& text, std::string& header)
{
  std::stringstream ss(text);
  std::getline(ss, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(ss, line))
  {
    std::vector<double> row;
    std::stringstream ls(line);
    std::string cell;
    while (std::getline(ls, cell, ','))
    {
      row.push_back(std::stod(cell));
    }
    rows.push_back(row);
  }
  return rows;
}
} // namespace

TEST(CliTest, BrdfFresnelTableHasHeaderRowsAndKnownValues)
{
  const auto r = RunCli("brdf --model cook-torrance --m 0.3 --eta 1.5 --theta-l 0:90:5 "
                        "--theta-v 30 --phi 180 --term F");
  ASSERT_EQ(r.status, 0) << r.err;
  std::string header;
  const auto rows = ParseCsv(r.out, header);
  EXPECT_EQ(header, "theta_l,theta_v,phi,r,g,b");
  ASSERT_EQ(rows.size(), 19u);
  for (const auto& row : rows)
  {
    ASSERT_EQ(row.size(), 6u);
  }
  // theta_l = 30 = theta_v, mirror side: H = N, L.H = cos 30.
  // theta_l = 90, theta_v = 30: L.H = cos 60 -> F = 0.08919 (REFERENCE.md).
  EXPECT_NEAR(rows.back()[3], 0.08919, 5e-6);
  EXPECT_EQ(rows.back()[0], 90.0);
}

TEST(CliTest, BrdfPrintsAtLeastNineSignificantDigits)
{
  const auto r = RunCli("brdf --theta-l 0 --theta-v 0 --term F --eta 1.7");
  ASSERT_EQ(r.status, 0) << r.err;
  // F0 = (0.7/2.7)^2 = 0.0672153635116598...
  EXPECT_NE(r.out.find("0.06721536351"), std::string::npos) << r.out;
}

TEST(CliTest, BrdfDAndGTermsAndMixture)
{
  // Normal incidence and view: alpha = 0, D = 1/m^2 (mixture: sum w/m^2).
  auto r = RunCli("brdf --theta-l 0 --theta-v 0 --term D --m 0.2,0.5 --w 0.25,0.75");
  ASSERT_EQ(r.status, 0) << r.err;
  std::string header;
  auto rows = ParseCsv(r.out, header);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_NEAR(rows[0][3], 0.25 / 0.04 + 0.75 / 0.25, 1e-9);
  r = RunCli("brdf --theta-l 0 --theta-v 0 --term G");
  ASSERT_EQ(r.status, 0) << r.err;
  rows = ParseCsv(r.out, header);
  EXPECT_EQ(rows[0][3], 1.0);
}

TEST(CliTest, BrdfPerChannelEtaAndConductor)
{
  const auto r = RunCli("brdf --theta-l 0 --theta-v 0 --term F --eta 1.5,1.0,0.35 --k 0,0,2.714");
  ASSERT_EQ(r.status, 0) << r.err;
  std::string header;
  const auto rows = ParseCsv(r.out, header);
  EXPECT_NEAR(rows[0][3], 0.04, 1e-12);
  EXPECT_EQ(rows[0][4], 0.0);
  EXPECT_NEAR(rows[0][5], 0.8476, 5e-5);
}

TEST(CliTest, BrdfLambertIsAlbedoOverPi)
{
  const auto r = RunCli("brdf --model lambert --theta-l 0:80:20 --theta-v 10,50 --phi 0,90");
  ASSERT_EQ(r.status, 0) << r.err;
  std::string header;
  const auto rows = ParseCsv(r.out, header);
  ASSERT_EQ(rows.size(), 5u * 2u * 2u);
  for (const auto& row : rows)
  {
    EXPECT_NEAR(row[3], 1.0 / 3.14159265358979, 1e-9);
  }
}

TEST(CliTest, BrdfVariantsDifferByFour)
{
  const auto a = RunCli("brdf --theta-l 40 --theta-v 40 --variant 1982");
  const auto b = RunCli("brdf --theta-l 40 --theta-v 40 --variant walter");
  ASSERT_EQ(a.status, 0);
  ASSERT_EQ(b.status, 0);
  std::string h;
  EXPECT_NEAR(ParseCsv(a.out, h)[0][3], 4.0 * ParseCsv(b.out, h)[0][3], 1e-8);
}

TEST(CliTest, LobeWeightsAreRelative)
{
  // One policy in every front end (shadinglab/render/Settings.h): weights
  // are normalized to sum to 1 over the used lobes.
  const auto a = RunCli("brdf --theta-l 0:80:20 --theta-v 30 --m 0.2,0.6 --w 0.1,0.3");
  const auto b = RunCli("brdf --theta-l 0:80:20 --theta-v 30 --m 0.2,0.6 --w 0.25,0.75");
  const auto c = RunCli("brdf --theta-l 0:80:20 --theta-v 30 --m 0.2,0.6 --w 0.5,0.5");
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(a.out, c.out);
}

TEST(CliTest, BadArgumentsExitTwoWithOneLineError)
{
  const char* bad[] = {
    "brdf",                                       // missing --theta-l
    "brdf --theta-l 0:90:0",                      // zero step
    "brdf --theta-l 0:90:-5",                     // negative step
    "brdf --theta-l abc",                         // not a number
    "brdf --theta-l 95",                          // out of range
    "brdf --theta-l nan",                         // not finite
    "brdf --theta-l 10 --kd 0.8 --ks 0.5",        // kd + ks > 1
    "brdf --theta-l 10 --m 0",                    // m = 0
    "brdf --theta-l 10 --m 0.2,0.4 --w 0,0",     // no weight at all
    "brdf --theta-l 10 --m 0.2,0.4 --w 0.5",      // one weight for two lobes
    "brdf --theta-l 10 --m 0.2,0.4 --w -1,2",     // a negative weight
    "brdf --theta-l 10 --eta -1",                 // eta < 0
    "brdf --theta-l 10 --eta 1,2",                // two channels
    "brdf --theta-l 10 --term X",                 // unknown term
    "brdf --theta-l 10 --model lambert --term F", // term needs cook-torrance
    "brdf --theta-l 10 --bogus 1",                // unknown option
    "brdf --theta-l 0:90:0.000001 --theta-v 0:90:0.001", // absurd row count
    "frobnicate",                                 // unknown command
    "settings",                                   // settings without --markdown
    "settings --markdown extra",                  // settings takes no argument
  };
  for (const char* args : bad)
  {
    const auto r = RunCli(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(CountLines(r.err), 1) << args << ": " << r.err.substr(0, 300);
    EXPECT_NE(r.err.find("error"), std::string::npos) << args;
  }
}

namespace
{
const std::string kData = std::string(SHADINGLAB_SOURCE_DIR) + "/datasets/";

// Width and height from a PNG's IHDR chunk.
bool PngSize(const std::string& path, int& w, int& h)
{
  std::ifstream f(path, std::ios::binary);
  unsigned char b[24];
  if (!f.read(reinterpret_cast<char*>(b), 24) || b[1] != 'P' || b[2] != 'N' || b[3] != 'G')
  {
    return false;
  }
  w = (b[16] << 24) | (b[17] << 16) | (b[18] << 8) | b[19];
  h = (b[20] << 24) | (b[21] << 16) | (b[22] << 8) | b[23];
  return true;
}

std::string WriteTemp(const std::string& name, const std::string& contents)
{
  const std::string path = ::testing::TempDir() + "/shadinglab_cli_" + name;
  std::ofstream(path) << contents;
  return path;
}
} // namespace

TEST(CliTest, RenderEveryFormatAndMode)
{
  const char* files[] = { "icosphere_2.vtp", "quad_strip.vtk", "sphere_lowpoly.ply",
    "corrugated_plane.obj", "cylinder_8.stl", "t_junctions.off" };
  const char* modes[] = { "flat", "gouraud", "phong", "fast-phong", "cook-torrance" };
  int k = 0;
  for (const char* f : files)
  {
    for (const char* m : modes)
    {
      const std::string out = ::testing::TempDir() + "/shadinglab_render_" + std::to_string(k++) + ".png";
      const auto r = RunCli("render " + kData + f + " --backend cpu --mode " + m +
        " --size 96x64 --out " + out);
      ASSERT_EQ(r.status, 0) << f << " " << m << ": " << r.err;
      int w = 0, h = 0;
      ASSERT_TRUE(PngSize(out, w, h)) << out;
      EXPECT_EQ(w, 96);
      EXPECT_EQ(h, 64);
    }
  }
}

TEST(CliTest, ShadingModeAndReflectanceModelAreIndependent)
{
  // Every mode with every model it has a form for; fast Phong with Phong's
  // (R.V)^n included (R.V = 2 (N.L)(N.V) - L.V from its quadratics).
  const char* modes[] = { "flat", "gouraud", "phong", "fast-phong" };
  const char* models[] = { "lambert", "phong", "blinn-phong", "cook-torrance" };
  int k = 0;
  for (const char* m : modes)
  {
    for (const char* model : models)
    {
      const std::string out = ::testing::TempDir() + "/shadinglab_mm_" + std::to_string(k++) + ".png";
      const auto r = RunCli("render " + kData + "torus_24x12.vtp --backend cpu --mode " + m +
        " --model " + model + " --size 64x48 --stats --out " + out);
      if (std::string(m) == "fast-phong" && std::string(model) == "cook-torrance")
      {
        EXPECT_EQ(r.status, 2) << r.err;
        continue;
      }
      ASSERT_EQ(r.status, 0) << m << " " << model << ": " << r.err;
      EXPECT_NE(r.out.find(std::string("\"mode\":\"") + m + "\""), std::string::npos) << r.out;
      EXPECT_NE(r.out.find(std::string("\"model\":\"") + model + "\""), std::string::npos) << r.out;
    }
  }
  // The shorthand is phong interpolation of a Cook-Torrance material.
  const auto r = RunCli("render " + kData + "torus_24x12.vtp --backend cpu --mode cook-torrance "
                        "--size 64x48 --stats --out " + ::testing::TempDir() + "/shadinglab_ct.png");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"mode\":\"phong\",\"model\":\"cook-torrance\""), std::string::npos) << r.out;
  // compare takes mode/model panels.
  const std::string strip = ::testing::TempDir() + "/shadinglab_mm_strip.png";
  const auto c = RunCli("compare " + kData + "torus_24x12.vtp --modes gouraud/cook-torrance,"
                        "phong/cook-torrance,fast-phong/phong --material gold --size 80x60 --out " + strip);
  ASSERT_EQ(c.status, 0) << c.err;
  int w = 0, h = 0;
  ASSERT_TRUE(PngSize(strip, w, h));
  EXPECT_EQ(w, 3 * 80 + 2 * 4);
}

TEST(CliTest, RenderStatsIsOneJsonLine)
{
  const std::string out = ::testing::TempDir() + "/shadinglab_stats.png";
  const auto r = RunCli("render " + kData + "torus_24x12.vtp --backend cpu --size 64x48 --ssaa 2 "
                        "--polygons direct --interp screen --light dir:0,0,1 --light point:3,3,3 "
                        "--stats --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(CountLines(r.out), 1);
  EXPECT_EQ(r.out.front(), '{');
  EXPECT_NE(r.out.find("\"triangles\":576"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"milliseconds\":"), std::string::npos) << r.out;
  // No normals in the file: the renderer says it computed them.
  EXPECT_NE(r.err.find("area-weighted"), std::string::npos) << r.err;
}

TEST(CliTest, RenderBadInputExitsTwoWithOneLine)
{
  const std::string empty = WriteTemp("empty.stl", "");
  const std::string nan = WriteTemp("nan.off", "OFF\n3 1 0\n0 0 0\nnan 1 0\n0 1 0\n3 0 1 2\n");
  const std::string garbage = WriteTemp("garbage.vtp", "<VTKFile garbage");
  const std::string noFaces = WriteTemp("nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  const std::string good = kData + "icosphere_1.vtp";
  const std::string out = " --out " + ::testing::TempDir() + "/shadinglab_bad.png";
  const std::string bad[] = {
    "render /nonexistent.vtp" + out,
    "render " + empty + out,
    "render " + nan + out,
    "render " + garbage + out,
    "render " + noFaces + out,
    "render" + out,
    "render " + good + " --mode toon" + out,
    "render " + good + " --size 0x10" + out,
    "render " + good + " --size 100000x10" + out,
    "render " + good + " --ssaa 100" + out,
    "render " + good + " --zoom -1" + out,
    "render " + good + " --zoom 0.001" + out, // view angle beyond 180 degrees
    "render " + good + " --light dir:0,0,0" + out,
    "render " + good + " --light sun:1,1,1" + out,
    "render " + good + " --light spot:0,0,3:0,0,-1:120" + out, // cone over 90 degrees
    "render " + good + " --light spot:0,0,3:0,0,0:20" + out,   // no axis
    "render " + good + " --mode fast-phong --material gold" + out,
    "render " + good + " --mode fast-phong --model cook-torrance" + out,
    "render " + good + " --mode cook-torrance --model phong" + out,   // contradicts the shorthand
    "render " + good + " --mode cook-torrance --m 0" + out,           // shorthand validates too
    "render " + good + " --backend cpu --mode fast-phong --expansion middle" + out,
    "compare " + good + " --modes gouraud/toon" + out,
    "compare " + good + " --modes fast-phong/cook-torrance" + out,
    "render " + good + " --kd 2" + out,
    "render " + good + " --interp curved" + out,
    "render " + good + " --nonlinear-subdivision -1" + out,
    "render " + good + " --view-up 0,0,0" + out,
    "render " + good + " --camera-position 0,0,5 --focal-point 0,0,0 --view-up 0,0,2" + out,
    "render " + good + " --backend cpu --out /nonexistent-dir/x.png", // unwritable
  };
  for (const auto& args : bad)
  {
    const auto r = RunCli(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(CountLines(r.err), 1) << args << ": " << r.err.substr(0, 300);
  }
}

TEST(CliTest, NormalsJsonReportsRepairs)
{
  const std::string out = ::testing::TempDir() + "/shadinglab_normals.vtp";
  auto r = RunCli("normals " + kData + "t_junctions.off --out " + out + " --fix-t-junctions --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(CountLines(r.out), 1);
  for (const char* key : { "\"points_in\":101", "\"cells_in\":80", "\"points_out\":", "\"cells_out\":",
         "\"welded\":0", "\"t_junctions_fixed\":4", "\"degenerate_removed\":0",
         "\"nonmanifold_edges\":0", "\"flipped\":0", "\"crease_edges\":" })
  {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
  // A prism: 8 vertical edges at 45 degrees and 16 rim edges are creases.
  r = RunCli("normals " + kData + "cylinder_8.stl --weld --weights angle --out " + out + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"crease_edges\":24"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"points_out\":48"), std::string::npos) << r.out;
  // Subdivision: Loop on the 80-triangle icosphere, two levels.
  r = RunCli("normals " + kData + "icosphere_1.vtp --subdivide 2 --scheme loop --out " + out + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"cells_out\":1280"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"points_out\":642"), std::string::npos) << r.out;
}

TEST(CliTest, NormalsWritesEveryFormat)
{
  for (const char* ext : { "vtp", "ply", "obj", "stl", "vtk", "off" })
  {
    const std::string out = ::testing::TempDir() + "/shadinglab_normals_out." + ext;
    const auto r = RunCli("normals " + kData + "icosphere_2.vtp --out " + out);
    EXPECT_EQ(r.status, 0) << ext << ": " << r.err;
    std::ifstream f(out);
    EXPECT_TRUE(f.good()) << out;
  }
}

TEST(CliTest, NormalsBadInputExitsTwoWithOneLine)
{
  const std::string out = " --out " + ::testing::TempDir() + "/shadinglab_normals_bad.vtp";
  const std::string good = kData + "icosphere_1.vtp";
  const std::string bad[] = {
    "normals " + good,                                    // no --out
    "normals /nonexistent.off" + out,                     // missing file
    "normals " + good + " --weights funny" + out,         // bad weights
    "normals " + good + " --subdivide 9" + out,           // too many levels
    "normals " + good + " --scheme loop" + out,           // scheme without subdivide
    "normals " + good + " --subdivide 1 --weights angle" + out, // weights the limit surface ignores
    "normals " + kData + "cylinder_8.vtp --subdivide 1 --scheme loop" + out, // loop on quads
    "normals " + good + " --feature-angle 200" + out,     // angle out of range
    "normals " + good + " --weld 5" + out,                // absurd tolerance
    "normals " + good + " --out /tmp/x.xyz",              // unknown output format
    "normals " + kData + "torus_96x48.vtp --subdivide 6" + out, // 37.7M faces: over budget
    "normals " + good + " --out /nonexistent-dir/x.vtp",  // unwritable
    "normals " + good + " --nonlinear-subdivision 5" + out, // over ParaView's 4
    "normals " + good + " --nonlinear-subdivision 1.5" + out, // not an integer
  };
  for (const auto& args : bad)
  {
    const auto r = RunCli(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(CountLines(r.err), 1) << args << ": " << r.err.substr(0, 300);
  }
}

TEST(CliTest, RenderIsTheSameAtAnyScaleAndDistance)
{
  // One icosahedron at unit scale, 1e7 from the origin, and scaled by 1e-30
  // and 1e30: meshes are converted in a local frame (in double) before the
  // renderers' float, so all four pictures are the same, pixel for pixel.
  const double t = (1 + std::sqrt(5.0)) / 2;
  const double v[12][3] = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t },
    { 0, 1, t }, { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  const int f[20][3] = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 },
    { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 },
    { 9, 8, 1 } };
  std::string reference;
  for (const auto& [name, scale, offset] : { std::tuple<const char*, double, double>{ "unit", 1.0, 0.0 },
         { "far", 1.0, 1e7 }, { "tiny", 1e-30, 0.0 }, { "huge", 1e30, 0.0 } })
  {
    std::ostringstream off;
    off.precision(17);
    off << "OFF\n12 20 0\n";
    for (const auto& p : v)
    {
      off << offset + scale * p[0] << " " << offset + scale * p[1] << " " << offset + scale * p[2] << "\n";
    }
    for (const auto& q : f)
    {
      off << "3 " << q[0] << " " << q[1] << " " << q[2] << "\n";
    }
    const std::string in = WriteTemp(std::string("scale_") + name + ".off", off.str());
    const std::string out = ::testing::TempDir() + "/shadinglab_scale_" + name + ".png";
    const auto r = RunCli("render " + in + " --backend cpu --mode gouraud --size 160x120 --out " + out);
    ASSERT_EQ(r.status, 0) << name << ": " << r.err;
    std::ifstream png(out, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(png)), std::istreambuf_iterator<char>());
    if (reference.empty())
    {
      reference = bytes;
    }
    EXPECT_EQ(bytes, reference) << name << " renders differently from the unit mesh";
  }
}

TEST(CliTest, RenderMakesInconsistentOrientationConsistent)
{
  // Two triangles of a square, the second wound the other way: their shared
  // edge runs the same way in both. Render says so and repairs it, and the
  // picture equals the consistently wound square's.
  const std::string good = WriteTemp("square_good.off",
    "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  const std::string bad = WriteTemp("square_bad.off",
    "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 3 2\n");
  std::string pictures[2];
  int k = 0;
  for (const std::string& in : { good, bad })
  {
    const std::string out = ::testing::TempDir() + "/shadinglab_orient_" + std::to_string(k) + ".png";
    const auto r = RunCli("render " + in + " --backend cpu --mode gouraud --size 64x64 --out " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.find("oriented inconsistently") != std::string::npos, k == 1) << r.err;
    std::ifstream png(out, std::ios::binary);
    pictures[k++].assign(std::istreambuf_iterator<char>(png), std::istreambuf_iterator<char>());
  }
  EXPECT_EQ(pictures[0], pictures[1]);
}

TEST(CliTest, NormalsRefusesToOverwriteItsInput)
{
  // A copy of a dataset as the input, and --out naming that same file.
  const std::string copy = ::testing::TempDir() + "/shadinglab_self.vtp";
  {
    std::ifstream src(kData + "icosphere_1.vtp", std::ios::binary);
    std::ofstream dst(copy, std::ios::binary);
    dst << src.rdbuf();
  }
  std::ifstream before(copy, std::ios::binary);
  const std::string original((std::istreambuf_iterator<char>(before)), std::istreambuf_iterator<char>());
  const auto r = RunCli("normals " + copy + " --out " + copy);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(CountLines(r.err), 1) << r.err;
  std::ifstream after(copy, std::ios::binary);
  const std::string now((std::istreambuf_iterator<char>(after)), std::istreambuf_iterator<char>());
  EXPECT_EQ(now, original);
}

TEST(CliTest, RenderUsesTheMeshFilters)
{
  const std::string out = ::testing::TempDir() + "/shadinglab_render_filters.png";
  auto r = RunCli("render " + kData + "icosphere_1.vtp --backend cpu --size 64x48 --subdivide 2 --stats --out " + out +
    " --light spot:0,0,3:0,0,-1:25:2 --light dir:1,0,0");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"triangles\":1280"), std::string::npos) << r.out;
  // The subdivision's limit normals are made for the render: computed.
  EXPECT_NE(r.out.find("\"normals_computed\":true"), std::string::npos) << r.out;
  // The default normals made for a mesh without them are reported too;
  // flat shading makes none.
  r = RunCli("render " + kData + "torus_24x12.vtp --backend cpu --size 64x48 --stats --out " + out);
  EXPECT_NE(r.out.find("\"normals_computed\":true"), std::string::npos) << r.out;
  r = RunCli("render " + kData + "torus_24x12.vtp --backend cpu --mode flat --size 64x48 --stats --out " + out);
  EXPECT_NE(r.out.find("\"normals_computed\":false"), std::string::npos) << r.out;
  r = RunCli("render " + kData + "cylinder_8.vtp --backend cpu --size 64x48 --normals max --feature-angle 40 --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
}

TEST(CliTest, GpuBackendUnderXAndNeverAbortsWithoutDisplay)
{
  const std::string out = ::testing::TempDir() + "/shadinglab_gpu.png";
  const std::string input = kData + "icosphere_2.vtp";
  // Without DISPLAY: gpu is a clear error, auto falls back to the CPU.
  const std::string env = "env -u DISPLAY ";
  auto r = shadinglab::testing::RunCli("render " + input + " --backend gpu --size 64x48 --out " + out, env);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(CountLines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("DISPLAY"), std::string::npos) << r.err;
  r = shadinglab::testing::RunCli("render " + input + " --backend auto --size 64x48 --stats --out " + out, env);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"backend\":\"cpu\""), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("using the CPU renderer"), std::string::npos) << r.err;
  // With the suite's X server: the GPU path renders.
  if (std::getenv("DISPLAY"))
  {
    r = RunCli("render " + input + " --backend gpu --mode cook-torrance --material gold --size 64x48 --stats --out " + out);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("\"backend\":\"gpu\""), std::string::npos) << r.out;
    int w = 0, h = 0;
    EXPECT_TRUE(PngSize(out, w, h));
    EXPECT_EQ(w, 64);
  }
}

TEST(CliTest, AutoModeChoosesByTheErrorBudgetAndSaysWhy)
{
  const std::string in = std::string(SHADINGLAB_SOURCE_DIR) + "/datasets/torus_48x24.vtp";
  const std::string out = ::testing::TempDir() + "/shadinglab_auto.png";
  std::string loose, tight;
  for (const auto& [budget, mode] : { std::pair<std::string, std::string*>{ "50", &loose },
         { "0.05", &tight } })
  {
    const auto r = RunCli("render " + in + " --backend cpu --mode auto --max-error " + budget +
      " --size 160x120 --stats --out " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto at = r.out.find("\"mode\":\"");
    ASSERT_NE(at, std::string::npos) << r.out;
    *mode = r.out.substr(at + 8, r.out.find('"', at + 8) - at - 8);
    EXPECT_NE(r.out.find("\"auto\":\"normal spread"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"skipped\":"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"overdraw\":"), std::string::npos) << r.out;
  }
  // A loose budget takes a cheap mode; one below what any mode can promise
  // takes the most accurate and says so.
  EXPECT_NE(loose, "phong");
  EXPECT_EQ(tight, "phong");
  // Without --max-error, the table's default budget (1/255), as --help says.
  const auto byDefault = RunCli("render " + in + " --backend cpu --mode auto --size 160x120 --stats --out " + out);
  EXPECT_EQ(byDefault.status, 0) << byDefault.err;
  EXPECT_NE(byDefault.out.find("\"auto\":\"normal spread"), std::string::npos) << byDefault.out;
  for (const char* bad : { "--mode auto --max-error 0", "--mode auto --max-error nan",
         "--mode phong --max-error 1" })
  {
    const auto r = RunCli("render " + in + " --backend cpu " + bad + " --out " + out);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_EQ(CountLines(r.err), 1) << bad << ": " << r.err;
  }
}

namespace
{
/// The number after "KEY": in a one-line JSON object, or NaN when absent.
double JsonNumber(const std::string& json, const std::string& key)
{
  const auto at = json.find("\"" + key + "\":");
  if (at == std::string::npos)
  {
    return std::nan("");
  }
  return std::strtod(json.c_str() + at + key.size() + 3, nullptr);
}
} // namespace

TEST(CliTest, StatsBreakTheRunIntoReadPrepareRenderWrite)
{
  // Where a user's wait goes (issue 13): each phase timed, and the phases
  // add up to no more than the whole.
  const std::string in = std::string(SHADINGLAB_SOURCE_DIR) + "/datasets/torus_48x24.vtp";
  const std::string png = ::testing::TempDir() + "/shadinglab_phases.png";
  const auto r = RunCli("render " + in + " --backend cpu --size 64x48 --stats --out " + png);
  ASSERT_EQ(r.status, 0) << r.err;
  double sum = 0;
  for (const char* key : { "read_ms", "prepare_ms", "render_ms", "write_ms" })
  {
    const double v = JsonNumber(r.out, key);
    EXPECT_TRUE(v >= 0 && v < 60000) << key << " in " << r.out;
    sum += v;
  }
  EXPECT_GT(JsonNumber(r.out, "read_ms"), 0.0) << r.out;
  EXPECT_EQ(JsonNumber(r.out, "render_ms"), JsonNumber(r.out, "milliseconds")) << r.out;
  EXPECT_LE(sum, JsonNumber(r.out, "total_ms") + 1e-3) << r.out;

  const std::string vtp = ::testing::TempDir() + "/shadinglab_phases.vtp";
  const auto n = RunCli("normals " + in + " --out " + vtp + " --json");
  ASSERT_EQ(n.status, 0) << n.err;
  sum = 0;
  for (const char* key : { "read_ms", "prepare_ms", "write_ms" })
  {
    const double v = JsonNumber(n.out, key);
    EXPECT_TRUE(v >= 0 && v < 60000) << key << " in " << n.out;
    sum += v;
  }
  EXPECT_GT(JsonNumber(n.out, "write_ms"), 0.0) << n.out;
  EXPECT_LE(sum, JsonNumber(n.out, "total_ms") + 1e-3) << n.out;
}

// The formats the reader takes are one list (ReadableExtensions): the
// help names each, and an unknown extension's error names them all.
TEST(CliTest, HelpAndErrorsNameEveryReadableFormat)
{
  const auto help = RunCli("render --help");
  ASSERT_EQ(help.status, 0);
  const std::string unknown = shadinglab::testing::PerTestTempPath("shadinglab_unknown", ".xyz");
  std::ofstream(unknown) << "0 0 0\n";
  const auto bad = RunCli("render " + unknown);
  EXPECT_EQ(bad.status, 2);
  for (const std::string& ext : shadinglab::ReadableExtensions())
  {
    EXPECT_NE(help.out.find(" ." + ext), std::string::npos) << ext;
    EXPECT_NE(bad.err.find(" ." + ext), std::string::npos) << ext << ": " << bad.err;
  }
}

// A .pvd series: the first step by default, another by --time-step or
// --time; a step the file lacks is one line and exit 2 (render and normals).
TEST(CliTest, TimeSeriesStepsAreChosenByTimeOrIndex)
{
  const std::string dir = ::testing::TempDir() + "/";
  const std::string pvd = shadinglab::testing::PerTestTempPath("shadinglab_series", ".pvd");
  // Step 0: a 16x8 sphere (224 polygons), step 1 at t = 2: a 32x16 one (960).
  std::ofstream(pvd) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
                        "<Collection>\n"
                        "<DataSet timestep=\"0\" file=\"" << kData << "uv_sphere_16x8.vtp\"/>\n"
                        "<DataSet timestep=\"2\" file=\"" << kData << "uv_sphere_32x16.vtp\"/>\n"
                        "</Collection>\n</VTKFile>\n";
  const std::string out = " --backend cpu --size 64x48 --stats --out " + dir + "shadinglab_series.png";
  auto polygons = [](const std::string& stats) {
    const auto at = stats.find("\"polygons\":");
    return at == std::string::npos ? -1 : std::stol(stats.substr(at + 11));
  };
  const auto first = RunCli("render " + pvd + out);
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_EQ(polygons(first.out), 224);
  for (const std::string pick : { " --time-step 1", " --time 2", " --time 7e-1 --mode flat" })
  {
    const auto r = RunCli("render " + pvd + pick + out);
    ASSERT_EQ(r.status, 0) << pick << ": " << r.err;
    EXPECT_EQ(polygons(r.out), pick == " --time 7e-1 --mode flat" ? 224 : 960) << pick;
  }
  for (const std::string bad : { " --time-step 2", " --time 9", " --time -1", " --time 1 --time-step 0",
         " --time-step -3", " --time abc" })
  {
    const auto r = RunCli("render " + pvd + bad + out);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_EQ(CountLines(r.err), 1) << bad << ": " << r.err;
  }
  const auto plain = RunCli("render " + kData + "uv_sphere_16x8.vtp --time-step 0" + out);
  EXPECT_EQ(plain.status, 2);
  EXPECT_NE(plain.err.find("has no time steps"), std::string::npos) << plain.err;
  const auto normals = RunCli("normals " + pvd + " --time-step 1 --json --out " + dir + "shadinglab_series.vtp");
  EXPECT_EQ(normals.status, 0) << normals.err;
}
