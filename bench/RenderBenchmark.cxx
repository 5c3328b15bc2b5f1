// SPDX-License-Identifier: BSD-3-Clause
// CPU renderer frame time per mode, 1 and 2 threads, at 1920x1080, beside
// VTK's own OpenGL pipeline (Mesa llvmpipe under Xvfb: the software GL a user
// without a GPU gets) on the same mesh and view in the same run.
//
//   build/bin/shadinglab_bench_render --benchmark_repetitions=7
//       --benchmark_report_aggregates_only=true   (under scripts/with-xvfb)
//
// Meshes: a ~100k-triangle torus (316 x 158 x 2 = 99,856) and a ~1M-triangle
// icosphere (level 8: 1,310,720). VTK rows are skipped without DISPLAY.
// SHADINGLAB_BENCH_NO_HIDDEN_CULL=1 turns the CPU renderer's culling of
// hidden back faces off in BM_Cpu (both meshes are closed), to compare.
#include "AnalyticMeshes.h"
#include "PolyDataMesh.h"
#include "VtkCamera.h"
#include "VtkLights.h"
#include "shadinglab/model/Spectrum.h"
#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/render/AutoMode.h"
#include "shadinglab/render/ColorMap.h"
#include "shadinglab/render/Settings.h"
#include "shadinglab/model/Materials.h"
#include "vtkShadingLabPolyDataMapper.h"

#include <benchmark/benchmark.h>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkElevationFilter.h>
#include <vtkLightKit.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <thread>
#include <vector>

namespace sl = shadinglab;
namespace cpu = shadinglab::cpu;
namespace render = shadinglab::render;

namespace
{

constexpr int kWidth = 1920;
constexpr int kHeight = 1080;

struct Scene
{
  vtkSmartPointer<vtkPolyData> polydata; // with area-weighted point normals
  render::Mesh mesh;
  render::Camera camera;
};

const Scene& GetScene(int which)
{
  static std::map<int, std::unique_ptr<Scene>> scenes;
  auto& s = scenes[which];
  if (!s)
  {
    s = std::make_unique<Scene>();
    vtkSmartPointer<vtkPolyData> raw;
    // 0: the 100k torus, 1: the 1.3M icosphere, 10 + L: icosphere level L.
    raw.TakeReference(which == 0 ? sl::datasets::MakeTorus(1.0, 0.4, 316, 158)
        : which == 1             ? sl::datasets::MakeIcosphere(8)
                                 : sl::datasets::MakeIcosphere(which - 10));
    raw->GetPointData()->SetNormals(raw->GetPointData()->GetArray(sl::datasets::kExactNormalArray));
    s->polydata = raw;
    s->mesh = render::MeshFromPolyData(raw);
    double bounds[6];
    s->mesh.Bounds(bounds);
    s->camera = render::FitCamera(bounds, 20.0, 35.0, 1.6, double(kWidth) / kHeight, false);
  }
  return *s;
}

sl::Lighting<double> Headlight(const render::Camera& cam)
{
  sl::Lighting<double> l;
  l.lightCount = 1;
  l.lights[0].vector = sl::NormalizeOr(cam.position - cam.focalPoint, sl::Vec3d(0, 0, 1));
  return l;
}

/// The lights of ParaView's render view: its light kit (vtkLightKit's
/// defaults: head, key, fill and two back lights, intensities 0.25, 0.75,
/// 0.25, 0.21, 0.21) following the camera, converted as the CPU backend
/// converts a renderer's lights (LightingFromVtk, the settings' defaults).
sl::Lighting<double> ParaViewLights(const render::Camera& cam)
{
  vtkNew<vtkRenderer> renderer;
  render::ApplyToVtkCamera(cam, renderer->GetActiveCamera());
  vtkNew<vtkLightKit> kit;
  kit->AddLightsToRenderer(renderer);
  renderer->UpdateLightsGeometryToFollowCamera();
  const render::Settings defaults;
  return render::LightingFromVtk(renderer, defaults.lightIntensity, defaults.lightSolidAngle);
}

void BM_Cpu(benchmark::State& state)
{
  const Scene& scene = GetScene(static_cast<int>(state.range(0)));
  render::RenderOptions opt;
  opt.width = kWidth;
  opt.height = kHeight;
  opt.mode = static_cast<render::ShadingMode>(state.range(1));
  opt.threads = static_cast<int>(state.range(3));
  sl::Material<double> material;
  material.model = static_cast<sl::ReflectanceModel>(state.range(2));
  opt.cullHiddenBackFaces = std::getenv("SHADINGLAB_BENCH_NO_HIDDEN_CULL") == nullptr;
  const render::Scene renderScene{ &scene.mesh, scene.camera, Headlight(scene.camera), material };
  render::RenderStats stats;
  // One renderer for all frames: buffers persist, as in VTK's render window.
  // One frame first, as BM_VtkOpenGL's window->Render(): the timed frames
  // are steady-state redraws, not the first frame's buffer allocation.
  cpu::SoftwareRenderer renderer;
  renderer.Render(renderScene, opt);
  for (auto _ : state)
  {
    const auto& image = renderer.Render(renderScene, opt, &stats);
    benchmark::DoNotOptimize(image.rgb.data());
  }
  state.counters["triangles"] = static_cast<double>(stats.triangles);
  state.counters["pixels_shaded"] = static_cast<double>(stats.pixelsShaded);
  state.counters["pixels_covered"] = static_cast<double>(stats.pixelsCovered);
  state.counters["culled"] = static_cast<double>(stats.culled);
  state.SetLabel(std::string(render::ShadingModeName(opt.mode)) + "/" +
    sl::ReflectanceModelName(material.model) + " threads=" + std::to_string(opt.threads));
}

/// Cook-Torrance in the forms issue 13 names besides the one-lobe dielectric
/// of BM_Cpu: 0, a two-lobe dielectric mixture (plastic with a sharp and a
/// broad Beckmann lobe, weights 0.6 / 0.4); 1, a conductor (the gold preset:
/// complex Fresnel per pixel); 2, both (gold with the same two lobes).
sl::Material<double> CookTorranceVariant(int variant)
{
  sl::Material<double> material =
    sl::FindMaterialPreset(variant == 0 ? "plastic" : "gold")->material;
  if (variant != 1)
  {
    material.lobeCount = 2;
    material.lobes[0] = { 0.6, 0.1 };
    material.lobes[1] = { 0.4, 0.4 };
  }
  return material;
}
const char* const kCookTorranceVariantNames[] = { "two-lobe dielectric", "conductor (gold)",
  "two-lobe conductor" };

void BM_CpuCookTorrance(benchmark::State& state)
{
  const Scene& scene = GetScene(static_cast<int>(state.range(0)));
  const int variant = static_cast<int>(state.range(1));
  const sl::Material<double> material = CookTorranceVariant(variant);
  render::RenderOptions opt;
  opt.width = kWidth;
  opt.height = kHeight;
  opt.mode = render::ShadingMode::Phong;
  opt.threads = static_cast<int>(state.range(2));
  const render::Scene renderScene{ &scene.mesh, scene.camera, Headlight(scene.camera), material };
  cpu::SoftwareRenderer renderer;
  renderer.Render(renderScene, opt); // steady state, as in BM_Cpu
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(renderer.Render(renderScene, opt).rgb.data());
  }
  state.SetLabel(std::string("phong/cook-torrance ") + kCookTorranceVariantNames[variant] +
    " threads=" + std::to_string(opt.threads));
}

