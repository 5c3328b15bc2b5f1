// SPDX-License-Identifier: BSD-3-Clause
// The CPU renderer's SIMD pixel kernels (plugin/cpu/src/WideShading*.cpp):
// 4 lanes (SSE2) and 8 (AVX2, where the CPU has it) against one pixel at a
// time, the scalar model, for every reflectance model, every light type,
// per-vertex colours, perspective and parallel views.
#include "AnalyticMeshes.h"
#include "PolyDataMesh.h"
#include "RenderTestUtil.h"
#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/model/Materials.h"

#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace sl = shadinglab;
namespace render = shadinglab::render;
using sl::Vec3d;
using sl::Vec3f;

namespace
{

/// The kernels round +, -, *, / and sqrt as the scalar model does (no FMA
/// contraction); only pow, exp and cos are xsimd's instead of libm's, a few
/// float ulps apart. 2e-6 of a pixel's value (about 16 ulps) bounds that
/// through a whole Shade(): measured worst 3.1e-7 over the 96 cases below.
constexpr double kWideRelativeBound = 2e-6;

/// Restores the CPU's own lane count when a test ends.
struct LanesGuard
{
  ~LanesGuard() { sl::cpu::SetPixelLanes(0); }
};

render::Mesh Torus(bool colours)
{
  vtkSmartPointer<vtkPolyData> pd;
  pd.TakeReference(sl::datasets::MakeTorus(1.0, 0.4, 40, 20));
  pd->GetPointData()->SetNormals(pd->GetPointData()->GetArray(sl::datasets::kExactNormalArray));
  render::Mesh mesh = render::MeshFromPolyData(pd);
  if (colours)
  {
    mesh.colors.resize(mesh.points.size());
    for (size_t k = 0; k < mesh.colors.size(); ++k)
    {
      mesh.colors[k] = 0.5f + 0.5f * std::sin(3.0f * mesh.points[k] + static_cast<float>(k % 3));
    }
  }
  return mesh;
}

sl::Lighting<float> Lights(bool local)
{
  sl::Lighting<float> l;
  l.lights[0].vector = Vec3f(0.3f, 0.6f, 0.7f);
  l.lightCount = 1;
  if (local)
  {
    // A point light with attenuation and a spot light whose cone edge
    // crosses the torus.
    l.lights[1].type = sl::LightType::Point;
    l.lights[1].vector = Vec3f(1.5f, 1.0f, 2.0f);
    l.lights[1].attenuation = Vec3f(1.0f, 0.2f, 0.05f);
    l.lights[2].type = sl::LightType::Point;
    l.lights[2].vector = Vec3f(-1.0f, 2.0f, 1.0f);
    l.lights[2].spotDirection = Vec3f(0.5f, -1.0f, -0.5f);
    l.lights[2].coneAngle = 25.0f;
    l.lights[2].coneExponent = 4.0f;
    l.lights[2].intensity = Vec3f(0.8f, 0.6f, 0.4f);
    l.lightCount = 3;
  }
  return l;
}

std::vector<std::pair<std::string, sl::Material<float>>> Materials()
{
  std::vector<std::pair<std::string, sl::Material<float>>> out;
  sl::Material<float> m;
  m.kd = 0.6f;
  m.ks = 0.35f;
  m.shininess = 60.0f;
  for (auto model : { sl::ReflectanceModel::Lambert, sl::ReflectanceModel::Phong,
         sl::ReflectanceModel::BlinnPhong, sl::ReflectanceModel::LommelSeeliger })
  {
    m.model = model;
    out.emplace_back(sl::ReflectanceModelName(model), m);
  }
  m.model = sl::ReflectanceModel::CookTorrance;
  m.lobeCount = 2;
  m.lobes[0] = { 0.25f, 0.2f };
  m.lobes[1] = { 0.75f, 0.5f };
  out.emplace_back("cook-torrance two lobes, dielectric", m);
  m.variant = sl::SpecularVariant::Walter2007;
  m.eta = Vec3f(0.2f, 0.45f, 1.4f); // gold-like conductor
  m.k = Vec3f(3.5f, 2.4f, 1.8f);
  out.emplace_back("cook-torrance two lobes, conductor, Walter", m);
  return out;
}

render::Camera Camera(bool parallel)
{
  render::Camera cam;
  cam.position = Vec3d(0.6, 2.2, 2.6);
  cam.focalPoint = Vec3d(0, 0, 0);
  cam.viewUp = Vec3d(0, 1, 0);
  cam.viewAngle = 40;
  cam.nearClip = 0.1;
  cam.farClip = 100;
  cam.parallel = parallel;
  cam.parallelScale = 1.3;
  return cam;
}

} // namespace

