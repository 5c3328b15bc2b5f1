// SPDX-License-Identifier: BSD-3-Clause
// Polarization (docs/model.md section 8): Rs and Rp against the complex
// Fresnel amplitudes, Brewster's angle, and the analyser obeying Malus's law
// in the model's EvaluateBrdf and Shade.
#include "shadinglab/model/Fresnel.h"
#include "shadinglab/model/Materials.h"
#include "shadinglab/model/Shading.h"
#include "shadinglab/model/Spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>

namespace sl = shadinglab;

namespace
{
/// |rs|^2 and |rp|^2 from the complex amplitudes (Born & Wolf sec. 1.5.2,
/// 14.2): rs = (cos ti - n cos tt) / (cos ti + n cos tt),
/// rp = (n cos ti - cos tt) / (n cos ti + cos tt), n = eta + i k.
void ComplexRsRp(double cosTi, double eta, double k, double& Rs, double& Rp)
{
  const std::complex<double> n(eta, k);
  const double sin2 = 1.0 - cosTi * cosTi;
  const std::complex<double> cosTt = std::sqrt(1.0 - sin2 / (n * n));
  const std::complex<double> rs = (cosTi - n * cosTt) / (cosTi + n * cosTt);
  const std::complex<double> rp = (n * cosTi - cosTt) / (n * cosTi + cosTt);
  Rs = std::norm(rs);
  Rp = std::norm(rp);
}

sl::Analyser<double> AnalyserAt(double degrees)
{
  sl::Analyser<double> a;
  a.on = true;
  a.cos2Theta = std::cos(2.0 * degrees * sl::kPi<double> / 180.0);
  a.sin2Theta = std::sin(2.0 * degrees * sl::kPi<double> / 180.0);
  return a;
}
} // namespace

TEST(PolarizationTest, RsRpAreTheComplexAmplitudesSquared)
{
  const std::pair<double, double> indices[] = { { 1.5, 0.0 }, { 1.33, 0.0 }, { 0.27, 3.4 },
    { 1.5, 7.6 }, { 0.05, 4.4 }, { 2.4, 0.01 } };
  for (const auto& [eta, k] : indices)
  {
    for (double deg = 0.0; deg <= 89.5; deg += 0.5)
    {
      const double c = std::cos(deg * sl::kPi<double> / 180.0);
      double Rs = 0, Rp = 0, rs = 0, rp = 0;
      sl::F_ConductorSP(c, eta, k, Rs, Rp);
      ComplexRsRp(c, eta, k, rs, rp);
      EXPECT_NEAR(Rs, rs, 1e-12) << eta << "+i" << k << " at " << deg;
      EXPECT_NEAR(Rp, rp, 1e-12) << eta << "+i" << k << " at " << deg;
      EXPECT_NEAR(0.5 * (Rs + Rp), sl::F_Conductor(c, eta, k), 1e-12);
      EXPECT_GE(Rs + 1e-15, Rp) << "Rs >= Rp for passive media";
    }
  }
}

// Brewster's angle, tan(theta_B) = eta: Rp = 0, so the specular reflection
// of unpolarized light is fully s-polarized, DoLP = |B| / A = 1.
TEST(PolarizationTest, BrewsterAngleIsFullyPolarized)
{
  for (double eta : { 1.33, 1.5, 1.9 })
  {
    const double thetaB = std::atan(eta);
    sl::Vec3d A, B;
    sl::F_RGB_SP(std::cos(thetaB), sl::Vec3d(eta, eta, eta), sl::Vec3d(), A, B);
    EXPECT_NEAR(A.x - B.x, 0.0, 1e-14) << "Rp at Brewster, eta " << eta;
    EXPECT_NEAR(std::abs(B.x) / A.x, 1.0, 1e-12) << eta;
    // Away from it, partially polarized; at normal incidence not at all.
    sl::F_RGB_SP(std::cos(thetaB - 0.3), sl::Vec3d(eta, eta, eta), sl::Vec3d(), A, B);
    EXPECT_LT(std::abs(B.x) / A.x, 0.95);
    sl::F_RGB_SP(1.0, sl::Vec3d(eta, eta, eta), sl::Vec3d(), A, B);
    EXPECT_NEAR(B.x, 0.0, 1e-15);
  }
  // Spectral glass (N-BK7): Brewster at each wavelength's own index, so the
  // colour's Rp is ~0 (below 1e-5) near 56.6 degrees, not exactly 0.
  sl::Material<double> glass = sl::FindMaterialPreset("glass")->material;
  ASSERT_EQ(sl::SetSpectral(glass, *sl::PresetDispersion("glass")), "");
  sl::Vec3d A, B;
  glass.FresnelSP(std::cos(std::atan(1.5168)), A, B);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_LT(A[c] - B[c], 1e-5) << c;
    EXPECT_GT(std::abs(B[c]) / A[c], 0.999) << c;
  }
}

