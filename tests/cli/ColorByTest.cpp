// SPDX-License-Identifier: BSD-3-Clause
// shadinglab render --color-by / --colormap / --range: the picture shows the
// map, the PNG carries a legend, and every misspelling is one line, exit 2.
#include "CliTestUtil.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <fstream>
#include <string>

using shadinglab::testing::CountLines;
using shadinglab::testing::PerTestTempPath;
using shadinglab::testing::RunCli;

namespace
{
/// An n x n height field z = 0.3 x y over [-1, 1]^2 as legacy VTK polygons
/// (quads), up to its attributes.
void WriteGrid(std::ostream& f, int n)
{
  f << "# vtk DataFile Version 3.0\nfield\nASCII\nDATASET POLYDATA\nPOINTS " << n * n << " float\n";
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double x = -1 + 2.0 * i / (n - 1), y = -1 + 2.0 * j / (n - 1);
      f << x << " " << y << " " << 0.3 * x * y << "\n";
    }
  }
  const int cells = (n - 1) * (n - 1);
  f << "POLYGONS " << cells << " " << 5 * cells << "\n";
  for (int j = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i)
    {
      const int a = j * n + i;
      f << "4 " << a << " " << a + 1 << " " << a + n + 1 << " " << a + n << "\n";
    }
  }
}

/// A 20 x 20 height field z = x y as legacy VTK: point array "height"
/// (one component), point vectors "flow" (three), cell array "patch".
std::string WriteField()
{
  const std::string path = PerTestTempPath("shadinglab_field", ".vtk");
  std::ofstream f(path);
  const int n = 20;
  WriteGrid(f, n);
  f << "POINT_DATA " << n * n << "\nSCALARS height float 1\nLOOKUP_TABLE default\n";
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      f << j << "\n";
    }
  }
  f << "VECTORS flow float\n";
  for (int k = 0; k < n * n; ++k)
  {
    f << "3 4 0\n";
  }
  const int cells = (n - 1) * (n - 1);
  f << "CELL_DATA " << cells << "\nSCALARS patch int 1\nLOOKUP_TABLE default\n";
  for (int c = 0; c < cells; ++c)
  {
    f << (c % 2) << "\n";
  }
  return path;
}

struct Png
{
  int width = 0, height = 0;
  vtkSmartPointer<vtkUnsignedCharArray> rgb;
  const unsigned char* At(int x, int y) const // y from the top
  {
    return rgb->GetPointer(static_cast<vtkIdType>((height - 1 - y) * width + x) * rgb->GetNumberOfComponents());
  }
};

Png ReadPng(const std::string& path)
{
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  Png png;
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  png.width = dims[0];
  png.height = dims[1];
  png.rgb = vtkUnsignedCharArray::SafeDownCast(reader->GetOutput()->GetPointData()->GetScalars());
  return png;
}
} // namespace

