// SPDX-License-Identifier: BSD-3-Clause
// The colour maps' legends: ticks evenly spaced, an end that is zero but
// for float rounding printed as 0, and a constant field's bar its one colour.
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

TEST(ColorMapTest, AConstantFieldsLegendIsTheOneColourDrawn)
{
  sr::ColorMap map;
  ASSERT_TRUE(sr::FindColorMap("cool-to-warm", map));
  map.rangeMin = 0.0;
  map.rangeMax = 2.0;
  EXPECT_FALSE(map.IsConstant());
  EXPECT_EQ(map.LegendColor(0.0).x, map.colors.front().x);
  EXPECT_EQ(map.LegendColor(1.0).x, map.colors.back().x);
  EXPECT_EQ(map.LegendColor(0.999).z, map.Map(1.998).z);
  map.rangeMin = map.rangeMax = 1.0;
  EXPECT_TRUE(map.IsConstant());
  for (double t : { 0.0, 0.5, 1.0 })
  {
    const auto c = map.LegendColor(t), drawn = map.Map(1.0 + 1e-7);
    EXPECT_EQ(c.x, drawn.x);
    EXPECT_EQ(c.y, drawn.y);
    EXPECT_EQ(c.z, drawn.z);
  }
}
