// SPDX-License-Identifier: BSD-3-Clause
// shadinglab render: one image of a mesh in one shading mode.
#include "Commands.h"

#include "MeshIO.h"
#include "GpuRenderer.h"
#include "MeshPipeline.h"
#include "PolyDataMesh.h"
#include "shadinglab/cpu/SoftwareRenderer.h"

#include <vtkFreeTypeTools.h>
#include <vtkImageData.h>
#include <vtkTextProperty.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkPointData.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace shadinglab::cli
{

namespace
{

const char* kRenderHelp =
  "usage: shadinglab render INPUT [--backend auto|cpu|gpu] [--mode MODE] [--size WxH]\n"
  "                         [--out OUT.png] [options]\n"
  "\n"
  "INPUT: .vtp .vtk .vtu .ply .obj .stl .off\n"
  "  --mode M            flat | gouraud | phong | fast-phong | cook-torrance (default phong)\n"
  "  --size WxH          image size (default 1024x768)\n"
  "  --out FILE.png      output image (default out.png)\n"
  "  --backend B         cpu | gpu | auto (default auto: gpu when an X display with\n"
  "                      OpenGL >= 3.2 exists, cpu otherwise, said on stderr)\n"
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
  "  --display D         clamp (default) | srgb\n"
  "  --expansion E       fast-phong Taylor point: centroid (default) | vertex\n"
  "  --fast-phong-max-spread DEG  fast-phong evaluates a triangle exactly when its vertex\n"
  "                      normals spread more than DEG (default 30; 180 shows the raw\n"
  "                      Taylor quadratic everywhere, artifacts included)\n"
  "  --stats             print one JSON line of timings and counts\n"
  "  --normals W         recompute vertex normals: uniform | area | angle | max\n"
  "  --feature-angle DEG crease angle for --normals / --subdivide (default 30)\n"
  "  --subdivide N [--scheme loop|catmull-clark]   OpenSubdiv refinement, limit normals\n"
  "  --weld [TOL] --fix-t-junctions   repair as 'shadinglab normals'\n"
  "\n"
  "fast-phong uses Blinn's (N.H)^n for the specular term (a phong material's (R.V)^n\n"
  "has no affine-normal form) and always interpolates in screen space.\n"
  "\n";

Vec3<double> ParseVector(const std::string& text, const std::string& what)
{
  const auto v = ParseList(text, what);
  if (v.size() != 3)
  {
    throw UsageError(what + ": expected X,Y,Z");
  }
  return { v[0], v[1], v[2] };
}

void WritePng(const cpu::Image& image, const std::vector<uint8_t>& rgb8, const std::string& path)
{
  vtkNew<vtkImageData> vtkImage;
  vtkImage->SetDimensions(image.width, image.height, 1);
  vtkNew<vtkUnsignedCharArray> pixels;
  pixels->SetNumberOfComponents(3);
  pixels->SetNumberOfTuples(static_cast<vtkIdType>(image.width) * image.height);
  // VTK images start at the bottom row.
  for (int y = 0; y < image.height; ++y)
  {
    const int src = image.height - 1 - y;
    for (int x = 0; x < image.width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        pixels->SetTypedComponent(static_cast<vtkIdType>(y) * image.width + x, c,
          rgb8[(static_cast<size_t>(src) * image.width + x) * 3 + c]);
      }
    }
  }
  vtkImage->GetPointData()->SetScalars(pixels);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(vtkImage);
  writer->SetFileName(path.c_str());
  // VTK reports an unopenable file in several log lines: keep them quiet and
  // say it once.
  const int warnings = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOff();
  writer->Write();
  vtkObject::SetGlobalWarningDisplay(warnings);
  if (writer->GetErrorCode() != 0)
  {
    throw UsageError("cannot write '" + path + "' (missing directory, no permission or disk full?)");
  }
}

} // namespace

/// Everything a render needs, parsed from the command line and the input file.
struct Scene
{
  explicit Scene(Arguments arguments)
    : args(std::move(arguments))
  {
  }
  Arguments args;
  bool helpShown = false;
  vtkSmartPointer<vtkPolyData> polydata;
  std::string input;
  std::string backend;
  cpu::Mesh mesh;
  cpu::Camera camera;
  Lighting<double> lighting;
  Material<double> material;
  cpu::RenderOptions options;
  cpu::DisplayTransform display = cpu::DisplayTransform::Clamp;
};

