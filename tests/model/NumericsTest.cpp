// SPDX-License-Identifier: BSD-3-Clause
// Numerical robustness: no NaN or Inf for any finite input, explicit limits,
// and float within a stated tolerance of double.
#include "shadinglab/model/Materials.h"
#include "shadinglab/model/Shading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace sl = shadinglab;

namespace
{

template <typename T>
sl::Vec3<T> RandomVector(std::mt19937_64& rng)
{
  // Mix of ordinary unit-ish vectors, zero, denormal, huge and axis-aligned
  // components: the hazards named in the foundation issue.
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  switch (kind(rng))
  {
    case 0:
      return { T(0), T(0), T(0) };
    case 1:
    {
      const T tiny = std::numeric_limits<T>::denorm_min() * T(7);
      return { tiny, -tiny, tiny };
    }
    case 2:
      return sl::Vec3<T>(T(u(rng)), T(u(rng)), T(u(rng))) * T(1e30);
    case 3:
      return { T(0), T(0), T(u(rng) > 0 ? 1 : -1) };
    default:
      return { T(u(rng)), T(u(rng)), T(u(rng)) };
  }
}

template <typename T>
void Sweep(int count, uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> modelPick(0, 3);
  int nonFinite = 0;
  for (int i = 0; i < count; ++i)
  {
    sl::Material<T> m;
    m.model = static_cast<sl::ReflectanceModel>(modelPick(rng));
    m.kd = T(u(rng));
    m.ks = T(1) - m.kd;
    m.shininess = T(std::pow(10.0, 4.0 * u(rng)));
    m.lobeCount = 1 + static_cast<int>(u(rng) * sl::kMaxLobes) % sl::kMaxLobes;
    for (int k = 0; k < m.lobeCount; ++k)
    {
      // m far outside the clamp range on purpose: 1e-8 .. 1e8.
      m.lobes[k] = { T(1) / T(m.lobeCount), T(std::pow(10.0, -8.0 + 16.0 * u(rng))) };
    }
    const T eta = T(std::pow(10.0, -2.0 + 4.0 * u(rng)));
    m.eta = { eta, u(rng) < 0.1 ? T(1) : eta, T(1) / eta };
    m.k = u(rng) < 0.5 ? sl::Vec3<T>() : sl::Vec3<T>(T(100 * u(rng)), T(u(rng)), T(0));
    m.variant = u(rng) < 0.5 ? sl::SpecularVariant::CookTorrance1982
                             : sl::SpecularVariant::Walter2007;
    sl::Lighting<T> lighting;
    lighting.lightCount = 2;
    lighting.lights[0].vector = RandomVector<T>(rng);
    lighting.lights[1].type = sl::LightType::Point;
    lighting.lights[1].vector = RandomVector<T>(rng);
    lighting.lights[1].attenuation = { T(u(rng)), T(u(rng)), T(u(rng)) + T(1e-3) };
    const sl::Vec3<T> P = RandomVector<T>(rng);
    const sl::Vec3<T> up(T(0), T(0), T(1));
    const sl::Vec3<T> N = sl::NormalizeOr(RandomVector<T>(rng), up);
    sl::Vec3<T> V = sl::NormalizeOr(RandomVector<T>(rng), up);
    if (u(rng) < 0.05)
    {
      // L = -V exactly: the half vector has no direction.
      lighting.lights[0].vector = -V;
    }
    const sl::Vec3<T> I = sl::Shade(m, lighting, m.diffuseColor, P, N, V);
    if (!sl::IsFinite(I))
    {
      if (++nonFinite <= 5)
      {
        ADD_FAILURE() << "non-finite output at sample " << i;
      }
    }
  }
  EXPECT_EQ(nonFinite, 0);
}

} // namespace

TEST(NumericsTest, MillionRandomConfigurationsStayFiniteInFloat)
{
  Sweep<float>(1000000, 1);
}

TEST(NumericsTest, MillionRandomConfigurationsStayFiniteInDouble)
{
  Sweep<double>(1000000, 2);
}

