// SPDX-License-Identifier: BSD-3-Clause
// GPU mapper against the CPU renderer: same mesh, camera, lights, material
// and mode; images compared over pixels both cover. Needs an X server with
// OpenGL (label "gl"; scripts/test runs ctest under Xvfb with llvmpipe).
#include "AnalyticMeshes.h"
#include "shadinglab/model/Materials.h"
#include "shadinglab/model/Spectrum.h"
#include "shadinglab/gl/GpuRenderer.h"
#include "PolyDataMesh.h"
#include "shadinglab/cpu/SoftwareRenderer.h"
#include "RenderTestUtil.h"
#include "vtkShadingLabCompositePolyDataMapper.h"
#include "vtkShadingLabPolyDataMapper.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkLight.h>
#include <vtkPoints.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace sl = shadinglab;
namespace render = shadinglab::render;
namespace test = shadinglab::test;

namespace
{

struct Difference
{
  double mean = 0;   // in 1/255 units
  double p99 = 0;    // in 1/255 units
  int64_t pixels = 0;
};

/// Compared as the user sees them: in the display values of the transform
/// the GPU image went through (its shader applies it), Clamp otherwise.
Difference Compare(const render::Image& a, const render::Image& b)
{
  const render::DisplayTransform display = a.displayApplied ? a.appliedDisplay
    : b.displayApplied                                      ? b.appliedDisplay
                                                            : render::DisplayTransform::Clamp;
  const std::vector<uint8_t> a8 = a.ToRGB8(display), b8 = b.ToRGB8(display);
  std::vector<double> d;
  for (size_t p = 0; p < a.covered.size(); ++p)
  {
    if (!a.covered[p] || !b.covered[p])
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      d.push_back(std::abs(double(a8[3 * p + c]) - double(b8[3 * p + c])));
    }
  }
  Difference r;
  r.pixels = static_cast<int64_t>(d.size() / 3);
  if (d.empty())
  {
    return r;
  }
  double sum = 0;
  for (double v : d)
  {
    sum += v;
  }
  r.mean = sum / d.size();
  std::sort(d.begin(), d.end());
  r.p99 = d[static_cast<size_t>(0.99 * (d.size() - 1))];
  return r;
}

// scripts/test always provides an X server and sets SHADINGLAB_REQUIRE_GL:
// there a missing GL is a failure, not a skip. Run by hand without X, the
// tests skip with the reason.
bool HaveGpu()
{
  std::string why;
  if (!sl::gl::GpuAvailable(why))
  {
    if (std::getenv("SHADINGLAB_REQUIRE_GL"))
    {
      ADD_FAILURE() << "OpenGL required but unavailable: " << why;
    }
    std::printf("GPU unavailable: %s\n", why.c_str());
    return false;
  }
  return true;
}

render::Camera Camera(bool parallel = false)
{
  render::Camera cam;
  cam.position = { 0.6, 1.1, 3.4 };
  cam.focalPoint = { 0, 0, 0 };
  cam.viewUp = { 0, 1, 0 };
  cam.viewAngle = 40;
  cam.nearClip = 1.0;
  cam.farClip = 8.0;
  cam.parallel = parallel;
  cam.parallelScale = 1.3;
  return cam;
}

sl::Lighting<double> Lights(bool withPoint)
{
  sl::Lighting<double> l;
  l.lightCount = 1;
  l.lights[0].vector = { -0.4, 0.6, 1.0 };
  l.lights[0].intensity = { 0.9, 0.85, 0.8 };
  if (withPoint)
  {
    l.lightCount = 2;
    l.lights[1].type = sl::LightType::Point;
    l.lights[1].vector = { 2.0, -1.0, 2.5 };
    l.lights[1].intensity = { 0.6, 0.6, 0.9 };
    l.lights[1].attenuation = { 1.0, 0.1, 0.02 };
  }
  l.ambientIntensity = { 1, 1, 1 };
  return l;
}

sl::Material<double> BlinnPhong()
{
  sl::Material<double> m;
  m.model = sl::ReflectanceModel::BlinnPhong;
  m.kd = 0.7;
  m.ks = 0.3;
  m.shininess = 24;
  m.diffuseColor = { 0.9, 0.8, 0.7 };
  return m;
}

vtkSmartPointer<vtkPolyData> WithExactNormals(vtkPolyData* raw)
{
  vtkSmartPointer<vtkPolyData> pd;
  pd.TakeReference(raw);
  pd->GetPointData()->SetNormals(pd->GetPointData()->GetArray(sl::datasets::kExactNormalArray));
  return pd;
}

/// One frame of a fresh GL renderer, through the render::Renderer interface.
render::Image RenderGpu(vtkPolyData* pd, const render::Camera& camera,
  const sl::Lighting<double>& lighting, const sl::Material<double>& material,
  const render::RenderOptions& options, int* shaderBuilds = nullptr)
{
  const render::Mesh mesh = render::MeshFromPolyData(pd);
  sl::gl::GpuRenderer renderer;
  render::RenderStats stats;
  auto image = test::RenderWith(renderer, mesh, camera, lighting, material, options, &stats);
  if (shaderBuilds)
  {
    *shaderBuilds = stats.shaderBuilds;
  }
  return image;
}

// Thresholds (in 1/255): mean over covered pixels and 99th percentile.
// llvmpipe evaluates the same float formulas, so most pixels agree to the
// 8-bit rounding; the tail comes from pixels on triangle edges where the two
// rasterizers' attribute interpolation differs in the last bits and from
// highlight pixels where pow() amplifies that.
constexpr double kMeanThreshold = 1.0;
constexpr double kP99Threshold = 4.0;

} // namespace

/// The reflectance models of the parity table, each a named material.
std::vector<std::pair<std::string, sl::Material<double>>> ParityMaterials()
{
  std::vector<std::pair<std::string, sl::Material<double>>> out;
  auto m = BlinnPhong();
  m.model = sl::ReflectanceModel::Lambert;
  out.emplace_back("lambert", m);
  m.model = sl::ReflectanceModel::Phong;
  out.emplace_back("phong", m);
  m.model = sl::ReflectanceModel::BlinnPhong;
  out.emplace_back("blinn-phong", m);
  m.model = sl::ReflectanceModel::CookTorrance;
  m.lobeCount = 1;
  m.lobes[0] = { 1.0, 0.3 };
  m.eta = { 1.5, 1.5, 1.5 };
  out.emplace_back("ct-dielectric", m);
  m.lobeCount = 2;
  m.lobes[0] = { 0.6, 0.2 };
  m.lobes[1] = { 0.4, 0.5 };
  m.eta = { 0.14, 0.43, 1.38 };
  m.k = { 3.7, 2.45, 1.9 };
  m.variant = sl::SpecularVariant::Walter2007;
  out.emplace_back("ct-conductor", m);
  // Fresnel per wavelength (eq. 7.3): measured gold and N-BK7 glass.
  for (const char* preset : { "gold", "glass" })
  {
    sl::Material<double> spectral = sl::FindMaterialPreset(preset)->material;
    spectral.kd = 0.2;
    spectral.ks = 0.8;
    EXPECT_EQ(sl::SetSpectral(spectral, *sl::PresetDispersion(preset)), "");
    out.emplace_back(std::string("ct-spectral-") + preset, spectral);
  }
  return out;
}