Scene SceneFromArguments(int argc, char** argv, const char* help, bool compare)
{
  std::vector<std::string> valued = { "backend", "mode", "size", "out", "interp", "polygons",
    "azimuth", "elevation", "zoom", "camera-position", "focal-point", "view-up", "view-angle",
    "light-intensity", "ssaa", "threads", "display", "expansion", "fast-phong-max-spread",
    "normals", "feature-angle", "subdivide", "scheme" };
  for (const auto& o : MaterialOptions())
  {
    valued.push_back(o);
  }
  if (compare)
  {
    valued.push_back("modes");
  }
  Scene scene{ Arguments(
    argc, argv, valued, { "help", "stats", "cull", "parallel", "fix-t-junctions" }, { "light" }, { "weld" }) };
  const Arguments& args = scene.args;
  if (args.Has("help"))
  {
    std::cout << help << MaterialHelp();
    scene.helpShown = true;
    return scene;
  }
  if (args.Positionals().size() != 1)
  {
    throw UsageError(args.Positionals().empty() ? "missing INPUT mesh" : "more than one INPUT given");
  }
  const std::string input = args.Positionals()[0];

  cpu::RenderOptions& options = scene.options;
  if (!cpu::ParseMode(args.Get("mode", "phong"), options.mode))
  {
    throw UsageError("unknown --mode '" + args.Get("mode") +
      "' (expected flat, gouraud, phong, fast-phong or cook-torrance)");
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
    if (w != std::floor(w) || h != std::floor(h) || w < 1 || h < 1 || w > 16384 || h > 16384)
    {
      throw UsageError("--size must be WxH with integers 1..16384 (got '" + size + "')");
    }
    options.width = static_cast<int>(w);
    options.height = static_cast<int>(h);
  }
  const std::string interp = args.Get("interp", "perspective");
  if (interp == "perspective")
  {
    options.interpolation = cpu::InterpolationSpace::Perspective;
  }
  else if (interp == "screen")
  {
    options.interpolation = cpu::InterpolationSpace::Screen;
  }
  else
  {
    throw UsageError("unknown --interp '" + interp + "' (expected perspective or screen)");
  }
  const std::string polygons = args.Get("polygons", "triangulate");
  if (polygons == "triangulate")
  {
    options.polygons = cpu::PolygonHandling::Triangulate;
  }
  else if (polygons == "direct")
  {
    options.polygons = cpu::PolygonHandling::Direct;
  }
  else
  {
    throw UsageError("unknown --polygons '" + polygons + "' (expected triangulate or direct)");
  }
  const std::string expansion = args.Get("expansion", "centroid");
  if (expansion == "centroid" || expansion == "vertex")
  {
    options.expansion = expansion == "vertex" ? ExpansionPoint::Vertex : ExpansionPoint::Centroid;
  }
  else
  {
    throw UsageError("unknown --expansion '" + expansion + "' (expected centroid or vertex)");
  }
  const std::string displayName = args.Get("display", "clamp");
  cpu::DisplayTransform& display = scene.display;
  if (displayName == "srgb")
  {
    display = cpu::DisplayTransform::SRGB;
  }
  else if (displayName != "clamp")
  {
    throw UsageError("unknown --display '" + displayName + "' (expected clamp or srgb)");
  }
  options.ssaa = args.GetInt("ssaa", 1);
  if (options.ssaa < 1 || options.ssaa > 8)
  {
    throw UsageError("--ssaa must be 1..8");
  }
  options.threads = args.GetInt("threads", 0);
  if (options.threads < 0 || options.threads > 256)
  {
    throw UsageError("--threads must be 0..256");
  }
  options.cullBackFaces = args.Has("cull");
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
  scene.material = MaterialFromArguments(args, true);

  const std::string& backend = scene.backend = args.Get("backend", "auto");
  if (backend != "cpu" && backend != "auto" && backend != "gpu")
  {
    throw UsageError("unknown --backend '" + backend + "' (expected auto, cpu or gpu)");
  }

  vtkSmartPointer<vtkPolyData> polydata;
  try
  {
    polydata.TakeReference(ReadMesh(input));
  }
  catch (const MeshError& e)
  {
    throw UsageError(e.what());
  }
  scene.input = input;
  if (WantsMeshPipeline(args))
  {
    // The same filters as 'shadinglab normals'.
    MeshPipelineReport report;
    polydata = RunMeshPipeline(polydata, MeshPipelineFromArguments(args, false), report);
  }
  scene.polydata = polydata;
  scene.mesh = cpu::MeshFromPolyData(polydata);
  const cpu::Mesh& mesh = scene.mesh;

  double bounds[6];
  mesh.Bounds(bounds);
  const double aspect = static_cast<double>(options.width) / options.height;
  cpu::Camera& camera = scene.camera;
  camera = cpu::FitCamera(bounds, args.GetDouble("azimuth", 0.0),
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
      camera.position = ParseVector(args.Get("camera-position"), "--camera-position");
    }
    if (args.Has("focal-point"))
    {
      camera.focalPoint = ParseVector(args.Get("focal-point"), "--focal-point");
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
  }
  if (args.Has("view-angle"))
  {
    camera.viewAngle = args.GetDouble("view-angle", 30.0);
    if (!(camera.viewAngle > 0 && camera.viewAngle < 180))
    {
      throw UsageError("--view-angle must be in (0, 180)");
    }
  }

  Lighting<double>& lighting = scene.lighting;
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
    // Key light above-left of the camera, in world coordinates.
    const Vec3<double> toEye = NormalizeOr(camera.position - camera.focalPoint, Vec3<double>(0, 0, 1));
    const Vec3<double> right = NormalizeOr(Cross(camera.viewUp, toEye), Vec3<double>(1, 0, 0));
    const Vec3<double> up = Cross(toEye, right);
    Light<double> key;
    key.vector = NormalizeOr(toEye + up * 0.5 - right * 0.4, toEye);
    key.intensity = Vec3<double>(lightIntensity, lightIntensity, lightIntensity);
    lighting.lights[0] = key;
    lighting.lightCount = 1;
  }
  lighting.ambientIntensity = Vec3<double>(1, 1, 1);

  return scene;
}

