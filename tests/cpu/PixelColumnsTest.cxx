// SPDX-License-Identifier: BSD-3-Clause
// Polygons between pixel centres: binning skips a polygon whose x range
// holds no pixel-centre column (as one whose y range holds no row), and the
// picture is the one a full scan draws. A parallel camera maps world x and
// y to pixel coordinates, so each triangle sits at known pixel positions.
#include "RenderTestUtil.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace render = shadinglab::render;
namespace test = shadinglab::test;
using shadinglab::Vec3f;

namespace
{

constexpr int kWidth = 64;
constexpr int kHeight = 32;

render::Camera PixelCamera()
{
  return test::PixelCamera(kWidth, kHeight);
}

/// One triangle, counter-clockwise seen from +z, spanning rows 4-28.
render::Mesh Sliver(float left, float right, float apex)
{
  render::Mesh mesh;
  mesh.points = { left, 4, 0, right, 4, 0, apex, 28, 0 };
  mesh.offsets = { 0, 3 };
  mesh.connectivity = { 0, 1, 2 };
  return mesh;
}

struct Drawn
{
  render::Image image;
  render::RenderStats stats;
};

Drawn Draw(const render::Mesh& mesh, render::ScanConversion scan)
{
  shadinglab::Lighting<float> light;
  light.lightCount = 1;
  light.lights[0].vector = Vec3f(0, 0, 1);
  render::RenderOptions opt;
  opt.width = kWidth;
  opt.height = kHeight;
  opt.mode = render::ShadingMode::Gouraud;
  opt.scan = scan;
  Drawn d;
  d.image = test::RenderCpu(mesh, PixelCamera(), light, shadinglab::Material<float>(), opt, &d.stats);
  return d;
}

int Covered(const render::Image& image)
{
  return static_cast<int>(std::count(image.covered.begin(), image.covered.end(), uint8_t(1)));
}

} // namespace

TEST(PixelColumnsTest, ASliverBetweenColumnsIsSkippedAndDrawsWhatTheScanDraws)
{
  // x in [10.6, 11.4]: no centre 10.5 or 11.5, so no pixel in any row.
  const render::Mesh between = Sliver(10.6f, 11.4f, 11.0f);
  const Drawn plane = Draw(between, render::ScanConversion::Plane);
  EXPECT_EQ(plane.stats.rasterized, 0);
  EXPECT_EQ(plane.stats.skipped, 1);
  EXPECT_EQ(plane.stats.binned, 0);
  EXPECT_EQ(Covered(plane.image), 0);
  // The incremental scan has no column test: it scan-converts the sliver
  // and finds no pixel either.
  const Drawn incremental = Draw(between, render::ScanConversion::Incremental);
  EXPECT_EQ(incremental.stats.rasterized, 1);
  EXPECT_EQ(incremental.image.covered, plane.image.covered);
}

TEST(PixelColumnsTest, ASliverOnACentreColumnIsDrawn)
{
  // The left edge runs down the centres of column 20 (x = 20.5): spans are
  // half-open, xl <= i + 0.5 < xr, so every row's pixel 20 is inside.
  const Drawn onEdge = Draw(Sliver(20.5f, 20.9f, 20.5f), render::ScanConversion::Plane);
  EXPECT_EQ(onEdge.stats.rasterized, 1);
  EXPECT_GE(Covered(onEdge.image), 20); // the rows whose span is still wider than 0
  for (int j = 0; j < kHeight; ++j)
  {
    for (int i = 0; i < kWidth; ++i)
    {
      if (onEdge.image.covered[static_cast<size_t>(j) * kWidth + i])
      {
        EXPECT_EQ(i, 20) << "row " << j;
      }
    }
  }
  // A hair narrower than the centre on the right: x in [20.1, 20.5) holds
  // no centre (the right end is open), skipped.
  const Drawn rightOpen = Draw(Sliver(20.1f, 20.5f, 20.5f), render::ScanConversion::Plane);
  EXPECT_EQ(Covered(rightOpen.image), 0);
}
