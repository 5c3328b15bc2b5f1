// SPDX-License-Identifier: BSD-3-Clause
#include "SceneArguments.h"

#include "Commands.h"
#include "shadinglab/gl/GpuRenderer.h"
#include "MeshIO.h"
#include "MeshArrays.h"
#include "MeshPipeline.h"
#include "PolyDataMesh.h"
#include "VertexNormals.h"
#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/model/Materials.h"

#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace shadinglab::cli
{

std::string SceneOptionsHelp()
{
  return "Render options (from the settings table, shadinglab/render/Settings.h):\n" +
    render::CliHelp(render::SettingGroup::Render) +
    "  --mode cook-torrance is phong with --model cook-torrance; --mode auto keeps the mean error\n"
    "  under --max-error (default 1/255).\n"
    "  fast-phong expands N.L, N.H (blinn-phong) and N.V (phong: R.V = 2 N.L N.V - L.V) as\n"
    "  quadratics; it has no cook-torrance or lommel-seeliger form, and always interpolates in\n"
    "  screen space.\n"
    "\n"
    "Scene options:\n"
    "  --backend B                 cpu | gpu | auto (auto: gpu when an X display with OpenGL >= 3.2\n"
    "                              answers, unless it is a software rasterizer and the mesh has\n"
    "                              " + std::to_string(render::kAutoCpuMinPolygons) + " polygons or more; cpu otherwise, said on stderr)\n"
    "  --azimuth DEG --elevation DEG --zoom F   camera about the fitted view\n"
    "  --parallel                parallel projection\n"
    "  --camera-position X,Y,Z --focal-point X,Y,Z --view-up X,Y,Z --view-angle DEG\n"
    "  --light dir:X,Y,Z | point:X,Y,Z | spot:X,Y,Z:DX,DY,DZ:ANGLE[:EXP]\n"
    "                              (repeatable; world coordinates; dir points towards the light;\n"
    "                              default: one key light above-left of the camera)\n" +
    render::CliHelp(render::SettingGroup::Lights) +
    "\n"
    "Reading files:\n" +
    render::CliHelp(render::SettingGroup::Mesh) +
    "\n"
    "Mesh preparation:\n"
    "  --normals W                 recompute vertex normals: uniform | area | angle | max\n"
    "  --feature-angle DEG         crease angle for --normals / --subdivide (default 30)\n"
    "  --subdivide N [--scheme loop|catmull-clark]   OpenSubdiv refinement, limit normals\n"
    "  --weld [TOL] --fix-t-junctions   repair as 'shadinglab normals'\n"
    "\n";
}

namespace
{

Vec3<double> ParseVector(const std::string& text, const std::string& what)
{
  const auto v = ParseList(text, what);
  if (v.size() != 3)
  {
    throw UsageError(what + ": expected X,Y,Z");
  }
  return { v[0], v[1], v[2] };
}


/// The settings table's flags, the image size, the material and the backend.
void SettingsFromArguments(const Arguments& args, SceneArguments& scene)
{
  // Every render setting from the table; --mode cook-torrance is the
  // documented shorthand for phong with a Cook-Torrance material.
  render::Settings& settings = scene.settings;
  const bool cookTorranceShorthand = args.Get("mode") == "cook-torrance";
  if (cookTorranceShorthand && args.Has("model") && args.Get("model") != "cook-torrance")
  {
    throw UsageError("--mode cook-torrance contradicts --model " + args.Get("model"));
  }
  std::map<std::string, std::string> implied;
  if (cookTorranceShorthand)
  {
    implied["mode"] = "phong";
  }
  ApplySettingArguments(args, render::SettingGroup::Render, settings, implied);
  ApplySettingArguments(args, render::SettingGroup::Lights, settings);
  render::RenderOptions& options = settings.render;
  const bool autoMode = options.mode == render::ShadingMode::Auto;
  if (!autoMode && args.Has("max-error"))
  {
    throw UsageError("--max-error is for --mode auto");
  }
  {
    const std::string size = args.Get("size", "1024x768");
    const auto x = size.find('x');
    if (x == std::string::npos)
    {
      throw UsageError("--size must be WxH (got '" + size + "')");
    }
    const double w = ParseDouble(size.substr(0, x), "--size"),
                 h = ParseDouble(size.substr(x + 1), "--size");
    if (w != std::floor(w) || h != std::floor(h) || w < 1 || h < 1 ||
      w > render::kMaxImageSize || h > render::kMaxImageSize)
    {
      throw UsageError("--size must be WxH with integers 1.." +
        std::to_string(render::kMaxImageSize) + " (got '" + size + "')");
    }
    options.width = static_cast<int>(w);
    options.height = static_cast<int>(h);
  }
  const double zoom = args.GetDouble("zoom", 1.0);
  if (!(zoom > 0 && zoom <= 1e3))
  {
    throw UsageError("--zoom must be in (0, 1000]");
  }
  ApplyMaterialArguments(args, true, cookTorranceShorthand ? "cook-torrance" : "", settings);
  const Material<double>& material = settings.material;
  if (!render::SupportsModel(options.mode, material.model))
  {
    throw UsageError(std::string("fast-phong evaluates (N.L), (N.H)^n and (R.V)^n quadratics: use "
                                 "a lambert, phong or blinn-phong material (or another --mode for ") +
      ReflectanceModelName(material.model) + ")");
  }
  scene.scene.material = material;

  const std::string problem = render::ParseBackend(args.Get("backend", "auto"), scene.backend);
  if (!problem.empty())
  {
    throw UsageError(problem);
  }
  if (options.scan == render::ScanConversion::Incremental)
  {
    // The lecture's DDA is the CPU renderer's: auto takes it there.
    scene.cpuOnly = "--scan incremental is the CPU renderer's (the GPU's rasterizer interpolates "
                    "in hardware)";
  }
}

/// Concave polygons kept whole for --polygons direct's even-odd scan,
/// split by ear clipping otherwise (render::ScansPolygonsWhole).
render::PolygonHandling ConvertedPolygons(const SceneArguments& scene)
{
  return render::ScansPolygonsWhole(scene.settings.render) ? render::PolygonHandling::Direct
                                                          : render::PolygonHandling::Triangulate;
}

/// --color-by, --colormap, --range: the mesh with the array's values and
/// the colour map over the range asked for (or the data's).
void ColorByFromArguments(vtkPolyData* polydata, SceneArguments& scene)
{
  const std::string problem = render::MeshColoredBy(polydata, scene.frame, scene.settings.color,
    "--", scene.mesh, scene.colorMap, scene.colorTitle, ConvertedPolygons(scene));
  if (!problem.empty())
  {
    throw UsageError(problem);
  }
  scene.scene.colorMap = &scene.colorMap;
}

/// Appends one notice ("; " between notices).
void AddNotice(SceneArguments& scene, const std::string& notice)
{
  scene.notices += (scene.notices.empty() ? "" : "; ") + notice;
}

/// Reads INPUT, makes its faces' orientation consistent when they are not,
/// prepares it as asked (the filters of 'shadinglab normals') and converts
/// it to the renderers' arrays in a local frame.
void ReadAndPrepare(const Arguments& args, const std::string& input, SceneArguments& scene)
{
  vtkSmartPointer<vtkPolyData> polydata;
  const Stopwatch reading;
  try
  {
    polydata.TakeReference(ReadMesh(input, ReadOptionsFromArguments(args)));
  }
  catch (const MeshError& e)
  {
    throw UsageError(e.what());
  }
  scene.readMs = reading.Milliseconds();
  scene.readPeakMb = PeakRssMb();
  if (!scene.settings.color.array.empty())
  {
    // The arrays of the file as read: preparing adds Normals and
    // OriginalPointIds, which a misspelt name's error must not list.
    const std::string problem = render::CheckColorArray(polydata, scene.settings.color, "--");
    if (!problem.empty())
    {
      throw UsageError(problem);
    }
  }
  const Stopwatch preparing;
  scene.input = input;
  mesh::PreparationOptions preparation = MeshPipelineFromArguments(args, false);
  if (!WantsMeshPipeline(args))
  {
    // Faces whose neighbours run their shared edges the same way average
    // opposite normals into speckles: make the orientation consistent.
    if (polydata->GetNumberOfStrips() == 0 && mesh::InconsistentlyOriented(polydata))
    {
      preparation.repair = true;
      AddNotice(scene, "faces oriented inconsistently: made consistent (as 'normals' does)");
    }
    else
    {
      preparation.knownConsistent = polydata->GetNumberOfStrips() == 0;
    }
    // No normals and a smooth mode: the default normals, split at creases
    // as ParaView's Generate Surface Normals does (flat needs none).
    preparation.computeNormals = !polydata->GetPointData()->GetNormals() &&
      scene.settings.render.mode != render::ShadingMode::Flat;
    if (preparation.computeNormals)
    {
      char angle[32];
      std::snprintf(angle, sizeof angle, "%g", preparation.featureAngle);
      AddNotice(scene, std::string("no point normals: ") +
          mesh::NormalWeightingName(preparation.weighting) +
          "-weighted vertex normals made, split where faces meet at more than " + angle +
          " degrees (--feature-angle 180: not split)");
    }
  }
  if (preparation.repair || preparation.computeNormals)
  {
    // The same filters as 'shadinglab normals'.
    mesh::PreparationReport report;
    try
    {
      polydata = mesh::PrepareMesh(polydata, preparation, report);
      scene.normalsMade = preparation.computeNormals;
      mesh::ReleaseNormalScratch(); // made once: not kept for a next call
    }
    catch (const std::invalid_argument& e)
    {
      throw UsageError(e.what());
    }
  }
  // The mesh in a local frame (centred, unit size, converted from double):
  // camera and light positions given in world coordinates are mapped into
  // it below, so far-off or tiny meshes render like unit ones.
  if (scene.settings.color.array.empty())
  {
    // Not needed after: its cells go as soon as they are copied.
    scene.mesh =
      render::MeshFromPolyDataReleasing(std::move(polydata), scene.frame, ConvertedPolygons(scene));
  }
  else
  {
    ColorByFromArguments(polydata, scene);
  }
  scene.scene.mesh = &scene.mesh;
  // Made once and never changed: the renderer's caches keyed without
  // hashing the mesh.
  scene.scene.meshHash = render::UniqueMeshKey();
  scene.prepareMs = preparing.Milliseconds();

}

/// The material as drawn on this mesh (render::MaterialForData): a surface
/// coloured by data loses its highlights and grey ambient unless --ks or
/// --highlights on asks for them; what was kept or changed is noticed.
void DataColorFromArguments(const Arguments& args, SceneArguments& scene)
{
  render::Settings& settings = scene.settings;
  const bool colored = scene.scene.colorMap != nullptr;
  if (colored && args.Has("ks") && !args.Has("highlights"))
  {
    settings.highlights = render::Highlights::On; // an explicit --ks is honoured
  }
  scene.scene.material = render::MaterialForData(settings.material, settings.highlights, colored);
  const std::string notice =
    render::DataColorNotice(settings.material, settings.highlights, colored, settings.preset);
  if (!notice.empty())
  {
    AddNotice(scene, notice);
  }
}

/// The camera fitted to the mesh and moved by the camera flags.
void CameraFromArguments(const Arguments& args, SceneArguments& scene)
{
  const render::Mesh& mesh = scene.mesh;
  const render::RenderOptions& options = scene.settings.render;
  const double zoom = args.GetDouble("zoom", 1.0); // checked by SettingsFromArguments
  double bounds[6];
  mesh.Bounds(bounds);
  const double aspect = static_cast<double>(options.width) / options.height;
  render::Camera& camera = scene.scene.camera;
  camera = render::FitCamera(bounds, args.GetDouble("azimuth", 0.0),
    args.GetDouble("elevation", 0.0), zoom, aspect, args.Has("parallel"));
  if (!camera.parallel && !(camera.viewAngle < 180.0))
  {
    throw UsageError("--zoom " + args.Get("zoom") + " widens the view angle to " +
      std::to_string(camera.viewAngle) + " degrees (must stay below 180)");
  }
  if (args.Has("camera-position") || args.Has("focal-point"))
  {
    if (args.Has("camera-position"))
    {
      camera.position =
        scene.frame.ToLocal(ParseVector(args.Get("camera-position"), "--camera-position"));
    }
    if (args.Has("focal-point"))
    {
      camera.focalPoint =
        scene.frame.ToLocal(ParseVector(args.Get("focal-point"), "--focal-point"));
    }
    if (Length(camera.position - camera.focalPoint) <= 0)
    {
      throw UsageError("--camera-position and --focal-point coincide");
    }
    // Near/far from the bounds as seen from the new position.
    const Vec3<double> center(0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
      0.5 * (bounds[4] + bounds[5]));
    const double radius = 0.5 *
      Length(Vec3<double>(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]));
    const double d = Length(camera.position - center);
    camera.farClip = d + 1.01 * radius + 1e-6;
    camera.nearClip = std::max(1e-4 * camera.farClip, d - 1.01 * radius);
  }
  if (args.Has("view-up"))
  {
    camera.viewUp = ParseVector(args.Get("view-up"), "--view-up");
    // The up vector must have a direction, and one not along the view.
    const Vec3<double> forward = camera.focalPoint - camera.position;
    if (!(Length(Cross(camera.viewUp, forward)) > 1e-9 * Length(camera.viewUp) * Length(forward)))
    {
      throw UsageError("--view-up must be non-zero and not parallel to the view direction");
    }
  }
  if (args.Has("view-angle"))
  {
    camera.viewAngle = args.GetDouble("view-angle", 30.0);
    if (!(camera.viewAngle > 0 && camera.viewAngle < 180))
    {
      throw UsageError("--view-angle must be in (0, 180)");
    }
  }

}

/// The --light flags (world coordinates), or the default key light.
void LightsFromArguments(const Arguments& args, SceneArguments& scene)
{
  const double lightIntensity = scene.settings.lightIntensity;
  const render::Camera& camera = scene.scene.camera;
  Lighting<double>& lighting = scene.scene.lighting;
  lighting.lightCount = 0;
  const auto lights = args.GetAll("light");
  if (lights.size() > static_cast<size_t>(kMaxLights))
  {
    throw UsageError("at most " + std::to_string(kMaxLights) + " --light options");
  }
  for (const auto& spec : lights)
  {
    Light<double> light;
    if (spec.rfind("dir:", 0) == 0)
    {
      light.type = LightType::Directional;
      light.vector = ParseVector(spec.substr(4), "--light dir");
      if (!(Length(light.vector) > 0))
      {
        throw UsageError("--light dir: direction has zero length");
      }
    }
    else if (spec.rfind("point:", 0) == 0)
    {
      light.type = LightType::Point;
      light.vector = ParseVector(spec.substr(6), "--light point");
    }
    else if (spec.rfind("spot:", 0) == 0)
    {
      // spot:X,Y,Z:DX,DY,DZ:ANGLE[:EXPONENT]
      std::vector<std::string> parts;
      std::stringstream ss(spec.substr(5));
      std::string part;
      while (std::getline(ss, part, ':'))
      {
        parts.push_back(part);
      }
      if (parts.size() < 3 || parts.size() > 4)
      {
        throw UsageError("--light spot:X,Y,Z:DX,DY,DZ:ANGLE[:EXPONENT] (got '" + spec + "')");
      }
      light.type = LightType::Point;
      light.vector = ParseVector(parts[0], "--light spot position");
      light.spotDirection = ParseVector(parts[1], "--light spot direction");
      light.coneAngle = ParseDouble(parts[2], "--light spot angle");
      light.coneExponent = parts.size() == 4 ? ParseDouble(parts[3], "--light spot exponent") : 1.0;
      if (!(Length(light.spotDirection) > 0) || !(light.coneAngle > 0 && light.coneAngle <= 90) ||
        !(light.coneExponent >= 0 && light.coneExponent <= 128))
      {
        throw UsageError(
          "--light spot: direction must be non-zero, angle in (0, 90], exponent in [0, 128]");
      }
    }
    else
    {
      throw UsageError("--light must be dir:X,Y,Z, point:X,Y,Z or spot:X,Y,Z:DX,DY,DZ:ANGLE[:EXP] "
                       "(got '" + spec + "')");
    }
    light.intensity = Vec3<double>(lightIntensity, lightIntensity, lightIntensity);
    lighting.lights[lighting.lightCount++] = light;
  }
  if (lighting.lightCount == 0)
  {
    lighting = render::LightKit(camera, lightIntensity);
  }
  else
  {
    render::ToLocal(scene.frame, lighting); // the given lights are in world coordinates
  }
  for (int k = 0; k < lighting.lightCount; ++k)
  {
    lighting.lights[k].solidAngle = scene.settings.lightSolidAngle;
  }
  lighting.ambientIntensity = Vec3<double>(1, 1, 1);

}

} // namespace

