// SPDX-License-Identifier: BSD-3-Clause
// Binning's four-at-once tests (plugin/cpu/src/BinFour.h) against the
// scalar tests they stand for (TestPolygon, Rasterizer::BinPolygon's): every lane must
// give the scalar rows, reject, column test and facing bit for bit, on
// triangles made to sit on the rules' edges: vertices on pixel centres and
// half-integers, sub-pixel and zero-area triangles, areas around
// kDegenerateArea, negative, huge, infinite and NaN coordinates. And the
// span test binning makes on triangles of a few pixel rows against the
// scan that draws them (raster::ScanTriangle): binning drops exactly the
// triangles that would draw no pixel.
#include "BinFour.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace cpu = shadinglab::cpu;
namespace raster = shadinglab::cpu::raster;

namespace
{

float Pick(std::mt19937& rng)
{
  const float special[] = { 0.0f, -0.0f, 0.5f, 1.5f, 99.5f, 100.0f, 199.5f, 200.0f, -0.5f,
    1e-20f, 3e9f, -3e9f, std::numeric_limits<float>::infinity(),
    -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN() };
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_int_distribution<int> which(0, static_cast<int>(std::size(special)) - 1);
  std::uniform_real_distribution<float> coordinate(-20.0f, 220.0f);
  std::uniform_int_distribution<int> halfInteger(-40, 440);
  switch (kind(rng))
  {
    case 0:
      return special[which(rng)];
    case 1:
    case 2:
    case 3:
      return 0.5f * static_cast<float>(halfInteger(rng));
    default:
      return coordinate(rng);
  }
}

} // namespace

#if defined(__SSE2__)
TEST(BinFourTest, EveryLaneIsTheScalarTestBitForBit)
{
  const int width = 200, height = 150;
  std::mt19937 rng(20261204);
  std::uniform_real_distribution<float> small(-0.7f, 0.7f), depth(-1.2f, 1.3f);
  int checked = 0, rows = 0, degenerate = 0, back = 0, emptySpan = 0;
  for (int trial = 0; trial < 50000; ++trial)
  {
    cpu::ProjectedVertex verts[4][3];
    for (int t = 0; t < 4; ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        cpu::ProjectedVertex& v = verts[t][k];
        v = { Pick(rng), Pick(rng), depth(rng), 1.0f };
        if (trial % 3 == 1 && k > 0)
        {
          // Sub-pixel triangles around the first vertex, some of them
          // collinear or of an area near kDegenerateArea.
          v.x = verts[t][0].x + small(rng) * (trial % 7 == 0 ? 1e-5f : 1.0f);
          v.y = verts[t][0].y + (trial % 5 == 0 ? (v.x - verts[t][0].x) : small(rng));
        }
      }
    }
    const cpu::ProjectedVertex* lanes[3][4];
    for (int t = 0; t < 4; ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        lanes[k][t] = &verts[t][k];
      }
    }
    for (bool columnTest : { true, false })
    {
      const cpu::FourTriangleTests four = cpu::TestFourTriangles(lanes, width, height, columnTest);
      for (int t = 0; t < 4; ++t)
      {
        const cpu::ProjectedVertex* sv[3] = { &verts[t][0], &verts[t][1], &verts[t][2] };
        const cpu::PolygonTests s = cpu::TestPolygon<3>(sv, 3, width, height, columnTest);
        const bool sDegenerate =
          !(std::abs(s.twiceArea) * 0.5 >= raster::kDegenerateArea) || !std::isfinite(s.twiceArea);
        SCOPED_TRACE("trial " + std::to_string(trial) + " lane " + std::to_string(t));
        ASSERT_EQ(four.j0[t], s.j0);
        ASSERT_EQ(four.j1[t], s.j1);
        ASSERT_EQ((four.hasRow >> t & 1) != 0, s.hasRow);
        ASSERT_EQ((four.rejected >> t & 1) != 0, s.rejected);
        ASSERT_EQ((four.noPixel >> t & 1) != 0, s.noPixel);
        ASSERT_EQ(four.pixel[t].column, s.pixel.column);
        ASSERT_EQ(four.pixel[t].row, s.pixel.row);
        ASSERT_EQ((four.degenerate >> t & 1) != 0, sDegenerate);
        if (!sDegenerate)
        {
          ASSERT_EQ((four.back >> t & 1) != 0, s.twiceArea > 0);
        }
        ++checked;
        rows += s.hasRow;
        degenerate += sDegenerate;
        back += !sDegenerate && s.twiceArea > 0;
        // Dropped by the span test, not by the column test.
        emptySpan += columnTest && s.noPixel && s.hasRow && s.j1 - s.j0 <= cpu::kBinSpanRows &&
          !cpu::TestPolygon<3>(sv, 3, width, height, false).noPixel &&
          raster::CeilToInt(std::max({ sv[0]->x, sv[1]->x, sv[2]->x }) - 0.5f +
            cpu::kBinColumnMargin) >
            raster::CeilToInt(std::min({ sv[0]->x, sv[1]->x, sv[2]->x }) - 0.5f -
              cpu::kBinColumnMargin);
      }
    }
  }
  // The corpus reaches every outcome.
  EXPECT_EQ(checked, 400000);
  EXPECT_GT(rows, checked / 10);
  EXPECT_GT(degenerate, checked / 20);
  EXPECT_GT(back, checked / 5);
  EXPECT_GT(emptySpan, checked / 100);
}
#endif