/// Spectral Fresnel (16 wavelengths, docs/model.md eq. 7.3) against the
/// three-sample RGB material, frame by frame in alternating pairs (as
/// AlternateOneAndTwoThreads): Phong/Cook-Torrance gold, 1920x1080,
/// range(1) threads; range(2) 1: an analyser instead of the spectrum; 2: a
/// polarizer in front of the light as well (Fresnel's full Mueller matrix).
/// `ratio` is the median of spectral (or polarized) / RGB over the pairs.
void BM_CpuSpectral(benchmark::State& state);

/// Times run(1) and run(2) in alternating pairs (which goes first
/// alternates too), so both see the same moments of a noisy machine: a
/// BM_Cpu row's 1- and 2-thread runs are seconds apart, and these VMs'
/// speed drifts by 1.5x over seconds (the same frame took 19 and 27 ms in
/// one run). Reports the median of each (`ms_1_thread`, `ms_2_threads`)
/// and `scaling`, the median over the pairs of one thread's time over two
/// threads': the two runs of a pair are back to back, so a drift cancels
/// in their ratio where it would not in the ratio of the two medians.
/// `scaling_best`, the fastest one-thread frame over the fastest
/// two-thread frame: what the code gave in the run's least disturbed
/// moments (a neighbour on the host only ever slows a frame, and a
/// two-thread frame more, as it needs both cores at once). Under steady
/// load no frame is undisturbed, so it is no steadier than `scaling`
/// (docs/performance.md, "Two threads against one").
/// The counters' names: run(1)'s median, run(2)'s, their paired ratio
/// run(1)/run(2), and the ratio of the fastest frames.
struct PairNames
{
  const char* first = "ms_1_thread";
  const char* second = "ms_2_threads";
  const char* ratio = "scaling";
  const char* ratioBest = "scaling_best";
};
template<typename Run>
void AlternateOneAndTwoThreads(benchmark::State& state, Run&& run, const PairNames& names = {})
{
  run(1); // steady state, as in BM_Cpu
  run(2);
  std::vector<double> ms[2];
  int64_t pairIndex = 0;
  for (auto _ : state)
  {
    double pair = 0;
    for (int k = 0; k < 2; ++k)
    {
      const int r = static_cast<int>((pairIndex + k) % 2);
      const auto start = std::chrono::steady_clock::now();
      run(r + 1);
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      ms[r].push_back(1e3 * t);
      pair += t;
    }
    ++pairIndex;
    state.SetIterationTime(pair);
  }
  auto median = [](std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : 0.5 * (v[(v.size() - 1) / 2] + v[v.size() / 2]);
  };
  std::vector<double> ratios;
  for (size_t k = 0; k < std::min(ms[0].size(), ms[1].size()); ++k)
  {
    ratios.push_back(ms[1][k] > 0 ? ms[0][k] / ms[1][k] : 0.0);
  }
  state.counters[names.first] = median(ms[0]);
  state.counters[names.second] = median(ms[1]);
  state.counters[names.ratio] = median(ratios);
  if (!ms[0].empty() && !ms[1].empty())
  {
    state.counters[names.ratioBest] = *std::min_element(ms[0].begin(), ms[0].end()) /
      *std::min_element(ms[1].begin(), ms[1].end());
  }
}

