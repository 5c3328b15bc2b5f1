// SPDX-License-Identifier: BSD-3-Clause
#include "SceneArguments.h"

#include "Commands.h"
#include "GpuRenderer.h"
#include "MeshIO.h"
#include "MeshArrays.h"
#include "MeshPipeline.h"
#include "RepairCheck.h"
#include "PolyDataMesh.h"
#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/render/AutoMode.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace shadinglab::cli
{

const char* const kSceneOptionsHelp =
  "  --mode M            where the model is evaluated: flat | gouraud | phong | fast-phong\n"
  "                      (default phong); cook-torrance = phong with --model cook-torrance;\n"
  "                      auto = the cheapest of flat, gouraud, phong predicted to keep the\n"
  "                      mean error under --max-error E (1/255; docs/model.md eq. 4.1-4.5)\n"
      "  --backend B         cpu | gpu | auto (auto: gpu when an X display with OpenGL >= 3.2\n"
  "                      exists, cpu otherwise, said on stderr)\n"
  "  --interp I          perspective (perspective-correct, default) | screen (linear in\n"
  "                      screen space, as the lecture: shows perspective distortion)\n"
  "  --polygons P        triangulate (default) | direct (scan-convert polygons as such:\n"
  "                      shows orientation dependence)\n"
  "  --azimuth DEG --elevation DEG --zoom F   camera about the fitted view\n"
  "  --parallel          parallel projection\n"
  "  --camera-position X,Y,Z --focal-point X,Y,Z --view-up X,Y,Z --view-angle DEG\n"
  "  --light dir:X,Y,Z | point:X,Y,Z | spot:X,Y,Z:DX,DY,DZ:ANGLE[:EXP]\n"
  "                      (repeatable; world coordinates; dir points towards the light;\n"
  "                      default: one key light above-left of the camera)\n"
  "  --light-intensity I  intensity of every light (default 1)\n"
  "  --ssaa N            supersampling N x N (default 1)\n"
  "  --threads N         worker threads (default: all cores)\n"
  "  --cull              cull back faces\n"
  "  --fast-phong-as-is  fast-phong with its quadratics even on triangles too small\n"
  "                      for them to pay (cpu; default: exact Phong there, said on stderr)\n"
  "  --display D         clamp (default) | srgb\n"
  "  --expansion E       fast-phong Taylor point: vertex (the provoking vertex, default;\n"
  "                      both backends) | centroid (lower error; cpu only)\n"
  "  --fast-phong-max-spread DEG  fast-phong evaluates a pixel exactly where its normal is\n"
  "                      more than DEG from the expansion point's (default 30; 180 shows\n"
  "                      the raw Taylor quadratic everywhere, artifacts included)\n"
    "  --normals W         recompute vertex normals: uniform | area | angle | max\n"
  "  --feature-angle DEG crease angle for --normals / --subdivide (default 30)\n"
  "  --subdivide N [--scheme loop|catmull-clark]   OpenSubdiv refinement, limit normals\n"
  "  --weld [TOL] --fix-t-junctions   repair as 'shadinglab normals'\n"
  "\n"
  "fast-phong expands N.L, N.H (blinn-phong) and N.V (phong: R.V = 2 N.L N.V - L.V) as\n"
  "quadratics; it has no cook-torrance form, and always interpolates in screen space.\n"
  "\n";

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

} // namespace