TEST(GpuParityGLTest, EveryModeTimesModelBothInterpolationSpaces)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  auto torus = WithExactNormals(sl::datasets::MakeTorus(1.0, 0.4, 48, 24));
  auto sphere = WithExactNormals(sl::datasets::MakeIcosphere(3));
  // Irregular meshes as a user brings them: non-uniform triangle sizes and
  // valences (a noisy decimated surface; a marching-cubes isosurface).
  vtkSmartPointer<vtkPolyData> irregular, blobs;
  irregular.TakeReference(sl::datasets::MakeNoisyDecimatedSphere(5, 0.08, 0.15));
  blobs.TakeReference(sl::datasets::MakeMetaballIsosurface(40));
  struct Case
  {
    const char* name;
    vtkPolyData* pd;
    int width, height;
  };
  const Case cases[] = { { "torus", torus, 320, 240 }, { "icosphere", sphere, 320, 240 },
    { "noisy-decimated", irregular, 640, 480 }, { "metaballs", blobs, 640, 480 } };
  sl::gl::GpuRenderer gpuRenderer;
  sl::cpu::SoftwareRenderer cpuRenderer;
  std::printf("%-16s %-11s %-14s %-12s %8s %8s %8s\n", "mesh", "mode", "model", "interp",
    "mean", "p99", "pixels");
  for (const auto& c : cases)
  {
    const render::Mesh mesh = render::MeshFromPolyData(c.pd);
    double bounds[6];
    mesh.Bounds(bounds);
    const render::Camera camera = c.pd == torus.Get() || c.pd == sphere.Get()
      ? Camera()
      : render::FitCamera(bounds, 20, 15, 1.0, static_cast<double>(c.width) / c.height, false);
    for (const auto& [modelName, material] : ParityMaterials())
    {
      for (const auto& mode : render::kShadingModes)
      {
        for (bool perspective : { true, false })
        {
          render::RenderOptions opt;
          opt.width = c.width;
          opt.height = c.height;
          opt.mode = mode.value;
          opt.interpolation =
            perspective ? render::InterpolationSpace::Perspective : render::InterpolationSpace::Screen;
          // Like with like: the GPU draws fast Phong's quadratics at any
          // triangle size, so the CPU must not switch to exact Phong here.
          opt.fastPhongFallback = false;
          const auto lights = Lights(true);
          if (!render::SupportsModel(mode.value, material.model))
          {
            // No quadratic form: both backends refuse with the same error.
            EXPECT_THROW(test::RenderWith(gpuRenderer, mesh, camera, lights, material, opt),
              std::invalid_argument);
            EXPECT_THROW(test::RenderWith(cpuRenderer, mesh, camera, lights, material, opt),
              std::invalid_argument);
            continue;
          }
          const auto gpu = test::RenderWith(gpuRenderer, mesh, camera, lights, material, opt);
          const auto ref = test::RenderWith(cpuRenderer, mesh, camera, lights, material, opt);
          const auto d = Compare(ref, gpu);
          std::printf("%-16s %-11s %-14s %-12s %8.3f %8.3f %8lld\n", c.name, mode.name,
            modelName.c_str(), perspective ? "perspective" : "screen", d.mean, d.p99,
            static_cast<long long>(d.pixels));
          EXPECT_GT(d.pixels, 5000);
          EXPECT_LE(d.mean, kMeanThreshold) << c.name << " " << mode.name << " " << modelName;
          EXPECT_LE(d.p99, kP99Threshold) << c.name << " " << mode.name << " " << modelName;
        }
      }
    }
  }
  // Flat mode drew from a copy without point normals: the inputs keep theirs.
  EXPECT_NE(torus->GetPointData()->GetNormals(), nullptr);
  EXPECT_NE(sphere->GetPointData()->GetNormals(), nullptr);
}

namespace
{
/// A dielectric and a spectral conductor for the polarization tests: glass
/// with a diffuse part (depolarized) and gold from its measured n, k.
std::pair<sl::Material<double>, sl::Material<double>> PolarizationMaterials()
{
  sl::Material<double> glass = sl::FindMaterialPreset("glass")->material;
  glass.kd = 0.3;
  glass.ks = 0.7;
  sl::Material<double> gold = sl::FindMaterialPreset("gold")->material;
  if (!sl::SetSpectral(gold, *sl::PresetDispersion("gold")).empty())
  {
    throw std::runtime_error("gold's measured dispersion does not load");
  }
  return { glass, gold };
}
} // namespace

// An analyser in front of the camera (--polarizer, docs/model.md section 8):
// the GPU draws what the CPU draws at every angle, for every smooth mode and
// spectral too; and the CPU's linear frames obey Malus's law, I(0) + I(90)
// = I(45) + I(135) = the frame without an analyser.
TEST(GpuParityGLTest, PolarizerMatchesTheCpuAndObeysMalus)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  const render::Mesh mesh =
    render::MeshFromPolyData(WithExactNormals(sl::datasets::MakeTorus(1.0, 0.4, 48, 24)));
  const auto [glass, gold] = PolarizationMaterials();
  sl::gl::GpuRenderer gpuRenderer;
  sl::cpu::SoftwareRenderer cpuRenderer;
  const auto lights = Lights(true);
  for (const auto& [name, material] : { std::make_pair("glass", glass), std::make_pair("spectral gold", gold) })
  {
    for (render::ShadingMode mode : { render::ShadingMode::Gouraud, render::ShadingMode::Phong })
    {
      render::RenderOptions opt;
      opt.width = 320;
      opt.height = 240;
      opt.mode = mode;
      const auto none = test::RenderWith(cpuRenderer, mesh, Camera(), lights, material, opt);
      std::vector<render::Image> analysed;
      for (double deg : { 0.0, 45.0, 90.0, 135.0 })
      {
        opt.polarizer = deg;
        const auto gpu = test::RenderWith(gpuRenderer, mesh, Camera(), lights, material, opt);
        analysed.push_back(test::RenderWith(cpuRenderer, mesh, Camera(), lights, material, opt));
        const auto d = Compare(analysed.back(), gpu);
        std::printf("polarizer %-13s %-8s %5.0f deg: mean %.3f p99 %.3f over %lld pixels\n", name,
          render::ShadingModeName(mode), deg, d.mean, d.p99, static_cast<long long>(d.pixels));
        EXPECT_GT(d.pixels, 5000);
        EXPECT_LE(d.mean, kMeanThreshold) << name << " " << deg;
        EXPECT_LE(d.p99, kP99Threshold) << name << " " << deg;
      }
      double worst = 0, angleMatters = 0, peak = 0;
      for (size_t i = 0; i < none.rgb.size(); ++i)
      {
        if (!none.covered[i / 3])
        {
          continue;
        }
        const double sum0 = analysed[0].rgb[i] + analysed[2].rgb[i];
        const double sum45 = analysed[1].rgb[i] + analysed[3].rgb[i];
        worst = std::max({ worst, std::abs(sum0 - none.rgb[i]), std::abs(sum45 - none.rgb[i]) });
        angleMatters = std::max(angleMatters, std::abs(double(analysed[0].rgb[i]) - analysed[2].rgb[i]));
        peak = std::max(peak, static_cast<double>(none.rgb[i]));
      }
      std::printf("Malus %s %s: |I0 + I90 - I|, |I45 + I135 - I| <= %.2e (peak %.3f); "
                  "|I0 - I90| up to %.3f\n",
        name, render::ShadingModeName(mode), worst, peak, angleMatters);
      EXPECT_LE(worst, 1e-5 * std::max(1.0, peak)) << name;
      EXPECT_GT(angleMatters, 0.01) << name << ": the analyser's angle changes the picture";
    }
  }
}