/// Two threads against one, frame by frame (AlternateOneAndTwoThreads): a
/// renderer with one thread and one with two draw alternate frames.
/// Variants: 0-3 the modes with Blinn-Phong, 4 Phong with Cook-Torrance
/// (dielectric), 5-7 BM_CpuCookTorrance's two-lobe dielectric, gold,
/// two-lobe gold. BM_MachineScaling is the same measurement of work with
/// nothing serial in it: the ceiling this machine puts on the ratio.
void BM_CpuThreadScaling(benchmark::State& state)
{
  const Scene& scene = GetScene(static_cast<int>(state.range(0)));
  const int variant = static_cast<int>(state.range(1));
  render::RenderOptions opt;
  opt.width = kWidth;
  opt.height = kHeight;
  opt.mode = static_cast<render::ShadingMode>(variant < 4 ? variant : 2);
  sl::Material<double> material;
  if (variant == 4)
  {
    material.model = sl::ReflectanceModel::CookTorrance;
  }
  else if (variant > 4)
  {
    material = CookTorranceVariant(variant - 5);
  }
  const render::Scene renderScene{ &scene.mesh, scene.camera, Headlight(scene.camera), material };
  cpu::SoftwareRenderer renderers[2];
  render::RenderOptions opts[2] = { opt, opt };
  opts[0].threads = 1;
  opts[1].threads = 2;
  AlternateOneAndTwoThreads(state,
    [&](int threads)
    {
      benchmark::DoNotOptimize(
        renderers[threads - 1].Render(renderScene, opts[threads - 1]).rgb.data());
    });
  const std::string name = variant < 4 ? render::ShadingModeName(opt.mode)
    : variant == 4                   ? std::string("phong/cook-torrance")
                     : std::string("cook-torrance ") + kCookTorranceVariantNames[variant - 5];
  state.SetLabel(name + ", 1 and 2 threads alternating");
}

void BM_CpuSpectral(benchmark::State& state)
{
  const Scene& scene = GetScene(static_cast<int>(state.range(0)));
  const bool polarized = state.range(2) != 0;
  const bool polarizedLight = state.range(2) == 2;
  sl::Material<double> rgb = sl::FindMaterialPreset("gold")->material;
  sl::Material<double> spectral = rgb;
  sl::SetSpectral(spectral, *sl::PresetDispersion("gold"));
  render::RenderOptions opt;
  opt.width = kWidth;
  opt.height = kHeight;
  opt.mode = render::ShadingMode::Phong;
  opt.threads = static_cast<int>(state.range(1));
  // range(2) = 1: RGB gold through an analyser at 30 degrees against RGB
  // gold without (the polarized specular term's cost, eq. 8.4).
  render::RenderOptions analysed = opt;
  analysed.polarizer = 30.0;
  // range(2) = 2: and a polarizer at 45 degrees in front of the light
  // (eq. 8.6: the rs rp* phase terms, the light's Stokes frame).
  analysed.lightPolarizer = polarizedLight ? 45.0 : -1.0;
  const render::Scene scenes[2] = {
    { &scene.mesh, scene.camera, Headlight(scene.camera), polarized ? rgb : spectral },
    { &scene.mesh, scene.camera, Headlight(scene.camera), rgb } };
  const render::RenderOptions options[2] = { polarized ? analysed : opt, opt };
  cpu::SoftwareRenderer renderers[2];
  AlternateOneAndTwoThreads(state,
    [&](int which) {
      benchmark::DoNotOptimize(
        renderers[which - 1].Render(scenes[which - 1], options[which - 1]).rgb.data());
    },
    polarized ? PairNames{ "ms_polarized", "ms_rgb", "ratio", "ratio_best" }
              : PairNames{ "ms_spectral", "ms_rgb", "ratio", "ratio_best" });
  state.SetLabel(std::string("phong/cook-torrance gold, ") +
    (polarizedLight ? "polarized light through an analyser"
                    : polarized ? "through an analyser" : "spectral (16)") +
    " against RGB, threads=" +
    std::to_string(opt.threads));
}

