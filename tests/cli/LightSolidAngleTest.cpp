// SPDX-License-Identifier: BSD-3-Clause
// The lights' solid angle dw (eq. 1.1, setting light-solid-angle): the
// irradiance is I_L dw, so a white Lambertian sphere lit head-on reaches
// exactly 1 (255 with --display clamp) at dw = pi, and half at pi / 2.
#include "CliTestUtil.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

using shadinglab::testing::RunCli;

namespace
{
/// The brightest green value of a PNG.
int Brightest(const std::string& path)
{
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(reader->GetOutput()->GetPointData()->GetScalars());
  int best = 0;
  for (vtkIdType i = 0; rgb && i < rgb->GetNumberOfTuples(); ++i)
  {
    best = std::max(best, static_cast<int>(rgb->GetComponent(i, 1)));
  }
  return best;
}
} // namespace

TEST(LightSolidAngleTest, IrradianceScalesWithTheSolidAngle)
{
  const std::string common = "render " + std::string(SHADINGLAB_SOURCE_DIR) +
    "/datasets/icosphere_4.vtp --backend cpu --mode phong --model lambert --kd 1 --ks 0 --ambient 0 "
    "--display clamp --light dir:0,0,1 --parallel --size 96x96 ";
  const std::string dir = ::testing::TempDir();
  ASSERT_EQ(RunCli(common + "--out " + dir + "/sl_dw_pi.png").status, 0);
  ASSERT_EQ(RunCli(common + "--light-solid-angle 1.5707963267948966 --out " + dir + "/sl_dw_half.png").status, 0);
  const int full = Brightest(dir + "/sl_dw_pi.png"), half = Brightest(dir + "/sl_dw_half.png");
  EXPECT_EQ(full, 255) << "dw = pi: a unit light on a white Lambertian surface gives 1";
  EXPECT_NEAR(half, 128, 1) << "dw = pi/2: half the irradiance";
  const auto bad = RunCli(common + "--light-solid-angle 20 --out " + dir + "/sl_dw_bad.png");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--light-solid-angle must be in"), std::string::npos) << bad.err;
}
