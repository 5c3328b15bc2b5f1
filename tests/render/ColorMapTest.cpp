// SPDX-License-Identifier: BSD-3-Clause
// The colour maps' legend ticks: evenly spaced, and an end that is zero but
// for float rounding prints as 0.
#include "shadinglab/render/ColorMap.h"

#include <gtest/gtest.h>

namespace sr = shadinglab::render;

TEST(ColorMapTest, LegendTicksAreEvenAndNearZeroIsZero)
{
  sr::ColorMap map;
  ASSERT_TRUE(sr::FindColorMap("viridis", map));
  map.rangeMin = -2.615137084660546e-08; // OCCT's bearing.stl, Elevation from z = 0
  map.rangeMax = 31.35;
  EXPECT_EQ(map.LegendTick(0, 4), 0.0);
  EXPECT_DOUBLE_EQ(map.LegendTick(4, 4), 31.35);
  EXPECT_NEAR(map.LegendTick(2, 4), 15.675, 1e-6);
  // A real value small against its range but above the fraction stays.
  map.rangeMin = -1e-3;
  map.rangeMax = 1.0;
  EXPECT_EQ(map.LegendTick(0, 4), -1e-3);
  // A tiny range keeps its tiny values (the fraction is of the width).
  map.rangeMin = 1e-12;
  map.rangeMax = 3e-12;
  EXPECT_EQ(map.LegendTick(0, 2), 1e-12);
}