TEST(WideShadingTest, LanesAgreeWithOnePixelAtATime)
{
  LanesGuard guard;
  const int best = sl::cpu::PixelLanes();
  ASSERT_TRUE(best == 4 || best == 8) << best;
  std::vector<int> wide = { 4 };
  if (best == 8)
  {
    wide.push_back(8);
  }
  double worst = 0;
  int cases = 0;
  for (bool colours : { false, true })
  {
    const render::Mesh mesh = Torus(colours);
    for (bool local : { false, true })
    {
      for (bool parallel : { false, true })
      {
        for (const auto& [name, material] : Materials())
        {
          render::RenderOptions opt;
          opt.width = 160;
          opt.height = 120;
          opt.mode = render::ShadingMode::Phong;
          opt.threads = 2;
          const auto lights = Lights(local);
          const auto cam = Camera(parallel);
          sl::cpu::SetPixelLanes(1);
          render::RenderStats oneStats;
          const auto one = sl::test::RenderCpu(mesh, cam, lights, material, opt, &oneStats);
          for (int lanes : wide)
          {
            SCOPED_TRACE(name + (colours ? ", colours" : "") + (local ? ", local lights" : "") +
              (parallel ? ", parallel" : "") + ", lanes " + std::to_string(lanes));
            sl::cpu::SetPixelLanes(lanes);
            ASSERT_EQ(sl::cpu::PixelLanes(), lanes);
            render::RenderStats stats;
            const auto img = sl::test::RenderCpu(mesh, cam, lights, material, opt, &stats);
            EXPECT_EQ(img.covered, one.covered);
            EXPECT_EQ(stats.pixelsShaded, oneStats.pixelsShaded);
            ASSERT_EQ(img.rgb.size(), one.rgb.size());
            double caseWorst = 0;
            for (size_t k = 0; k < img.rgb.size(); ++k)
            {
              ASSERT_TRUE(std::isfinite(img.rgb[k])) << k;
              const double d = std::abs(double(img.rgb[k]) - one.rgb[k]);
              caseWorst = std::max(caseWorst, d / std::max(1.0, std::abs(double(one.rgb[k]))));
            }
            EXPECT_LE(caseWorst, kWideRelativeBound);
            worst = std::max(worst, caseWorst);
            ++cases;
          }
        }
      }
    }
  }
  std::printf("wide kernels: %d cases, worst relative difference %.3g\n", cases, worst);
}

/// The queue is shaded after the depth test, in queue order: where a later
/// triangle covers a pixel again, its colour must win, as when each pixel
/// was shaded in turn. Two coincident-in-screen, differently coloured
/// spheres drawn far-then-near and near-then-far give the near one's colour.
TEST(WideShadingTest, LastFragmentWinsAfterQueuedShading)
{
  LanesGuard guard;
  vtkSmartPointer<vtkPolyData> pd;
  pd.TakeReference(sl::datasets::MakeUVSphere(24, 12));
  render::Mesh sphere = render::MeshFromPolyData(pd);
  // The same sphere twice: far copy red (z - 3), near copy green, far first.
  render::Mesh two;
  const int64_t nv = sphere.NumberOfPoints();
  for (int copy = 0; copy < 2; ++copy)
  {
    for (int64_t v = 0; v < nv; ++v)
    {
      two.points.push_back(sphere.points[3 * v]);
      two.points.push_back(sphere.points[3 * v + 1]);
      two.points.push_back(sphere.points[3 * v + 2] - (copy == 0 ? 3.0f : 0.0f));
      two.colors.push_back(copy == 0 ? 1.0f : 0.0f);
      two.colors.push_back(copy == 0 ? 0.0f : 1.0f);
      two.colors.push_back(0.0f);
    }
  }
  two.offsets.push_back(0);
  for (int copy = 0; copy < 2; ++copy)
  {
    for (int64_t p = 0; p < sphere.NumberOfPolygons(); ++p)
    {
      for (int64_t k = sphere.offsets[p]; k < sphere.offsets[p + 1]; ++k)
      {
        two.connectivity.push_back(sphere.connectivity[k] + copy * nv);
      }
      two.offsets.push_back(static_cast<int64_t>(two.connectivity.size()));
    }
  }
  render::Camera cam = Camera(false);
  cam.position = Vec3d(0, 0, 6);
  render::RenderOptions opt;
  opt.width = 64;
  opt.height = 64;
  opt.mode = render::ShadingMode::Phong;
  opt.threads = 1;
  sl::Material<float> m;
  m.ks = 0.0f;
  for (int lanes : { 1, 4, sl::cpu::PixelLanes() == 8 ? 8 : 4 })
  {
    sl::cpu::SetPixelLanes(lanes);
    const auto img = sl::test::RenderCpu(two, cam, Lights(false), m, opt);
    const size_t centre = 3 * (32 * 64 + 32);
    EXPECT_GT(img.rgb[centre + 1], 0.3f) << "lanes " << lanes;  // green: the near sphere
    EXPECT_LT(img.rgb[centre], 0.1f) << "lanes " << lanes;      // no red from the far one
  }
}