// A polarizer in front of the lights (--light-polarizer, docs/model.md eq.
// 8.6), alone and with a linear or circular analyser: the GPU draws what
// the CPU draws, for a dielectric and a spectral conductor, with lights
// from the side and a headlight (where the plane of incidence is undefined).
TEST(GpuParityGLTest, LightPolarizerMatchesTheCpu)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  const render::Mesh mesh =
    render::MeshFromPolyData(WithExactNormals(sl::datasets::MakeTorus(1.0, 0.4, 48, 24)));
  const auto [glass, gold] = PolarizationMaterials();
  sl::Lighting<double> headlight;
  headlight.lightCount = 1;
  headlight.lights[0].vector = Camera().position;
  headlight.lights[0].intensity = { 1, 1, 1 };
  headlight.ambientIntensity = { 1, 1, 1 };
  sl::gl::GpuRenderer gpuRenderer;
  sl::cpu::SoftwareRenderer cpuRenderer;
  struct Analysis
  {
    const char* name;
    double polarizer;
    bool circular;
  };
  const Analysis analyses[] = { { "none", -1, false }, { "linear 90", 90, false },
    { "linear 30", 30, false }, { "circular", 0, true } };
  for (const auto& [name, material] :
    { std::make_pair("glass", glass), std::make_pair("spectral gold", gold) })
  {
    for (const auto& [lightsName, lights] :
      { std::make_pair("side", Lights(true)), std::make_pair("headlight", headlight) })
    {
      for (render::ShadingMode mode : { render::ShadingMode::Gouraud, render::ShadingMode::Phong })
      {
        std::vector<render::Image> drawn; // GPU, by light polarizer then analysis
        for (double lightPolarizer : { 0.0, 60.0 })
        {
          for (const Analysis& a : analyses)
          {
            render::RenderOptions opt;
            opt.width = 320;
            opt.height = 240;
            opt.mode = mode;
            opt.lightPolarizer = lightPolarizer;
            opt.polarizer = a.polarizer;
            opt.circularAnalyser = a.circular;
            const auto gpu = test::RenderWith(gpuRenderer, mesh, Camera(), lights, material, opt);
            const auto cpu = test::RenderWith(cpuRenderer, mesh, Camera(), lights, material, opt);
            const auto d = Compare(cpu, gpu);
            std::printf("light polarizer %3.0f %-13s %-9s %-7s analyser %-9s: mean %.3f p99 %.3f "
                        "over %lld pixels\n",
              lightPolarizer, name, lightsName, render::ShadingModeName(mode), a.name, d.mean, d.p99,
              static_cast<long long>(d.pixels));
            EXPECT_GT(d.pixels, 5000);
            EXPECT_LE(d.mean, kMeanThreshold) << name << " " << lightsName << " " << a.name;
            EXPECT_LE(d.p99, kP99Threshold) << name << " " << lightsName << " " << a.name;
            drawn.push_back(gpu);
          }
        }
        // The GPU turns both polarizers: the analyser's angle and the
        // lights' polarizer each change the picture.
        auto largest = [](const render::Image& a, const render::Image& b) {
          double m = 0;
          for (size_t i = 0; i < a.rgb.size(); ++i)
          {
            m = std::max(m, std::abs(double(a.rgb[i]) - b.rgb[i]));
          }
          return m;
        };
        EXPECT_GT(largest(drawn[1], drawn[2]), 0.01) << name << " " << lightsName << ": analyser";
        EXPECT_GT(largest(drawn[1], drawn[5]), 0.01) << name << " " << lightsName << ": light";
      }
    }
  }
}

namespace
{
/// Linear image read back from a render window (rows top-down).
render::Image Grab(vtkRenderWindow* window)
{
  int* size = window->GetSize();
  const int W = size[0], H = size[1];
  unsigned char* pixels = window->GetPixelData(0, 0, W - 1, H - 1, 0, 0);
  std::vector<unsigned char> rgb(pixels, pixels + static_cast<size_t>(W) * H * 3);
  delete[] pixels;
  std::vector<float> z(static_cast<size_t>(W) * H);
  window->GetZbufferData(0, 0, W - 1, H - 1, z.data());
  render::Image image;
  image.width = W;
  image.height = H;
  image.rgb.resize(rgb.size());
  image.covered.resize(z.size());
  for (int y = 0; y < H; ++y)
  {
    for (int x = 0; x < W; ++x)
    {
      const size_t src = static_cast<size_t>(H - 1 - y) * W + x, dst = static_cast<size_t>(y) * W + x;
      for (int c = 0; c < 3; ++c)
      {
        image.rgb[3 * dst + c] = rgb[3 * src + c] / 255.0f;
      }
      image.covered[dst] = z[src] < 1.0f;
    }
  }
  // The mapper's shader applied its (default) display transform.
  image.displayApplied = true;
  image.appliedDisplay = render::RenderOptions().display;
  return image;
}

/// An offscreen window (no multisampling, as the CPU renderer) showing `ren`,
/// rendered once.
vtkSmartPointer<vtkRenderWindow> RenderOffscreen(vtkRenderer* ren, int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  window->AddRenderer(ren);
  window->Render();
  return window;
}

/// The renderer's one light: a directional scene light from (x, y, z)
/// towards the origin (no automatic light). The renderer owns it.
vtkLight* AddDirectionalLight(vtkRenderer* ren, double x, double y, double z)
{
  ren->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(false);
  light->SetPosition(x, y, z);
  light->SetFocalPoint(0, 0, 0);
  ren->AddLight(light);
  return light;
}

void SetCamera(vtkRenderer* ren, const render::Camera& c)
{
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(c.position.x, c.position.y, c.position.z);
  cam->SetFocalPoint(c.focalPoint.x, c.focalPoint.y, c.focalPoint.z);
  cam->SetViewUp(c.viewUp.x, c.viewUp.y, c.viewUp.z);
  cam->SetViewAngle(c.viewAngle);
  cam->SetClippingRange(c.nearClip, c.farClip);
}
} // namespace

TEST(GpuParityGLTest, ScreenSpaceInterpolationMatchesTheCpu)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  // A floor receding from the camera whose vertex normals tilt differently
  // at the near and far edges: Gouraud intensities vary along depth, and
  // screen-linear interpolation visibly differs from perspective-correct.
  auto floor = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  // x = +-0.5 keeps the quad inside the side planes: no GPU clipping.
  for (const auto& p : { std::array<double, 3>{ -0.5, -1, -2 }, { 0.5, -1, -2 }, { 0.5, -1, -12 }, { -0.5, -1, -12 } })
  {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType quad[4] = { 0, 1, 2, 3 };
  polys->InsertNextCell(4, quad);
  floor->SetPoints(points);
  floor->SetPolys(polys);
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  const float near[3] = { 0.0f, 0.2f, 0.98f }, far[3] = { 0.0f, 0.98f, 0.2f };
  for (const float* n : { near, near, far, far })
  {
    normals->InsertNextTuple(n);
  }
  floor->GetPointData()->SetNormals(normals);
  const render::Mesh mesh = render::MeshFromPolyData(floor);
  render::Camera cam;
  cam.position = { 0, 0, 0 };
  cam.focalPoint = { 0, 0, -1 };
  cam.viewAngle = 60;
  cam.nearClip = 0.5;
  cam.farClip = 20;
  sl::Lighting<double> lights;
  lights.lightCount = 1;
  lights.lights[0].vector = { 0, 0, 1 };
  sl::Material<double> m = BlinnPhong();
  m.ks = 0.0;
  m.kd = 1.0;
  render::RenderOptions opt;
  opt.width = 200;
  opt.height = 300;
  opt.mode = render::ShadingMode::Gouraud;
  render::Image gpu[2], ref[2];
  for (int i = 0; i < 2; ++i)
  {
    opt.interpolation = i == 0 ? render::InterpolationSpace::Perspective : render::InterpolationSpace::Screen;
    gpu[i] = RenderGpu(floor, cam, lights, m, opt);
    ref[i] = test::RenderCpu(mesh, cam, lights.Cast<float>(), m.Cast<float>(), opt);
    const auto d = Compare(ref[i], gpu[i]);
    EXPECT_LE(d.mean, kMeanThreshold) << i;
    EXPECT_LE(d.p99, kP99Threshold) << i;
  }
  const auto between = Compare(gpu[0], gpu[1]);
  std::printf("GPU perspective vs screen: mean %.2f/255, p99 %.0f/255\n", between.mean, between.p99);
  EXPECT_GT(between.mean, 5.0); // the distortion is there, on the GPU too
}