TEST(NumericsTest, NormalizeSurvivesDenormalsAndHugeVectors)
{
  const sl::Vec3f fallback(0, 0, 1);
  const float tiny = std::numeric_limits<float>::denorm_min();
  const sl::Vec3f a = sl::NormalizeOr(sl::Vec3f(tiny, 0, 0), fallback);
  EXPECT_FLOAT_EQ(a.x, 1.0f);
  const sl::Vec3f b = sl::NormalizeOr(sl::Vec3f(3e38f, 3e38f, 0), fallback);
  EXPECT_NEAR(b.x, std::sqrt(0.5f), 1e-6f);
  const sl::Vec3f c = sl::NormalizeOr(sl::Vec3f(0, 0, 0), fallback);
  EXPECT_EQ(c.z, 1.0f);
  const sl::Vec3f d = sl::NormalizeOr(sl::Vec3f(std::nanf(""), 0, 0), fallback);
  EXPECT_EQ(d.z, 1.0f);
}

TEST(NumericsTest, HalfVectorOfOppositeDirectionsFallsBackToNormal)
{
  const sl::Vec3d N(0, 0, 1);
  const sl::Vec3d H = sl::HalfVector(sl::Vec3d(1, 0, 0), sl::Vec3d(-1, 0, 0), N);
  EXPECT_EQ(H.z, 1.0);
}

TEST(NumericsTest, RoughnessLimitsAreFinite)
{
  for (double c : { 1.0, 0.999999, 0.5, 1e-3, 1e-5, 0.0 })
  {
    for (double m : { 0.0, 1e-12, 1e-3, 1e3, 1e12 })
    {
      EXPECT_TRUE(std::isfinite(sl::D_Beckmann(c, m))) << c << " " << m;
      EXPECT_TRUE(std::isfinite(sl::D_Beckmann(float(c), float(m)))) << c << " " << m;
    }
  }
  // m -> 0 concentrates the lobe at N.H = 1.
  EXPECT_DOUBLE_EQ(sl::D_Beckmann(1.0, 0.0), 1.0 / (1e-3 * 1e-3));
}

TEST(NumericsTest, GrazingBrdfIsFinite)
{
  sl::Material<float> m;
  m.model = sl::ReflectanceModel::CookTorrance;
  m.lobes[0].m = 1e-3f;
  m.kd = 0;
  m.ks = 1;
  const sl::Vec3f N(0, 0, 1);
  for (float eps : { 1e-2f, 1e-4f, 1e-6f, 1e-8f, 1e-20f, 1e-38f })
  {
    const sl::Vec3f L = sl::NormalizeOr(sl::Vec3f(1, 0, eps), N);
    const sl::Vec3f V = sl::NormalizeOr(sl::Vec3f(-1, 0, eps), N);
    EXPECT_TRUE(sl::IsFinite(sl::EvaluateBrdf(m, m.diffuseColor, N, L, V))) << eps;
  }
}

TEST(NumericsTest, FloatBrdfWithinToleranceOfDouble)
{
  // pbrt-v4 style: the float model against the double reference over random
  // directions and materials. Tolerance: relative 2e-4 (plus 1e-6 absolute
  // for values near 0). Float carries 6e-8 relative precision; exp(-x) in
  // Beckmann amplifies an input error by x = tan^2(alpha)/m^2, and only
  // configurations with x <= ~100 (D above 1e-43 of its peak) matter, hence
  // errors up to ~1e-5; pow(c, n) amplifies by n*|ln c|, similar. 2e-4 leaves
  // a factor of ~10 of margin over the largest error measured (see note).
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0;
  const sl::Vec3d N(0, 0, 1);
  for (const auto& preset : sl::MaterialPresets())
  {
    for (int i = 0; i < 20000; ++i)
    {
      sl::Material<double> md = preset.material;
      md.lobes[0].m = 0.05 + 0.95 * u(rng);
      const auto mf = md.Cast<float>();
      const double tl = std::acos(u(rng)), tv = std::acos(u(rng)), pl = 6.283 * u(rng),
                   pv = 6.283 * u(rng);
      const sl::Vec3d L(std::sin(tl) * std::cos(pl), std::sin(tl) * std::sin(pl), std::cos(tl));
      const sl::Vec3d V(std::sin(tv) * std::cos(pv), std::sin(tv) * std::sin(pv), std::cos(tv));
      const sl::Vec3d d = sl::EvaluateBrdf(md, md.diffuseColor, N, L, V);
      const sl::Vec3f f = sl::EvaluateBrdf(
        mf, mf.diffuseColor, sl::Vec3f(N), sl::Vec3f(L), sl::Vec3f(V));
      for (int c = 0; c < 3; ++c)
      {
        const double err = std::abs(f[c] - d[c]) / (std::abs(d[c]) + 1e-6 / 2e-4);
        worst = std::max(worst, err);
      }
    }
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
  std::printf("worst float/double relative error: %.3g\n", worst);
  EXPECT_LT(worst, 2e-4);
}