// Malus's law through the analyser: I(theta) = (S0 + S1 cos 2 theta +
// S2 sin 2 theta) / 2, so I(0) + I(90) = I(45) + I(135) = S0, the picture
// without an analyser; for every model, in EvaluateBrdf and in Shade.
TEST(PolarizationTest, MalusLawHoldsForEveryModel)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto randomUnit = [&]() {
    sl::Vec3d v;
    do
    {
      v = sl::Vec3d(u(rng), u(rng), std::abs(u(rng)) + 0.05);
    } while (sl::Length(v) > 1.0);
    return sl::NormalizeOr(v, sl::Vec3d(0, 0, 1));
  };
  std::vector<sl::Material<double>> materials;
  for (const char* preset : { "glass", "gold", "copper", "plastic" })
  {
    materials.push_back(sl::FindMaterialPreset(preset)->material);
  }
  sl::Material<double> spectralGold = materials[1];
  ASSERT_EQ(sl::SetSpectral(spectralGold, *sl::PresetDispersion("gold")), "");
  materials.push_back(spectralGold);
  sl::Material<double> phong;
  phong.model = sl::ReflectanceModel::Phong;
  materials.push_back(phong);
  int polarizedCases = 0;
  for (const auto& m : materials)
  {
    for (int trial = 0; trial < 200; ++trial)
    {
      const sl::Vec3d N(0, 0, 1), L = randomUnit(), V = randomUnit();
      const sl::Vec3d rho(0.8, 0.6, 0.4);
      const sl::Vec3d none = sl::EvaluateBrdf(m, rho, N, L, V);
      sl::Vec3d I[4];
      for (int a = 0; a < 4; ++a)
      {
        const sl::Analyser<double> analyser = AnalyserAt(45.0 * a);
        I[a] = sl::EvaluateBrdf(m, rho, N, L, V, &analyser);
      }
      for (int c = 0; c < 3; ++c)
      {
        const double scale = 1e-12 * (1.0 + std::abs(none[c]));
        EXPECT_NEAR(I[0][c] + I[2][c], none[c], scale);
        EXPECT_NEAR(I[1][c] + I[3][c], none[c], scale);
        EXPECT_GE(I[0][c], -scale);
      }
      polarizedCases += std::abs(I[0].x - I[2].x) > 1e-3 * none.x;
    }
  }
  EXPECT_GT(polarizedCases, 100) << "the analyser's angle matters for Cook-Torrance";

  // Shade: the ambient and the diffuse light pass by half too.
  sl::Lighting<double> lighting;
  lighting.lights[0].vector = sl::NormalizeOr(sl::Vec3d(0.6, 0.1, 0.8), sl::Vec3d(0, 0, 1));
  const sl::Vec3d P(0, 0, 0), N(0, 0, 1), V = sl::NormalizeOr(sl::Vec3d(-0.5, 0.2, 0.8), sl::Vec3d(0, 0, 1));
  const sl::Vec3d none = sl::Shade(materials[1], lighting, sl::Vec3d(1, 1, 1), P, N, V);
  sl::Vec3d sum;
  for (double deg : { 30.0, 120.0 })
  {
    lighting.analyser = AnalyserAt(deg);
    sum += sl::Shade(materials[1], lighting, sl::Vec3d(1, 1, 1), P, N, V);
  }
  EXPECT_NEAR(sum.x, none.x, 1e-12);
  EXPECT_NEAR(sum.z, none.z, 1e-12);
}