TEST(GpuParityGLTest, MeshesWithoutNormalsAndWithCellNormals)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  // No point normals: both compute area-weighted vertex normals.
  vtkSmartPointer<vtkPolyData> bare;
  bare.TakeReference(sl::datasets::MakeUVSphere(24, 12));
  render::RenderOptions opt;
  opt.width = 240;
  opt.height = 180;
  for (auto mode : { render::ShadingMode::Gouraud, render::ShadingMode::Phong })
  {
    opt.mode = mode;
    const auto gpu = RenderGpu(bare, Camera(), Lights(false), BlinnPhong(), opt);
    const auto ref = test::RenderCpu(render::MeshFromPolyData(bare), Camera(), Lights(false).Cast<float>(),
      BlinnPhong().Cast<float>(), opt);
    const auto d = Compare(ref, gpu);
    EXPECT_LE(d.mean, kMeanThreshold) << render::ShadingModeName(mode);
    EXPECT_LE(d.p99, kP99Threshold) << render::ShadingModeName(mode);
  }
  // The mapper computed normals on a copy: the input still has none.
  EXPECT_EQ(bare->GetPointData()->GetNormals(), nullptr);
  // Cell normals drive flat mode on both (here: normals of a coarser
  // faceting than the geometry, so using them is visible).
  vtkNew<vtkPolyDataNormals> cellNormals;
  cellNormals->SetInputData(bare);
  cellNormals->ComputeCellNormalsOn();
  cellNormals->ComputePointNormalsOff();
  cellNormals->SplittingOff();
  cellNormals->Update();
  vtkPolyData* withCells = cellNormals->GetOutput();
  ASSERT_NE(withCells->GetCellData()->GetNormals(), nullptr);
  opt.mode = render::ShadingMode::Flat;
  const auto gpu = RenderGpu(withCells, Camera(), Lights(false), BlinnPhong(), opt);
  const auto ref = test::RenderCpu(render::MeshFromPolyData(withCells), Camera(), Lights(false).Cast<float>(),
    BlinnPhong().Cast<float>(), opt);
  const auto d = Compare(ref, gpu);
  EXPECT_LE(d.mean, kMeanThreshold);
  EXPECT_LE(d.p99, kP99Threshold);
}

TEST(GpuParityGLTest, HeadlightAndCameraLight)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  auto torus = WithExactNormals(sl::datasets::MakeTorus(1.0, 0.4, 48, 24));
  const render::Camera cam = Camera();
  // Both lights shine from the camera: a directional light towards the eye.
  sl::Lighting<double> equivalent;
  equivalent.lightCount = 1;
  equivalent.lights[0].vector = cam.position - cam.focalPoint;
  render::RenderOptions opt;
  opt.width = 240;
  opt.height = 180;
  const auto ref = test::RenderCpu(render::MeshFromPolyData(torus), cam, equivalent.Cast<float>(),
    BlinnPhong().Cast<float>(), opt);
  for (int kind = 0; kind < 2; ++kind)
  {
    vtkNew<vtkShadingLabPolyDataMapper> mapper;
    mapper->SetInputData(torus);
    mapper->SetMaterial(BlinnPhong());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetDiffuseColor(0.9, 0.8, 0.7);
    vtkNew<vtkRenderer> ren;
    ren->AddActor(actor);
    ren->SetBackground(0.32, 0.34, 0.43);
    vtkNew<vtkLight> light;
    if (kind == 0)
    {
      light->SetLightTypeToHeadlight();
    }
    else
    {
      light->SetLightTypeToCameraLight();
      light->SetPosition(0, 0, 1); // camera coordinates: along the view axis
      light->SetFocalPoint(0, 0, 0);
    }
    ren->AddLight(light);
    SetCamera(ren, cam);
    auto window = RenderOffscreen(ren, opt.width, opt.height);
    const auto d = Compare(ref, Grab(window));
    EXPECT_GT(d.pixels, 5000);
    EXPECT_LE(d.mean, kMeanThreshold) << (kind == 0 ? "headlight" : "camera light");
    EXPECT_LE(d.p99, kP99Threshold) << (kind == 0 ? "headlight" : "camera light");
  }
}

TEST(GpuParityGLTest, SpotLight)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  auto torus = WithExactNormals(sl::datasets::MakeTorus(1.0, 0.4, 96, 48));
  sl::Lighting<double> lights;
  lights.lightCount = 1;
  auto& spot = lights.lights[0];
  spot.type = sl::LightType::Point;
  spot.vector = { 0.5, 1.5, 2.5 };
  spot.spotDirection = sl::Vec3d(0, 0, 0) - spot.vector;
  spot.coneAngle = 20;
  spot.coneExponent = 2;
  spot.intensity = { 2, 2, 2 };
  render::RenderOptions opt;
  opt.width = 320;
  opt.height = 240;
  opt.mode = render::ShadingMode::Phong;
  const auto gpu = RenderGpu(torus, Camera(), lights, BlinnPhong(), opt);
  const auto ref = test::RenderCpu(render::MeshFromPolyData(torus), Camera(), lights.Cast<float>(),
    BlinnPhong().Cast<float>(), opt);
  const auto d = Compare(ref, gpu);
  EXPECT_LE(d.mean, kMeanThreshold);
  EXPECT_LE(d.p99, kP99Threshold);
  // The cone really cuts: some covered pixels get ambient light only.
  int dark = 0, lit = 0;
  for (size_t p = 0; p < ref.covered.size(); ++p)
  {
    if (ref.covered[p])
    {
      (ref.rgb[3 * p] < 0.06f ? dark : lit) += 1;
    }
  }
  EXPECT_GT(dark, 1000);
  EXPECT_GT(lit, 1000);
}

TEST(GpuParityGLTest, MultiblockInput)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  auto a = WithExactNormals(sl::datasets::MakeIcosphere(3));
  auto b = WithExactNormals(sl::datasets::MakeTorus(1.0, 0.4, 48, 24));
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, a);
  blocks->SetBlock(1, b);
  vtkNew<vtkShadingLabCompositePolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  sl::render::Settings settings = mapper->GetSettings();
  settings.render.mode = sl::render::ShadingMode::Gouraud;
  mapper->SetSettings(settings);
  mapper->SetMaterial(BlinnPhong());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetDiffuseColor(0.9, 0.8, 0.7);
  vtkNew<vtkRenderer> ren;
  ren->AddActor(actor);
  ren->SetBackground(0.32, 0.34, 0.43);
  AddDirectionalLight(ren, -0.4, 0.6, 1.0);
  SetCamera(ren, Camera());
  auto window = RenderOffscreen(ren, 240, 180);
  EXPECT_GE(mapper->GetShaderBuildCount(), 1);
  // The CPU reference: both blocks as one mesh.
  render::Mesh both = render::MeshFromPolyData(a);
  const render::Mesh second = render::MeshFromPolyData(b);
  const int64_t offset = both.NumberOfPoints();
  both.points.insert(both.points.end(), second.points.begin(), second.points.end());
  both.normals.insert(both.normals.end(), second.normals.begin(), second.normals.end());
  const int64_t base = both.connectivity.size();
  for (int64_t v : second.connectivity)
  {
    both.connectivity.push_back(v + offset);
  }
  for (size_t i = 1; i < second.offsets.size(); ++i)
  {
    both.offsets.push_back(second.offsets[i] + base);
  }
  sl::Lighting<double> lights;
  lights.lightCount = 1;
  lights.lights[0].vector = { -0.4, 0.6, 1.0 };
  render::RenderOptions opt;
  opt.width = 240;
  opt.height = 180;
  opt.mode = render::ShadingMode::Gouraud;
  const auto ref = test::RenderCpu(both, Camera(), lights.Cast<float>(), BlinnPhong().Cast<float>(), opt);
  const auto d = Compare(ref, Grab(window));
  EXPECT_GT(d.pixels, 8000);
  EXPECT_LE(d.mean, kMeanThreshold);
  EXPECT_LE(d.p99, kP99Threshold);
}