/// What this machine gives two threads, measured as BM_CpuThreadScaling
/// measures the renderer, on work split in two halves with no serial part
/// and no shared data: 0, compute (independent multiply-add chains in
/// registers, ~20 ms on one thread); 1, memory (read-modify-write of a
/// 34 MB float buffer, the size of a 1080p frame's colour, depth and
/// coverage, ~8 passes). A renderer cannot scale better than this in the
/// same run; these VMs share their host's cores, caches and memory with
/// other machines. The second thread is a fresh std::thread per run (~0.1
/// ms of the compute kernel's ~13, which the ratio then slightly under-states).
void BM_MachineScaling(benchmark::State& state)
{
  const bool memory = state.range(0) == 1;
  constexpr int64_t kChains = 8, kSteps = 6000000;
  constexpr size_t kFloats = 34u << 18; // 34 MB
  std::vector<float> buffer(memory ? kFloats : 0, 1.0f);
  auto half = [&](int part, int parts)
  {
    if (memory)
    {
      const size_t b = kFloats * part / parts, e = kFloats * (part + 1) / parts;
      for (int pass = 0; pass < 8; ++pass)
      {
        for (size_t i = b; i < e; ++i)
        {
          buffer[i] = buffer[i] * 0.999f + 1e-3f;
        }
      }
      benchmark::DoNotOptimize(buffer.data());
      return;
    }
    float acc[kChains];
    for (int64_t c = 0; c < kChains; ++c)
    {
      acc[c] = 1.0f + 1e-3f * static_cast<float>(c + part);
    }
    for (int64_t k = 0; k < kSteps / parts; ++k)
    {
      for (int64_t c = 0; c < kChains; ++c)
      {
        acc[c] = acc[c] * 0.9999999f + 1e-7f;
      }
      benchmark::ClobberMemory();
    }
    benchmark::DoNotOptimize(acc);
  };
  AlternateOneAndTwoThreads(state,
    [&](int threads)
    {
      if (threads == 1)
      {
        half(0, 1);
        return;
      }
      std::thread other([&] { half(1, 2); });
      half(0, 2);
      other.join();
    });
  state.SetLabel(memory ? "memory: 34 MB read-modify-write, 1 and 2 threads alternating"
                        : "compute: multiply-add chains, 1 and 2 threads alternating");
}

/// The Phong stage's pixel kernels side by side: one pixel at a time (the
/// scalar model), 4 lanes (SSE2) and 8 (AVX2, where the CPU has it).
void BM_CpuLanes(benchmark::State& state)
{
  const int lanes = static_cast<int>(state.range(2));
  cpu::SetPixelLanes(lanes);
  if (cpu::PixelLanes() != lanes)
  {
    cpu::SetPixelLanes(0);
    state.SkipWithError("this CPU has no AVX2 with FMA");
    return;
  }
  const Scene& scene = GetScene(static_cast<int>(state.range(0)));
  render::RenderOptions opt;
  opt.width = kWidth;
  opt.height = kHeight;
  opt.mode = render::ShadingMode::Phong;
  opt.threads = static_cast<int>(state.range(3));
  sl::Material<double> material;
  material.model = static_cast<sl::ReflectanceModel>(state.range(1));
  const render::Scene renderScene{ &scene.mesh, scene.camera, Headlight(scene.camera), material };
  cpu::SoftwareRenderer renderer;
  renderer.Render(renderScene, opt); // steady state, as in BM_Cpu
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(renderer.Render(renderScene, opt).rgb.data());
  }
  cpu::SetPixelLanes(0);
  state.SetLabel(std::string("phong/") + sl::ReflectanceModelName(material.model) +
    " lanes=" + std::to_string(lanes) + " threads=" + std::to_string(opt.threads));
}

/// Fast Phong against Phong by triangle size: icospheres of 20 * 4^L
/// triangles filling the same 1920x1080 view (one thread), so the pixels per
/// triangle fall from ~40,000 (L = 1) to ~2 (L = 7).
void BM_CpuModeBySize(benchmark::State& state)
{
  const Scene& scene = GetScene(10 + static_cast<int>(state.range(0)));
  render::RenderOptions opt;
  opt.width = kWidth;
  opt.height = kHeight;
  opt.mode = static_cast<render::ShadingMode>(state.range(1));
  opt.threads = 1;
  const render::Scene renderScene{ &scene.mesh, scene.camera, Headlight(scene.camera),
    sl::Material<double>() };
  cpu::SoftwareRenderer renderer;
  render::RenderStats stats;
  renderer.Render(renderScene, opt); // steady state, as in BM_Cpu
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(renderer.Render(renderScene, opt, &stats).rgb.data());
  }
  state.counters["rasterized"] = static_cast<double>(stats.rasterized);
  state.counters["px_per_triangle"] =
    stats.rasterized ? double(stats.pixelsShaded) / double(stats.rasterized) : 0.0;
  state.SetLabel(std::string(render::ShadingModeName(opt.mode)) + " icosphere level " +
    std::to_string(state.range(0)));
}