/// GPU when asked or (auto) when an X display with OpenGL >= 3.2 answers.
/// An auto fallback is explained in `autoNotice`, which the caller prints
/// after success so that an error stays one line.
bool ChooseGpu(const std::string& backend, const char* command, std::string& autoNotice)
{
  if (backend == "cpu")
  {
    return false;
  }
  std::string why;
  if (gl::GpuAvailable(why))
  {
    return true;
  }
  if (backend == "gpu")
  {
    throw UsageError("--backend gpu: " + why);
  }
  autoNotice = std::string("shadinglab ") + command + ": backend auto: " + why +
    "; using the CPU renderer\n";
  return false;
}

int RunRender(int argc, char** argv)
{
  Scene scene = SceneFromArguments(argc, argv, kRenderHelp, false);
  if (scene.helpShown)
  {
    return 0;
  }
  const Arguments& args = scene.args;
  const cpu::RenderOptions& options = scene.options;
  const std::string& input = scene.input;
  const std::string& backend = scene.backend;
  const cpu::DisplayTransform display = scene.display;
  // GPU when asked or (auto) when an X display with OpenGL >= 3.2 answers.
  std::string autoNotice;
  const bool useGpu = ChooseGpu(backend, "render", autoNotice);
  cpu::RenderStats stats;
  cpu::Image image;
  try
  {
    if (useGpu)
    {
      const auto start = std::chrono::steady_clock::now();
      image = gl::RenderGpu(scene.polydata, scene.camera, scene.lighting, scene.material, options);
      stats.milliseconds = std::chrono::duration<double, std::milli>(
        std::chrono::steady_clock::now() - start).count();
      stats.polygons = scene.polydata->GetNumberOfPolys();
      for (uint8_t c : image.covered)
      {
        stats.pixelsCovered += c;
      }
    }
    else
    {
      image = cpu::Render(scene.mesh, scene.camera, scene.lighting.Cast<float>(),
        scene.material.Cast<float>(), options, &stats);
    }
  }
  catch (const std::invalid_argument& e)
  {
    throw UsageError(e.what());
  }
  catch (const std::runtime_error& e)
  {
    throw UsageError(e.what());
  }
  const std::string out = args.Get("out", "out.png");
  WritePng(image, image.ToRGB8(display), out);
  // Notices come after success, so that an error stays one line.
  if (stats.normalsComputed)
  {
    std::cerr << "shadinglab render: notice: '" << input
              << "' has no point normals; using area-weighted vertex normals\n";
  }
  std::cerr << autoNotice;

  if (args.Has("stats"))
  {
    std::printf("{\"backend\":\"%s\",\"mode\":\"%s\",\"width\":%d,\"height\":%d,\"ssaa\":%d,"
                "\"milliseconds\":%.3f,\"polygons\":%lld,\"triangles\":%lld,\"rasterized\":%lld,"
                "\"clipped\":%lld,\"degenerate\":%lld,\"pixels_covered\":%lld,"
                "\"pixels_shaded\":%lld,\"fast_phong_exact\":%lld,\"threads\":%d,"
                "\"normals_computed\":%s}\n",
      useGpu ? "gpu" : "cpu", cpu::ModeName(options.mode), options.width, options.height, options.ssaa,
      stats.milliseconds, static_cast<long long>(stats.polygons),
      static_cast<long long>(stats.triangles), static_cast<long long>(stats.rasterized),
      static_cast<long long>(stats.clipped), static_cast<long long>(stats.degenerate),
      static_cast<long long>(stats.pixelsCovered), static_cast<long long>(stats.pixelsShaded),
      static_cast<long long>(stats.fastPhongExact), stats.threads, stats.normalsComputed ? "true" : "false");
  }
  return 0;
}

} // namespace shadinglab::cli