TEST(GpuParityGLTest, ShadersRebuildOnlyForVariantChanges)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  auto torus = WithExactNormals(sl::datasets::MakeTorus(1.0, 0.4, 24, 12));
  vtkNew<vtkShadingLabPolyDataMapper> mapper;
  mapper->SetInputData(torus);
  auto material = BlinnPhong();
  mapper->SetMaterial(material);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> ren;
  ren->AddActor(actor);
  AddDirectionalLight(ren, 0.0, 0.0, 1.0);
  SetCamera(ren, Camera());
  auto window = RenderOffscreen(ren, 64, 48);
  EXPECT_EQ(mapper->GetFailedSubstitutionCount(), 0);
  const int first = mapper->GetShaderBuildCount();
  EXPECT_GE(first, 1);
  const int uploads = mapper->GetUniformUploadCount();
  window->Render(); // nothing changed: no rebuild, no upload
  EXPECT_EQ(mapper->GetShaderBuildCount(), first);
  EXPECT_EQ(mapper->GetUniformUploadCount(), uploads);
  material.shininess = 64; // uniform only
  mapper->SetMaterial(material);
  window->Render();
  EXPECT_EQ(mapper->GetShaderBuildCount(), first);
  EXPECT_GT(mapper->GetUniformUploadCount(), uploads);
  mapper->SetSetting("mode", "gouraud"); // variant
  window->Render();
  const int afterMode = mapper->GetShaderBuildCount();
  EXPECT_GT(afterMode, first);
  material.ks = 0.0; // specular off: variant
  mapper->SetMaterial(material);
  window->Render();
  const int afterSpecular = mapper->GetShaderBuildCount();
  EXPECT_GT(afterSpecular, afterMode);
  vtkNew<vtkLight> second; // light count: variant
  second->SetLightTypeToSceneLight();
  ren->AddLight(second);
  window->Render();
  const int afterLight = mapper->GetShaderBuildCount();
  EXPECT_GT(afterLight, afterSpecular);
  mapper->SetSetting("interp", "screen"); // interpolation space: variant
  window->Render();
  EXPECT_GT(mapper->GetShaderBuildCount(), afterLight);
  const int settled = mapper->GetShaderBuildCount();
  window->Render();
  window->Render();
  EXPECT_EQ(mapper->GetShaderBuildCount(), settled);
  EXPECT_EQ(mapper->GetFailedSubstitutionCount(), 0);
  std::printf("shader builds over the sequence: %d (variants: %s)\n", settled,
    mapper->GetLastVariant().c_str());
}

TEST(GpuParityGLTest, AutoChoiceFollowsTheLightsAndTheCamera)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  auto sphere = WithExactNormals(sl::datasets::MakeIcosphere(2));
  vtkNew<vtkShadingLabPolyDataMapper> mapper;
  mapper->SetInputData(sphere);
  mapper->SetMaterial(BlinnPhong());
  mapper->SetSetting("mode", "auto");
  mapper->SetSetting("max-error", "1");
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> ren;
  ren->AddActor(actor);
  vtkLight* light = AddDirectionalLight(ren, -0.4, 0.6, 1.0);
  SetCamera(ren, Camera());
  auto window = RenderOffscreen(ren, 240, 180);
  const std::string lit = mapper->GetAutoChoice();
  ASSERT_FALSE(lit.empty());
  window->Render();
  EXPECT_EQ(mapper->GetAutoChoice(), lit); // nothing changed
  // The light behind the sphere: the distances between modes (eq. 4.4)
  // are measured under it, so the reasons change (a choice cached on the
  // old light, or a light without its direction, would not).
  light->SetPosition(0.4, -0.6, -1.0);
  window->Render();
  const std::string behind = mapper->GetAutoChoice();
  EXPECT_NE(behind, lit);
  // A closer camera: larger triangles on the screen.
  ren->GetActiveCamera()->Zoom(2.0);
  window->Render();
  EXPECT_NE(mapper->GetAutoChoice(), behind);
}

TEST(GpuParityGLTest, TranslucentActorsAreDrawn)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  // An actor with opacity 0.4 goes through VTK's translucent pass: it must
  // be drawn (plain and composite mapper), blended with the background.
  auto torus = WithExactNormals(sl::datasets::MakeTorus(1.0, 0.4, 48, 24));
  for (bool composite : { false, true })
  {
    vtkSmartPointer<vtkMapper> mapper;
    if (composite)
    {
      auto m = vtkSmartPointer<vtkShadingLabCompositePolyDataMapper>::New();
      m->SetInputDataObject(torus);
      m->SetMaterial(BlinnPhong());
      mapper = m;
    }
    else
    {
      auto m = vtkSmartPointer<vtkShadingLabPolyDataMapper>::New();
      m->SetInputData(torus);
      m->SetMaterial(BlinnPhong());
      mapper = m;
    }
    double means[2];
    for (int pass = 0; pass < 2; ++pass)
    {
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->GetProperty()->SetOpacity(pass == 0 ? 1.0 : 0.4);
      vtkNew<vtkRenderer> ren;
      ren->AddActor(actor);
      ren->SetBackground(0.0, 0.0, 0.0);
      SetCamera(ren, Camera());
      auto window = RenderOffscreen(ren, 160, 120);
      const auto image = Grab(window);
      double sum = 0;
      for (float v : image.rgb)
      {
        sum += v;
      }
      means[pass] = sum / image.rgb.size();
    }
    EXPECT_GT(means[1], 0.05 * means[0]) << (composite ? "composite" : "plain") << " translucent not drawn";
    EXPECT_LT(means[1], 0.9 * means[0]) << (composite ? "composite" : "plain") << " not blended";
  }
}