TEST(ColorByTest, ThePictureShowsTheMapAndTheLegendItsRange)
{
  const std::string field = WriteField();
  const std::string out = ::testing::TempDir() + "/shadinglab_colored.png";
  const auto r = RunCli("render " + field + " --backend cpu --size 400x300 --color-by height --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const Png png = ReadPng(out);
  ASSERT_EQ(png.width, 400);
  ASSERT_TRUE(png.rgb);
  // Cool to Warm over rows 0..19 of the field: bluish and reddish pixels
  // on the surface (the centre column, away from the legend).
  int blue = 0, red = 0;
  for (int y = 0; y < png.height; ++y)
  {
    const unsigned char* p = png.At(200, y);
    blue += p[2] > p[0] + 40;
    red += p[0] > p[2] + 40;
  }
  EXPECT_GT(blue, 10);
  EXPECT_GT(red, 10);
  // The legend's bar at the right edge: the map's ends, red above blue.
  int top = -1, bottom = -1;
  for (int y = 0; y < png.height; ++y)
  {
    for (int x = png.width - 100; x < png.width; ++x)
    {
      const unsigned char* p = png.At(x, y);
      if (p[0] > 150 && p[2] < 60 && top < 0)
      {
        top = y;
      }
      if (p[2] > 150 && p[0] < 80)
      {
        bottom = y;
      }
    }
  }
  EXPECT_GE(top, 0);
  EXPECT_GT(bottom, top + 50) << "the legend runs from the maximum (top) to the minimum";
  // Cell data, a vector's magnitude and a component, another map and a
  // fixed range render too.
  for (const std::string extra : { "--color-by CELLS:patch", "--color-by flow", "--color-by flow:1",
         "--color-by POINTS:height --colormap Viridis --range 0,5", "--color-by height --mode flat" })
  {
    const auto c = RunCli("render " + field + " --backend cpu --size 160x120 " + extra + " --out " + out);
    EXPECT_EQ(c.status, 0) << extra << ": " << c.err;
  }
}

TEST(ColorByTest, AFieldConstantUpToRoundingIsDrawnAsAConstantOne)
{
  // A unit vector's magnitude computed in double is 1 +- 2e-16: its range
  // is rounding noise, and the perspective interpolation's own float
  // rounding, stretched over that range, speckled the surface with both
  // ends of the map. It must draw exactly as the constant 1.
  auto write = [](const char* stem, bool noisy)
  {
    const std::string path = PerTestTempPath(stem, ".vtk");
    std::ofstream f(path);
    const int n = 12;
    WriteGrid(f, n);
    f << "POINT_DATA " << n * n << "\nSCALARS s double 1\nLOOKUP_TABLE default\n";
    for (int k = 0; k < n * n; ++k)
    {
      f << (!noisy ? "1" : k % 3 == 0 ? "1.0000000000000002" : k % 3 == 1 ? "0.9999999999999998" : "1")
        << "\n";
    }
    return path;
  };
  const std::string exact = write("shadinglab_constant", false);
  const std::string noisy = write("shadinglab_nearly_constant", true);
  const std::string outExact = PerTestTempPath("shadinglab_constant", ".png");
  const std::string outNoisy = PerTestTempPath("shadinglab_nearly_constant", ".png");
  for (const std::string mode : { "phong", "gouraud" })
  {
    const std::string flags = " --backend cpu --size 200x150 --mode " + mode + " --color-by s --out ";
    ASSERT_EQ(RunCli("render " + exact + flags + outExact).status, 0);
    ASSERT_EQ(RunCli("render " + noisy + flags + outNoisy).status, 0);
    const Png a = ReadPng(outExact), b = ReadPng(outNoisy);
    ASSERT_TRUE(a.rgb && b.rgb);
    ASSERT_EQ(a.rgb->GetNumberOfValues(), b.rgb->GetNumberOfValues());
    int64_t differ = 0;
    for (vtkIdType k = 0; k < a.rgb->GetNumberOfValues(); ++k)
    {
      differ += a.rgb->GetValue(k) != b.rgb->GetValue(k);
    }
    EXPECT_EQ(differ, 0) << mode;
    // The legend shows the one colour drawn, not the map's ramp: no pixel
    // of the map's red end at the right edge.
    int red = 0;
    for (int y = 0; y < a.height; ++y)
    {
      for (int x = a.width - 60; x < a.width; ++x)
      {
        const unsigned char* p = a.At(x, y);
        red += p[0] > 150 && p[2] < 60;
      }
    }
    EXPECT_EQ(red, 0) << mode;
  }
}

TEST(ColorByTest, MisspellingsAreOneLineAndExitTwo)
{
  const std::string field = WriteField();
  const std::string out = ::testing::TempDir() + "/shadinglab_colored_bad.png";
  const struct
  {
    const char* flags;
    const char* says;
  } cases[] = {
    { "--color-by pressure", "point arrays: height" },
    { "--color-by CELLS:height", "no cell array 'height'" },
    { "--color-by flow:3", "3 component(s)" },
    { "--color-by height --range 5,1", "MIN < MAX" },
    { "--color-by height --range nan,1", "--range" },
    { "--color-by height --colormap nope", "colormap" },
    { "--color-by POINTS:", "array name" },
  };
  for (const auto& c : cases)
  {
    const auto r = RunCli("render " + field + " --backend cpu --size 64x48 " + c.flags + " --out " + out);
    EXPECT_EQ(r.status, 2) << c.flags;
    EXPECT_EQ(CountLines(r.err), 1) << c.flags << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.flags << ": " << r.err;
  }
  // The arrays listed are the file's, not those the normals filter adds
  // (the field has no normals: phong makes them).
  const auto r = RunCli("render " + field + " --backend cpu --size 64x48 --mode phong --color-by heigth --out " + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("point arrays: height, flow;"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("Normals"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("OriginalPointIds"), std::string::npos) << r.err;
}

namespace
{
/// `--stats`' color_fidelity fraction (docs/model.md eq. 9.3), or -1.
double FidelityOf(const std::string& stats)
{
  const std::string key = "\"color_fidelity\":{";
  const auto at = stats.find(key);
  if (at == std::string::npos)
  {
    return -1;
  }
  const auto fraction = stats.find("\"fraction\":", at);
  return fraction == std::string::npos ? -1 : std::stod(stats.substr(fraction + 11));
}
} // namespace

TEST(ColorByTest, ByDefaultEveryPixelIsTheMapsColourScaledByShading)
{
  // docs/model.md section 9: without --ks no white highlight and no grey
  // ambient is added to the map's colours; an explicit --ks is honoured
  // (with a notice), and so is --highlights on, whose picture is then
  // measurably untrue to the map.
  const std::string field = WriteField();
  const std::string out = ::testing::TempDir() + "/shadinglab_fidelity.png";
  const std::string base = "render " + field +
    " --backend cpu --size 320x240 --mode phong --elevation 40 --stats --color-by height --out " + out;
  const auto plain = RunCli(base);
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(FidelityOf(plain.out), 0.0) << plain.out;
  EXPECT_EQ(plain.err.find("not data"), std::string::npos) << plain.err;
  for (const std::string extra : { " --ks 0.3", " --highlights on" })
  {
    const auto lit = RunCli(base + extra);
    ASSERT_EQ(lit.status, 0) << lit.err;
    EXPECT_GT(FidelityOf(lit.out), 0.5) << extra << ": " << lit.out;
    EXPECT_NE(lit.err.find("highlights on a surface coloured by data"), std::string::npos) << lit.err;
  }
  // --highlights auto wins over an explicit --ks.
  const auto automatic = RunCli(base + " --ks 0.3 --highlights auto");
  ASSERT_EQ(automatic.status, 0) << automatic.err;
  EXPECT_EQ(FidelityOf(automatic.out), 0.0) << automatic.out;
  // A conductor on data: its F0 is the data colour (eq. 9.4), and it says
  // so; with highlights off it is diffuse in the data colour, true to the map.
  const auto gold = RunCli(base + " --material gold");
  ASSERT_EQ(gold.status, 0) << gold.err;
  EXPECT_NE(gold.err.find("gold is a conductor"), std::string::npos) << gold.err;
  EXPECT_NE(gold.err.find("Fresnel F0"), std::string::npos) << gold.err;
  const auto matte = RunCli(base + " --material gold --highlights off");
  ASSERT_EQ(matte.status, 0) << matte.err;
  EXPECT_EQ(FidelityOf(matte.out), 0.0) << matte.out;
  // Without colour by data --stats carries no fidelity.
  const auto uncoloured = RunCli("render " + field + " --backend cpu --size 80x60 --stats --out " + out);
  ASSERT_EQ(uncoloured.status, 0) << uncoloured.err;
  EXPECT_EQ(FidelityOf(uncoloured.out), -1) << uncoloured.out;
}

TEST(ColorByTest, AnEmptyPictureSaysWhy)
{
  // The height field seen exactly edge-on: no polygon covers a pixel.
  const std::string path = PerTestTempPath("shadinglab_flat", ".vtk");
  {
    std::ofstream f(path);
    f << "# vtk DataFile Version 3.0\nflat\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
         "-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\nPOLYGONS 1 5\n4 0 1 2 3\n";
  }
  const std::string out = ::testing::TempDir() + "/shadinglab_empty.png";
  const auto r = RunCli("render " + path + " --backend cpu --size 80x60 --elevation 90 --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("the picture is empty"), std::string::npos) << r.err;
  const auto seen = RunCli("render " + path + " --backend cpu --size 80x60 --out " + out);
  EXPECT_EQ(seen.err.find("the picture is empty"), std::string::npos) << seen.err;
}