/// Renders `actor` in an offscreen 1920x1080 window with the scene's camera,
/// once to upload, then times steady-state redraws (`afterFrame`, when
/// given, runs after each, inside the timing).
void TimeFrames(benchmark::State& state, const Scene& scene, vtkActor* actor,
  const std::function<void()>& afterFrame = {})
{
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.32, 0.34, 0.43);
  vtkCamera* cam = renderer->GetActiveCamera();
  cam->SetPosition(scene.camera.position.x, scene.camera.position.y, scene.camera.position.z);
  cam->SetFocalPoint(
    scene.camera.focalPoint.x, scene.camera.focalPoint.y, scene.camera.focalPoint.z);
  cam->SetViewUp(scene.camera.viewUp.x, scene.camera.viewUp.y, scene.camera.viewUp.z);
  cam->SetViewAngle(scene.camera.viewAngle);
  cam->SetClippingRange(scene.camera.nearClip, scene.camera.farClip);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(kWidth, kHeight);
  window->AddRenderer(renderer);
  window->Render(); // upload once; frames below are steady-state redraws
  for (auto _ : state)
  {
    cam->Azimuth(0.0); // marks the camera modified so the frame is redrawn
    window->Render();
    window->WaitForCompletion();
    if (afterFrame)
    {
      afterFrame();
    }
  }
}

void BM_VtkOpenGL(benchmark::State& state)
{
  if (!std::getenv("DISPLAY"))
  {
    state.SkipWithError("no DISPLAY: run under xvfb-run for the VTK OpenGL rows");
    return;
  }
  const Scene& scene = GetScene(static_cast<int>(state.range(0)));
  const int interpolation = static_cast<int>(state.range(1)); // VTK_GOURAUD / VTK_PHONG
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(scene.polydata);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolation(interpolation);
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetDiffuse(0.7);
  actor->GetProperty()->SetSpecularPower(32);
  if (interpolation == VTK_PBR)
  {
    actor->GetProperty()->SetMetallic(0.0);
    actor->GetProperty()->SetRoughness(0.3);
  }
  TimeFrames(state, scene, actor);
  state.SetLabel(interpolation == VTK_PHONG ? "vtk-phong llvmpipe"
      : interpolation == VTK_PBR          ? "vtk-pbr llvmpipe"
                                          : "vtk-gouraud llvmpipe");
}

/// Our mapper, each mode, same scene and window setup as BM_VtkOpenGL, on
/// the backend `cpu` names: the GLSL shaders, or the CPU renderer's frame
/// handed to OpenGL as colour and depth (CpuBackend.h; counter
/// handover_ms: the hand-over's share of a frame, the median over the
/// frames: display transform, texture upload of the rectangle the surface
/// covers and the quad's fragments, with OpenGL finished before and after
/// it (SetCpuHandOverTimingFinishes: llvmpipe runs the fragments when the
/// frame is finished, outside the draw call's time).
void TimeShadingLabMapper(benchmark::State& state, bool cpu)
{
  if (!std::getenv("DISPLAY"))
  {
    state.SkipWithError("no DISPLAY: run under scripts/with-xvfb");
    return;
  }
  const Scene& scene = GetScene(static_cast<int>(state.range(0)));
  const int mode = static_cast<int>(state.range(1));
  vtkNew<vtkShadingLabPolyDataMapper> mapper;
  mapper->SetInputData(scene.polydata);
  mapper->SetSetting("mode", sl::render::ShadingModeName(static_cast<sl::render::ShadingMode>(mode)));
  mapper->SetSetting("backend", cpu ? "cpu" : "gpu");
  sl::Material<double> material;
  material.model = static_cast<sl::ReflectanceModel>(state.range(2));
  material.shininess = 32;
  mapper->SetMaterial(material);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  std::vector<double> handOver;
  std::function<void()> afterFrame;
  if (cpu)
  {
    mapper->SetCpuHandOverTimingFinishes(true);
    afterFrame = [&]() { handOver.push_back(mapper->GetCpuHandOverMilliseconds()); };
  }
  TimeFrames(state, scene, actor, afterFrame);
  if (cpu)
  {
    std::sort(handOver.begin(), handOver.end());
    state.counters["handover_ms"] = handOver.empty() ? 0.0 : handOver[handOver.size() / 2];
  }
  state.SetLabel(std::string(cpu ? "shadinglab-cpu-backend " : "shadinglab-gl ") +
    render::ShadingModeName(static_cast<render::ShadingMode>(mode)) + "/" +
    sl::ReflectanceModelName(material.model) + (cpu ? " llvmpipe window" : " llvmpipe"));
}

void BM_ShadingLabGL(benchmark::State& state)
{
  TimeShadingLabMapper(state, false);
}

void BM_ShadingLabCpuBackend(benchmark::State& state)
{
  TimeShadingLabMapper(state, true);
}

