// SPDX-License-Identifier: BSD-3-Clause
// The fill rule across the two plane scans of Raster.h: a triangle
// (ScanTriangle) and a polygon (ScanPolygon, --polygons direct) sharing an
// edge give each pixel centre on that edge to exactly one of them. The
// edges are built through pixel centres, where an ulp decides the side:
// the case a mesh of triangles and quads meets on some of its edges.
#include "Raster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace raster = shadinglab::cpu::raster;

namespace
{

constexpr int kWidth = 320;
constexpr int kHeight = 240;

raster::ScreenVertex At(float x, float y)
{
  raster::ScreenVertex v{};
  v.x = x;
  v.y = y;
  v.a[raster::kAttrInvW] = 1.0f;
  return v;
}

/// Adds one to the coverage of every pixel the part's scan draws.
void Cover(const raster::ScreenVertex* const* verts, int n, std::vector<int>& coverage)
{
  auto pixel = [&](int j, int i, const float*) { ++coverage[static_cast<size_t>(j) * kWidth + i]; };
  auto span = [](int, int) {};
  if (n == 3)
  {
    raster::ScanTriangle<raster::kAttrFirst>(kWidth, verts, 0, kHeight, span, pixel);
  }
  else
  {
    raster::ScanPolygon(kWidth, 0, verts, n, 0, kHeight, span, pixel);
  }
}

} // namespace

TEST(SharedEdgeTest, TriangleAndPolygonCoverEachCentreOnTheirEdgeOnce)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int trials = 0, misses = 0, doubles = 0;
  for (int t = 0; t < 4000; ++t)
  {
    // The shared edge P-Q passes through the centre c of pixel (ci, cj),
    // up to the rounding of its float endpoints.
    const int ci = 60 + static_cast<int>(unit(rng) * 200), cj = 60 + static_cast<int>(unit(rng) * 120);
    const float cx = ci + 0.5f, cy = cj + 0.5f;
    const float angle = 6.2831853f * unit(rng);
    const float dx = std::cos(angle), dy = std::sin(angle);
    if (std::abs(dy) < 0.05f)
    {
      continue; // nearly horizontal: the edge may miss row cj
    }
    const float s = 2 + 20 * unit(rng), e = 2 + 20 * unit(rng), w = 3 + 20 * unit(rng);
    const raster::ScreenVertex p = At(cx - s * dx, cy - s * dy), q = At(cx + e * dx, cy + e * dy);
    // A triangle on one side of the edge, a parallelogram on the other.
    const raster::ScreenVertex r = At(cx - w * dy, cy + w * dx);
    const raster::ScreenVertex q2 = At(q.x + w * dy, q.y - w * dx), p2 = At(p.x + w * dy, p.y - w * dx);
    const raster::ScreenVertex* tri[3] = { &p, &q, &r };
    const raster::ScreenVertex* quad[4] = { &q, &p, &p2, &q2 };
    std::vector<int> coverage(static_cast<size_t>(kWidth) * kHeight, 0);
    Cover(tri, 3, coverage);
    Cover(quad, 4, coverage);
    ++trials;
    const int c = coverage[static_cast<size_t>(cj) * kWidth + ci];
    misses += c == 0;
    doubles += c > 1;
  }
  EXPECT_GT(trials, 3500);
  EXPECT_EQ(misses, 0) << "pixel centres on a shared edge left out, of " << trials;
  EXPECT_EQ(doubles, 0) << "pixel centres on a shared edge drawn twice, of " << trials;
}
