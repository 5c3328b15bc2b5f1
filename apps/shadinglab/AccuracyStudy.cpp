// SPDX-License-Identifier: BSD-3-Clause
#include "AccuracyStudy.h"

#include "AnalyticMeshes.h"
#include "MeshPreparation.h"
#include "PolyDataMesh.h"
#include "shadinglab/render/AutoMode.h"
#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/model/Materials.h"
#include "shadinglab/reference/AnalyticSurface.h"

#include "shadinglab/gl/GpuRenderer.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <thread>

namespace shadinglab::cli
{

namespace
{

using Clock = std::chrono::steady_clock;

double Milliseconds(Clock::time_point a, Clock::time_point b)
{
  return std::chrono::duration<double, std::milli>(b - a).count();
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

/// One warm-up frame (buffers, shader variant), then `frames` timed ones:
/// the median in ms; `image` gets the first timed frame.
double TimedFrames(render::Renderer& renderer, const render::Scene& scene,
  const render::RenderOptions& options, int frames, render::Image& image)
{
  renderer.Render(scene, options);
  std::vector<double> times;
  for (int f = 0; f < frames; ++f)
  {
    const auto t0 = Clock::now();
    const render::Image& out = renderer.Render(scene, options);
    times.push_back(Milliseconds(t0, Clock::now()));
    if (f == 0)
    {
      image = out;
    }
  }
  return Median(times);
}

struct Shape
{
  std::string name;
  std::unique_ptr<reference::AnalyticSurface> exact;
  std::function<vtkPolyData*(int)> tessellate;
  std::vector<int> levels;
};

std::vector<Shape> Shapes(bool quick)
{
  std::vector<Shape> shapes;
  // Levels run from a few dozen triangles to ~0.5-1M (UV sphere s x s/2
  // has ~s^2 triangles, the torus 2s x s has 4 s^2, the metaballs ~3 n^2).
  shapes.push_back({ "sphere", reference::MakeSphere(),
    [](int s) { return datasets::MakeUVSphere(s, s / 2); },
    quick ? std::vector<int>{ 8, 32, 128 } : std::vector<int>{ 8, 16, 32, 64, 128, 256, 1024 } });
  shapes.push_back({ "torus", reference::MakeTorus(1.0, 0.4),
    [](int s) { return datasets::MakeTorus(1.0, 0.4, 2 * s, s); },
    quick ? std::vector<int>{ 6, 24 } : std::vector<int>{ 4, 8, 16, 32, 64, 128, 362 } });
  if (!quick)
  {
    shapes.push_back({ "ellipsoid", reference::MakeEllipsoid(1.0, 0.7, 0.5),
      [](int s) { return datasets::MakeEllipsoid(1.0, 0.7, 0.5, s, s / 2); },
      { 8, 16, 32, 64, 128, 256 } });
    shapes.push_back({ "metaballs", reference::MakeMetaballs(),
      [](int n) { return datasets::MakeMetaballIsosurface(n); }, { 12, 20, 32, 48, 80, 128 } });
  }
  return shapes;
}

struct Shading
{
  render::ShadingMode mode;
  std::string model; ///< a name in the CSV
  Material<double> material;
};

Material<double> BlinnPhongPlastic()
{
  Material<double> m;
  m.model = ReflectanceModel::BlinnPhong;
  m.kd = 0.6;
  m.ks = 0.4;
  m.shininess = 60;
  m.diffuseColor = { 0.85, 0.35, 0.25 };
  return m;
}

std::vector<Shading> Shadings(bool quick)
{
  using M = render::ShadingMode;
  const Material<double> bp = BlinnPhongPlastic();
  Material<double> dielectric = FindMaterialPreset("plastic")->material;
  Material<double> conductor = FindMaterialPreset("gold")->material;
  std::vector<Shading> out;
  for (M mode : { M::Flat, M::Gouraud, M::Phong, M::FastPhong })
  {
    out.push_back({ mode, "blinn-phong", bp });
  }
  for (M mode : { M::Flat, M::Gouraud, M::Phong })
  {
    if (!quick || mode == M::Phong)
    {
      out.push_back({ mode, "ct-dielectric", dielectric });
    }
    if (!quick || mode == M::Gouraud)
    {
      out.push_back({ mode, "ct-conductor", conductor });
    }
  }
  return out;
}

/// Normals other than area-weighted are studied with Phong + Blinn-Phong,
/// the mode where the normal is all that differs.
struct NormalsChoice
{
  std::string name;
  mesh::PreparationOptions options;
};

std::vector<NormalsChoice> NormalChoices(bool quick)
{
  std::vector<NormalsChoice> out;
  auto weighted = [](const char* name, mesh::NormalWeighting w) {
    NormalsChoice c{ name, {} };
    c.options.repair = false;
    c.options.weighting = w;
    c.options.featureAngle = 180.0; // smooth analytic surfaces: no creases
    return c;
  };
  out.push_back(weighted("area", mesh::NormalWeighting::Area));
  if (!quick)
  {
    out.push_back(weighted("uniform", mesh::NormalWeighting::Uniform));
    out.push_back(weighted("angle", mesh::NormalWeighting::Angle));
    out.push_back(weighted("max", mesh::NormalWeighting::Max));
  }
  for (int levels = 1; levels <= (quick ? 1 : 2); ++levels)
  {
    NormalsChoice c{ "limit-L" + std::to_string(levels), {} };
    c.options.repair = false;
    c.options.subdivisionLevels = levels;
    c.options.scheme = mesh::SubdivisionScheme::Loop;
    c.options.featureAngle = 180.0;
    out.push_back(c);
  }
  return out;
}

/// Subdivision is studied on meshes it keeps under this many triangles:
/// beyond, a level costs more memory and time than the study should.
constexpr long long kMaxSubdividedTriangles = 1100000;
/// Rounds of the held-out check (one frame per mode per round): 15 frames
/// of 0.5-5 ms put each median within a few percent on this 2-core machine
/// (5 moved it by ~20%), for ~10 s in all.
constexpr int kAutoRounds = 15;

void Measure(const render::Image& image, const render::Image& exact, StudyRow& row)
{
  const std::vector<uint8_t> a8 = image.ToRGB8(render::DisplayTransform::Clamp);
  const std::vector<uint8_t> b8 = exact.ToRGB8(render::DisplayTransform::Clamp);
  std::vector<double> lin, d8;
  long either = 0, one = 0;
  for (size_t p = 0; p < image.covered.size(); ++p)
  {
    const bool a = image.covered[p], b = exact.covered[p];
    either += a || b;
    one += a != b;
    if (!(a && b))
    {
      continue;
    }
    double e = 0, e8 = 0;
    for (int c = 0; c < 3; ++c)
    {
      e = std::max(e, static_cast<double>(std::abs(image.rgb[3 * p + c] - exact.rgb[3 * p + c])));
      e8 = std::max(e8, std::abs(static_cast<double>(a8[3 * p + c]) - b8[3 * p + c]));
    }
    lin.push_back(e);
    d8.push_back(e8);
  }
  auto summarize = [](std::vector<double>& v, double& mean, double& rmse, double& p99,
                     double& max) {
    if (v.empty())
    {
      return;
    }
    double sum = 0, sq = 0;
    for (double x : v)
    {
      sum += x;
      sq += x * x;
      max = std::max(max, x);
    }
    mean = sum / v.size();
    rmse = std::sqrt(sq / v.size());
    const size_t k = v.size() * 99 / 100;
    std::nth_element(v.begin(), v.begin() + k, v.end());
    p99 = v[k];
  };
  summarize(lin, row.meanLinear, row.rmseLinear, row.p99Linear, row.maxLinear);
  summarize(d8, row.mean255, row.rmse255, row.p99_255, row.max255);
  row.coverageMismatch = either ? static_cast<double>(one) / either : 0.0;
}

} // namespace

const char* StudyCsvHeader()
{
  return "shape,level,triangles,backend,mode,model,normals,width,height,threads,prepare_ms,"
         "frame_ms,mean_lin,rmse_lin,p99_lin,max_lin,mean_255,rmse_255,p99_255,max_255,"
         "coverage_mismatch,pareto,normal_spread_deg,triangle_px,sharpness,peak,front_px,view,"
         "diff_flat_255,diff_gouraud_255,diff_normals_255";
}

std::string StudyCsvRow(const StudyRow& r)
{
  std::ostringstream s;
  s.precision(6);
  s << r.shape << ',' << r.level << ',' << r.triangles << ',' << r.backend << ',' << r.mode << ','
    << r.model << ',' << r.normals << ',' << r.width << ',' << r.height << ',' << r.threads << ','
    << r.prepareMs << ',' << r.frameMs << ',' << r.meanLinear << ',' << r.rmseLinear << ','
    << r.p99Linear << ',' << r.maxLinear << ',' << r.mean255 << ',' << r.rmse255 << ','
    << r.p99_255 << ',' << r.max255 << ',' << r.coverageMismatch << ',' << (r.pareto ? 1 : 0)
    << ',' << r.normalSpreadDeg << ',' << r.trianglePixels << ',' << r.sharpness << ',' << r.peak
    << ',' << r.frontPixels << ',' << r.view << ',' << r.diffFlat << ',' << r.diffGouraud << ',' << r.diffNormals;
  return s.str();
}

void MarkParetoFront(std::vector<StudyRow>& rows)
{
  for (StudyRow& r : rows)
  {
    // Against the same shape on the same backend only: errors of different
    // surfaces are not comparable.
    r.pareto = std::none_of(rows.begin(), rows.end(), [&](const StudyRow& o) {
      return o.shape == r.shape && o.backend == r.backend && o.view == r.view &&
        o.frameMs <= r.frameMs &&
        o.mean255 <= r.mean255 && (o.frameMs < r.frameMs || o.mean255 < r.mean255);
    });
  }
}

std::vector<StudyRow> RunStudy(
  const StudyOptions& options, const std::function<void(const StudyRow&)>& progress)
{
  std::vector<std::unique_ptr<render::Renderer>> renderers;
  renderers.push_back(std::make_unique<cpu::SoftwareRenderer>());
  if (options.gpu)
  {
    renderers.push_back(std::make_unique<gl::GpuRenderer>());
  }
  std::vector<StudyRow> rows;
  // Views (azimuth, elevation, zoom): the quick study has the first; the
  // auto mode's error model is fitted on all three (its held-out check uses
  // a fourth, ValidateAutoMode).
  const double views[3][3] = { { 25.0, 20.0, 1.0 }, { 120.0, 45.0, 0.9 }, { -100.0, -30.0, 1.1 } };
  const int viewCount = options.quick ? 1 : 3;
  for (const Shape& shape : Shapes(options.quick))
  for (int viewIndex = 0; viewIndex < viewCount; ++viewIndex)
  {
    double bounds[6];
    shape.exact->Bounds(bounds);
    const double aspect = static_cast<double>(options.width) / options.height;
    const render::Camera camera = render::FitCamera(
      bounds, views[viewIndex][0], views[viewIndex][1], views[viewIndex][2], aspect, false);
    Lighting<double> lighting;
    lighting.lights[0] = render::KeyLight(camera);
    const Vec3<float> background(0.0f, 0.0f, 0.0f);
    std::map<std::string, render::Image> references; // per model
    for (int level : shape.levels)
    {
      vtkSmartPointer<vtkPolyData> raw;
      raw.TakeReference(shape.tessellate(level));
      const long long rawTriangles = raw->GetNumberOfPolys();
      for (const NormalsChoice& normals : NormalChoices(options.quick))
      {
        if (normals.options.subdivisionLevels > 0 &&
          rawTriangles << (2 * normals.options.subdivisionLevels) > kMaxSubdividedTriangles)
        {
          continue;
        }
        std::vector<double> prepTimes;
        vtkSmartPointer<vtkPolyData> prepared;
        for (int i = 0; i < 3; ++i)
        {
          mesh::PreparationReport report;
          const auto t0 = Clock::now();
          prepared = mesh::PrepareMesh(raw, normals.options, report);
          prepTimes.push_back(Milliseconds(t0, Clock::now()));
        }
        const render::Mesh mesh = render::MeshFromPolyData(prepared);
        const render::ViewPredictors view =
          render::PredictorsOf(mesh, mesh.normals, camera, options.width, options.height);
        for (const Shading& shading : Shadings(options.quick))
        {
          const bool studyNormals = shading.mode == render::ShadingMode::Phong &&
            shading.model == "blinn-phong";
          if (normals.name != "area" && !studyNormals)
          {
            continue;
          }
          auto ref = references.find(shading.model);
          if (ref == references.end())
          {
            ref = references
                    .emplace(shading.model,
                      reference::RayCast(*shape.exact, camera, lighting, shading.material,
                        options.width, options.height, background))
                    .first;
          }
          for (auto& renderer : renderers)
          {
            render::Scene scene{ &mesh, camera, lighting, shading.material };
            render::RenderOptions ro;
            ro.mode = shading.mode;
            ro.width = options.width;
            ro.height = options.height;
            ro.threads = options.threads;
            ro.background = background;
            ro.fastPhongFallback = false; // the study measures fast Phong itself
            // Errors are measured in linear intensity clamped to [0, 1]
            // (docs/accuracy.md), on both backends.
            ro.display = render::DisplayTransform::Clamp;
            render::Image image;
            const double frameMs = TimedFrames(*renderer, scene, ro, options.frames, image);
            StudyRow row;
            row.shape = shape.name;
            row.view = viewIndex;
            row.level = level;
            row.triangles = mesh.NumberOfPolygons();
            row.backend = render::BackendName(renderer->GetBackend());
            row.mode = render::ShadingModeName(shading.mode);
            row.model = shading.model;
            row.normals = normals.name;
            row.width = options.width;
            row.height = options.height;
            row.threads = renderer->GetBackend() != render::Backend::CPU ? 0
              : options.threads > 0 ? options.threads
                                    : static_cast<int>(std::thread::hardware_concurrency());
            row.prepareMs = Median(prepTimes);
            row.frameMs = frameMs;
            Measure(image, ref->second, row);
            row.normalSpreadDeg = view.normalSpread * 180.0 / kPi<double>;
            row.trianglePixels = view.trianglePixels;
            row.sharpness = render::LobeSharpness(shading.material);
            row.peak = render::LobePeak(shading.material);
            row.frontPixels = view.frontPixels;
            const render::ModeDifferences diff = render::EstimateModeDifferences(
              mesh, mesh.normals, camera, lighting, shading.material, options.width, options.height);
            row.diffFlat = diff.flat;
            row.diffGouraud = diff.gouraud;
            row.diffNormals = diff.normals;
            rows.push_back(row);
            progress(row);
          }
        }
      }
    }
  }
  MarkParetoFront(rows);
  return rows;
}

std::vector<AutoCase> ValidateAutoMode(
  const StudyOptions& options, const std::function<void(const AutoCase&)>& progress)
{
  struct HeldOut
  {
    std::string name;
    std::unique_ptr<reference::AnalyticSurface> exact;
    vtkSmartPointer<vtkPolyData> mesh;
  };
  std::vector<HeldOut> meshes;
  auto add = [&](std::string name, std::unique_ptr<reference::AnalyticSurface> exact,
               vtkPolyData* mesh) {
    vtkSmartPointer<vtkPolyData> owned;
    owned.TakeReference(mesh);
    meshes.push_back({ std::move(name), std::move(exact), owned });
  };
  // Other shapes (a thin torus, a flattened ellipsoid), another tessellation
  // pattern (icospheres) and other sizes (metaballs) than the study's.
  const std::vector<int> tori = options.quick ? std::vector<int>{ 12, 48 } : std::vector<int>{ 10, 20, 40, 80 };
  for (int s : tori)
  {
    add("thin torus " + std::to_string(s), reference::MakeTorus(1.0, 0.25),
      datasets::MakeTorus(1.0, 0.25, 3 * s, s));
  }
  const std::vector<int> ellipsoids = options.quick ? std::vector<int>{ 24 } : std::vector<int>{ 12, 24, 48, 96 };
  for (int s : ellipsoids)
  {
    add("ellipsoid 1:0.5:0.8 " + std::to_string(s), reference::MakeEllipsoid(1.0, 0.5, 0.8),
      datasets::MakeEllipsoid(1.0, 0.5, 0.8, s, s / 2));
  }
  const std::vector<int> icospheres = options.quick ? std::vector<int>{ 2, 4 } : std::vector<int>{ 1, 2, 3, 4, 5 };
  for (int level : icospheres)
  {
    add("icosphere " + std::to_string(level), reference::MakeSphere(),
      datasets::MakeIcosphere(level));
  }
  if (!options.quick)
  {
    for (int n : { 16, 24, 40, 64 })
    {
      add("metaballs " + std::to_string(n), reference::MakeMetaballs(),
        datasets::MakeMetaballIsosurface(n));
    }
  }
  std::vector<std::pair<std::string, Material<double>>> materials;
  Material<double> dull = BlinnPhongPlastic();
  dull.shininess = 20;
  materials.push_back({ "blinn-phong n=20", dull });
  Material<double> sharp = BlinnPhongPlastic();
  sharp.shininess = 150;
  materials.push_back({ "blinn-phong n=150", sharp });
  Material<double> ct = FindMaterialPreset("plastic")->material;
  ct.lobes[0].m = 0.2;
  materials.push_back({ "ct-dielectric m=0.2", ct });
  materials.push_back({ "ct-conductor gold", FindMaterialPreset("gold")->material });
  const std::vector<double> budgets = { 0.5, 1.0, 2.0, 4.0 };
  cpu::SoftwareRenderer renderer;
  std::vector<AutoCase> cases;
  for (const HeldOut& h : meshes)
  {
    double bounds[6];
    h.exact->Bounds(bounds);
    // Another view than the study's (azimuth 25, elevation 20).
    const render::Camera camera = render::FitCamera(bounds, -50.0, -15.0, 1.2,
      static_cast<double>(options.width) / options.height, false);
    Lighting<double> lighting;
    lighting.lights[0] = render::KeyLight(camera);
    mesh::PreparationOptions prep;
    prep.repair = false;
    prep.featureAngle = 180.0;
    mesh::PreparationReport report;
    const render::Mesh mesh = render::MeshFromPolyData(mesh::PrepareMesh(h.mesh, prep, report));
    for (const auto& [materialName, material] : materials)
    {
      const render::Image exact = reference::RayCast(*h.exact, camera, lighting, material,
        options.width, options.height, Vec3<float>(0, 0, 0));
      // The three modes timed side by side, one frame of each per round, so
      // that a change of the machine's load falls on all three alike (frames
      // here take 0.5-5 ms: the medians of 5 separate frames moved by 20%).
      const render::ShadingMode modes[3] = { render::ShadingMode::Flat,
        render::ShadingMode::Gouraud, render::ShadingMode::Phong };
      const render::Scene scene{ &mesh, camera, lighting, material };
      std::vector<double> times[3];
      double errors[3] = { 0, 0, 0 };
      for (int round = -1; round < std::max(options.frames, kAutoRounds); ++round)
      {
        for (int k = 0; k < 3; ++k)
        {
          render::RenderOptions ro;
          ro.mode = modes[k];
          ro.width = options.width;
          ro.height = options.height;
          ro.threads = options.threads;
          ro.background = Vec3<float>(0, 0, 0);
          ro.display = render::DisplayTransform::Clamp; // as the study's other rows
          const auto t0 = Clock::now();
          const render::Image& image = renderer.Render(scene, ro);
          const double ms = Milliseconds(t0, Clock::now());
          if (round < 0) // a warm-up frame, measured for its error only
          {
            StudyRow row;
            Measure(image, exact, row);
            errors[k] = row.mean255;
          }
          else
          {
            times[k].push_back(ms);
          }
        }
      }
      double medianMs[3];
      for (int k = 0; k < 3; ++k)
      {
        medianMs[k] = Median(times[k]);
      }
      for (double budget : budgets)
      {
        const render::ModeChoice choice = render::ChooseMode(mesh, mesh.normals, camera,
          lighting, material, options.width, options.height, budget);
        AutoCase c;
        c.mesh = h.name;
        c.material = materialName;
        c.maxError = budget;
        c.chosen = render::ShadingModeName(choice.mode);
        c.predicted = choice.predicted;
        c.choice = choice;
        for (int k = 0; k < 3; ++k)
        {
          c.modeError[k] = errors[k];
          c.modeMs[k] = medianMs[k];
          if (modes[k] == choice.mode)
          {
            c.chosenError = errors[k];
            c.chosenMs = medianMs[k];
          }
          if (errors[k] <= budget && (c.cheapest.empty() || medianMs[k] < c.cheapestMs))
          {
            c.cheapest = render::ShadingModeName(modes[k]);
            c.cheapestMs = medianMs[k];
          }
        }
        c.met = c.chosenError <= budget;
        cases.push_back(c);
        progress(c);
      }
    }
  }
  return cases;
}

} // namespace shadinglab::cli
