// SPDX-License-Identifier: BSD-3-Clause
// The accuracy study's ground truth: analytic surfaces ray-cast through the
// renderers' pixel centres, shaded with the exact normal.
#include "shadinglab/reference/AnalyticSurface.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sl = shadinglab;

namespace
{

sl::render::Camera Orthographic()
{
  sl::render::Camera camera;
  camera.position = { 0, 0, 5 };
  camera.focalPoint = { 0, 0, 0 };
  camera.viewUp = { 0, 1, 0 };
  camera.parallel = true;
  camera.parallelScale = 1.25;
  return camera;
}

sl::Lighting<double> Headlight()
{
  sl::Lighting<double> lighting;
  lighting.lights[0].vector = { 0, 0, 1 };
  return lighting;
}

sl::Material<double> Lambert()
{
  sl::Material<double> m;
  m.model = sl::ReflectanceModel::Lambert;
  m.kd = 0.8;
  m.ks = 0.0;
  m.ambient = { 0, 0, 0 };
  return m;
}

} // namespace

TEST(ReferenceTest, SphereFollowsTheCosineLawAtPixelCentres)
{
  const int W = 101, H = 101;
  const auto sphere = sl::reference::MakeSphere();
  const sl::render::Image image = sl::reference::RayCast(
    *sphere, Orthographic(), Headlight(), Lambert(), W, H, { 0, 0, 0 });
  long covered = 0;
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      // Pixel centre (i + 0.5, j + 0.5) in world units of the 2.5-wide view.
      const double x = ((i + 0.5) / W * 2 - 1) * 1.25, y = (1 - (j + 0.5) / H * 2) * 1.25;
      const double r2 = x * x + y * y;
      const size_t o = static_cast<size_t>(j) * W + i;
      ASSERT_EQ(image.covered[o] != 0, r2 < 1.0) << i << "," << j;
      if (r2 < 1.0)
      {
        ++covered;
        EXPECT_NEAR(image.rgb[3 * o], 0.8 * std::sqrt(1 - r2), 1e-6);
      }
    }
  }
  // The disk's area in pixels: pi (W / 2.5)^2.
  EXPECT_NEAR(covered, M_PI * (W / 2.5) * (W / 2.5), 0.02 * covered);
}

TEST(ReferenceTest, TorusAndMetaballsHitTheirSurfaces)
{
  const auto torus = sl::reference::MakeTorus(1.0, 0.4);
  double t = 0;
  // Down the z axis through the ring's tube at x = 1: hits z = 0.4.
  ASSERT_TRUE(torus->Intersect({ 1, 0, 5 }, { 0, 0, -1 }, 0, 100, t));
  EXPECT_NEAR(5 - t, 0.4, 1e-8);
  // Through the hole: misses.
  EXPECT_FALSE(torus->Intersect({ 0, 0, 5 }, { 0, 0, -1 }, 0, 100, t));
  const sl::Vec3<double> n = torus->Normal({ 1.4, 0, 0 });
  EXPECT_NEAR(n.x, 1.0, 1e-12);
  const auto blobs = sl::reference::MakeMetaballs();
  ASSERT_TRUE(blobs->Intersect({ -0.35, 0, 5 }, { 0, 0, -1 }, 0, 100, t));
  // The first blob (centre -0.35, 0, 0; width 0.35) dominates there: the
  // field 0.5 is reached near z = 0.35 sqrt(ln 2) plus the others' share.
  EXPECT_GT(5 - t, 0.25);
  EXPECT_LT(5 - t, 0.45);
  const sl::Vec3<double> up = blobs->Normal({ -0.35, 0, 5 - t });
  EXPECT_GT(up.z, 0.9);
}

TEST(ReferenceTest, EllipsoidNormalIsTheNormalizedGradient)
{
  const auto e = sl::reference::MakeEllipsoid(2.0, 1.0, 0.5);
  double t = 0;
  ASSERT_TRUE(e->Intersect({ 5, 0, 0 }, { -1, 0, 0 }, 0, 100, t));
  EXPECT_NEAR(5 - t, 2.0, 1e-12);
  const sl::Vec3<double> n = e->Normal({ 2.0 / std::sqrt(2.0), 0, 0.5 / std::sqrt(2.0) });
  // gradient (x/a^2, z/c^2) = (0.3536, 2.828): mostly +z.
  EXPECT_NEAR(n.z / n.x, (0.5 / std::sqrt(2.0) / 0.25) / (2.0 / std::sqrt(2.0) / 4.0), 1e-9);
}