TEST(GpuParityGLTest, ColourByPointAndCellDataBothBackends)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  // The Renderer interface on both backends with a colour map: point
  // scalars interpolated then mapped (every mode), cell scalars per polygon.
  const auto sphere = WithExactNormals(sl::datasets::MakeUVSphere(32, 16));
  render::Mesh mesh = render::MeshFromPolyData(sphere);
  for (int64_t v = 0; v < mesh.NumberOfPoints(); ++v)
  {
    mesh.scalars.push_back(mesh.points[3 * v + 1] + 0.5f * mesh.points[3 * v]);
  }
  render::Mesh cells = mesh;
  cells.scalars.clear();
  for (int64_t p = 0; p < cells.NumberOfPolygons(); ++p)
  {
    cells.cellScalars.push_back(static_cast<float>(p % 7));
  }
  render::ColorMap map;
  ASSERT_TRUE(render::FindColorMap("Cool to Warm", map));
  map.rangeMin = -1.2;
  map.rangeMax = 1.2;
  render::ColorMap cellMap;
  ASSERT_TRUE(render::FindColorMap("viridis", cellMap));
  cellMap.rangeMin = 0;
  cellMap.rangeMax = 6;
  sl::cpu::SoftwareRenderer cpuRenderer;
  sl::gl::GpuRenderer gpuRenderer;
  render::RenderOptions opt;
  opt.width = 240;
  opt.height = 180;
  opt.fastPhongFallback = false; // fast Phong itself on both backends
  for (const auto& [colored, colorMap] : { std::pair{ &mesh, &map }, std::pair{ &cells, &cellMap } })
  {
    for (auto mode : { render::ShadingMode::Flat, render::ShadingMode::Gouraud,
           render::ShadingMode::Phong, render::ShadingMode::FastPhong })
    {
      opt.mode = mode;
      render::Scene scene{ colored, Camera(), Lights(false), BlinnPhong(), colorMap };
      const render::Image ref = cpuRenderer.Render(scene, opt);
      const render::Image gpu = gpuRenderer.Render(scene, opt);
      const auto d = Compare(ref, gpu);
      const std::string what = std::string(render::ShadingModeName(mode)) +
        (colored == &mesh ? " by point data" : " by cell data");
      EXPECT_GT(d.pixels, 10000) << what;
      EXPECT_LE(d.mean, kMeanThreshold) << what;
      EXPECT_LE(d.p99, kP99Threshold) << what;
      // The colours are there: red and blue ends of Cool to Warm differ.
      scene.colorMap = nullptr;
      const auto plain = Compare(ref, cpuRenderer.Render(scene, opt));
      EXPECT_GT(plain.mean, 10.0) << what << ": colour by data changes the picture";
    }
  }
  // A metal coloured by data (docs/model.md eq. 9.4: the data colour as its
  // Fresnel F0, a tinted surround), polarized or not, on both backends.
  const sl::Material<double> gold = render::MaterialForData(
    sl::FindMaterialPreset("gold")->material, render::Highlights::Auto, true);
  ASSERT_TRUE(gold.albedoTintsFresnel);
  for (auto mode : { render::ShadingMode::Gouraud, render::ShadingMode::Phong })
  {
    for (double polarizer : { -1.0, 30.0 })
    {
      opt.mode = mode;
      opt.polarizer = polarizer;
      render::Scene scene{ &mesh, Camera(), Lights(false), gold, &map };
      const render::Image ref = cpuRenderer.Render(scene, opt);
      const auto d = Compare(ref, gpuRenderer.Render(scene, opt));
      const std::string what = std::string("tinted gold, ") + render::ShadingModeName(mode) +
        (polarizer >= 0 ? ", analyser at 30 deg" : "");
      EXPECT_GT(d.pixels, 10000) << what;
      EXPECT_LE(d.mean, kMeanThreshold) << what;
      EXPECT_LE(d.p99, kP99Threshold) << what;
      // The tint is there: untinted gold differs.
      scene.material.albedoTintsFresnel = false;
      EXPECT_GT(Compare(ref, cpuRenderer.Render(scene, opt)).mean, 10.0) << what;
    }
  }
  opt.polarizer = -1.0;
}

namespace
{
/// One actor of `pd` through a vtkShadingLabPolyDataMapper with `settings`,
/// under `cam` and one directional light along `light`, rendered
/// offscreen; `extra` (if any) is added to the same renderer.
struct MapperScene
{
  vtkNew<vtkShadingLabPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;
  vtkNew<vtkRenderer> ren;
  vtkSmartPointer<vtkRenderWindow> window;

  MapperScene(vtkPolyData* pd, const render::Settings& settings, const render::Camera& cam,
    const sl::Vec3d& light, int width, int height, vtkActor* extra = nullptr)
  {
    this->mapper->SetInputData(pd);
    this->mapper->SetSettings(settings);
    this->actor->SetMapper(this->mapper);
    const sl::Vec3d& rho = settings.material.diffuseColor;
    this->actor->GetProperty()->SetDiffuseColor(rho.x, rho.y, rho.z);
    this->ren->AddActor(this->actor);
    if (extra)
    {
      this->ren->AddActor(extra);
    }
    this->ren->SetBackground(0.32, 0.34, 0.43);
    AddDirectionalLight(this->ren, light.x, light.y, light.z);
    SetCamera(this->ren, cam);
    this->window = RenderOffscreen(this->ren, width, height);
  }
};
} // namespace

// Backend CPU: the mapper's pixels are the CPU renderer's (the same frame,
// handed to OpenGL as colour and depth), within the parity thresholds of
// the GL path, for every mode and Cook-Torrance; a camera move re-renders
// without converting the mesh again.
TEST(GpuParityGLTest, CpuBackendDrawsWhatTheCpuRendererDraws)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  auto torus = WithExactNormals(sl::datasets::MakeTorus(1.0, 0.4, 48, 24));
  const render::Mesh mesh = render::MeshFromPolyData(torus);
  const render::Camera cam = Camera();
  const sl::Vec3d toLight(0.4, 0.6, 1.0);
  sl::Lighting<double> lights;
  lights.lightCount = 1;
  lights.lights[0].vector = sl::NormalizeOr(toLight, sl::Vec3d(0, 0, 1));
  const std::pair<render::ShadingMode, sl::ReflectanceModel> cases[] = {
    { render::ShadingMode::Flat, sl::ReflectanceModel::BlinnPhong },
    { render::ShadingMode::Gouraud, sl::ReflectanceModel::BlinnPhong },
    { render::ShadingMode::Phong, sl::ReflectanceModel::BlinnPhong },
    { render::ShadingMode::FastPhong, sl::ReflectanceModel::BlinnPhong },
    { render::ShadingMode::Phong, sl::ReflectanceModel::CookTorrance },
  };
  for (const auto& [mode, model] : cases)
  {
    SCOPED_TRACE(std::string(render::ShadingModeName(mode)) + " model " +
      std::to_string(static_cast<int>(model)));
    render::Settings settings;
    settings.material = BlinnPhong();
    settings.material.model = model;
    settings.render.mode = mode;
    settings.render.fastPhongFallback = false; // fast Phong itself on both backends
    render::RenderOptions opt = settings.render;
    opt.width = 240;
    opt.height = 180;
    const auto ref =
      test::RenderCpu(mesh, cam, lights.Cast<float>(), settings.material.Cast<float>(), opt);
    settings.backend = render::Backend::CPU;
    MapperScene cpu(torus, settings, cam, toLight, opt.width, opt.height);
    const auto onCpu = Grab(cpu.window);
    const auto same = Compare(ref, onCpu);
    EXPECT_GT(same.pixels, 5000);
    EXPECT_LE(same.mean, 0.05); // the same frame, through 8 bits and a texture
    EXPECT_LE(same.p99, 1.0);
    settings.backend = render::Backend::GPU;
    MapperScene gpu(torus, settings, cam, toLight, opt.width, opt.height);
    const auto parity = Compare(Grab(gpu.window), onCpu);
    EXPECT_LE(parity.mean, kMeanThreshold);
    EXPECT_LE(parity.p99, kP99Threshold);
    EXPECT_EQ(cpu.mapper->GetCpuMeshConversions(), 1);
    cpu.ren->GetActiveCamera()->Azimuth(15);
    cpu.window->Render();
    EXPECT_EQ(cpu.mapper->GetCpuMeshConversions(), 1);
    EXPECT_GT(cpu.mapper->GetCpuRenderMilliseconds(), 0.0);
  }
}

