// SPDX-License-Identifier: BSD-3-Clause
// render --polarizer and --output (docs/model.md section 8) from the command
// line: the Stokes image a polarization camera would measure, as a .vti
// VTK reads, physically plausible; brdf's polarized terms; bad requests one
// line and exit 2.
#include "CliTestUtil.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataReader.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using shadinglab::testing::RunCli;

namespace
{
const std::string kData = std::string(SHADINGLAB_SOURCE_DIR) + "/datasets/";
const std::string kSphere = kData + "icosphere_4.vtp";
// Light from the side: the glass's highlight lies near Brewster's angle.
const std::string kScene = " --backend cpu --size 120x90 --light dir:-1,0.1,0.1 --ambient 0 ";
} // namespace

TEST(PolarizationCliTest, StokesImageIsWhatAPolarizationCameraSees)
{
  const std::string dir = ::testing::TempDir();
  ASSERT_EQ(RunCli("render " + kSphere + kScene +
              "--material glass --kd 0 --ks 1 --m 0.4 --output stokes --out " + dir + "/sl_glass.vti")
              .status,
    0);
  ASSERT_EQ(RunCli("render " + kSphere + kScene + "--model lambert --output stokes --out " + dir +
              "/sl_lambert.vti")
              .status,
    0);
  auto read = [](const std::string& path) {
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkSmartPointer<vtkImageData> image = reader->GetOutput();
    return image;
  };
  auto glass = read(dir + "/sl_glass.vti");
  auto lambert = read(dir + "/sl_lambert.vti");
  ASSERT_EQ(glass->GetNumberOfPoints(), 120 * 90);
  for (const char* name : { "S0", "S1", "S2", "S3", "DoLP", "AoP" })
  {
    ASSERT_NE(glass->GetPointData()->GetArray(name), nullptr) << name;
  }
  vtkDataArray* dolp = glass->GetPointData()->GetArray("DoLP");
  vtkDataArray* aop = glass->GetPointData()->GetArray("AoP");
  double best = 0;
  int lit = 0, vertical = 0;
  for (vtkIdType i = 0; i < dolp->GetNumberOfTuples(); ++i)
  {
    const double d = dolp->GetComponent(i, 0);
    if (std::isnan(d))
    {
      continue; // no light
    }
    EXPECT_GE(d, 0.0);
    EXPECT_LE(d, 1.0);
    best = std::max(best, d);
    ++lit;
    // Light in the image's x-z plane: the plane of incidence is roughly
    // horizontal, so the reflected light is polarized vertically (s).
    vertical += std::abs(std::abs(aop->GetComponent(i, 0)) - 90.0) < 20.0;
  }
  EXPECT_GT(lit, 500);
  // Rough glass (m = 0.4): the facets that reflect cover a range of
  // incidence angles around Brewster's; the most polarized pixel is 0.86.
  EXPECT_GT(best, 0.8) << "near Brewster's angle the reflection is strongly polarized";
  EXPECT_GT(vertical, lit / 2);
  // Lambert has no Fresnel term: unpolarized, S1 = S2 = 0, DoLP 0.
  vtkDataArray* s1 = lambert->GetPointData()->GetArray("S1");
  vtkDataArray* s2 = lambert->GetPointData()->GetArray("S2");
  double worst = 0;
  for (vtkIdType i = 0; i < s1->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max({ worst, std::abs(s1->GetComponent(i, c)), std::abs(s2->GetComponent(i, c)) });
    }
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(PolarizationCliTest, BrdfPolarizedTermsAndBadRequests)
{
  // Brewster's angle of eta 1.5: tan(theta) = 1.5, theta = 56.3099 degrees.
  const auto r = RunCli("brdf --eta 1.5 --term dolp --theta-l 56.309932474 --theta-v 56.309932474");
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream in(r.out);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_NE(row.find(",1,1,1"), std::string::npos) << row;
  const auto fp = RunCli("brdf --eta 1.5 --term Fp --theta-l 56.309932474 --theta-v 56.309932474");
  ASSERT_EQ(fp.status, 0);
  const std::string last = fp.out.substr(fp.out.find('\n') + 1);
  const double rp = std::stod(last.substr(last.rfind(',') + 1));
  EXPECT_LT(std::abs(rp), 1e-12) << "Rp vanishes at Brewster: " << fp.out;

  const std::string dir = ::testing::TempDir();
  const std::pair<std::string, std::string> bad[] = {
    { "render " + kSphere + " --output colour --out " + dir + "/x.png", "--output must be" },
    { "render " + kSphere + " --output dolp --backend gpu --out " + dir + "/x.png", "--backend cpu" },
    { "render " + kSphere + " --output dolp --polarizer 30 --backend cpu --out " + dir + "/x.png",
      "drop --polarizer" },
    { "render " + kSphere + " --polarizer 200 --backend cpu --out " + dir + "/x.png",
      "--polarizer must be in" },
    { "brdf --term polarization --theta-l 10", "unknown --term" },
    { "render " + kSphere + " --output s2 --backend cpu --out " + dir + "/x.png", "writes a .vti" },
    { "render " + kSphere + " --output dolp --backend cpu --out " + dir + "/x.vti", "writes a .png" },
    { "render " + kSphere + " --light-polarizer 200 --backend cpu --out " + dir + "/x.png",
      "--light-polarizer must be in" },
    { "render " + kSphere + " --light-polarizer nan --backend cpu --out " + dir + "/x.png",
      "--light-polarizer" },
  };
  for (const auto& [command, expected] : bad)
  {
    const auto b = RunCli(command);
    EXPECT_EQ(b.status, 2) << command;
    EXPECT_NE(b.err.find(expected), std::string::npos) << command << ": " << b.err;
    EXPECT_EQ(std::count(b.err.begin(), b.err.end(), '\n'), 1) << b.err;
  }
}

namespace
{
vtkSmartPointer<vtkImageData> RenderStokes(const std::string& options, const std::string& name)
{
  const std::string path = ::testing::TempDir() + "/" + name + ".vti";
  const auto r = RunCli("render " + kSphere + " --backend cpu --size 120x90 --ambient 0 " +
    options + " --output stokes --out " + path);
  EXPECT_EQ(r.status, 0) << r.err;
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkImageData> image = reader->GetOutput();
  return image;
}

/// The Stokes vector of pixel i, channel c.
std::array<double, 4> Stokes(vtkImageData* image, vtkIdType i, int c)
{
  std::array<double, 4> s{};
  const char* names[4] = { "S0", "S1", "S2", "S3" };
  for (int k = 0; k < 4; ++k)
  {
    s[k] = image->GetPointData()->GetArray(names[k])->GetComponent(i, c);
  }
  return s;
}

/// Pixels where light arrives (DoLP is NaN where it does not).
std::vector<vtkIdType> Lit(vtkImageData* image)
{
  std::vector<vtkIdType> lit;
  vtkDataArray* dolp = image->GetPointData()->GetArray("DoLP");
  for (vtkIdType i = 0; i < dolp->GetNumberOfTuples(); ++i)
  {
    if (!std::isnan(dolp->GetComponent(i, 0)))
    {
      lit.push_back(i);
    }
  }
  return lit;
}
} // namespace

// eq. 8.6: a polarizer in front of the light. A headlight's reflection off
// glass keeps the light's polarization (rp = -rs at normal incidence, the
// same axis in the image), so an analyser crossed with it (cross-polarized
// photography) removes the highlight; a diffuse surface depolarizes and
// passes half; a metal lit at 45 degrees turns linear light elliptical (S3).
TEST(PolarizationCliTest, LightPolarizerCrossedWithTheAnalyserRemovesTheHeadlightsHighlight)
{
  const std::string glassScene = "--light dir:0,0,1 --material glass --kd 0 --ks 1 --m 0.3 ";
  auto glass = RenderStokes(glassScene + "--light-polarizer 0", "sl_headlight_glass");
  const auto lit = Lit(glass);
  ASSERT_GT(lit.size(), 500u); // kd 0: the glass is dark away from the highlight
  double brightest = 0, crossed = 0, worstS3 = 0;
  for (vtkIdType i : lit)
  {
    for (int c = 0; c < 3; ++c)
    {
      const auto s = Stokes(glass, i, c);
      brightest = std::max(brightest, s[0]);
      crossed = std::max(crossed, 0.5 * (s[0] - s[1])); // through an analyser at 90 degrees
      worstS3 = std::max(worstS3, std::abs(s[3]));
    }
  }
  EXPECT_GT(brightest, 0.05) << "the highlight is there without the crossed analyser";
  EXPECT_LT(crossed, 1e-3 * brightest) << "crossed polarizers remove the headlight's highlight";
  EXPECT_LT(worstS3, 1e-5) << "a dielectric's reflection stays linear";

  // Lambert: half the light, unpolarized.
  auto plain = RenderStokes("--model lambert --light dir:-1,0.5,1", "sl_lambert_plain");
  auto polarized =
    RenderStokes("--model lambert --light dir:-1,0.5,1 --light-polarizer 30", "sl_lambert_pol");
  double worstHalf = 0, worstPolarized = 0;
  for (vtkIdType i : Lit(plain))
  {
    for (int c = 0; c < 3; ++c)
    {
      const auto a = Stokes(plain, i, c);
      const auto b = Stokes(polarized, i, c);
      worstHalf = std::max(worstHalf, std::abs(b[0] - 0.5 * a[0]));
      worstPolarized = std::max({ worstPolarized, std::abs(b[1]), std::abs(b[2]), std::abs(b[3]) });
    }
  }
  EXPECT_LT(worstHalf, 1e-5);
  EXPECT_LT(worstPolarized, 1e-6);

  // Gold lit from the side through a polarizer at 45 degrees: fully
  // polarized still (DoP = 1 per channel), and elliptical.
  auto gold = RenderStokes(
    "--light dir:-1,0.1,0.1 --material gold --kd 0 --ks 1 --m 0.3 --light-polarizer 45", "sl_gold");
  double ellipticity = 0, worstDop = 0;
  for (vtkIdType i : Lit(gold))
  {
    for (int c = 0; c < 3; ++c)
    {
      const auto s = Stokes(gold, i, c);
      if (s[0] < 1e-3)
      {
        continue;
      }
      const double dop = std::sqrt(s[1] * s[1] + s[2] * s[2] + s[3] * s[3]) / s[0];
      worstDop = std::max(worstDop, std::abs(dop - 1.0));
      ellipticity = std::max(ellipticity, std::abs(s[3]) / s[0]);
    }
  }
  EXPECT_LT(worstDop, 1e-3);
  EXPECT_GT(ellipticity, 0.05) << "a metal's phase between s and p makes S3";
}
