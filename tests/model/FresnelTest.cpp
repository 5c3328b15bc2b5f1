// SPDX-License-Identifier: BSD-3-Clause
// Fresnel reflectance against hand-computed values with cited sources
// (Born & Wolf, Principles of Optics, 7th ed., sec. 1.5.2-1.5.4;
// Hecht, Optics, 4th ed., sec. 4.6), in the spirit of Mitsuba 3's
// test_fresnel.py.
#include "shadinglab/model/Fresnel.h"
#include "shadinglab/model/Materials.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

namespace sl = shadinglab;

namespace
{
constexpr double kDeg = 3.14159265358979323846 / 180.0;

// The lecture's slide-15 form, evaluated literally with trigonometry.
double FresnelLectureForm(double thetaI, double eta)
{
  const double thetaT = std::asin(std::sin(thetaI) / eta);
  const double sMinus = std::sin(thetaI - thetaT), sPlus = std::sin(thetaI + thetaT);
  const double cMinus = std::cos(thetaI - thetaT), cPlus = std::cos(thetaI + thetaT);
  return 0.5 * (sMinus * sMinus) / (sPlus * sPlus) * (1.0 + (cPlus * cPlus) / (cMinus * cMinus));
}

// The conductor's Fresnel in complex arithmetic, as Born & Wolf write it
// (pbrt-v4's FrComplex): cos(theta_t) from Snell's law with n = eta + i k.
double FresnelComplexForm(double cosTheta_i, double eta, double k)
{
  using C = std::complex<double>;
  const C n(eta, k);
  const C sin2Theta_t = C(1.0 - cosTheta_i * cosTheta_i) / (n * n);
  const C cosTheta_t = std::sqrt(C(1.0) - sin2Theta_t);
  const C rs = (C(cosTheta_i) - n * cosTheta_t) / (C(cosTheta_i) + n * cosTheta_t);
  const C rp = (n * C(cosTheta_i) - cosTheta_t) / (n * C(cosTheta_i) + cosTheta_t);
  return 0.5 * (std::norm(rs) + std::norm(rp));
}
} // namespace

TEST(FresnelTest, NormalIncidenceIsSquaredReflectionCoefficient)
{
  // ((eta - 1)/(eta + 1))^2 = (0.5/2.5)^2 = 0.04 for eta = 1.5.
  EXPECT_NEAR(sl::F_Dielectric(1.0, 1.5), 0.04, 1e-15);
  EXPECT_NEAR(sl::F_Dielectric(1.0, 1.33), std::pow(0.33 / 2.33, 2), 1e-15);
  // Reciprocal index gives the same normal-incidence value.
  EXPECT_NEAR(sl::F_Dielectric(1.0, 1.0 / 1.5), 0.04, 1e-15);
}

TEST(FresnelTest, SixtyDegreesOnGlass)
{
  // REFERENCE.md: F(60 deg) = 0.08919 for eta = 1.5 (Rs = 0.17737,
  // Rp = 0.00101, Hecht fig. 4.49 values).
  EXPECT_NEAR(sl::F_Dielectric(std::cos(60 * kDeg), 1.5), 0.08919, 5e-6);
}

TEST(FresnelTest, BrewsterAngleHasNoPPolarizedReflection)
{
  // Brewster: tan(theta_B) = eta -> 56.3099 deg for eta = 1.5.
  const double thetaB = std::atan(1.5);
  EXPECT_NEAR(thetaB / kDeg, 56.3099, 1e-4);
  double Rs = 0, Rp = 0;
  sl::F_DielectricPolarized(std::cos(thetaB), 1.5, Rs, Rp);
  EXPECT_LT(Rp, 1e-28);
  EXPECT_GT(Rs, 0.1);
  // Rp's minimum over a 0.001-degree scan sits at Brewster's angle.
  double bestAngle = 0, bestRp = 1;
  for (double a = 50.0; a <= 60.0; a += 0.001)
  {
    sl::F_DielectricPolarized(std::cos(a * kDeg), 1.5, Rs, Rp);
    if (Rp < bestRp)
    {
      bestRp = Rp;
      bestAngle = a;
    }
  }
  EXPECT_NEAR(bestAngle, 56.3099, 1e-3);
}

TEST(FresnelTest, TotalInternalReflectionBeyondCriticalAngle)
{
  const double eta = 1.0 / 1.5; // glass to air
  const double critical = std::asin(eta) / kDeg;
  EXPECT_NEAR(critical, 41.8103, 1e-4);
  EXPECT_EQ(sl::F_Dielectric(std::cos(45 * kDeg), eta), 1.0);
  EXPECT_EQ(sl::F_Dielectric(std::cos(41.82 * kDeg), eta), 1.0);
  EXPECT_LT(sl::F_Dielectric(std::cos(41.80 * kDeg), eta), 1.0);
  EXPECT_EQ(sl::F_Conductor(std::cos(45 * kDeg), eta, 0.0), 1.0);
}

TEST(FresnelTest, MatchedIndexIsInvisible)
{
  for (double a = 0; a <= 90.0; a += 1.0)
  {
    EXPECT_EQ(sl::F_Dielectric(std::cos(a * kDeg), 1.0), 0.0) << a;
    EXPECT_EQ(sl::F_Dielectric(static_cast<float>(std::cos(a * kDeg)), 1.0f), 0.0f) << a;
  }
}