/// The GL path's spectral Fresnel (a 16-sample loop per light per pixel)
/// and polarized Fresnel against RGB: Phong/Cook-Torrance gold, range(1)
/// 0 RGB, 1 spectral, 2 RGB through an analyser at 30 degrees (eq.
/// 8.3-8.4), 3 and polarized light at 45 degrees (eq. 8.6), as
/// BM_CpuSpectral's range(2).
void BM_ShadingLabGLSpectral(benchmark::State& state)
{
  if (!std::getenv("DISPLAY"))
  {
    state.SkipWithError("no DISPLAY: run under scripts/with-xvfb");
    return;
  }
  const Scene& scene = GetScene(static_cast<int>(state.range(0)));
  const int variant = static_cast<int>(state.range(1));
  const bool spectral = variant == 1;
  vtkNew<vtkShadingLabPolyDataMapper> mapper;
  mapper->SetInputData(scene.polydata);
  mapper->SetSetting("mode", "phong");
  mapper->SetSetting("material", "gold");
  mapper->SetSetting("spectral", spectral ? "on" : "off");
  if (variant >= 2)
  {
    mapper->SetSetting("polarizer", "30");
  }
  if (variant == 3)
  {
    mapper->SetSetting("light-polarizer", "45");
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  TimeFrames(state, scene, actor);
  const char* what[] = { "RGB", "spectral (16)", "RGB through an analyser",
    "RGB, polarized light through an analyser" };
  state.SetLabel(std::string("shadinglab-gl phong/cook-torrance gold ") + what[variant] +
    " llvmpipe");
}

/// {mode, model}: every shading mode with Blinn-Phong, and Cook-Torrance per pixel.
constexpr int kBlinnPhong = static_cast<int>(sl::ReflectanceModel::BlinnPhong);
constexpr int kCookTorrance = static_cast<int>(sl::ReflectanceModel::CookTorrance);
const std::pair<int, int> kModeModels[] = { { 0, kBlinnPhong }, { 1, kBlinnPhong },
  { 2, kBlinnPhong }, { 3, kBlinnPhong }, { 2, kCookTorrance } };

void CpuArgs(benchmark::internal::Benchmark* b)
{
  for (int mesh : { 0, 1 })
  {
    for (const auto& [mode, model] : kModeModels)
    {
      for (int threads : { 1, 2 })
      {
        b->Args({ mesh, mode, model, threads });
      }
    }
  }
}

void GlArgs(benchmark::internal::Benchmark* b)
{
  for (const auto& [mode, model] : kModeModels)
  {
    b->Args({ 1, mode, model });
  }
}

/// The renderer's part of the pvbatch timing (bench/paraview_backends.py,
/// docs/paraview-backends.md): ParaView's Sphere (ThetaResolution 1000,
/// PhiResolution 500: 998,000 triangles, with normals) coloured by
/// Elevation through Cool to Warm, 1920x1080, seen as ParaView's
/// ResetCamera leaves it (from +z, 30-degree view angle, the bounding
/// sphere filling the view: most triangles cover less than a pixel), lit
/// by ParaView's five lights (ParaViewLights), two threads, as the CPU
/// backend draws it. range(0): {mode, model} of kModeModels.
void ParaViewSphereFrames(benchmark::State& state, int modeModel)
{
  // The mesh in the local frame MeshFromPolyData gives it (centred, scaled
  // to a unit bounding sphere), with that frame: the CPU backend moves the
  // camera and the lights into it (render::ToLocal), and so does this.
  struct LocalMesh
  {
    render::Mesh mesh;
    render::WorldFrame frame;
  };
  static const LocalMesh local = []
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(1000);
    sphere->SetPhiResolution(500);
    vtkNew<vtkElevationFilter> elevation;
    elevation->SetInputConnection(sphere->GetOutputPort());
    elevation->SetLowPoint(0, 0, -0.5);
    elevation->SetHighPoint(0, 0, 0.5);
    elevation->Update();
    LocalMesh out;
    render::ScalarField field;
    field.name = "Elevation";
    double range[2];
    out.mesh = render::MeshFromPolyData(
      vtkPolyData::SafeDownCast(elevation->GetOutput()), out.frame, field, range);
    return out;
  }();
  const render::Mesh& mesh = local.mesh;
  static const render::ColorMap map = []
  {
    render::ColorMap m;
    render::FindColorMap("cool-to-warm", m);
    return m;
  }();
  render::Camera camera;
  camera.focalPoint = sl::Vec3d(0, 0, 0);
  camera.viewUp = sl::Vec3d(0, 1, 0);
  camera.viewAngle = 30.0;
  // vtkRenderer::ResetCamera, in world coordinates: the bounding sphere
  // (radius sqrt(3)/2 of the unit box) fits the view angle.
  camera.position = sl::Vec3d(0, 0, std::sqrt(3.0) / 2.0 / std::sin(15.0 * sl::kPi<double> / 180.0));
  const auto [mode, model] = kModeModels[modeModel];
  render::RenderOptions opt;
  opt.width = kWidth;
  opt.height = kHeight;
  opt.mode = static_cast<render::ShadingMode>(mode);
  opt.threads = 2;
  opt.keepDepth = true; // as the CPU backend asks, for the hand-over
  opt.displayBytes = true;
  sl::Material<double> material;
  material.model = static_cast<sl::ReflectanceModel>(model);
  sl::Lighting<double> lights = ParaViewLights(camera);
  render::ToLocal(local.frame, camera);
  render::ToLocal(local.frame, lights);
  render::Scene s{ &mesh, camera, lights, material };
  s.colorMap = &map;
  // As the CPU backend: the mesh hashed once per conversion, not per frame.
  s.meshHash = mesh.ContentHash();
  cpu::SoftwareRenderer renderer;
  render::RenderStats stats;
  renderer.Render(s, opt, &stats);
  renderer.Render(s, opt, &stats); // the second frame runs the closed-mesh test
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(renderer.Render(s, opt, &stats).rgb.data());
  }
  state.counters["rasterized"] = static_cast<double>(stats.rasterized);
  state.counters["binned"] = static_cast<double>(stats.binned);
  state.counters["culled"] = static_cast<double>(stats.culled);
  state.counters["culled_in_runs"] = static_cast<double>(stats.culledInClusters);
  state.counters["pixels_covered"] = static_cast<double>(stats.pixelsCovered);
  state.counters["vertices_drawn"] = static_cast<double>(stats.verticesDrawn);
  state.counters["compact_records"] = stats.compactScreenRecords ? 1 : 0;
  state.SetLabel(std::string(render::ShadingModeName(opt.mode)) + "/" +
    sl::ReflectanceModelName(material.model) + ", ParaView's 1M sphere by Elevation, " +
    std::to_string(s.lighting.lightCount) + " lights");
}