// The hand-over writes depth: a native VTK plane cutting through a
// ShadingLab sphere occludes the same pixels whether the sphere is drawn
// by the GPU or the CPU backend (the plane is unlit green, so its visible
// pixels can be counted), and the pictures agree within the parity
// thresholds.
TEST(GpuParityGLTest, CpuBackendIsDepthCorrectAgainstNativeActors)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  auto sphere = WithExactNormals(sl::datasets::MakeUVSphere(48, 24));
  auto plane = vtkSmartPointer<vtkPolyData>::New();
  {
    vtkNew<vtkPoints> points;
    // Tilted through the centre: it enters the sphere on one side.
    for (const auto& p : { std::array<double, 3>{ -1.6, -1.6, -0.8 }, { 1.6, -1.6, 0.8 },
           { 1.6, 1.6, 0.8 }, { -1.6, 1.6, -0.8 } })
    {
      points->InsertNextPoint(p.data());
    }
    vtkNew<vtkCellArray> polys;
    const vtkIdType quad[4] = { 0, 1, 2, 3 };
    polys->InsertNextCell(4, quad);
    plane->SetPoints(points);
    plane->SetPolys(polys);
  }
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputData(plane);
  vtkNew<vtkActor> planeActor;
  planeActor->SetMapper(planeMapper);
  planeActor->GetProperty()->SetColor(0, 1, 0);
  planeActor->GetProperty()->SetAmbient(1);
  planeActor->GetProperty()->SetDiffuse(0);
  planeActor->GetProperty()->SetSpecular(0);
  render::Camera cam = Camera();
  render::Settings settings;
  settings.material = BlinnPhong();
  auto greenPixels = [](const render::Image& image)
  {
    int64_t n = 0;
    for (size_t i = 0; i < image.covered.size(); ++i)
    {
      const float* c = &image.rgb[3 * i];
      n += c[1] > 0.9f && c[0] < 0.1f && c[2] < 0.1f;
    }
    return n;
  };
  settings.backend = render::Backend::GPU;
  MapperScene gpu(sphere, settings, cam, sl::Vec3d(0.4, 0.6, 1.0), 240, 180, planeActor);
  const auto onGpu = Grab(gpu.window);
  settings.backend = render::Backend::CPU;
  MapperScene cpu(sphere, settings, cam, sl::Vec3d(0.4, 0.6, 1.0), 240, 180, planeActor);
  const auto onCpu = Grab(cpu.window);
  const int64_t g = greenPixels(onGpu), c = greenPixels(onCpu);
  EXPECT_GT(g, 3000);
  EXPECT_NEAR(static_cast<double>(c), static_cast<double>(g), 0.01 * g);
  const auto d = Compare(onGpu, onCpu);
  EXPECT_LE(d.mean, kMeanThreshold);
  EXPECT_LE(d.p99, kP99Threshold);
  // Without the sphere's depth the plane would show through it: many more
  // green pixels (the check above could not pass with depth ignored).
  vtkNew<vtkPolyData> nothing;
  MapperScene planeOnly(nothing, settings, cam, sl::Vec3d(0.4, 0.6, 1.0), 240, 180, planeActor);
  EXPECT_GT(greenPixels(Grab(planeOnly.window)), g + 1000);
}

// A closed mesh wound inward (a marching-cubes isosurface can come out so)
// without normals: its made normals point inward, every face is a back
// face, and two-sided lighting flips the normals once, outward. Phong on
// the GPU once flipped them twice (a comment in the fragment shader spelt
// VTK's normal tag, which VTK substituted a second time) and drew it black.
TEST(GpuParityGLTest, InwardWoundMeshIsLitOnBothBackends)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  vtkSmartPointer<vtkPolyData> torus;
  torus.TakeReference(sl::datasets::MakeTorus(1.0, 0.4, 48, 24));
  torus->GetPointData()->SetNormals(nullptr);
  auto inward = vtkSmartPointer<vtkPolyData>::New();
  inward->DeepCopy(torus);
  for (vtkIdType c = 0; c < inward->GetPolys()->GetNumberOfCells(); ++c)
  {
    inward->GetPolys()->ReverseCellAtId(c);
  }
  const render::Camera cam = Camera();
  for (const auto mode : { render::ShadingMode::Phong, render::ShadingMode::Gouraud,
         render::ShadingMode::FastPhong, render::ShadingMode::Flat })
  {
    SCOPED_TRACE(render::ShadingModeName(mode));
    render::Settings settings;
    settings.material = BlinnPhong();
    settings.render.mode = mode;
    settings.render.fastPhongFallback = false;
    settings.normals.featureAngle = 180.0;
    MapperScene outwardGpu(torus, settings, cam, sl::Vec3d(0.4, 0.6, 1.0), 240, 180);
    MapperScene inwardGpu(inward, settings, cam, sl::Vec3d(0.4, 0.6, 1.0), 240, 180);
    settings.backend = render::Backend::CPU;
    MapperScene inwardCpu(inward, settings, cam, sl::Vec3d(0.4, 0.6, 1.0), 240, 180);
    const auto a = Grab(outwardGpu.window), b = Grab(inwardGpu.window), c = Grab(inwardCpu.window);
    const auto sameAsOutward = Compare(a, b), parity = Compare(c, b);
    EXPECT_GT(sameAsOutward.pixels, 5000);
    if (mode == render::ShadingMode::Phong || mode == render::ShadingMode::Gouraud)
    {
      // (Flat and fast Phong light at the provoking vertex, the last one:
      // reversing the winding moves it. Their pictures then differ in
      // detail, not in brightness.)
      EXPECT_LE(sameAsOutward.mean, kMeanThreshold);
      EXPECT_LE(sameAsOutward.p99, kP99Threshold);
    }
    EXPECT_LE(sameAsOutward.mean, 3.0); // lit as the outward torus, not black
    EXPECT_LE(parity.mean, kMeanThreshold);
    EXPECT_LE(parity.p99, kP99Threshold);
  }
}

// Two renderers side by side in one window, the left drawn by the GPU
// backend and the right by the CPU backend: the hand-over lands in its own
// renderer's viewport, and the halves agree within the parity thresholds.
TEST(GpuParityGLTest, CpuBackendDrawsIntoItsOwnViewport)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  auto torus = WithExactNormals(sl::datasets::MakeTorus(1.0, 0.4, 48, 24));
  const render::Camera cam = Camera();
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(480, 180);
  std::vector<vtkSmartPointer<vtkShadingLabPolyDataMapper>> mappers;
  for (int side = 0; side < 2; ++side)
  {
    render::Settings settings;
    settings.material = BlinnPhong();
    settings.backend = side == 0 ? render::Backend::GPU : render::Backend::CPU;
    auto mapper = vtkSmartPointer<vtkShadingLabPolyDataMapper>::New();
    mapper->SetInputData(torus);
    mapper->SetSettings(settings);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetDiffuseColor(0.9, 0.8, 0.7);
    vtkNew<vtkRenderer> ren;
    ren->SetViewport(0.5 * side, 0, 0.5 * side + 0.5, 1);
    ren->AddActor(actor);
    ren->SetBackground(0.32, 0.34, 0.43);
    AddDirectionalLight(ren, 0.4, 0.6, 1.0);
    SetCamera(ren, cam);
    window->AddRenderer(ren);
    mappers.push_back(mapper);
  }
  window->Render();
  const render::Image both = Grab(window);
  render::Image half[2];
  for (int side = 0; side < 2; ++side)
  {
    half[side].width = 240;
    half[side].height = 180;
    half[side].displayApplied = true;
    half[side].appliedDisplay = both.appliedDisplay;
    for (int j = 0; j < 180; ++j)
    {
      for (int i = 0; i < 240; ++i)
      {
        const size_t s = static_cast<size_t>(j) * 480 + 240 * side + i;
        half[side].covered.push_back(both.covered[s]);
        for (int c = 0; c < 3; ++c)
        {
          half[side].rgb.push_back(both.rgb[3 * s + c]);
        }
      }
    }
  }
  const auto d = Compare(half[0], half[1]);
  EXPECT_GT(d.pixels, 5000);
  EXPECT_LE(d.mean, kMeanThreshold);
  EXPECT_LE(d.p99, kP99Threshold);
  EXPECT_EQ(mappers[1]->GetCpuMeshConversions(), 1);
  EXPECT_GT(mappers[1]->GetCpuHandOverMilliseconds(), 0.0);
}