TEST(FresnelTest, GrazingIncidenceReflectsEverything)
{
  EXPECT_NEAR(sl::F_Dielectric(0.0, 1.5), 1.0, 1e-15);
  EXPECT_NEAR(sl::F_Conductor(0.0, 0.35, 2.714), 1.0, 1e-12);
}

TEST(FresnelTest, CosineFormEqualsTheLectureFormAwayFromNormalIncidence)
{
  for (double eta : { 1.2, 1.5, 2.4, 0.8 })
  {
    for (double a = 1.0; a < 89.5; a += 0.5)
    {
      if (eta < 1.0 && std::sin(a * kDeg) / eta >= 1.0)
      {
        continue; // the lecture form has no real theta_t under TIR
      }
      EXPECT_NEAR(sl::F_Dielectric(std::cos(a * kDeg), eta), FresnelLectureForm(a * kDeg, eta),
        1e-12)
        << "eta " << eta << " angle " << a;
    }
  }
}

TEST(FresnelTest, ConductorGoldAtNormalIncidence)
{
  // REFERENCE.md: gold at 550 nm, n = 0.350, k = 2.714: F0 = 0.8476.
  EXPECT_NEAR(sl::F0_Conductor(0.350, 2.714), 0.8476, 5e-5);
  EXPECT_NEAR(sl::F_Conductor(1.0, 0.350, 2.714), sl::F0_Conductor(0.350, 2.714), 1e-12);
}

TEST(FresnelTest, ConductorRealFormEqualsTheComplexForm)
{
  // The metal presets' channels (Materials.cpp) and a few made-up indices,
  // including eta < 1 with little absorption (near total reflection).
  const double indices[][2] = { { 0.14, 3.697 }, { 0.43, 2.455 }, { 1.38, 1.914 },
    { 0.272, 3.24 }, { 1.037, 2.59 }, { 1.49, 7.61 }, { 0.686, 5.64 }, { 0.35, 2.714 },
    { 0.6, 0.01 }, { 2.5, 0.3 }, { 1.0, 1e-3 }, { 30.0, 40.0 } };
  for (const auto& [eta, k] : indices)
  {
    for (double a = 0.0; a <= 90.0; a += 0.25)
    {
      const double c = std::cos(a * kDeg);
      EXPECT_NEAR(sl::F_Conductor(c, eta, k), FresnelComplexForm(c, eta, k), 1e-12)
        << "eta " << eta << " k " << k << " angle " << a;
      // Float, as both renderers evaluate it, against the exact value at
      // the same (float) arguments. The complex form in float is 2.4e-6 off
      // at eta = 1, k = 1e-3 (F ~ 0 there: cancellation in rs and rp).
      const float cf = static_cast<float>(c), etaf = static_cast<float>(eta),
                  kf = static_cast<float>(k);
      EXPECT_NEAR(sl::F_Conductor(cf, etaf, kf), FresnelComplexForm(cf, etaf, kf), 3e-6)
        << "eta " << eta << " k " << k << " angle " << a;
    }
  }
}

TEST(FresnelTest, ConductorIsFiniteAndBoundedForExtremeIndices)
{
  for (double eta : { 1e-3, 0.05, 1.0, 1.5, 1e3 })
  {
    for (double k : { 1e-30, 1e-6, 0.5, 3.0, 1e3 })
    {
      for (double c : { 0.0, 1e-8, 1e-3, 0.3, 0.7, 1.0 })
      {
        const float F = sl::F_Conductor(
          static_cast<float>(c), static_cast<float>(eta), static_cast<float>(k));
        EXPECT_TRUE(std::isfinite(F) && F >= 0.0f && F <= 1.0f + 1e-6f)
          << F << " at eta " << eta << " k " << k << " cos " << c;
      }
    }
  }
}

TEST(FresnelTest, ConductorWithoutAbsorptionIsTheDielectric)
{
  for (double a = 0.0; a <= 90.0; a += 5.0)
  {
    const double c = std::cos(a * kDeg);
    // A tiny k exercises the complex path itself.
    EXPECT_NEAR(sl::F_Conductor(c, 1.5, 1e-9), sl::F_Dielectric(c, 1.5), 1e-8) << a;
  }
}

TEST(FresnelTest, RealEtaFitUnderestimatesMetalsAtGrazing)
{
  // Cook & Torrance 1982 sec. 4: eta fitted to F0 by (1 + sqrt F0)/(1 - sqrt F0),
  // then the dielectric formula. Exact conductor is brighter towards grazing.
  const double n = 0.350, k = 2.714;
  const double F0 = sl::F0_Conductor(n, k);
  const double etaFit = (1 + std::sqrt(F0)) / (1 - std::sqrt(F0));
  EXPECT_NEAR(sl::F_Dielectric(1.0, etaFit), F0, 1e-12);
  const double c80 = std::cos(80 * kDeg);
  EXPECT_LT(sl::F_Dielectric(c80, etaFit), sl::F_Conductor(c80, n, k));
}

TEST(FresnelTest, FloatAgreesWithDouble)
{
  for (double a = 0.0; a <= 90.0; a += 0.25)
  {
    for (double eta : { 0.5, 1.0, 1.5, 3.0 })
    {
      const double d = sl::F_Dielectric(std::cos(a * kDeg), eta);
      const float f = sl::F_Dielectric(static_cast<float>(std::cos(a * kDeg)),
        static_cast<float>(eta));
      // float: 24-bit mantissa; the ratio of differences near TIR loses a
      // few more bits; 1e-5 absolute covers it with margin.
      EXPECT_NEAR(f, d, 1e-5) << a << " " << eta;
    }
  }
}

