// SPDX-License-Identifier: BSD-3-Clause
// Flat shading's two paths give one intensity per polygon: a large polygon
// is lit once (FlatStage::PolygonColor), a polygon of at most
// FlatStage::kQueuedArea px has its pixels shaded in SIMD batches from the
// polygon's normal and provoking vertex. Both must draw every pixel of the
// polygon with the model's value there (docs/model.md eq. 2.1), and a
// queued pixel a later polygon overdraws must show the later polygon.
#include "RenderTestUtil.h"

#include "shadinglab/model/Shading.h"

#include <gtest/gtest.h>

#include <cmath>

namespace render = shadinglab::render;
namespace test = shadinglab::test;
using shadinglab::Vec3f;

namespace
{

constexpr int kWidth = 64;
constexpr int kHeight = 32;


shadinglab::Lighting<float> OneLight()
{
  shadinglab::Lighting<float> light;
  light.lightCount = 1;
  light.lights[0].vector = NormalizeOr(Vec3f(0.3f, 0.2f, 1.0f), Vec3f(0, 0, 1));
  return light;
}

/// The model at a triangle's last (provoking) vertex with its unit face
/// normal, seen along +z: what every pixel of a flat triangle shows.
Vec3f Expected(const render::Mesh& mesh, int triangle)
{
  auto point = [&](int k)
  {
    const int64_t v = mesh.connectivity[3 * triangle + k];
    return Vec3f(mesh.points[3 * v], mesh.points[3 * v + 1], mesh.points[3 * v + 2]);
  };
  const Vec3f N = NormalizeOr(Cross(point(1) - point(0), point(2) - point(0)), Vec3f(0, 0, 1));
  const shadinglab::Material<float> material;
  return shadinglab::Shade(material, OneLight(), material.diffuseColor, point(2), N, Vec3f(0, 0, 1));
}

void ExpectPixel(const render::Image& image, int i, int j, const Vec3f& c)
{
  const size_t pix = static_cast<size_t>(j) * kWidth + i;
  ASSERT_TRUE(image.covered[pix]) << i << "," << j;
  // The SIMD kernel's pow differs from libm's by a few ulps.
  EXPECT_NEAR(image.rgb[3 * pix], c.x, 1e-5) << i << "," << j;
  EXPECT_NEAR(image.rgb[3 * pix + 1], c.y, 1e-5) << i << "," << j;
  EXPECT_NEAR(image.rgb[3 * pix + 2], c.z, 1e-5) << i << "," << j;
}

render::Image DrawFlat(const render::Mesh& mesh)
{
  render::RenderOptions opt;
  opt.width = kWidth;
  opt.height = kHeight;
  opt.mode = render::ShadingMode::Flat;
  opt.threads = 1;
  return test::RenderCpu(
    mesh, test::PixelCamera(kWidth, kHeight), OneLight(), shadinglab::Material<float>(), opt);
}

} // namespace

TEST(FlatSmallPolygonsTest, SmallAndLargePolygonsEachShowTheirOneIntensity)
{
  // A large tilted triangle (~200 px) and a small one (1.5 px, queued)
  // tilted the other way, apart on screen.
  render::Mesh mesh;
  mesh.points = { 2, 2, 0, 22, 2, 3, 2, 22, 1, //
    40.2f, 10.2f, 0, 42.2f, 10.2f, -1, 40.2f, 11.7f, 0.5f };
  mesh.offsets = { 0, 3, 6 };
  mesh.connectivity = { 0, 1, 2, 3, 4, 5 };
  const render::Image image = DrawFlat(mesh);
  const Vec3f large = Expected(mesh, 0), small = Expected(mesh, 1);
  ASSERT_GT(std::abs(large.x - small.x), 0.01f); // the test tells them apart
  // Pixel (i, j) has centre (i + 0.5, kHeight - j - 0.5) in world x, y.
  ExpectPixel(image, 5, kHeight - 6, large);
  ExpectPixel(image, 12, kHeight - 5, large);
  ExpectPixel(image, 40, kHeight - 11, small);
}

TEST(FlatSmallPolygonsTest, AQueuedPixelOverdrawnByALaterLargePolygonShowsTheLargeOne)
{
  // A small triangle (queued) at z = 0, then a large one in front of it
  // (z = 1) drawn later: the pixel must show the large one, although the
  // small one's queued colour is written only when its queue is shaded.
  render::Mesh mesh;
  mesh.points = { 20.2f, 10.2f, 0, 22.2f, 10.2f, -1, 20.2f, 11.7f, 0.5f, //
    10, 2, 1, 40, 2, 1.5f, 10, 28, 1.2f };
  mesh.offsets = { 0, 3, 6 };
  mesh.connectivity = { 0, 1, 2, 3, 4, 5 };
  const render::Image image = DrawFlat(mesh);
  ExpectPixel(image, 20, kHeight - 11, Expected(mesh, 1));
  // And the other order: the large one first, the small one in front.
  render::Mesh reversed = mesh;
  reversed.connectivity = { 3, 4, 5, 0, 1, 2 };
  for (int k = 0; k < 3; ++k)
  {
    reversed.points[3 * k + 2] += 2.0f; // the small one now in front
  }
  const render::Image front = DrawFlat(reversed);
  ExpectPixel(front, 20, kHeight - 11, Expected(reversed, 1));
}