std::unique_ptr<SceneArguments> SceneFromArguments(int argc, char** argv, const std::string& help,
  const std::vector<std::string>& extraValued)
{
  std::vector<std::string> valued = { "backend", "size", "out", "azimuth", "elevation", "zoom",
    "camera-position", "focal-point", "view-up", "view-angle", "normals", "feature-angle",
    "subdivide", "scheme", "time", "time-step" };
  std::vector<std::string> flags = { "help", "stats", "parallel", "fix-t-junctions" };
  for (auto group : { render::SettingGroup::Render, render::SettingGroup::Lights,
         render::SettingGroup::Material, render::SettingGroup::Mesh })
  {
    AddSettingFlags(valued, flags, group);
  }
  valued.insert(valued.end(), extraValued.begin(), extraValued.end());
  auto result =
    std::make_unique<SceneArguments>(Arguments(argc, argv, valued, flags, { "light" }, { "weld" }));
  SceneArguments& scene = *result;
  const Arguments& args = scene.args;
  if (args.Has("help"))
  {
    std::cout << help << SceneOptionsHelp() << MaterialHelp();
    scene.helpShown = true;
    return result;
  }
  if (args.Positionals().size() != 1)
  {
    throw UsageError(args.Positionals().empty() ? "missing INPUT mesh" : "more than one INPUT given");
  }
  const std::string input = args.Positionals()[0];

  SettingsFromArguments(args, scene);
  ReadAndPrepare(args, input, scene);
  DataColorFromArguments(args, scene);
  const Stopwatch placing;
  CameraFromArguments(args, scene);
  LightsFromArguments(args, scene);
  scene.prepareMs += placing.Milliseconds();
  scene.preparePeakMb = PeakRssMb();
  return result;
}