std::unique_ptr<SceneArguments> SceneFromArguments(int argc, char** argv, const std::string& help,
  const std::vector<std::string>& extraValued)
{
  std::vector<std::string> valued = { "backend", "mode", "max-error", "size", "out", "interp", "polygons",
    "azimuth", "elevation", "zoom", "camera-position", "focal-point", "view-up", "view-angle",
    "light-intensity", "ssaa", "threads", "display", "expansion", "fast-phong-max-spread",
    "normals", "feature-angle", "subdivide", "scheme" };
  for (const auto& o : MaterialOptions())
  {
    valued.push_back(o);
  }
  valued.insert(valued.end(), extraValued.begin(), extraValued.end());
  auto result = std::make_unique<SceneArguments>(Arguments(
    argc, argv, valued, { "help", "stats", "cull", "parallel", "fix-t-junctions", "fast-phong-as-is" }, { "light" }, { "weld" }));
  SceneArguments& scene = *result;
  const Arguments& args = scene.args;
  if (args.Has("help"))
  {
    std::cout << help << kSceneOptionsHelp << MaterialHelp();
    scene.helpShown = true;
    return result;
  }
  if (args.Positionals().size() != 1)
  {
    throw UsageError(args.Positionals().empty() ? "missing INPUT mesh" : "more than one INPUT given");
  }
  const std::string input = args.Positionals()[0];

  render::RenderOptions& options = scene.options;
  // --mode cook-torrance: the documented shorthand for per-pixel (phong)
  // interpolation of a Cook-Torrance material.
  const std::string modeName = args.Get("mode", "phong");
  const bool cookTorranceShorthand = modeName == "cook-torrance";
  const bool autoMode = modeName == "auto";
  double maxError = 0;
  if (autoMode)
  {
    if (!args.Has("max-error"))
    {
      throw UsageError("--mode auto needs --max-error E (the mean error allowed, in 1/255)");
    }
    maxError = ParseDouble(args.Get("max-error"), "--max-error");
    // Below 0.01/255 no mode is predicted to comply (the fit's floor);
    // above 255 every mode does.
    if (!(maxError >= 0.01 && maxError <= 255))
    {
      throw UsageError("--max-error must be in [0.01, 255] (1/255 units)");
    }
    options.mode = render::ShadingMode::Phong; // until the choice below
  }
  else if (args.Has("max-error"))
  {
    throw UsageError("--max-error is for --mode auto");
  }
  if (!autoMode && !cookTorranceShorthand && !render::ParseShadingMode(modeName, options.mode))
  {
    throw UsageError("unknown --mode '" + modeName + "' (expected " +
      render::ShadingModeChoices() + ", or cook-torrance for phong with --model cook-torrance)");
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
    if (w != std::floor(w) || h != std::floor(h) || w < 1 || h < 1 || w > render::kMaxImageSize || h > render::kMaxImageSize)
    {
      throw UsageError("--size must be WxH with integers 1.." + std::to_string(render::kMaxImageSize) + " (got '" + size + "')");
    }
    options.width = static_cast<int>(w);
    options.height = static_cast<int>(h);
  }
  const std::string interp = args.Get("interp", "perspective");
  if (!render::ParseInterpolationSpace(interp, options.interpolation))
  {
    throw UsageError("unknown --interp '" + interp + "' (expected perspective or screen)");
  }
  const std::string polygons = args.Get("polygons", "triangulate");
  if (polygons == "triangulate")
  {
    options.polygons = render::PolygonHandling::Triangulate;
  }
  else if (polygons == "direct")
  {
    options.polygons = render::PolygonHandling::Direct;
  }
  else
  {
    throw UsageError("unknown --polygons '" + polygons + "' (expected triangulate or direct)");
  }
  const std::string expansion = args.Get("expansion", "vertex");
  if (expansion == "centroid" || expansion == "vertex")
  {
    options.expansion = expansion == "vertex" ? ExpansionPoint::Vertex : ExpansionPoint::Centroid;
  }
  else
  {
    throw UsageError("unknown --expansion '" + expansion + "' (expected centroid or vertex)");
  }
  const std::string displayName = args.Get("display", "clamp");
  render::DisplayTransform& display = scene.display;
  if (displayName == "srgb")
  {
    display = render::DisplayTransform::SRGB;
  }
  else if (displayName != "clamp")
  {
    throw UsageError("unknown --display '" + displayName + "' (expected clamp or srgb)");
  }
  options.ssaa = args.GetInt("ssaa", 1);
  if (options.ssaa < 1 || options.ssaa > render::kMaxSupersampling)
  {
    throw UsageError("--ssaa must be 1.." + std::to_string(render::kMaxSupersampling));
  }
  options.threads = args.GetInt("threads", 0);
  if (options.threads < 0 || options.threads > 256)
  {
    throw UsageError("--threads must be 0..256");
  }
  options.cullBackFaces = args.Has("cull");
  options.fastPhongFallback = !args.Has("fast-phong-as-is");
  options.fastPhongMaxSpread = args.GetDouble("fast-phong-max-spread", 30.0);
  if (!(options.fastPhongMaxSpread >= 0 && options.fastPhongMaxSpread <= 180))
  {
    throw UsageError("--fast-phong-max-spread must be in [0, 180] degrees");
  }
  const double zoom = args.GetDouble("zoom", 1.0);
  if (!(zoom > 0 && zoom <= 1e3))
  {
    throw UsageError("--zoom must be in (0, 1000]");
  }
  const double lightIntensity = args.GetDouble("light-intensity", 1.0);
  if (!(lightIntensity >= 0 && lightIntensity <= 1e6))
  {
    throw UsageError("--light-intensity must be in [0, 1e6]");
  }
  Material<double>& material = scene.scene.material;
  if (cookTorranceShorthand)
  {
    if (args.Has("model") && args.Get("model") != "cook-torrance")
    {
      throw UsageError("--mode cook-torrance contradicts --model " + args.Get("model"));
    }
    // The shorthand: phong interpolation with a Cook-Torrance material,
    // validated like any other (MaterialFromArguments with that model).
    std::vector<std::string> extended(argv, argv + argc);
    extended.push_back("--model");
    extended.push_back("cook-torrance");
    std::vector<char*> raw;
    for (auto& a : extended)
    {
      raw.push_back(a.data());
    }
    if (!args.Has("model"))
    {
      const Arguments withModel(static_cast<int>(raw.size()), raw.data(), valued,
        { "help", "stats", "cull", "parallel", "fix-t-junctions", "fast-phong-as-is" }, { "light" }, { "weld" });
      material = MaterialFromArguments(withModel, true);
    }
    else
    {
      material = MaterialFromArguments(args, true);
    }
    options.mode = render::ShadingMode::Phong;
  }
  else
  {
    material = MaterialFromArguments(args, true);
  }
  if (!render::SupportsModel(options.mode, material.model))
  {
    throw UsageError("fast-phong evaluates (N.L), (N.H)^n and (R.V)^n quadratics: use a lambert, "
                     "phong or blinn-phong material (or another --mode for cook-torrance)");
  }

  const std::string& backend = scene.backend = args.Get("backend", "auto");
  if (backend != "cpu" && backend != "auto" && backend != "gpu")
  {
    throw UsageError("unknown --backend '" + backend + "' (expected auto, cpu or gpu)");
  }

  vtkSmartPointer<vtkPolyData> polydata;
  const Stopwatch reading;
  try
  {
    polydata.TakeReference(ReadMesh(input));
  }
  catch (const MeshError& e)
  {
    throw UsageError(e.what());
  }
  scene.readMs = reading.Milliseconds();
  const Stopwatch preparing;
  scene.input = input;
  mesh::PreparationOptions preparation = MeshPipelineFromArguments(args, false);
  if (!WantsMeshPipeline(args))
  {
    // Faces whose neighbours run their shared edges the same way average
    // opposite normals into speckles: make the orientation consistent
    // (only the repair; the renderers make their own normals).
    mesh::FlatPolygons flat;
    mesh::FlatPolygonsFromPolyData(polydata, flat);
    if (polydata->GetNumberOfStrips() == 0 && mesh::CheckRepairNeeds(flat).inconsistentEdges > 0)
    {
      preparation.repair = true;
      preparation.computeNormals = false;
      scene.notices += "faces oriented inconsistently: made consistent (as 'normals' does)";
    }
  }
  if (preparation.repair)
  {
    // The same filters as 'shadinglab normals'.
    mesh::PreparationReport report;
    try
    {
      polydata = mesh::PrepareMesh(polydata, preparation, report);
    }
    catch (const std::invalid_argument& e)
    {
      throw UsageError(e.what());
    }
  }
  // The mesh in a local frame (centred, unit size, converted from double):
  // camera and light positions given in world coordinates are mapped into
  // it below, so far-off or tiny meshes render like unit ones.
  scene.mesh = render::MeshFromPolyData(polydata, scene.frame);
  scene.scene.mesh = &scene.mesh;
  const render::Mesh& mesh = scene.mesh;

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
    lighting.lights[0] = render::KeyLight(camera, lightIntensity);
    lighting.lightCount = 1;
  }
  else
  {
    render::ToLocal(scene.frame, lighting); // the given lights are in world coordinates
  }
  lighting.ambientIntensity = Vec3<double>(1, 1, 1);

  if (autoMode)
  {
    // The renderers' normals when the mesh has none: area-weighted.
    const std::vector<float> normals =
      result->mesh.normals.empty() ? cpu::AreaWeightedNormals(result->mesh) : result->mesh.normals;
    const render::ModeChoice choice = render::ChooseMode(result->mesh, normals,
      scene.scene.camera, lighting, scene.scene.material, options.width, options.height, maxError);
    options.mode = choice.mode;
    result->autoChoice = choice.why;
  }
  result->prepareMs = preparing.Milliseconds();
  return result;
}

std::unique_ptr<render::Renderer> MakeRenderer(
  const std::string& backend, const char* command, std::string& autoNotice)
{
  if (backend == "cpu")
  {
    return std::make_unique<cpu::SoftwareRenderer>();
  }
  std::string why;
  if (gl::GpuAvailable(why))
  {
    return std::make_unique<gl::GpuRenderer>();
  }
  if (backend == "gpu")
  {
    throw UsageError("--backend gpu: " + why);
  }
  autoNotice = std::string("shadinglab ") + command + ": backend auto: " + why +
    "; using the CPU renderer\n";
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
