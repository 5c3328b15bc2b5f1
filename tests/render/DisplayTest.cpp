// SPDX-License-Identifier: BSD-3-Clause
// render::ToByte, the 8-bit rounding of display values (the CPU backend's
// hand-over and Image::ToRGB8), against std::lround, the rounding it replaces.
#include "shadinglab/render/Display.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

TEST(DisplayTest, ToByteRoundsAsLround)
{
  auto check = [](float v)
  {
    ASSERT_EQ(static_cast<long>(shadinglab::render::ToByte(v)), std::lround(v * 255.0f)) << v;
  };
  // Every level's half-way point and the floats on either side of it, where
  // a rounding in float (v * 255 + 0.5f) would go wrong.
  for (int k = 0; k < 255; ++k)
  {
    const float half = (k + 0.5f) / 255.0f;
    float below = half, above = half;
    for (int step = 0; step < 8; ++step)
    {
      check(below);
      check(above);
      below = std::nextafter(below, 0.0f);
      above = std::nextafter(above, 1.0f);
    }
  }
  // And a million values spread over [0, 1], its ends included.
  for (int i = 0; i <= 1000000; ++i)
  {
    check(static_cast<float>(i) / 1000000.0f);
  }
  EXPECT_EQ(shadinglab::render::ToByte(0.0f), 0);
  EXPECT_EQ(shadinglab::render::ToByte(1.0f), 255);
}
