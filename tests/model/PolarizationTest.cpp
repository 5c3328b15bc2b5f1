// SPDX-License-Identifier: BSD-3-Clause
// Polarization (docs/model.md section 8): Rs and Rp against the complex
// Fresnel amplitudes, Brewster's angle, and the analyser obeying Malus's law
// in the model's EvaluateBrdf and Shade.
#include "shadinglab/model/Fresnel.h"
#include "shadinglab/model/Materials.h"
#include "shadinglab/model/Shading.h"
#include "shadinglab/model/Spectrum.h"

#include <gtest/gtest.h>

#include <array>
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

/// A and B of Fresnel's Mueller matrix per channel.
void RgbSP(double cosTheta_i, const sl::Vec3d& eta, const sl::Vec3d& k, sl::Vec3d& A, sl::Vec3d& B)
{
  sl::Vec3d C, D;
  sl::F_RGB_Mueller(cosTheta_i, eta, k, A, B, C, D);
}

const sl::Analyser<double>* const kNoAnalyser = nullptr;

sl::Analyser<double> AnalyserAt(double degrees)
{
  sl::Analyser<double> a;
  a.on = true;
  a.cos2Theta = std::cos(2.0 * degrees * sl::kPi<double> / 180.0);
  a.sin2Theta = std::sin(2.0 * degrees * sl::kPi<double> / 180.0);
  return a;
}
/// A random unit vector above the surface (z > 0), uniform in the ball's
/// directions, away from grazing.
sl::Vec3d RandomUpperUnit(std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  sl::Vec3d v;
  do
  {
    v = sl::Vec3d(u(rng), u(rng), std::abs(u(rng)) + 0.05);
  } while (sl::Length(v) > 1.0);
  return sl::NormalizeOr(v, sl::Vec3d(0, 0, 1));
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
    RgbSP(std::cos(thetaB), sl::Vec3d(eta, eta, eta), sl::Vec3d(), A, B);
    EXPECT_NEAR(A.x - B.x, 0.0, 1e-14) << "Rp at Brewster, eta " << eta;
    EXPECT_NEAR(std::abs(B.x) / A.x, 1.0, 1e-12) << eta;
    // Away from it, partially polarized; at normal incidence not at all.
    RgbSP(std::cos(thetaB - 0.3), sl::Vec3d(eta, eta, eta), sl::Vec3d(), A, B);
    EXPECT_LT(std::abs(B.x) / A.x, 0.95);
    RgbSP(1.0, sl::Vec3d(eta, eta, eta), sl::Vec3d(), A, B);
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
  auto randomUnit = [&]() { return RandomUpperUnit(rng); };
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

namespace
{
sl::Analyser<double> CircularAnalyser()
{
  sl::Analyser<double> a;
  a.on = true;
  a.cos2Theta = a.sin2Theta = 0.0;
  a.circular = 1.0;
  return a;
}

sl::LightPolarizer<double> LightPolarizerAt(double degrees)
{
  sl::LightPolarizer<double> p;
  p.on = true;
  const double psi = degrees * sl::kPi<double> / 180.0;
  p.axis = sl::Vec3d(std::cos(psi), std::sin(psi), 0.0);
  return p;
}

/// The Stokes vector of the Fresnel term as a polarimeter measures it:
/// analysers at 0, 45, 90, 135 degrees and a circular one (eq. 8.5).
std::array<sl::Vec3d, 4> MeasuredStokes(const sl::Material<double>& m, double cosTheta_i,
  const sl::Vec3d& L, const sl::Vec3d& V, const sl::LightPolarizer<double>* light)
{
  sl::Vec3d I[4];
  for (int a = 0; a < 4; ++a)
  {
    const sl::Analyser<double> analyser = AnalyserAt(45.0 * a);
    I[a] = sl::F_Polarized(m, cosTheta_i, L, V, &analyser, light);
  }
  const sl::Analyser<double> circular = CircularAnalyser();
  const sl::Vec3d Ic = sl::F_Polarized(m, cosTheta_i, L, V, &circular, light);
  const sl::Vec3d S0 = I[0] + I[2];
  return { S0, I[0] - I[2], I[1] - I[3], Ic * 2.0 - S0 };
}
} // namespace

// C + i D = rs rp* (eq. 8.2), in the frames where rp = -rs at normal
// incidence: against the complex amplitudes, for dielectrics (D = 0),
// glass seen from inside beyond the critical angle (total internal
// reflection: |rs| = |rp| = 1, a phase between them) and metals.
TEST(PolarizationTest, MuellerPhaseTermsAreRsTimesConjugateRp)
{
  const std::pair<double, double> indices[] = { { 1.5, 0.0 }, { 1.0 / 1.5, 0.0 },
    { 0.27, 3.4 }, { 1.5, 7.6 }, { 0.05, 4.4 }, { 2.4, 0.01 } };
  for (const auto& [eta, k] : indices)
  {
    const std::complex<double> n(eta, k);
    for (double deg = 0.0; deg <= 89.5; deg += 0.5)
    {
      const double c = std::cos(deg * sl::kPi<double> / 180.0);
      const std::complex<double> u = std::sqrt(n * n - (1.0 - c * c));
      const std::complex<double> rs = (c - u) / (c + u);
      const std::complex<double> rp = (n * n * c - u) / (n * n * c + u);
      const std::complex<double> expected = rs * std::conj(rp);
      double Rs, Rp, C, D;
      sl::F_ConductorMueller(c, eta, k, Rs, Rp, C, D);
      EXPECT_NEAR(C, expected.real(), 1e-12) << eta << "+i" << k << " at " << deg;
      EXPECT_NEAR(D, expected.imag(), 1e-12) << eta << "+i" << k << " at " << deg;
      EXPECT_NEAR(C * C + D * D, Rs * Rp, 1e-12);
      if (k == 0.0 && eta > 1.0)
      {
        EXPECT_EQ(D, 0.0) << "a dielectric from outside keeps linear light linear";
      }
    }
  }
  double Rs, Rp, C, D;
  sl::F_ConductorMueller(1.0, 1.5, 0.0, Rs, Rp, C, D);
  EXPECT_NEAR(C, -0.04, 1e-15) << "rp = -rs at normal incidence";
  // Fresnel's rhomb: inside glass at 54.6 degrees, s and p differ by 45 degrees.
  sl::F_ConductorMueller(std::cos(54.6 * sl::kPi<double> / 180.0), 1.0 / 1.51, 0.0, Rs, Rp, C, D);
  EXPECT_NEAR(Rs, 1.0, 1e-12);
  EXPECT_NEAR(std::abs(std::atan2(D, C)), sl::kPi<double> / 4.0, 0.01);
}

// Polarized light (eq. 8.6): crossed polarizers at the lamp and the camera
// remove a headlight's specular reflection (cross-polarized photography),
// parallel ones pass all of it; s-polarized light reflects Rs, p-polarized
// light at Brewster's angle nothing.
TEST(PolarizationTest, CrossedPolarizersRemoveTheHeadlightsReflection)
{
  for (const char* preset : { "glass", "gold", "aluminium" })
  {
    const sl::Material<double> m = sl::FindMaterialPreset(preset)->material;
    const sl::Vec3d N(0, 0, 1);
    const sl::Vec3d F = m.Fresnel(1.0);
    for (double psi : { 0.0, 30.0, 90.0 })
    {
      const sl::LightPolarizer<double> light = LightPolarizerAt(psi);
      const sl::Analyser<double> crossed = AnalyserAt(psi + 90.0), parallel = AnalyserAt(psi);
      const sl::Vec3d dark = sl::F_Polarized(m, 1.0, N, N, &crossed, &light);
      const sl::Vec3d bright = sl::F_Polarized(m, 1.0, N, N, &parallel, &light);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(dark[c], 0.0, 1e-12) << preset << " " << psi;
        EXPECT_NEAR(bright[c], F[c], 1e-12) << preset << " " << psi;
      }
    }
  }
  // Light in the x-z plane, camera mirrored: s is the y axis.
  const sl::Material<double> glass = sl::FindMaterialPreset("glass")->material;
  const double eta = glass.eta.x, thetaB = std::atan(eta);
  for (double theta : { 0.3, thetaB, 1.2 })
  {
    const sl::Vec3d L(std::sin(theta), 0.0, std::cos(theta)), V(-std::sin(theta), 0.0, std::cos(theta));
    double Rs, Rp;
    sl::F_DielectricPolarized(std::cos(theta), eta, Rs, Rp);
    const sl::LightPolarizer<double> sLight = LightPolarizerAt(90.0), pLight = LightPolarizerAt(0.0);
    EXPECT_NEAR(sl::F_Polarized(glass, std::cos(theta), L, V, kNoAnalyser, &sLight).x, Rs, 1e-12);
    EXPECT_NEAR(sl::F_Polarized(glass, std::cos(theta), L, V, kNoAnalyser, &pLight).x, Rp, 1e-12);
  }
  const sl::LightPolarizer<double> pLight = LightPolarizerAt(0.0);
  const sl::Vec3d L(std::sin(thetaB), 0.0, std::cos(thetaB)), V(-L.x, 0.0, L.z);
  EXPECT_NEAR(sl::F_Polarized(glass, std::cos(thetaB), L, V, kNoAnalyser, &pLight).x, 0.0, 1e-14);
}

