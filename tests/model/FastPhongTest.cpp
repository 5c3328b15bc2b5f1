// SPDX-License-Identifier: BSD-3-Clause
// Bishop & Weimer 1986 fast Phong: the Taylor coefficients are right, the
// forward differences reproduce them, and the error vanishes at third order
// as the normal spread over the triangle goes to zero.
#include "shadinglab/model/FastPhong.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace sl = shadinglab;
using sl::Vec3d;

namespace
{

struct TriangleCase
{
  double x[3] = { 10.0, 70.0, 25.0 };
  double y[3] = { 5.0, 20.0, 60.0 };
  Vec3d L = sl::NormalizeOr(Vec3d(0.3, 0.5, 0.8), Vec3d(0, 0, 1));
};

// Vertex normals N0 + t * delta_i: t controls the spread.
sl::FastPhongTriangle<double> MakeTriangle(const TriangleCase& s, double t)
{
  const Vec3d base(0.1, -0.2, 1.0);
  const Vec3d delta[3] = { { 0.7, 0.1, -0.2 }, { -0.4, 0.6, 0.1 }, { 0.2, -0.5, 0.3 } };
  Vec3d n[3];
  for (int i = 0; i < 3; ++i)
  {
    n[i] = sl::NormalizeOr(base + delta[i] * t, Vec3d(0, 0, 1));
  }
  sl::FastPhongTriangle<double> tri;
  tri.Setup(s.x, s.y, n);
  return tri;
}

bool Inside(const TriangleCase& s, double px, double py)
{
  double sign = 0;
  for (int i = 0; i < 3; ++i)
  {
    const int j = (i + 1) % 3;
    const double e = (s.x[j] - s.x[i]) * (py - s.y[i]) - (s.y[j] - s.y[i]) * (px - s.x[i]);
    if (sign == 0)
    {
      sign = e;
    }
    else if (e * sign < 0)
    {
      return false;
    }
  }
  return true;
}

double MaxError(const TriangleCase& s, const sl::FastPhongTriangle<double>& tri, sl::ExpansionPoint where)
{
  const auto q = tri.Expand(s.L, where);
  double worst = 0.0;
  for (double py = 0.5; py < 64; py += 1.0)
  {
    for (double px = 0.5; px < 72; px += 1.0)
    {
      if (Inside(s, px, py))
      {
        worst = std::max(worst, std::abs(q.Evaluate(px, py) - tri.Exact(s.L, px, py)));
      }
    }
  }
  return worst;
}

} // namespace

TEST(FastPhongTest, AffineNormalFieldInterpolatesTheVertices)
{
  TriangleCase s;
  const auto tri = MakeTriangle(s, 0.5);
  const Vec3d base(0.1, -0.2, 1.0);
  const Vec3d n0 = sl::NormalizeOr(base + Vec3d(0.7, 0.1, -0.2) * 0.5, Vec3d(0, 0, 1));
  const Vec3d at0 = tri.Normal(s.x[0], s.y[0]);
  EXPECT_NEAR(at0.x, n0.x, 1e-12);
  EXPECT_NEAR(at0.y, n0.y, 1e-12);
  EXPECT_NEAR(at0.z, n0.z, 1e-12);
  EXPECT_TRUE(tri.affine);
}

TEST(FastPhongTest, QuadraticMatchesValueGradientAndHessianAtExpansionPoint)
{
  TriangleCase s;
  const auto tri = MakeTriangle(s, 0.8);
  const auto q = tri.Expand(s.L, sl::ExpansionPoint::Centroid);
  const double x0 = q.x0, y0 = q.y0, h = 1e-3;
  auto f = [&](double x, double y) { return tri.Exact(s.L, x, y); };
  EXPECT_NEAR(q.T0, f(x0, y0), 1e-14);
  EXPECT_NEAR(q.T2, (f(x0 + h, y0) - f(x0 - h, y0)) / (2 * h), 1e-9);
  EXPECT_NEAR(q.T1, (f(x0, y0 + h) - f(x0, y0 - h)) / (2 * h), 1e-9);
  const double fxx = (f(x0 + h, y0) - 2 * f(x0, y0) + f(x0 - h, y0)) / (h * h);
  const double fyy = (f(x0, y0 + h) - 2 * f(x0, y0) + f(x0, y0 - h)) / (h * h);
  const double fxy =
    (f(x0 + h, y0 + h) - f(x0 + h, y0 - h) - f(x0 - h, y0 + h) + f(x0 - h, y0 - h)) / (4 * h * h);
  // T5 u^2 is half the second derivative; finite differences of second
  // derivatives carry ~1e-16/h^2 = 1e-10 rounding.
  EXPECT_NEAR(2 * q.T5, fxx, 1e-7);
  EXPECT_NEAR(2 * q.T3, fyy, 1e-7);
  EXPECT_NEAR(q.T4, fxy, 1e-7);
}