// Binning's span test says "no pixel" for a triangle of at most
// kBinSpanRows pixel rows exactly when the scan that would draw it finds no
// pixel, and hands the draw the row and column of a single pixel exactly
// when the scan finds one, that one, with the same attributes: on
// sub-pixel and pixel-sized triangles scattered over a frame, many with
// vertices on pixel centres and half-integers, where a crossing lands on a
// centre.
TEST(BinFourTest, FewRowSpanTestIsTheScansOwn)
{
  const int width = 64, height = 48;
  std::mt19937 rng(20261205);
  std::uniform_real_distribution<float> at(-2.0f, 66.0f), small(-0.9f, 0.9f), large(-1.6f, 1.6f);
  std::uniform_int_distribution<int> grid(-8, 8), wideGrid(-12, 12);
  int tested = 0, dropped = 0, drawn = 0, single = 0;
  int byRows[cpu::kBinSpanRows + 1] = {}, singleBelowFirstRow = 0;
  for (int trial = 0; trial < 300000; ++trial)
  {
    raster::ScreenVertex verts[3] = {};
    const float cx = at(rng), cy = at(rng) * 0.75f;
    const bool wide = trial % 2 == 1; // up to ~3 rows
    for (auto& v : verts)
    {
      // Every fourth triangle on a quarter-pixel grid, crossings on centres.
      const bool onGrid = trial % 4 < 2;
      v.x = onGrid ? std::floor(cx) + 0.25f * (wide ? wideGrid(rng) : grid(rng))
                   : cx + (wide ? large(rng) : small(rng));
      v.y = onGrid ? std::floor(cy) + 0.25f * (wide ? wideGrid(rng) : grid(rng))
                   : cy + (wide ? large(rng) : small(rng));
    }
    cpu::ProjectedVertex projected[3];
    const cpu::ProjectedVertex* sv[3];
    const raster::ScreenVertex* tri[3];
    for (int k = 0; k < 3; ++k)
    {
      projected[k] = { verts[k].x, verts[k].y, 0.0f, 1.0f };
      sv[k] = &projected[k];
      tri[k] = &verts[k];
    }
    const cpu::PolygonTests t = cpu::TestPolygon<3>(sv, 3, width, height, true);
    const int rows = t.j1 - t.j0;
    if (!t.hasRow || t.rejected || rows > cpu::kBinSpanRows)
    {
      continue;
    }
    int pixels = 0, lastColumn = -1, lastRow = -1;
    raster::ScanTriangle<raster::kAttrFirst>(width, tri, 0, height, [](int, int) {},
      [&](int j, int i, const float*)
      {
        ++pixels;
        lastRow = j;
        lastColumn = i;
      });
    SCOPED_TRACE("trial " + std::to_string(trial));
    ASSERT_EQ(t.noPixel, pixels == 0);
    // The one pixel binning hands the draw is the scan's one pixel.
    ASSERT_EQ(t.pixel.column >= 0, pixels == 1);
    if (pixels == 1)
    {
      ASSERT_EQ(t.pixel.column, lastColumn);
      ASSERT_EQ(t.j0 + t.pixel.row, lastRow);
      // And drawn from that hint over the triangle's rows, the same pixel
      // with the same attributes.
      float full[raster::kMaxAttributes] = {}, hinted[raster::kMaxAttributes] = {};
      for (int k = 0; k < 3; ++k)
      {
        verts[k].a[raster::kAttrZ] = 0.1f * static_cast<float>(k + 1);
        verts[k].a[raster::kAttrInvW] = 1.0f;
      }
      int hintedPixels = 0;
      raster::ScanTriangle<raster::kAttrFirst>(width, tri, 0, height, [](int, int) {},
        [&](int, int, const float* a) { std::copy(a, a + raster::kAttrFirst, full); });
      raster::ScanTriangle<raster::kAttrFirst>(width, tri, t.j0, t.j1, [](int, int) {},
        [&](int j, int i, const float* a)
        {
          ++hintedPixels;
          ASSERT_EQ(j, lastRow);
          ASSERT_EQ(i, lastColumn);
          std::copy(a, a + raster::kAttrFirst, hinted);
        },
        nullptr, t.pixel);
      ASSERT_EQ(hintedPixels, 1);
      for (int k = 0; k < raster::kAttrFirst; ++k)
      {
        ASSERT_EQ(full[k], hinted[k]);
      }
      singleBelowFirstRow += t.pixel.row > 0;
    }
    ++tested;
    ++byRows[rows];
    dropped += t.noPixel;
    drawn += pixels > 0;
    single += pixels == 1;
  }
  // Every outcome, many times each, and every row count.
  EXPECT_GT(tested, 100000);
  EXPECT_GT(dropped, tested / 10);
  EXPECT_GT(drawn, tested / 10);
  EXPECT_GT(single, tested / 10);
  EXPECT_GT(singleBelowFirstRow, tested / 50);
  for (int r = 1; r <= cpu::kBinSpanRows; ++r)
  {
    EXPECT_GT(byRows[r], tested / 20) << r << " rows";
  }
}
