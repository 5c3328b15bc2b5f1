// SPDX-License-Identifier: BSD-3-Clause
// The scenes. Each is a list of panels and a view; the text cites
// docs/model.md's equations.
#include "Scenes.h"

#include "SceneMeshes.h"
#include "SceneParts.h"

#include "AnalyticMeshes.h"
#include "shadinglab/model/Materials.h"

#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

namespace shadinglab::gui
{

using render::ShadingMode;
using widgets::PanelSpec;

const std::vector<SceneInfo>& SceneList()
{
  static const std::vector<SceneInfo> list = {
    { "modes", "the five shading modes on one mesh" },
    { "mach-bands", "a low-poly cylinder, flat vs Gouraud: staircase, slope jumps, Mach bands" },
    { "perspective", "a receding plane: screen-space vs perspective-correct interpolation" },
    { "orientation", "one quad rotating in the image plane: scan conversion is not invariant" },
    { "shared-vertices", "T-junctions: the intensity discontinuity and the crack, then repaired" },
    { "silhouette", "polygonal silhouettes against OpenSubdiv refinement with limit normals" },
    { "normals", "uniform, area, angle and Max vertex normals against the exact normal" },
    { "creases", "unrepresentative averaged normals: a corrugation shaded flat, a cube rounded" },
    { "flat-conditions", "flat shading is exact only for a polyhedron seen and lit from afar" },
    { "scanline", "one triangle's scan conversion pixel by pixel: the lecture's equations in numbers" },
    { "moon", "a sphere lit from behind the viewer: Lambert vs Lommel-Seeliger" },
    { "metal", "Cook-Torrance gold and copper vs Phong plastic at grazing light" },
    { "brdf", "the BRDF lobes in the plane of incidence, parameters live" },
    { "polarization", "a polarizer turned in front of glass and gold: Brewster's angle" },
    { "spectral", "gold and copper with three RGB samples against their measured spectra" },
  };
  return list;
}

/// The lecture scenes plot the intensity I itself (DisplayTransform::Clamp),
/// so a highlight must peak below 1 or its shape is cut off flat. Under the
/// scenes' unit light (I_L dw = pi), normalized Blinn-Phong at n = 60 peaks
/// at ks (n + 8)/8 = 8.5 ks above the diffuse part (kd albedo = 0.51 in
/// red): 0.05 keeps red at ~0.97 (at 0.4 a tenth of the torus was white).
/// The test EveryScreenshotIsDrawn counts the saturated pixels.
constexpr double kScenePlasticKs = 0.05;
/// The same for the Cook-Torrance plastic preset in the modes scene (its
/// own ks, 0.2, saturated 24 pixels of the highlight).
constexpr double kSceneCookTorranceKs = 0.15;
/// The metal scene's Phong plastic, under its light of 0.06 (Metal).
constexpr double kMetalScenePlasticKs = 0.4;

Material<double> Lambert(double kd)
{
  Material<double> m;
  m.model = ReflectanceModel::Lambert;
  m.kd = kd;
  m.ks = 0.0;
  m.ambient = { 0.0, 0.0, 0.0 };
  return m;
}

Material<double> Plastic(ReflectanceModel model)
{
  Material<double> m;
  m.model = model;
  m.kd = 0.6;
  m.ks = kScenePlasticKs;
  m.shininess = 60;
  m.diffuseColor = { 0.85, 0.35, 0.25 };
  m.ambient = { 0.03, 0.03, 0.03 };
  return m;
}

Material<double> Preset(const char* name)
{
  const MaterialPreset* preset = FindMaterialPreset(name);
  if (!preset)
  {
    throw std::logic_error(std::string("no material preset ") + name);
  }
  return preset->material;
}

PanelSpec Panel(const std::string& title, const PolyPtr& mesh, ShadingMode mode,
  const Material<double>& material, render::Backend backend)
{
  PanelSpec spec;
  spec.title = title;
  spec.mesh = mesh;
  spec.mode = mode;
  spec.material = material;
  spec.backend = backend;
  return spec;
}

namespace
{

/// The user's mesh prepared as asked, or the scene's own.
PolyPtr InputOr(const SceneOptions& options, const std::function<PolyPtr()>& fallback)
{
  if (options.input)
  {
    return Prepared(options.input, options.preparation);
  }
  return fallback();
}

Scene Modes(const SceneOptions& o)
{
  Scene s;
  s.title = "The five shading modes, and auto";
  s.usesInput = true;
  // The built-in torus is smooth (its 30-degree facets are not creases);
  // the normal weighting is the user's.
  PolyPtr mesh = InputOr(o, [&] {
    return WithNormals(
      Adopt(datasets::MakeTorus(1.0, 0.45, 24, 12)), o.preparation.weighting, 180.0);
  });
  const auto b = o.backend;
  s.panels = { Panel("Flat", mesh, ShadingMode::Flat, Plastic(), b),
    Panel("Gouraud", mesh, ShadingMode::Gouraud, Plastic(), b),
    Panel("Phong", mesh, ShadingMode::Phong, Plastic(), b),
    Panel("Fast Phong (Bishop & Weimer)", mesh, ShadingMode::FastPhong, Plastic(), b),
    Panel("Cook-Torrance (Phong mode)", mesh, ShadingMode::Phong, [] {
      // The preset's ks (0.2) clipped the highlight's peak to white.
      Material<double> m = Preset("plastic");
      m.ks = kSceneCookTorranceKs;
      return m;
    }(), b),
    Panel("Auto: cheapest within 2/255", mesh, ShadingMode::Phong, Plastic(), b) };
  s.panels.back().mode = render::ShadingMode::Auto;
  s.panels.back().maxError = 2.0;
  s.elevation = 35;
  s.azimuth = 15;
  s.explanation =
    "Where the illumination model is evaluated: once per polygon (flat), at the vertices "
    "with the intensities interpolated (Gouraud), per pixel from interpolated normals "
    "(Phong), per pixel from a quadratic in screen space (fast Phong), and per pixel "
    "with a physically based BRDF (Cook-Torrance). Watch the highlight: Gouraud "
    "smears or loses it, flat shows the facets. The last panel picks, at every view, "
    "the cheapest mode predicted to stay within a mean error of 2/255 (eq. 4.1-4.5): "
    "zoom in and out and watch its title.";
  s.formula = "I = R<sub>a</sub>I<sub>a</sub> + &Sigma;<sub>j</sub> I<sub>Lj</sub> "
              "(N&middot;L<sub>j</sub>) d&omega;<sub>j</sub> (k<sub>d</sub>R<sub>d</sub> + "
              "k<sub>s</sub>R<sub>s</sub>) &nbsp; (eq. 1.1; modes eq. 2.1-2.8)";
  return s;
}

Scene MachBands(const SceneOptions&)
{
  Scene s;
  s.title = "Mach bands on a low-poly cylinder";
  // Axis along y (the generator's is z), smooth normals around the sides
  // (45 degree faces) and creased at the caps.
  // Turned by half a face about its axis so that no vertex sits on the
  // silhouette (a vertex normal at right angles to the view shades to 0).
  PolyPtr cylinder = WithNormals(
    Rotated(Rotated(Adopt(datasets::MakeLowPolyCylinder(8)), 0, -90.0), 1, 22.5),
    mesh::NormalWeighting::Area, 60.0);
  s.panels = { Panel("Flat: a staircase", cylinder, ShadingMode::Flat, Lambert(), render::Backend::CPU),
    Panel("Gouraud: slope jumps at edges", cylinder, ShadingMode::Gouraud,
      Lambert(), render::Backend::CPU),
    Panel("Phong: smooth", cylinder, ShadingMode::Phong, Lambert(), render::Backend::CPU) };
  s.parallel = true;
  s.zoom = 1.6;
  s.lightAzimuth = -60;
  s.lightElevation = 0;
  s.line = { 0.02, 0.5, 0.98, 0.5 };
  s.perceived = true;
  // CPU panels: float images, so the derivative is not quantized to 1/255
  // steps (a GPU panel's is; switch one to compare).
  s.explanation =
    "Flat shading gives each face one intensity: the profile is a staircase. Gouraud "
    "interpolates the vertex intensities linearly: the profile is continuous but its "
    "slope jumps at every edge. The eye's lateral inhibition exaggerates such jumps "
    "(dashed: the profile after a centre-surround filter), so bright and dark bands "
    "appear along the edges that are not in the image. (CPU panels: their float images "
    "give a derivative free of 8-bit steps.)";
  s.formula = "I(x) = I<sub>a</sub> + (I<sub>b</sub> - I<sub>a</sub>) (x - x<sub>a</sub>)/"
              "(x<sub>b</sub> - x<sub>a</sub>) (eq. 2.2-2.4); perceived = p + g (p - "
              "G<sub>&sigma;</sub>*p) (eq. 3.3)";
  return s;
}

Scene Perspective(const SceneOptions& o)
{
  Scene s;
  s.title = "Perspective distortion of screen-space interpolation";
  PolyPtr plane = Adopt(datasets::MakeRecedingPlane(8.0));
  Material<double> white = Lambert(1.0);
  PanelSpec correct =
    Panel("Perspective-correct", plane, ShadingMode::Phong, white, o.backend);
  PanelSpec screen = Panel("Screen-space (the lecture's)", plane, ShadingMode::Phong, white,
    o.backend);
  screen.interpolation = render::InterpolationSpace::Screen;
  PanelSpec difference = screen;
  difference.title = "|screen - perspective| (heat map)";
  difference.errorReference = 0;
  difference.errorScale = 128.0 / 255.0;
  s.panels = { correct, screen, difference };
  // Standing on the floor's near edge, looking down it: strong foreshortening.
  s.explicitCamera = true;
  // (Closer, the near edge crosses the frustum and the GPU's screen-space
  // path loses triangles on llvmpipe: a known GPU behaviour, docs/gpu-mapper.md.)
  s.camera.position = { 0.0, 0.45, 0.8 };
  s.camera.focalPoint = { 0.0, 0.0, -1.6 };
  s.camera.viewUp = { 0.0, 1.0, 0.0 };
  s.camera.viewAngle = 45.0;
  s.lightAzimuth = 0;
  s.lightElevation = 60;
  s.line = { 0.5, 0.98, 0.5, 0.02 };
  s.explanation =
    "The floor's colour goes from black at the near edge to white at the far edge, "
    "linearly in depth. Interpolated linearly on the screen, the far half of the floor, "
    "which covers few pixels, gets half of the ramp: the midpoint on the screen is not "
    "the midpoint in z. Perspective-correct interpolation divides by w.";
  s.formula = "t = (s / w<sub>1</sub>) / ((1 - s) / w<sub>0</sub> + s / w<sub>1</sub>) "
              "&nbsp; (eq. 3.1)";
  return s;
}

Scene Orientation(const SceneOptions& o)
{
  Scene s;
  s.title = "Orientation dependence of polygon scan conversion";
  const double a = o.rotation;
  PanelSpec first = Panel("Polygon scan-converted, " + std::to_string(int(a)) + " deg",
    OrientationQuad(a), ShadingMode::Phong, Lambert(1.0), render::Backend::CPU);
  first.polygons = render::PolygonHandling::Direct;
  PanelSpec second = first;
  second.title = "Polygon scan-converted, " + std::to_string(int(a) + 45) + " deg";
  second.mesh = OrientationQuad(a + 45.0);
  PanelSpec triangulated = first;
  triangulated.title = "Triangulated, " + std::to_string(int(a)) + " deg";
  triangulated.polygons = render::PolygonHandling::Triangulate;
  triangulated.backend = o.backend;
  s.panels = { first, second, triangulated };
  s.parallel = true;
  s.zoom = 1.6;
  s.lightAzimuth = 0;
  s.lightElevation = 0;
  s.plot = PlotKind::Parameter;
  s.explanation =
    "Opposite corners of the square have the same value (0.9 and 0.1), so bilinear "
    "interpolation gives 0.5 at the centre. Scan conversion interpolates along the edges "
    "a scanline meets, then along the scanline: rotate the square and the centre value "
    "changes, up to the corner values at 45 degrees. Triangulation depends on the "
    "diagonal instead.";
  s.formula = "I<sub>s</sub> = I<sub>a</sub> + (I<sub>b</sub> - I<sub>a</sub>)(x<sub>s</sub> - "
              "x<sub>a</sub>)/(x<sub>b</sub> - x<sub>a</sub>), edges met per scanline "
              "(eq. 2.3, 3.2)";
  return s;
}

Scene SharedVertices(const SceneOptions& o)
{
  Scene s;
  s.title = "Shared vertices: T-junctions";
  PolyPtr patch = WithExactNormals(Adopt(datasets::MakeTJunctionPatch(1)));
  PolyPtr cracked = CrackedTJunctions(patch);
  mesh::PreparationOptions repair;
  repair.repair = true;
  repair.fixTJunctions = true;
  repair.computeNormals = false;
  PolyPtr repaired = Prepared(patch, repair);
  if (!repaired->GetPointData()->GetNormals())
  {
    throw std::logic_error("repair dropped the exact normals");
  }
  // A dim, broad highlight: the jump stays inside [0, 1] on the plot.
  Material<double> m = Plastic(ReflectanceModel::BlinnPhong);
  m.kd = 0.45;
  m.ks = 0.08;
  m.shininess = 24;
  s.panels = { Panel("T-junctions: intensity jumps along x = 0", patch, ShadingMode::Gouraud,
                 m, o.backend),
    Panel("T vertices on the surface: cracks", cracked, ShadingMode::Gouraud, m,
      o.backend),
    Panel("Repaired: edges split at T vertices", repaired, ShadingMode::Gouraud, m,
      o.backend) };
  // The light mirrors the view about the patch's top normal (0, 0, 1), the
  // T vertex's own normal: its highlight is what the coarse edge misses.
  s.elevation = -30;
  s.azimuth = -15;
  s.zoom = 1.5;
  s.lightAzimuth = 28;
  s.lightElevation = 58;
  s.line = { 0.15, 0.5, 0.85, 0.5 };
  s.explanation =
    "The left half is meshed coarsely, the right half finely; the fine vertices on the "
    "shared column lie on the middle of coarse edges. Each gets its own shading value, "
    "which the coarse polygon's interpolation along its edge does not reproduce: the "
    "intensity jumps across x = 0. Lift those vertices onto the surface and the "
    "geometry cracks open. Splitting the coarse edges at the T vertices repairs both.";
  s.formula = "I(C) &ne; I(A) + t (I(B) - I(A)) for C = A + t (B - A) &nbsp; (eq. 3.5)";
  return s;
}

Scene Silhouette(const SceneOptions& o)
{
  Scene s;
  s.title = "Polygonal silhouettes and subdivision";
  s.usesInput = true;
  PolyPtr base = o.input ? Prepared(o.input, [&] {
    mesh::PreparationOptions p = o.preparation;
    p.subdivisionLevels = 0;
    return p;
  }())
                         : Adopt(datasets::MakeIcosphere(0));
  const Material<double> m = Plastic();
  // Four panels, levels 0..3, fewer for a large input (llvmpipe draws
  // ~kPanelMaxFaces at interactive rates).
  constexpr double kPanelMaxFaces = 2e6;
  // The built-in icosahedron's dihedral angles (41.8 degrees) are above the
  // default crease angle: refine it smooth. A user's mesh keeps its creases.
  mesh::PreparationOptions refine = o.preparation;
  refine.repair = false;
  if (!o.input)
  {
    refine.featureAngle = 180.0;
  }
  for (int level = 0; level < 4; ++level)
  {
    if (level > 1 && base->GetNumberOfPolys() * std::pow(4.0, level) > kPanelMaxFaces)
    {
      break;
    }
    mesh::PreparationOptions p = refine;
    p.subdivisionLevels = level;
    PolyPtr refined = Prepared(base, p);
    const std::string title = level == 0
      ? "Control mesh, " + std::to_string(refined->GetNumberOfPolys()) + " faces"
      : "Level " + std::to_string(level) + " (limit normals), " +
        std::to_string(refined->GetNumberOfPolys()) + " faces";
    s.panels.push_back(Panel(title, refined, ShadingMode::Phong, m, o.backend));
  }
  s.elevation = 20;
  s.azimuth = 20;
  s.plot = PlotKind::Parameter;
  s.explanation =
    "Phong shading makes the inside of a coarse mesh look smooth, but no shading "
    "changes its outline: the silhouette stays polygonal. Subdivision (OpenSubdiv: Loop "
    "for triangles, Catmull-Clark otherwise) converges to a smooth limit surface, whose "
    "exact normals the last level carries. The plot counts the pixels whose coverage "
    "differs from level 5.";
  s.formula = "faces &times; 4 per level; silhouette error ~ h<sup>2</sup>, h = edge "
              "length (eq. 3.6)";
  return s;
}

Scene Normals(const SceneOptions& o)
{
  Scene s;
  s.title = "Vertex normals: weightings against the exact normal";
  PolyPtr raw = o.variant == "isosurface" ? Adopt(datasets::MakeMetaballIsosurface(20))
                                          : CorrugatedSurface(12);
  if (o.variant != "isosurface" && o.variant != "corrugated")
  {
    throw std::invalid_argument("normals: --variant must be corrugated or isosurface");
  }
  // A highlight that stays below 1: clipped highlights hide differences.
  Material<double> m = Plastic();
  m.kd = 0.7;
  m.ks = 0.1;
  m.shininess = 30;
  PanelSpec exact = Panel("Exact (analytic gradient) normals", WithExactNormals(raw),
    ShadingMode::Phong, m, render::Backend::CPU);
  s.panels = { exact };
  const std::pair<const char*, mesh::NormalWeighting> weightings[] = {
    { "uniform", mesh::NormalWeighting::Uniform }, { "area", mesh::NormalWeighting::Area },
    { "angle", mesh::NormalWeighting::Angle }, { "Max 1999", mesh::NormalWeighting::Max } };
  for (const auto& [name, weighting] : weightings)
  {
    PanelSpec heat = Panel(std::string(name) + " weights: |I - I_exact|",
      WithNormals(raw, weighting, 180.0), ShadingMode::Phong, m, render::Backend::CPU);
    heat.errorReference = 0;
    heat.errorScale = 24.0 / 255.0;
    s.panels.push_back(heat);
  }
  s.elevation = o.variant == "isosurface" ? 20 : -45;
  s.azimuth = 10;
  s.zoom = 1.2;
  s.lightAzimuth = -30;
  s.lightElevation = 30;
  s.plot = PlotKind::Parameter;
  s.explanation =
    "A vertex normal is a weighted mean of the normals of the faces around it. Uniform "
    "weights ignore the faces' sizes, area weights favour large faces, angle weights "
    "(Thurmer & Wuthrich) the corner angles, Max's weights (1999) are exact for a "
    "sphere. On an uneven triangulation they disagree; the heat maps show the "
    "per-pixel error of Phong shading with each against the exact gradient normals.";
  s.formula = "N<sub>v</sub> = normalize(&Sigma;<sub>f</sub> w<sub>f</sub> N<sub>f</sub>), "
              "w = 1, A<sub>f</sub>, &alpha;<sub>f</sub>, sin&alpha;/(|e<sub>1</sub>||e<sub>2"
              "</sub>|) &nbsp; (eq. 2.2)";
  return s;
}

Scene Moon(const SceneOptions& o)
{
  Scene s;
  s.title = "The full moon";
  s.usesInput = true;
  PolyPtr sphere =
    InputOr(o, [] { return WithExactNormals(Adopt(datasets::MakeUVSphere(96, 48))); });
  Material<double> lambert = Lambert(0.9);
  Material<double> moon = lambert;
  moon.model = ReflectanceModel::LommelSeeliger;
  Material<double> ct = Preset("plastic");
  ct.diffuseColor = { 0.9, 0.9, 0.9 };
  ct.lobes[0].m = 0.5;
  s.panels = { Panel("Lambert: darkens toward the limb", sphere, ShadingMode::Phong, lambert,
                 o.backend),
    Panel("Lommel-Seeliger: the flat full moon", sphere, ShadingMode::Phong, moon, o.backend),
    Panel("Cook-Torrance, m = 0.5", sphere, ShadingMode::Phong, ct, o.backend) };
  s.parallel = true;
  s.zoom = 1.5;
  s.lightAzimuth = 0;
  s.lightElevation = 0;
  s.line = { 0.0, 0.5, 1.0, 0.5 };
  s.explanation =
    "Lit from behind the viewer, a Lambertian sphere's radiance falls as cos(theta) "
    "toward the limb. The full moon looks like a flat disk instead: its dusty regolith "
    "scatters like Lommel-Seeliger's law, whose radiance N.L/(N.L + N.V) is constant "
    "when L = V. The plot shows the profile across the disk.";
  s.formula = "Lambert: I = k<sub>d</sub> &rho; E cos&theta;; &nbsp; Lommel-Seeliger: "
              "R<sub>d</sub> = (2/&pi;)/(N&middot;L + N&middot;V) &nbsp; (eq. 1.12, 3.4)";
  return s;
}

Scene Metal(const SceneOptions& o)
{
  Scene s;
  s.title = "Metals at grazing light";
  s.usesInput = true;
  PolyPtr sphere =
    InputOr(o, [] { return WithExactNormals(Adopt(datasets::MakeUVSphere(24, 12))); });
  Material<double> plastic = Plastic(ReflectanceModel::Phong);
  // Under this dim light the plastic's highlight needs the specular weight
  // of a glossy plastic to show at all (Phong at n = 60 peaks at
  // 0.06 x 0.4 x 31 = 0.74, below 1); the scenes' 0.05 left a faint dot.
  plastic.ks = kMetalScenePlasticKs;
  s.panels = { Panel("Cook-Torrance gold", sphere, ShadingMode::Phong, Preset("gold"), o.backend),
    Panel("Cook-Torrance copper", sphere, ShadingMode::Phong, Preset("copper"), o.backend),
    Panel("Phong plastic", sphere, ShadingMode::Phong, plastic, o.backend),
    Panel("Gouraud gold: a faceted highlight", sphere, ShadingMode::Gouraud,
      Preset("gold"), o.backend) };
  s.lightAzimuth = 70;
  s.lightElevation = 15;
  // A dim light: the metals' highlights stay below 1 (the peak, at grazing
  // light, is ~14x the light's intensity for gold), so their colour shows.
  s.lightIntensity = 0.06;
  // Across the disk through the highlights (the plastic one sits a little lower).
  s.line = { 0.25, 0.5, 0.8, 0.5 };
  s.explanation =
    "With the light nearly at right angles to the view, the highlight sits near the "
    "limb. A metal's Fresnel reflectance rises toward white at grazing angles, so the "
    "gold and copper highlights shift in colour; Phong's plastic highlight keeps the "
    "light's colour. Gouraud on a 24 x 12 sphere lights the vertices only: the "
    "highlight takes the shape of the faces around it, and one narrower than a face "
    "would be missed altogether.";
  s.formula = "R<sub>s</sub> = F(&theta;) D G / (&pi; (N&middot;L)(N&middot;V)), F with "
              "complex index &eta; + i k &nbsp; (eq. 1.5-1.10)";
  return s;
}

Scene Brdf(const SceneOptions&)
{
  Scene s;
  s.title = "BRDF lobes";
  s.plot = PlotKind::Brdf;
  s.explanation =
    "The specular lobes in the plane of incidence, light from the left: Phong's lobe "
    "is centred on the mirror direction and keeps its shape; Blinn-Phong's and the "
    "microfacet lobes widen and lean toward grazing angles; a mixture of two "
    "roughnesses adds a wide base under a sharp peak.";
  s.formula = "Phong (n+2)/(2&pi;) (R&middot;V)<sup>n</sup>; Blinn (n+8)/(8&pi;) "
              "(N&middot;H)<sup>n</sup>; Cook-Torrance F D G/(&pi; N&middot;L N&middot;V) "
              "(eq. 1.3-1.7)";
  return s;
}

} // namespace

Scene MakeScene(const std::string& name, const SceneOptions& options)
{
  static const std::map<std::string, std::function<Scene(const SceneOptions&)>> makers = {
    { "modes", Modes }, { "mach-bands", MachBands }, { "perspective", Perspective },
    { "orientation", Orientation }, { "shared-vertices", SharedVertices },
    { "silhouette", Silhouette }, { "normals", Normals }, { "creases", Creases },
    { "flat-conditions", FlatConditions }, { "scanline", Scanline }, { "moon", Moon },
    { "metal", Metal }, { "brdf", Brdf }, { "polarization", Polarization },
    { "spectral", SpectralScene } };
  const auto it = makers.find(name);
  if (it == makers.end())
  {
    std::string names;
    for (const SceneInfo& info : SceneList())
    {
      names += (names.empty() ? "" : ", ") + std::string(info.name);
    }
    throw std::invalid_argument("unknown scene '" + name + "' (scenes: " + names + ")");
  }
  Scene scene = it->second(options);
  scene.name = name;
  if (scene.usesInput && options.input)
  {
    // The user's mesh is seen as the CLI and ParaView show it: the default
    // display transform and the light kit, its key light where vtkLightKit
    // puts it.
    scene.display = render::RenderOptions().display;
    scene.lightKit = true;
    scene.lightAzimuth = render::kLightKitKeyAzimuth;
    scene.lightElevation = render::kLightKitKeyElevation;
    scene.lightDistance = 0;
  }
  else if (!scene.panels.empty())
  {
    scene.explanation += " Lit by one light, as in the lecture: a face turned away from it "
                         "shows only the ambient term Ra Ia.";
  }
  return scene;
}

} // namespace shadinglab::gui