TEST(FastPhongTest, ForwardDifferencesReproduceTheQuadratic)
{
  TriangleCase s;
  const auto tri = MakeTriangle(s, 0.8);
  const auto q = tri.Expand(s.L, sl::ExpansionPoint::Vertex);
  sl::FastPhongScanline<double> line;
  line.Begin(q, 3.5, 17.5);
  for (int i = 0; i < 2000; ++i)
  {
    ASSERT_NEAR(line.Next(), q.Evaluate(3.5 + i, 17.5), 1e-9) << i;
  }
  // In float the forward differences drift by accumulated rounding; over a
  // 2000-pixel span it stays below 1/255 of full intensity.
  sl::FastPhongScanline<float> linef;
  const auto tf = MakeTriangle(s, 0.05);
  const auto qd = tf.Expand(s.L, sl::ExpansionPoint::Centroid);
  sl::FastPhongQuadratic<float> qf;
  qf.x0 = float(qd.x0), qf.y0 = float(qd.y0), qf.T0 = float(qd.T0), qf.T1 = float(qd.T1);
  qf.T2 = float(qd.T2), qf.T3 = float(qd.T3), qf.T4 = float(qd.T4), qf.T5 = float(qd.T5);
  linef.Begin(qf, 0.5f, 30.5f);
  for (int i = 0; i < 100; ++i)
  {
    ASSERT_NEAR(linef.Next(), qd.Evaluate(0.5 + i, 30.5), 1.0 / 255.0) << i;
  }
}

TEST(FastPhongTest, ErrorVanishesAtThirdOrderInTheNormalSpread)
{
  TriangleCase s;
  std::vector<double> spreads = { 0.4, 0.2, 0.1, 0.05, 0.025, 0.0125 };
  std::vector<double> errors;
  for (double t : spreads)
  {
    errors.push_back(MaxError(s, MakeTriangle(s, t), sl::ExpansionPoint::Centroid));
  }
  // Least-squares slope of log(error) against log(spread).
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(spreads.size());
  for (size_t i = 0; i < spreads.size(); ++i)
  {
    const double lx = std::log(spreads[i]), ly = std::log(errors[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  std::printf("fast phong max error vs spread:");
  for (size_t i = 0; i < spreads.size(); ++i)
  {
    std::printf(" %.4g:%.3e", spreads[i], errors[i]);
  }
  std::printf("\nfitted convergence rate: %.3f\n", slope);
  RecordProperty("convergence_rate", std::to_string(slope));
  // A second-order expansion leaves a third-order remainder.
  EXPECT_NEAR(slope, 3.0, 0.2);
  EXPECT_LT(errors.back(), 1e-6);
}

TEST(FastPhongTest, CentroidExpansionBeatsVertexExpansion)
{
  TriangleCase s;
  for (double t : { 0.4, 0.2, 0.1 })
  {
    const auto tri = MakeTriangle(s, t);
    EXPECT_LT(MaxError(s, tri, sl::ExpansionPoint::Centroid),
      MaxError(s, tri, sl::ExpansionPoint::Vertex))
      << t;
  }
}

TEST(FastPhongTest, DegenerateScreenTriangleGetsConstantNormal)
{
  const double x[3] = { 0, 10, 20 };
  const double y[3] = { 0, 10, 20 }; // collinear
  const Vec3d n[3] = { { 0, 0, 1 }, { 0, 1, 0 }, { 1, 0, 0 } };
  sl::FastPhongTriangle<double> tri;
  tri.Setup(x, y, n);
  EXPECT_FALSE(tri.affine);
  const auto q = tri.Expand(Vec3d(0, 0, 1), sl::ExpansionPoint::Centroid);
  EXPECT_TRUE(std::isfinite(q.T0));
  EXPECT_NEAR(q.Evaluate(5, 5), 1.0 / std::sqrt(3.0), 1e-12);
}

TEST(FastPhongTest, CancellingNormalsGiveZeroNotNaN)
{
  const double x[3] = { 0, 10, 0 };
  const double y[3] = { 0, 0, 10 };
  const Vec3d n[3] = { { 0, 0, 1 }, { 0, 0, -1 }, { 0, 0, 1 } };
  sl::FastPhongTriangle<double> tri;
  tri.Setup(x, y, n);
  // The normal field vanishes on the line x = 5.
  const auto q = tri.ExpandAbout(Vec3d(0, 0, 1), 5.0, 2.0);
  EXPECT_EQ(q.T0, 0.0);
  EXPECT_EQ(tri.Exact(Vec3d(0, 0, 1), 5.0, 2.0), 0.0);
}

TEST(FastPhongTest, SpecularPowerTableMatchesPow)
{
  for (double n : { 1.0, 8.0, 32.0, 128.0, 1000.0, 10000.0 })
  {
    sl::SpecularPowerTable table;
    table.Build(n);
    EXPECT_LE(table.Size(), sl::SpecularPowerTable::kMaxEntries);
    double worst = 0;
    for (int i = 0; i <= 100000; ++i)
    {
      const float x = static_cast<float>(i) / 100000.0f;
      worst = std::max(worst, std::abs(table.Lookup(x) - std::pow(double(x), n)));
    }
    // Interpolation tolerance 1e-5, plus the floor 1e-6 cut, plus float rounding.
    EXPECT_LT(worst, 2e-5) << "n = " << n;
  }
}
