// SPDX-License-Identifier: BSD-3-Clause
// Binning's four-at-once tests (plugin/cpu/src/BinFour.h) against the
// scalar tests they stand for (TestPolygon, Rasterizer::BinPolygon's): every lane must
// give the scalar rows, reject, column test and facing bit for bit, on
// triangles made to sit on the rules' edges: vertices on pixel centres and
// half-integers, sub-pixel and zero-area triangles, areas around
// kDegenerateArea, negative, huge, infinite and NaN coordinates.
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
  int checked = 0, rows = 0, degenerate = 0, back = 0;
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
        ASSERT_EQ((four.noColumn >> t & 1) != 0, s.noColumn);
        ASSERT_EQ((four.degenerate >> t & 1) != 0, sDegenerate);
        if (!sDegenerate)
        {
          ASSERT_EQ((four.back >> t & 1) != 0, s.twiceArea > 0);
        }
        ++checked;
        rows += s.hasRow;
        degenerate += sDegenerate;
        back += !sDegenerate && s.twiceArea > 0;
      }
    }
  }
  // The corpus reaches every outcome.
  EXPECT_EQ(checked, 400000);
  EXPECT_GT(rows, checked / 10);
  EXPECT_GT(degenerate, checked / 20);
  EXPECT_GT(back, checked / 5);
}
#endif