// Backend Auto: the CPU where OpenGL is a software rasterizer and the mesh
// has at least kAutoCpuMinPolygons polygons, the GPU otherwise; the choice
// is reported with its reason, and the big mesh's picture is the CPU
// backend's.
TEST(GpuParityGLTest, AutoBackendChoosesTheCpuOnASoftwareRasterizerForLargeMeshes)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  vtkSmartPointer<vtkPolyData> small, large;
  small.TakeReference(sl::datasets::MakeUVSphere(48, 24));
  large.TakeReference(sl::datasets::MakeUVSphere(400, 200));
  ASSERT_GE(large->GetNumberOfPolys(), sl::render::kAutoCpuMinPolygons);
  ASSERT_LT(small->GetNumberOfPolys(), sl::render::kAutoCpuMinPolygons);
  render::Settings settings;
  settings.material = BlinnPhong();
  settings.backend = render::Backend::Auto;
  const render::Camera cam = Camera();
  MapperScene a(small, settings, cam, sl::Vec3d(0.4, 0.6, 1.0), 240, 180);
  MapperScene b(large, settings, cam, sl::Vec3d(0.4, 0.6, 1.0), 240, 180);
  const std::string smallChoice = a.mapper->GetBackendChoice();
  const std::string largeChoice = b.mapper->GetBackendChoice();
  std::printf("auto, small: %s\nauto, large: %s\n", smallChoice.c_str(), largeChoice.c_str());
  EXPECT_EQ(smallChoice.rfind("gpu: OpenGL renderer '", 0), 0u) << smallChoice;
  const bool software = largeChoice.find("a software rasterizer") != std::string::npos;
  EXPECT_EQ(largeChoice.rfind(software ? "cpu: " : "gpu: ", 0), 0u) << largeChoice;
  EXPECT_EQ(b.mapper->GetCpuMeshConversions(), software ? 1 : 0);
  if (software)
  {
    settings.backend = render::Backend::CPU;
    MapperScene cpu(large, settings, cam, sl::Vec3d(0.4, 0.6, 1.0), 240, 180);
    const auto d = Compare(Grab(cpu.window), Grab(b.window));
    EXPECT_EQ(d.mean, 0.0);
  }
}

// Faces run inconsistently (every third reversed, no normals): the mapper
// turns them back before it makes the normals, so each backend and mode
// draws the intact mesh's picture, and auto chooses as for the intact mesh.
TEST(GpuParityGLTest, InconsistentlyOrientedMeshDrawsAsTheIntactOne)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  vtkSmartPointer<vtkPolyData> intact;
  intact.TakeReference(sl::datasets::MakeUVSphere(96, 48));
  intact->GetPointData()->SetNormals(nullptr);
  vtkNew<vtkPolyData> reversed;
  reversed->ShallowCopy(intact);
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < intact->GetNumberOfPolys(); ++c)
  {
    intact->GetPolys()->GetCellAtId(c, ids);
    std::vector<vtkIdType> corners(ids->begin(), ids->end());
    if (c % 3 == 1)
    {
      std::reverse(corners.begin(), corners.end());
    }
    cells->InsertNextCell(static_cast<vtkIdType>(corners.size()), corners.data());
  }
  reversed->SetPolys(cells);
  const render::Camera cam = Camera();
  for (auto backend : { render::Backend::GPU, render::Backend::CPU })
  {
    for (auto mode : { render::ShadingMode::Gouraud, render::ShadingMode::Phong,
           render::ShadingMode::Auto })
    {
      render::Settings settings;
      settings.material = BlinnPhong();
      settings.backend = backend;
      settings.render.mode = mode;
      MapperScene a(intact, settings, cam, sl::Vec3d(0.4, 0.6, 1.0), 240, 180);
      MapperScene b(reversed, settings, cam, sl::Vec3d(0.4, 0.6, 1.0), 240, 180);
      const auto d = Compare(Grab(a.window), Grab(b.window));
      const std::string what = std::string(backend == render::Backend::GPU ? "gpu " : "cpu ") +
        render::ShadingModeName(mode);
      EXPECT_GT(d.pixels, 5000) << what;
      EXPECT_EQ(d.mean, 0.0) << what;
      EXPECT_EQ(a.mapper->GetAutoChoice(), b.mapper->GetAutoChoice()) << what;
    }
  }
}

namespace
{
/// One polygon: a disc of radius 1 (n corners), cut open along +x to a hole
/// of radius `hole` when hole > 0 (a keyhole, 2n + 2 corners).
vtkSmartPointer<vtkPolyData> KeyholePolygon(int n, double hole)
{
  vtkNew<vtkPoints> points;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < (hole > 0 ? n + 1 : n); ++i)
  {
    points->InsertNextPoint(std::cos(2 * pi * i / n), std::sin(2 * pi * i / n), 0);
  }
  for (int i = 0; hole > 0 && i <= n; ++i)
  {
    points->InsertNextPoint(hole * std::cos(-2 * pi * i / n), hole * std::sin(-2 * pi * i / n), 0);
  }
  std::vector<vtkIdType> ids(static_cast<size_t>(points->GetNumberOfPoints()));
  for (size_t k = 0; k < ids.size(); ++k)
  {
    ids[k] = static_cast<vtkIdType>(k);
  }
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(polys);
  return pd;
}

int64_t Covered(const render::Image& image)
{
  int64_t n = 0;
  for (uint8_t c : image.covered)
  {
    n += c;
  }
  return n;
}
} // namespace

// The mapper as ParaView uses it, on a polygon VTK's fan would fill over
// its notch: a keyhole ring (one 66-corner polygon with a slit) covers
// 1 - 0.5^2 = 3/4 of its disc on both backends, its hole uncovered.
TEST(GpuParityGLTest, ConcavePolygonsAreDrawnAsTheyAre)
{
  if (!HaveGpu())
  {
    GTEST_SKIP() << "no X display with OpenGL";
  }
  const vtkSmartPointer<vtkPolyData> ring = KeyholePolygon(32, 0.5), disc = KeyholePolygon(32, 0);
  const double bounds[6] = { -1, 1, -1, 1, 0, 0 };
  const render::Camera cam = render::FitCamera(bounds, 0, 0, 1, 240.0 / 180.0, false);
  render::Settings settings;
  settings.render.mode = render::ShadingMode::Flat;
  MapperScene discGpu(disc, settings, cam, sl::Vec3d(0, 0, 1), 240, 180);
  MapperScene ringGpu(ring, settings, cam, sl::Vec3d(0, 0, 1), 240, 180);
  settings.backend = render::Backend::CPU;
  MapperScene ringCpu(ring, settings, cam, sl::Vec3d(0, 0, 1), 240, 180);
  const auto d = Grab(discGpu.window), g = Grab(ringGpu.window), c = Grab(ringCpu.window);
  ASSERT_GT(Covered(d), 5000);
  const double gpuShare = static_cast<double>(Covered(g)) / Covered(d);
  const double cpuShare = static_cast<double>(Covered(c)) / Covered(d);
  EXPECT_NEAR(gpuShare, 0.75, 0.02);
  EXPECT_NEAR(cpuShare, 0.75, 0.02);
  EXPECT_FALSE(g.covered[static_cast<size_t>(90 * 240 + 120)]) << "the hole's centre";
  EXPECT_EQ(ring->GetNumberOfPolys(), 1) << "the input is not modified";
  const auto parity = Compare(c, g);
  EXPECT_LE(parity.mean, kMeanThreshold);
}