namespace shadinglab::cli
{

namespace
{

const char* kCompareHelp =
  "usage: shadinglab compare INPUT [--modes M,M,..] [--size WxH] [--out OUT.png] [options]\n"
  "\n"
  "Renders INPUT once per shading mode (default: flat,gouraud,phong,fast-phong,cook-torrance)\n"
  "with the same camera, lights and material, side by side in one labelled PNG.\n"
  "--backend cpu (default for compare) | gpu | auto.\n"
  "--size is the size of one panel (default 400x300). Other options as 'render'.\n"
  "\n";

/// Draws `text` into the RGB8 canvas at (x, y) (top-left origin), white on
/// the canvas colour, using VTK's FreeType text rendering (no GL needed).
void DrawLabel(std::vector<uint8_t>& canvas, int canvasWidth, int canvasHeight, int x, int y,
  const std::string& text)
{
  vtkNew<vtkTextProperty> property;
  property->SetFontSize(15);
  property->SetColor(1.0, 1.0, 1.0);
  property->SetFontFamilyToArial();
  property->BoldOn();
  vtkNew<vtkImageData> label;
  if (!vtkFreeTypeTools::GetInstance()->RenderString(property, text, 72, label))
  {
    return; // no font: the panel stays unlabelled rather than failing
  }
  int dims[3];
  label->GetDimensions(dims);
  for (int ly = 0; ly < dims[1]; ++ly)
  {
    for (int lx = 0; lx < dims[0]; ++lx)
    {
      // VTK images start at the bottom row.
      const int cx = x + lx, cy = y + (dims[1] - 1 - ly);
      if (cx < 0 || cy < 0 || cx >= canvasWidth || cy >= canvasHeight)
      {
        continue;
      }
      const auto* px = static_cast<unsigned char*>(label->GetScalarPointer(lx, ly, 0));
      const float alpha = px[3] / 255.0f;
      for (int c = 0; c < 3; ++c)
      {
        uint8_t& dst = canvas[(static_cast<size_t>(cy) * canvasWidth + cx) * 3 + c];
        dst = static_cast<uint8_t>(std::lround(dst * (1 - alpha) + px[c] * alpha));
      }
    }
  }
}

} // namespace

int RunCompare(int argc, char** argv)
{
  // Default panel size for a comparison strip.
  bool hasSize = false, hasBackend = false;
  for (int i = 0; i < argc; ++i)
  {
    hasSize |= std::string(argv[i]).rfind("--size", 0) == 0;
    hasBackend |= std::string(argv[i]).rfind("--backend", 0) == 0;
  }
  std::vector<std::string> arguments(argv, argv + argc);
  if (!hasSize)
  {
    arguments.push_back("--size");
    arguments.push_back("400x300");
  }
  if (!hasBackend)
  {
    // The CPU renderer is the reference: comparisons default to it.
    arguments.push_back("--backend");
    arguments.push_back("cpu");
  }
  std::vector<char*> raw;
  for (auto& a : arguments)
  {
    raw.push_back(a.data());
  }
  Scene scene = SceneFromArguments(static_cast<int>(raw.size()), raw.data(), kCompareHelp, true);
  if (scene.helpShown)
  {
    return 0;
  }
  std::vector<cpu::ShadingMode> modes;
  {
    std::stringstream ss(scene.args.Get("modes", "flat,gouraud,phong,fast-phong,cook-torrance"));
    std::string name;
    while (std::getline(ss, name, ','))
    {
      cpu::ShadingMode mode;
      if (!cpu::ParseMode(name, mode))
      {
        throw UsageError("--modes: unknown mode '" + name + "'");
      }
      modes.push_back(mode);
    }
    if (modes.empty() || modes.size() > 8)
    {
      throw UsageError("--modes takes 1 to 8 modes");
    }
  }
  const int W = scene.options.width, H = scene.options.height;
  constexpr int kLabelBar = 26; // pixels above each panel for its name
  constexpr int kGap = 4;       // pixels between panels
  const int canvasW = static_cast<int>(modes.size()) * (W + kGap) - kGap;
  const int canvasH = H + kLabelBar;
  std::vector<uint8_t> canvas(static_cast<size_t>(canvasW) * canvasH * 3, 24);
  std::string autoNotice;
  const bool useGpu = ChooseGpu(scene.backend, "compare", autoNotice);
  cpu::SoftwareRenderer renderer;
  cpu::Image gpuImage;
  for (size_t m = 0; m < modes.size(); ++m)
  {
    cpu::RenderOptions options = scene.options;
    options.mode = modes[m];
    const cpu::Image* image = nullptr;
    try
    {
      if (useGpu)
      {
        gpuImage =
          gl::RenderGpu(scene.polydata, scene.camera, scene.lighting, scene.material, options);
        image = &gpuImage;
      }
      else
      {
        image = &renderer.Render(scene.mesh, scene.camera, scene.lighting.Cast<float>(),
          scene.material.Cast<float>(), options);
      }
    }
    catch (const std::invalid_argument& e)
    {
      throw UsageError(std::string(e.what()) + " (or leave " + cpu::ModeName(modes[m]) +
        " out with --modes)");
    }
    catch (const std::runtime_error& e)
    {
      throw UsageError(std::string(cpu::ModeName(modes[m])) + ": " + e.what());
    }
    const auto rgb8 = image->ToRGB8(scene.display);
    const int x0 = static_cast<int>(m) * (W + kGap);
    for (int y = 0; y < H; ++y)
    {
      std::copy(rgb8.begin() + static_cast<size_t>(y) * W * 3,
        rgb8.begin() + static_cast<size_t>(y + 1) * W * 3,
        canvas.begin() + (static_cast<size_t>(y + kLabelBar) * canvasW + x0) * 3);
    }
    DrawLabel(canvas, canvasW, canvasH, x0 + 8, 4,
      std::string(cpu::ModeName(modes[m])) + (useGpu ? " (gpu)" : " (cpu)"));
  }
  cpu::Image strip;
  strip.width = canvasW;
  strip.height = canvasH;
  WritePng(strip, canvas, scene.args.Get("out", "compare.png"));
  std::cerr << autoNotice;
  return 0;
}

} // namespace shadinglab::cli