void BM_CpuParaViewSphere(benchmark::State& state)
{
  ParaViewSphereFrames(state, static_cast<int>(state.range(0)));
}

/// The screen records' two layouts (cpu::ScreenRecords) on the same
/// frames: range(0) a {mode, model} of kModeModels, range(1) the layout
/// forced (0 by vertex, 1 compact). The sphere draws under half its
/// vertices, so Auto keeps compact records: this says what that costs
/// or saves in time, beside the memory it saves.
void BM_CpuScreenRecords(benchmark::State& state)
{
  cpu::SetScreenRecords(state.range(1) ? cpu::ScreenRecords::Compact : cpu::ScreenRecords::ByVertex);
  ParaViewSphereFrames(state, static_cast<int>(state.range(0)));
  cpu::SetScreenRecords(cpu::ScreenRecords::Auto);
}

/// The work a scene does not need is skipped: the same frame with the mesh
/// half outside the view (the camera panned by half the view's width, so
/// the torus's centre sits on the left edge) should cost about half, and
/// with the mesh behind the camera (turned round where it stands) about
/// what an empty frame costs.
void BM_CpuHalfOutside(benchmark::State& state)
{
  const Scene& scene = GetScene(0);
  render::Camera camera = scene.camera;
  if (state.range(1) == 2)
  {
    camera.focalPoint = camera.position + (camera.position - camera.focalPoint);
  }
  else if (state.range(1) == 1)
  {
    const sl::Vec3d right = render::BasisOf(camera).right;
    const double halfWidth = sl::Length(camera.focalPoint - camera.position) *
      std::tan(0.5 * camera.viewAngle * sl::kPi<double> / 180.0) * kWidth / kHeight;
    camera.position += right * halfWidth;
    camera.focalPoint += right * halfWidth;
  }
  render::RenderOptions opt;
  opt.width = kWidth;
  opt.height = kHeight;
  opt.mode = static_cast<render::ShadingMode>(state.range(0));
  opt.threads = 2;
  sl::Material<double> material;
  const render::Scene s{ &scene.mesh, camera, Headlight(camera), material };
  cpu::SoftwareRenderer renderer;
  render::RenderStats stats;
  renderer.Render(s, opt, &stats);
  for (auto _ : state)
  {
    renderer.Render(s, opt, &stats);
  }
  state.counters["rasterized"] = static_cast<double>(stats.rasterized);
  state.counters["skipped"] = static_cast<double>(stats.skipped);
  state.counters["binned"] = static_cast<double>(stats.binned);
  state.counters["pixels_shaded"] = static_cast<double>(stats.pixelsShaded);
  state.SetLabel(std::string(render::ShadingModeName(opt.mode)) +
    (state.range(1) == 2 ? ", behind the camera"
        : state.range(1)   ? ", half outside"
                           : ", all in view"));
}

/// A material change re-renders without re-preparing the mesh: the 1.3M
/// icosphere at 640x480, two threads, a new shininess every frame. 0: the
/// mesh has normals; 1: it has none, so the renderer makes area-weighted
/// ones, once (kept while its arrays hash the same); 2: as 1, with the
/// normals remade every frame as the renderer did before (the price a
/// redraw used to pay).
void BM_CpuMaterialChange(benchmark::State& state)
{
  const Scene& scene = GetScene(1);
  static const render::Mesh bare = []
  {
    render::Mesh m = GetScene(1).mesh;
    m.normals.clear();
    return m;
  }();
  const int variant = static_cast<int>(state.range(0));
  render::RenderOptions opt;
  opt.width = 640;
  opt.height = 480;
  opt.threads = 2;
  sl::Material<double> material;
  render::Scene s{ variant == 0 ? &scene.mesh : &bare, scene.camera, Headlight(scene.camera),
    material };
  cpu::SoftwareRenderer renderer;
  render::RenderStats stats;
  // Steady state: the mesh's first frame, and its second, which runs the
  // closed-mesh test (~0.16 s here, once; HiddenBackFaces.h).
  renderer.Render(s, opt, &stats);
  renderer.Render(s, opt, &stats);
  int step = 0;
  for (auto _ : state)
  {
    s.material.shininess = 20.0 + (step++ % 40);
    if (variant == 2)
    {
      benchmark::DoNotOptimize(cpu::AreaWeightedNormals(bare).data());
    }
    renderer.Render(s, opt, &stats);
  }
  state.counters["normals_cached"] = stats.normalsCached ? 1.0 : 0.0;
  state.counters["back_faces_culled"] = stats.hiddenBackFacesCulled ? 1.0 : 0.0;
  state.SetLabel(variant == 0 ? "mesh with normals"
      : variant == 1          ? "no normals: made once"
                              : "no normals: remade every frame (before)");
}