std::unique_ptr<render::Renderer> MakeRenderer(const SceneArguments& scene, std::string cpuOnly,
  const char* command, std::string& autoNotice)
{
  render::BackendFacts facts;
  facts.cpuOnly = cpuOnly.empty() ? scene.cpuOnly : std::move(cpuOnly);
  facts.polygons = scene.mesh.NumberOfPolygons();
  if (scene.backend != render::Backend::CPU && facts.cpuOnly.empty())
  {
    facts.glUsable = gl::GpuAvailable(
      facts.glProblem, scene.backend == render::Backend::Auto ? &facts.glRenderer : nullptr);
  }
  const render::BackendChoice choice = render::ChooseBackend(scene.backend, facts);
  if (!choice.conflict.empty())
  {
    throw UsageError(facts.glUsable ? choice.conflict + ": use --backend cpu or auto"
                                    : "--backend gpu: " + choice.conflict);
  }
  if (choice.backend == render::Backend::GPU)
  {
    return std::make_unique<gl::GpuRenderer>();
  }
  if (scene.backend == render::Backend::Auto)
  {
    autoNotice = std::string("shadinglab ") + command + ": backend auto: " + choice.why +
      "; using the CPU renderer\n";
  }
  return std::make_unique<cpu::SoftwareRenderer>();
}

const render::Image& RenderOrExplain(render::Renderer& renderer, const render::Scene& scene,
  const render::RenderOptions& options, render::RenderStats* stats, const std::string& context)
{
  try
  {
    return renderer.Render(scene, options, stats);
  }
  catch (const std::invalid_argument& e)
  {
    throw UsageError(e.what() + context);
  }
  catch (const std::runtime_error& e)
  {
    throw UsageError(e.what() + context);
  }
}


} // namespace shadinglab::cli
