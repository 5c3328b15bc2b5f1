// SPDX-License-Identifier: BSD-3-Clause
// render::ChooseBackend, the one chooser of the CLI, the explorer, the
// mapper and ParaView, and its parser (the settings table's "backend" row).
#include "shadinglab/render/Backend.h"

#include <gtest/gtest.h>

using namespace shadinglab::render;

namespace
{

BackendFacts Facts(const std::string& glRenderer, long long polygons)
{
  BackendFacts facts;
  facts.glRenderer = glRenderer;
  facts.polygons = polygons;
  return facts;
}

} // namespace

TEST(BackendTest, AutoTakesTheCpuOnlyOnASoftwareRasterizerWithALargeMesh)
{
  const std::string llvmpipe = "llvmpipe (LLVM 15.0.6, 256 bits)";
  EXPECT_EQ(ChooseBackend(Backend::Auto, Facts(llvmpipe, kAutoCpuMinPolygons)).backend, Backend::CPU);
  EXPECT_EQ(ChooseBackend(Backend::Auto, Facts(llvmpipe, kAutoCpuMinPolygons - 1)).backend, Backend::GPU);
  EXPECT_EQ(ChooseBackend(Backend::Auto, Facts("NVIDIA GeForce RTX 4090/PCIe/SSE2", 10000000)).backend,
    Backend::GPU);
  // An unknown renderer is taken as hardware.
  EXPECT_EQ(ChooseBackend(Backend::Auto, Facts("", 10000000)).backend, Backend::GPU);
  const BackendChoice choice = ChooseBackend(Backend::Auto, Facts(llvmpipe, 996000));
  EXPECT_EQ(choice.why,
    "cpu: OpenGL renderer '" + llvmpipe + "' is a software rasterizer, 996000 polygons >= 30000");
  EXPECT_TRUE(choice.conflict.empty());
}

TEST(BackendTest, ExplicitRequestsAreHonouredOrRefusedWithAReason)
{
  const std::string llvmpipe = "llvmpipe";
  EXPECT_EQ(ChooseBackend(Backend::GPU, Facts(llvmpipe, 1 << 24)).backend, Backend::GPU);
  EXPECT_EQ(ChooseBackend(Backend::CPU, Facts("Mesa Intel(R) UHD", 10)).backend, Backend::CPU);
  // No OpenGL: auto falls back and says why; gpu is a conflict.
  BackendFacts none;
  none.glUsable = false;
  none.glProblem = "no DISPLAY";
  BackendChoice choice = ChooseBackend(Backend::Auto, none);
  EXPECT_EQ(choice.backend, Backend::CPU);
  EXPECT_EQ(choice.why, "cpu: no DISPLAY");
  EXPECT_TRUE(choice.conflict.empty());
  choice = ChooseBackend(Backend::GPU, none);
  EXPECT_EQ(choice.backend, Backend::CPU);
  EXPECT_EQ(choice.conflict, "no DISPLAY");
  // A CPU-only feature takes the CPU whatever was asked; asking for the GPU
  // is a conflict a command line refuses.
  BackendFacts polarization = Facts("AMD Radeon", 10);
  polarization.cpuOnly = "a polarization image";
  for (Backend asked : { Backend::GPU, Backend::CPU, Backend::Auto })
  {
    choice = ChooseBackend(asked, polarization);
    EXPECT_EQ(choice.backend, Backend::CPU) << BackendName(asked);
    EXPECT_EQ(choice.conflict.empty(), asked != Backend::GPU) << BackendName(asked);
  }
}

TEST(BackendTest, NamesParseBackAndGlRendererIsReadFromVtksReport)
{
  for (Backend b : { Backend::GPU, Backend::CPU, Backend::Auto })
  {
    Backend parsed = b == Backend::GPU ? Backend::CPU : Backend::GPU;
    EXPECT_EQ(ParseBackend(BackendName(b), parsed), "");
    EXPECT_EQ(parsed, b);
  }
  Backend unchanged = Backend::CPU;
  const std::string problem = ParseBackend("vulkan", unchanged);
  EXPECT_NE(problem.find("--backend"), std::string::npos) << problem;
  EXPECT_NE(problem.find("vulkan"), std::string::npos) << problem;
  EXPECT_EQ(unchanged, Backend::CPU);
  EXPECT_EQ(GlRendererFromReport("OpenGL vendor string:  Mesa\nOpenGL renderer string:  llvmpipe "
                                 "(LLVM 15.0.6, 256 bits)\nOpenGL version string:  4.5"),
    "llvmpipe (LLVM 15.0.6, 256 bits)");
  EXPECT_EQ(GlRendererFromReport(nullptr), "");
  EXPECT_TRUE(IsSoftwareRasterizer("softpipe"));
  EXPECT_FALSE(IsSoftwareRasterizer("Mesa Intel(R) Xe Graphics (TGL GT2)"));
}