// A single facet reflects fully polarized light fully polarized:
// S0^2 = S1^2 + S2^2 + S3^2 as a polarimeter measures it; a metal turns
// linear light elliptical (S3 != 0), a dielectric does not; unpolarized
// light has no circular part; Malus's law holds with the light polarized.
TEST(PolarizationTest, PolarizedLightStaysFullyPolarizedAndMetalsMakeItElliptical)
{
  std::mt19937 rng(11);
  auto randomUnit = [&]() { return RandomUpperUnit(rng); };
  sl::Material<double> spectralGold = sl::FindMaterialPreset("gold")->material;
  ASSERT_EQ(sl::SetSpectral(spectralGold, *sl::PresetDispersion("gold")), "");
  const std::pair<const char*, sl::Material<double>> materials[] = {
    { "glass", sl::FindMaterialPreset("glass")->material },
    { "gold", sl::FindMaterialPreset("gold")->material },
    { "spectral gold", spectralGold },
  };
  for (const auto& [name, m] : materials)
  {
    const bool metal = m.IsConductor() || m.spectralCount > 0;
    double largestS3 = 0.0;
    for (int trial = 0; trial < 300; ++trial)
    {
      const sl::Vec3d L = randomUnit(), V = randomUnit();
      const double cosTheta_i = sl::Dot(V, sl::NormalizeOr(L + V, sl::Vec3d(0, 0, 1)));
      const sl::LightPolarizer<double> light = LightPolarizerAt(std::uniform_real_distribution<double>(0.0, 180.0)(rng));
      const auto S = MeasuredStokes(m, cosTheta_i, L, V, &light);
      const sl::Vec3d unanalysed = sl::F_Polarized(m, cosTheta_i, L, V, kNoAnalyser, &light);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(S[0][c], unanalysed[c], 1e-12) << name;
        if (m.spectralCount == 0)
        {
          // One wavelength per channel: fully polarized.
          EXPECT_NEAR(S[0][c] * S[0][c], S[1][c] * S[1][c] + S[2][c] * S[2][c] + S[3][c] * S[3][c],
            1e-12)
            << name;
        }
        largestS3 = std::max(largestS3, std::abs(S[3][c]) / S[0][c]);
      }
      if (m.spectralCount > 0)
      {
        // A spectral channel sums wavelengths with different phases and
        // XYZ-to-sRGB's negative weights; its luminance Y (the CIE y-bar
        // weighting, non-negative) is partially polarized: DoP <= 1.
        auto Y = [](const sl::Vec3d& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; };
        EXPECT_LE(Y(S[1]) * Y(S[1]) + Y(S[2]) * Y(S[2]) + Y(S[3]) * Y(S[3]), Y(S[0]) * Y(S[0]) + 1e-12);
      }
      const auto Su = MeasuredStokes(m, cosTheta_i, L, V, static_cast<const sl::LightPolarizer<double>*>(nullptr));
      EXPECT_NEAR(Su[3].y, 0.0, 1e-12) << name << ": unpolarized light has no circular part";
    }
    if (metal)
    {
      EXPECT_GT(largestS3, 0.3) << name << " turns linear light elliptical";
    }
    else
    {
      EXPECT_LT(largestS3, 1e-12) << name;
    }
  }
}