/// A small frame's fixed cost (the explorer's panels, the accuracy study's
/// 320x240 frames): a 2,304-triangle torus filling 320x240, each mode, two
/// threads. Whatever a frame does regardless of its size shows here.
void BM_CpuSmallFrame(benchmark::State& state)
{
  static const render::Mesh mesh = [] {
    vtkSmartPointer<vtkPolyData> raw;
    raw.TakeReference(sl::datasets::MakeTorus(1.0, 0.4, 48, 24));
    raw->GetPointData()->SetNormals(raw->GetPointData()->GetArray(sl::datasets::kExactNormalArray));
    return render::MeshFromPolyData(raw);
  }();
  double bounds[6];
  mesh.Bounds(bounds);
  const render::Camera camera = render::FitCamera(bounds, 20.0, 35.0, 1.6, 320.0 / 240.0, false);
  render::RenderOptions opt;
  opt.width = 320;
  opt.height = 240;
  opt.mode = static_cast<render::ShadingMode>(state.range(0));
  opt.threads = 2;
  const render::Scene s{ &mesh, camera, Headlight(camera), sl::Material<double>() };
  cpu::SoftwareRenderer renderer;
  renderer.Render(s, opt);
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(renderer.Render(s, opt).rgb.data());
  }
  state.SetLabel(std::string(render::ShadingModeName(opt.mode)) + ", 2,304 triangles, 320x240");
}

/// What `--mode auto` costs before a frame (docs/model.md section 4): 0, the
/// whole choice (ChooseMode: the view's predictors over every triangle, then
/// eq. 4.4's quadrature); 1, the quadrature alone (at most 4,096 triangles
/// and 16,384 points). Scenes 0 (100k torus) and 1 (1.3M icosphere) at
/// 1920x1080, as BM_Cpu's: compare with their frame times.
void BM_AutoChoice(benchmark::State& state)
{
  const Scene& scene = GetScene(static_cast<int>(state.range(0)));
  const sl::Material<double> material;
  const sl::Lighting<double> lights = Headlight(scene.camera);
  for (auto _ : state)
  {
    if (state.range(1) == 0)
    {
      benchmark::DoNotOptimize(render::ChooseMode(scene.mesh, scene.mesh.normals, scene.camera,
        lights, material, kWidth, kHeight, 1.0).mode);
    }
    else
    {
      benchmark::DoNotOptimize(render::EstimateModeDifferences(
        scene.mesh, scene.mesh.normals, scene.camera, lights, material, kWidth, kHeight).gouraud);
    }
  }
  state.SetLabel(state.range(1) == 0 ? "ChooseMode" : "EstimateModeDifferences");
}

} // namespace

BENCHMARK(BM_AutoChoice)
  ->ArgsProduct({ { 0, 1 }, { 0, 1 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_CpuSmallFrame)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(BM_CpuMaterialChange)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CpuHalfOutside)
  ->ArgsProduct({ { 0, 1, 2 }, { 0, 1, 2 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_CpuParaViewSphere)->DenseRange(0, 4)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CpuScreenRecords)
  ->ArgsProduct({ { 0, 2 }, { 0, 1 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_Cpu)->Apply(CpuArgs)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CpuCookTorrance)
  ->ArgsProduct({ { 0, 1 }, { 0, 1, 2 }, { 1, 2 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_CpuSpectral)
  ->ArgsProduct({ { 0, 1 }, { 2 }, { 0, 1, 2 } })
  ->Unit(benchmark::kMillisecond)
  ->UseManualTime();
BENCHMARK(BM_ShadingLabGLSpectral)
  ->ArgsProduct({ { 0, 1 }, { 0, 1, 2, 3 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_MachineScaling)->DenseRange(0, 1)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_CpuThreadScaling)
  ->ArgsProduct({ { 0, 1 }, { 0, 1, 2, 3, 4, 5, 6, 7 } })
  ->Unit(benchmark::kMillisecond)
  ->UseManualTime();
BENCHMARK(BM_CpuModeBySize)
  ->ArgsProduct({ { 1, 2, 3, 4, 5, 6, 7 }, { 2, 3 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_CpuLanes)
  ->ArgsProduct({ { 0, 1 }, { kBlinnPhong, kCookTorrance }, { 1, 4, 8 }, { 1, 2 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_VtkOpenGL)
  ->Args({ 0, VTK_GOURAUD })
  ->Args({ 0, VTK_PHONG })
  ->Args({ 1, VTK_GOURAUD })
  ->Args({ 1, VTK_PHONG })
  ->Args({ 1, VTK_PBR })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_ShadingLabGL)
  ->Apply(GlArgs)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_ShadingLabCpuBackend)
  ->Apply(GlArgs)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();

BENCHMARK_MAIN();