// Shade with the light's polarizer: the diffuse term is depolarized (half
// through any analyser), the picture through crossed polarizers is the
// diffuse half alone at normal incidence.
TEST(PolarizationTest, ShadeThroughCrossedPolarizersKeepsTheDiffuseHalf)
{
  const sl::Material<double> plastic = sl::FindMaterialPreset("plastic")->material;
  ASSERT_EQ(plastic.model, sl::ReflectanceModel::CookTorrance);
  sl::Lighting<double> lighting;
  lighting.lights[0].vector = sl::Vec3d(0, 0, 1);
  lighting.ambientIntensity = sl::Vec3d();
  lighting.lightPolarizer = LightPolarizerAt(0.0);
  const sl::Vec3d P, N(0, 0, 1), V(0, 0, 1), rho(0.5, 0.5, 0.5);
  lighting.analyser = AnalyserAt(90.0);
  const sl::Vec3d crossed = sl::Shade(plastic, lighting, rho, P, N, V);
  lighting.analyser = AnalyserAt(0.0);
  const sl::Vec3d parallel = sl::Shade(plastic, lighting, rho, P, N, V);
  const double irradiance = lighting.lights[0].solidAngle;
  const double diffuse = irradiance * 0.5 * rho.x * plastic.kd * sl::Fd_Lambert<double>();
  EXPECT_NEAR(crossed.x, diffuse, 1e-12);
  EXPECT_GT(parallel.x, crossed.x + 0.05) << "the highlight passes parallel polarizers";
}
