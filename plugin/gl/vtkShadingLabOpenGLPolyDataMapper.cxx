// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabOpenGLPolyDataMapper.h"

#include "MeshArrays.h"
#include "PolyDataMesh.h"
#include "VertexNormals.h"
#include "VtkCamera.h"
#include "VtkLights.h"
#include "vtkShadingLabSettings.h"
#include "vtkWeightedPolyDataNormals.h"
#include "shadinglab/model/Materials.h"
#include "shadinglab/render/AutoMode.h"
#include "shadinglab/render/Renderer.h"
#include "shadinglab_glsl.h"
#include "shadinglab_glsl_defines.h"

#include <vtkActor.h>
#include <vtkRenderWindow.h>
#include <vtkCellData.h>
#include <vtkExecutive.h>
#include <vtkScalarsToColors.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMatrix4x4.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLHelper.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt64Array.h>

#include <algorithm>
#include <cctype>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <tuple>
#include <vector>

namespace sl = shadinglab;

struct vtkShadingLabOpenGLPolyDataMapper::Internals
{
  sl::render::Settings Settings;
  // Input prepared for the mode: normals stripped (flat) or computed.
  vtkSmartPointer<vtkPolyData> Prepared;
  vtkMTimeType PreparedFrom = 0;
  vtkPolyData* PreparedInput = nullptr;
  int PreparedKind = -1;
  std::array<double, 2> PreparedSettings{ -1.0, -1.0 }; ///< weighting, feature angle
  /// What is drawn: the prepared input with its concave polygons split
  /// (mesh::WithConcavePolygonsSplit; VTK fans polygons), made once per
  /// change of what it came from.
  vtkSmartPointer<vtkPolyData> Split;
  vtkPolyData* SplitInput = nullptr;
  vtkMTimeType SplitFrom = 0;
  std::map<const vtkOpenGLHelper*, std::string> BuiltVariant;
  std::map<const vtkShaderProgram*, std::vector<float>> LastUniforms;
  // AUTO: the input in its local frame with its normals (the input's, else
  // area-weighted), re-made when the input changes, and the last choice.
  sl::render::Mesh AutoMesh;
  sl::render::WorldFrame AutoFrame;
  std::vector<float> AutoNormals;
  const vtkPolyData* AutoInput = nullptr;
  vtkMTimeType AutoFrom = 0;
  int AutoWeighting = -1; ///< the NormalWeighting AutoNormals were made with
  int Drawn = PHONG;
  std::string AutoChoice;
  bool WarnedFlatProperty = false; ///< the Flat-property warning was given
  bool WarnedNoForm = false;        ///< the FAST_PHONG-without-a-form warning, since the settings changed
  /// What the last choice was made from (input, mapper, camera and light
  /// modification times, lights on, renderer size, budget): a render that
  /// changes none of them keeps it (the choice costs ~10-35 ms on meshes of
  /// 0.1-1.3M triangles, BM_AutoChoice).
  std::vector<double> AutoKey;
};

vtkStandardNewMacro(vtkShadingLabOpenGLPolyDataMapper);

// The VTK enum is the render::ShadingMode list, checked at compile time.
static_assert(vtkShadingLabOpenGLPolyDataMapper::FLAT == static_cast<int>(shadinglab::render::ShadingMode::Flat) &&
  vtkShadingLabOpenGLPolyDataMapper::GOURAUD == static_cast<int>(shadinglab::render::ShadingMode::Gouraud) &&
  vtkShadingLabOpenGLPolyDataMapper::PHONG == static_cast<int>(shadinglab::render::ShadingMode::Phong) &&
  vtkShadingLabOpenGLPolyDataMapper::FAST_PHONG == static_cast<int>(shadinglab::render::ShadingMode::FastPhong) &&
  vtkShadingLabOpenGLPolyDataMapper::AUTO == static_cast<int>(shadinglab::render::ShadingMode::Auto) &&
  shadinglab::render::kShadingModeCount == 4);

vtkShadingLabOpenGLPolyDataMapper::vtkShadingLabOpenGLPolyDataMapper()
  : Internal(new Internals)
{
}

vtkShadingLabOpenGLPolyDataMapper::~vtkShadingLabOpenGLPolyDataMapper() = default;

namespace
{
/// What SetSettings must notice: the shaders' variant (mode, model,
/// specular on/off, lobe count, conductor, interpolation, display), the budget and
/// the normals to make. The rest reaches the GPU as uniforms. A tuple, not
/// a string: composite mappers pass their settings to every block each frame.
auto ModifyingPart(const sl::render::Settings& s)
{
  const sl::Material<double>& m = s.material;
  return std::make_tuple(m.model, m.ks > 0, s.highlights, m.lobeCount, m.IsConductor(), m.spectralCount > 0, s.render.polarizer >= 0,
    s.render.lightPolarizer >= 0, s.render.mode,
    s.render.interpolation, s.render.display, s.render.maxError, s.normals.weighting, s.normals.featureAngle,
    s.normals.recompute);
}
} // namespace

void vtkShadingLabOpenGLPolyDataMapper::SetSettings(const sl::render::Settings& settings)
{
  // A variant change needs new shaders, a change of the normals or of the
  // budget a new preparation or choice: mark the mapper modified then. The
  // other changes reach the GPU through the uniform comparison.
  sl::render::Settings& current = this->Internal->Settings;
  const bool modified = ModifyingPart(current) != ModifyingPart(settings);
  current = settings;
  if (modified)
  {
    this->Internal->WarnedNoForm = false;
    this->Modified();
  }
}

void vtkShadingLabOpenGLPolyDataMapper::SetSettingsFrom(vtkShadingLabSettings* settings)
{
  if (settings)
  {
    this->SetSettings(settings->GetSettings());
  }
}

const sl::render::Settings& vtkShadingLabOpenGLPolyDataMapper::GetSettings() const
{
  return this->Internal->Settings;
}

bool vtkShadingLabOpenGLPolyDataMapper::SetSetting(const char* key, const char* value)
{
  sl::render::Settings settings = this->Internal->Settings;
  const std::string problem =
    sl::render::ApplySettingText(settings, key ? key : "", value ? value : "");
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return false;
  }
  sl::render::NormalizeLobeWeights(settings.material);
  this->SetSettings(settings);
  return true;
}

void vtkShadingLabOpenGLPolyDataMapper::SetMaterial(const sl::Material<double>& material)
{
  sl::render::Settings settings = this->Internal->Settings;
  settings.material = material;
  this->SetSettings(settings);
}

const sl::Material<double>& vtkShadingLabOpenGLPolyDataMapper::GetMaterial() const
{
  return this->Internal->Settings.material;
}

void vtkShadingLabOpenGLPolyDataMapper::SetBlockOverrides(const double* color, double opacity)
{
  this->BlockColorSet = color != nullptr;
  if (color)
  {
    std::copy(color, color + 3, this->BlockColor);
  }
  this->BlockOpacity = opacity;
}

void vtkShadingLabOpenGLPolyDataMapper::SetPropertyShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetPropertyShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  if (!program)
  {
    return;
  }
  // VTK's uniforms from the property, replaced by the block's (VTK sets
  // diffuseColorUniform to Diffuse x DiffuseColor).
  if (this->BlockColorSet && program->IsUniformUsed("diffuseColorUniform"))
  {
    const double k = act->GetProperty()->GetDiffuse();
    const float rgb[3] = { static_cast<float>(k * this->BlockColor[0]),
      static_cast<float>(k * this->BlockColor[1]), static_cast<float>(k * this->BlockColor[2]) };
    program->SetUniform3f("diffuseColorUniform", rgb);
  }
  if (this->BlockOpacity >= 0.0 && program->IsUniformUsed("opacityUniform"))
  {
    program->SetUniformf("opacityUniform", static_cast<float>(this->BlockOpacity));
  }
}

int vtkShadingLabOpenGLPolyDataMapper::GetDrawnMode() const
{
  const sl::render::Settings& s = this->Internal->Settings;
  return s.render.mode == sl::render::ShadingMode::Auto ? this->Internal->Drawn
                                                       : static_cast<int>(s.render.mode);
}

const std::string& vtkShadingLabOpenGLPolyDataMapper::GetAutoChoice() const
{
  static const std::string none;
  return this->Internal->Settings.render.mode == sl::render::ShadingMode::Auto
    ? this->Internal->AutoChoice
    : none;
}

int vtkShadingLabOpenGLPolyDataMapper::EffectiveMode() const
{
  const int drawn = this->GetDrawnMode();
  const auto mode = static_cast<sl::render::ShadingMode>(drawn);
  return sl::render::SupportsModel(mode, this->Internal->Settings.material.model) ? drawn : PHONG;
}

void vtkShadingLabOpenGLPolyDataMapper::ChooseAutoMode(vtkRenderer* ren, vtkPolyData* input)
{
  Internals& in = *this->Internal;
  if (!input || input->GetNumberOfPolys() == 0)
  {
    in.Drawn = PHONG;
    in.AutoChoice = "no polygons: phong";
    in.AutoKey.clear();
    return;
  }
  if (in.AutoInput != input || in.AutoFrom != input->GetMTime() ||
    in.AutoWeighting != in.Settings.normals.weighting)
  {
    // What the smooth modes draw: inconsistently oriented faces turned, as
    // PrepareInput turns them, before the predictors see the mesh.
    vtkSmartPointer<vtkPolyData> oriented = sl::mesh::ConsistentlyOriented(input);
    in.AutoMesh = sl::render::MeshFromPolyData(oriented, in.AutoFrame);
    in.AutoNormals = in.AutoMesh.normals;
    if (in.AutoNormals.size() != in.AutoMesh.points.size())
    {
      // Without normals: this mapper's weighting (made once per input
      // change; RenderPieceStart makes its own copy only in the mode
      // chosen, which may be flat).
      sl::mesh::FlatPolygons polygons;
      sl::mesh::FlatPolygonsFromPolyData(oriented, polygons);
      std::vector<double> normals;
      sl::mesh::ComputeVertexNormalsNoSplit(
        polygons, static_cast<sl::mesh::NormalWeighting>(in.Settings.normals.weighting), normals);
      in.AutoNormals.assign(normals.begin(), normals.end());
    }
    in.AutoInput = input;
    in.AutoFrom = input->GetMTime();
    in.AutoWeighting = in.Settings.normals.weighting;
  }
  std::vector<double> key = { static_cast<double>(reinterpret_cast<uintptr_t>(input)),
    static_cast<double>(input->GetMTime()), static_cast<double>(this->GetMTime()),
    static_cast<double>(ren->GetActiveCamera()->GetMTime()),
    static_cast<double>(ren->GetSize()[0]), static_cast<double>(ren->GetSize()[1]),
    in.Settings.render.maxError, in.Settings.lightIntensity, in.Settings.lightSolidAngle };
  {
    vtkCollectionSimpleIterator lit;
    ren->GetLights()->InitTraversal(lit);
    while (vtkLight* light = ren->GetLights()->GetNextLight(lit))
    {
      key.push_back(static_cast<double>(light->GetMTime()));
      key.push_back(light->GetSwitch());
    }
  }
  if (key == in.AutoKey)
  {
    return; // nothing the choice reads has changed
  }
  in.AutoKey = key;
  sl::render::Camera camera = sl::render::CameraFromVtk(ren->GetActiveCamera());
  sl::render::ToLocal(in.AutoFrame, camera);
  // The lights as drawn, in the world, then in the mesh's local frame: the
  // prediction reads their strength (render::LightScale) and, for its
  // estimate of what interpolating colours costs (eq. 4.4), where they are.
  sl::Lighting<double> lighting =
    sl::render::LightingFromVtk(ren, in.Settings.lightIntensity, in.Settings.lightSolidAngle);
  sl::render::ToLocal(in.AutoFrame, lighting);
  const int* size = ren->GetSize();
  const sl::render::ModeChoice choice = sl::render::ChooseMode(in.AutoMesh, in.AutoNormals,
    camera, lighting, in.Settings.material, std::max(size[0], 1), std::max(size[1], 1),
    in.Settings.render.maxError);
  in.Drawn = static_cast<int>(choice.mode);
  in.AutoChoice = choice.why;
}

sl::Material<double> vtkShadingLabOpenGLPolyDataMapper::DrawnMaterial() const
{
  // VTK's MapScalars leaves vertex colours (Colors) or texture coordinates
  // into the colour map (ColorCoordinates) when the surface is coloured by
  // data: mapped scalars or direct RGB.
  const bool colored = this->Colors != nullptr || this->ColorCoordinates != nullptr;
  const sl::render::Settings& s = this->Internal->Settings;
  return sl::render::MaterialForData(s.material, s.highlights, colored);
}

std::string vtkShadingLabOpenGLPolyDataMapper::Variant(vtkRenderer* ren) const
{
  const sl::Material<double> m = this->DrawnMaterial();
  const int model = static_cast<int>(m.model);
  int lights = 0;
  bool point = false;
  bool headlightOnly = true;
  vtkLightCollection* collection = ren->GetLights();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    if (light->GetSwitch() && lights < sl::kMaxLights)
    {
      ++lights;
      point |= light->GetPositional() != 0;
      headlightOnly &= light->LightTypeIsHeadlight() && !light->GetPositional();
    }
  }
  headlightOnly &= lights == 1;
  const bool specular = m.model != sl::ReflectanceModel::Lambert &&
    m.model != sl::ReflectanceModel::LommelSeeliger && m.ks > 0;
  std::ostringstream v;
  v << "#define SL_MODE " << this->EffectiveMode() << "\n"
    << "#define SL_MODEL " << model << "\n"
    << "#define SL_LIGHT_COUNT " << lights << "\n"
    << "#define SL_POINT_LIGHTS " << (point ? 1 : 0) << "\n"
    << "#define SL_SPECULAR " << (specular ? 1 : 0) << "\n"
    << "#define SL_LOBE_COUNT " << std::max(1, std::min(m.lobeCount, sl::kMaxLobes)) << "\n"
    << "#define SL_CONDUCTOR " << (m.IsConductor() ? 1 : 0) << "\n"
    << "#define SL_TINT " << (m.albedoTintsFresnel ? 1 : 0) << "\n"
    << "#define SL_SPECTRAL " << (m.spectralCount > 0 ? 1 : 0) << "\n"
    << "#define SL_ANALYSER " << (this->Internal->Settings.render.polarizer >= 0 ? 1 : 0) << "\n"
    << "#define SL_LIGHT_POLARIZER " << (this->Internal->Settings.render.lightPolarizer >= 0 ? 1 : 0) << "\n"
    << "#define SL_HEADLIGHT " << (headlightOnly ? 1 : 0) << "\n"
    << "#define SL_DISPLAY " << static_cast<int>(this->Internal->Settings.render.display) << "\n"
    << "#define SL_INTERP " << ((this->Internal->Settings.render.interpolation == sl::render::InterpolationSpace::Perspective) ? "smooth" : "noperspective") << "\n";
  return v.str();
}

bool vtkShadingLabOpenGLPolyDataMapper::Substitute(
  vtkShader* shader, const std::string& tag, const std::string& code)
{
  if (!vtkShaderProgram::Substitute(shader, tag, code, false))
  {
    ++this->FailedSubstitutions;
    vtkErrorMacro("shader substitution failed: tag '" << tag << "' not found");
    return false;
  }
  return true;
}

void vtkShadingLabOpenGLPolyDataMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act)
{
  if (this->Internal->Settings.render.mode == sl::render::ShadingMode::Auto)
  {
    this->ChooseAutoMode(ren, this->CurrentInput);
  }
  this->CurrentInput = this->PrepareInput(this->CurrentInput);
  // VTK uploads no point normals for a property interpolated Flat (its
  // buffer building reads the property), and the smooth modes' shaders
  // need them: said once, not a blank surface without a word.
  if (act->GetProperty()->GetInterpolation() == VTK_FLAT && this->GetDrawnMode() != FLAT &&
    !this->Internal->WarnedFlatProperty)
  {
    vtkWarningMacro("the actor's property is interpolated Flat: VTK then uploads no point normals, "
                    "and the ShadingLab modes other than FLAT cannot draw; set the property's "
                    "interpolation to Gouraud (the ShadingLab mode decides the shading)");
    this->Internal->WarnedFlatProperty = true;
  }
  this->Superclass::RenderPieceStart(ren, act);
}

vtkPolyData* vtkShadingLabOpenGLPolyDataMapper::PrepareInput(vtkPolyData* input)
{
  vtkPolyData* prepared = this->PrepareNormals(input);
  Internals& in = *this->Internal;
  if (!prepared)
  {
    return prepared;
  }
  if (in.SplitInput != prepared || in.SplitFrom != prepared->GetMTime() || !in.Split)
  {
    // VTK's buffers fan every polygon: a concave one (a keyhole, a star)
    // would be filled over its notches. Its ear-clipped triangles instead.
    in.Split = sl::mesh::WithConcavePolygonsSplit(prepared);
    in.SplitInput = prepared;
    in.SplitFrom = prepared->GetMTime();
  }
  return in.Split;
}

vtkPolyData* vtkShadingLabOpenGLPolyDataMapper::PrepareNormals(vtkPolyData* input)
{
  const sl::render::NormalSettings& made = this->Internal->Settings.normals;
  const bool flat = this->GetDrawnMode() == FLAT;
  const bool hasNormals = input && input->GetPointData()->GetNormals();
  // Flat mode uploads no point normals; the other modes need them, made
  // here when the input has none or on request.
  const bool useInputNormals = hasNormals && !made.recompute;
  const int kind = flat ? (hasNormals ? 1 : 0) : (useInputNormals ? 0 : 2);
  const std::array<double, 2> settings{ static_cast<double>(made.weighting), made.featureAngle };
  if (kind != 0)
  {
    if (this->Internal->PreparedKind != kind || this->Internal->PreparedInput != input ||
      this->Internal->PreparedFrom != input->GetMTime() ||
      (kind == 2 && this->Internal->PreparedSettings != settings))
    {
      // A shallow copy has its own point-data object: the input keeps its arrays.
      auto prepared = vtkSmartPointer<vtkPolyData>::New();
      prepared->ShallowCopy(input);
      if (kind == 1)
      {
        prepared->GetPointData()->SetNormals(nullptr);
      }
      else
      {
        // Weighted vertex normals (mesh/core, the CPU renderer's), split
        // where faces meet at more than FeatureAngle (new points; the copy
        // is what is drawn), after inconsistently oriented faces are turned.
        vtkNew<vtkWeightedPolyDataNormals> normals;
        normals->SetInputData(prepared);
        normals->SetWeighting(made.weighting);
        normals->SetFeatureAngle(made.featureAngle);
        normals->SetSplitting(made.featureAngle < 180.0);
        normals->ConsistencyOn();
        normals->Update();
        prepared = normals->GetOutput();
      }
      this->Internal->Prepared = prepared;
      this->Internal->PreparedFrom = input->GetMTime();
      this->Internal->PreparedInput = input;
      this->Internal->PreparedKind = kind;
      this->Internal->PreparedSettings = settings;
    }
    return this->Internal->Prepared;
  }
  return input;
}

void vtkShadingLabOpenGLPolyDataMapper::SetDrawnElsewhere(int mode, const std::string& autoChoice)
{
  this->Internal->Drawn = mode;
  this->Internal->AutoChoice = autoChoice;
}

vtkUnsignedCharArray* vtkShadingLabOpenGLPolyDataMapper::MapScalars(double alpha)
{
  int cellFlag = 0;
  return this->MapScalars(alpha, cellFlag);
}

vtkUnsignedCharArray* vtkShadingLabOpenGLPolyDataMapper::MapScalars(double alpha, int& cellFlag)
{
  vtkDataSet* drawn = this->CurrentInput ? this->CurrentInput : this->GetInput();
  return this->Superclass::MapScalars(drawn, alpha, cellFlag);
}

bool vtkShadingLabOpenGLPolyDataMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  const std::string variant = this->Variant(ren);
  std::string& built = this->Internal->BuiltVariant[&cellBO];
  const bool changed = built != variant;
  built = variant;
  return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act) || changed;
}

void vtkShadingLabOpenGLPolyDataMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  ++this->ShaderBuildCount;
  if (this->EffectiveMode() != this->GetDrawnMode() && !this->Internal->WarnedNoForm)
  {
    // Said once per settings change (not per shader build: a mesh with
    // several primitive kinds builds several): not a silent substitution.
    this->Internal->WarnedNoForm = true;
    vtkWarningMacro("FAST_PHONG has no Cook-Torrance form (it expands N.L, N.H and N.V); "
                    "evaluating Cook-Torrance per fragment (PHONG)");
  }
  const std::string variant = this->Variant(ren);
  this->LastVariant = variant;
  vtkShader* vs = shaders[vtkShader::Vertex];
  vtkShader* fs = shaders[vtkShader::Fragment];
  const std::string library =
    std::string(sl_defines_glsl) + sl_brdf_glsl + sl_shading_glsl + sl_fastphong_glsl + sl_display_glsl;

  // Vertex shader: Gouraud lights here; flat and fast-phong pass the
  // provoking vertex's data.
  this->Substitute(vs, "//VTK::System::Dec", "//VTK::System::Dec\n" + variant +
      (this->GetDrawnMode() == GOURAUD ? library : std::string(sl_defines_glsl)));
  this->Substitute(vs, "//VTK::Light::Dec", "//VTK::Light::Dec\n" + std::string(sl_mapper_vs_dec_glsl));
  this->Substitute(vs, "//VTK::Light::Impl", std::string(sl_mapper_vs_impl_glsl) + "\n//VTK::Light::Impl");
  // Fragment shader: the model replaces VTK's lighting.
  this->Substitute(fs, "//VTK::System::Dec", "//VTK::System::Dec\n" + variant + library);
  this->Substitute(fs, "//VTK::Light::Dec", "//VTK::Light::Dec\n" + std::string(sl_mapper_fs_dec_glsl));
  this->Substitute(fs, "//VTK::Light::Impl", sl_mapper_fs_impl_glsl);

  this->Superclass::ReplaceShaderValues(shaders, ren, act);

  // Gouraud: colours per vertex (point scalars mapped to colours, VTK's
  // scalarColor attribute) are shaded at the vertex; otherwise rho is
  // applied per fragment (sl_mapper_vs_impl.glsl).
  const bool vertexColors =
    std::string(vs->GetSource()).find("vertexColorVSOutput = scalarColor") != std::string::npos;
  this->Substitute(vs, "//SL::VertexRho::Dec",
    vertexColors ? "#define SL_VERTEX_RHO scalarColor.rgb" : "// no per-vertex colours");

  if (!(this->Internal->Settings.render.interpolation == sl::render::InterpolationSpace::Perspective))
  {
    // Screen-space interpolation of VTK's own varyings (the lecture's
    // linear interpolation in screen coordinates).
    std::string vsSource = vs->GetSource();
    std::string fsSource = fs->GetSource();
    // vertexColorVSOutput exists only with scalar colouring: optional.
    for (const char* decl :
      { "vec4 vertexVCVSOutput;", "vec3 normalVCVSOutput;", "vec4 vertexColorVSOutput;" })
    {
      vtkShaderProgram::Substitute(vsSource, std::string("out ") + decl, std::string("noperspective out ") + decl);
      vtkShaderProgram::Substitute(fsSource, std::string("in ") + decl, std::string("noperspective in ") + decl);
    }
    vs->SetSource(vsSource);
    fs->SetSource(fsSource);
  }
  if (std::getenv("SHADINGLAB_DUMP_SHADERS"))
  {
    std::cerr << "=== VS ===\n" << vs->GetSource() << "\n=== FS ===\n" << fs->GetSource() << "\n";
  }
}

namespace
{
/// The lights' part of the uniform block (sl_mapper_fs_dec.glsl's order):
/// position or unit direction in view coordinates, I_L dw (through the
/// lights' polarizer when there is one, `lightPolarizer` >= 0),
/// attenuation, spot axis and cosine of the cone, spot exponent.
void AppendLights(std::vector<float>& block, const sl::Lighting<double>& lighting,
  vtkMatrix4x4* view, double lightPolarizer)
{
  float lightVector[4 * sl::kMaxLights] = {}, irradiance[3 * sl::kMaxLights] = {},
                                              attenuation[3 * sl::kMaxLights] = {};
  float spot[4 * sl::kMaxLights], spotExponent[sl::kMaxLights];
  for (int j = 0; j < sl::kMaxLights; ++j)
  {
    spot[4 * j] = spot[4 * j + 1] = 0.0f;
    spot[4 * j + 2] = -1.0f;
    spot[4 * j + 3] = -2.0f; // no cone
    spotExponent[j] = 1.0f;
  }
  const int count = lighting.lightCount;
  for (int j = 0; j < count; ++j)
  {
    const sl::Light<double>& light = lighting.lights[j];
    double v[4];
    if (light.type == sl::LightType::Point)
    {
      const double p[4] = { light.vector.x, light.vector.y, light.vector.z, 1.0 };
      view->MultiplyPoint(p, v);
      v[3] = 1.0;
      attenuation[3 * j] = static_cast<float>(light.attenuation.x);
      attenuation[3 * j + 1] = static_cast<float>(light.attenuation.y);
      attenuation[3 * j + 2] = static_cast<float>(light.attenuation.z);
      if (light.coneAngle <= 90.0)
      {
        const sl::Vec3d& d = light.spotDirection;
        const double axis[4] = { d.x, d.y, d.z, 0.0 };
        double a[4];
        view->MultiplyPoint(axis, a);
        const sl::Vec3d unit = sl::NormalizeOr(sl::Vec3d(a[0], a[1], a[2]), sl::Vec3d(0, 0, -1));
        spot[4 * j] = static_cast<float>(unit.x);
        spot[4 * j + 1] = static_cast<float>(unit.y);
        spot[4 * j + 2] = static_cast<float>(unit.z);
        spot[4 * j + 3] = static_cast<float>(std::cos(light.coneAngle * sl::kPi<double> / 180.0));
        spotExponent[j] = static_cast<float>(light.coneExponent);
      }
    }
    else
    {
      const double d[4] = { light.vector.x, light.vector.y, light.vector.z, 0.0 };
      view->MultiplyPoint(d, v);
      // Unit direction: the shader uses it as is.
      const sl::Vec3d unit = sl::NormalizeOr(sl::Vec3d(v[0], v[1], v[2]), sl::Vec3d(0, 0, 1));
      v[0] = unit.x, v[1] = unit.y, v[2] = unit.z;
      v[3] = 0.0;
      attenuation[3 * j] = 1.0f;
    }
    for (int c = 0; c < 4; ++c)
    {
      lightVector[4 * j + c] = static_cast<float>(v[c]);
    }
    // I_L dw with the model's solid angle convention (dw = pi), through
    // the lights' polarizer when there is one (Shading.h LightPolarizer).
    const double passed = light.solidAngle *
      (lightPolarizer >= 0 ? sl::kPolarizerTransmittance<double> : 1.0);
    irradiance[3 * j] = static_cast<float>(light.intensity.x * passed);
    irradiance[3 * j + 1] = static_cast<float>(light.intensity.y * passed);
    irradiance[3 * j + 2] = static_cast<float>(light.intensity.z * passed);
  }
  block.insert(block.end(), lightVector, lightVector + 4 * sl::kMaxLights);
  block.insert(block.end(), irradiance, irradiance + 3 * sl::kMaxLights);
  block.insert(block.end(), attenuation, attenuation + 3 * sl::kMaxLights);
  block.insert(block.end(), spot, spot + 4 * sl::kMaxLights);
  block.insert(block.end(), spotExponent, spotExponent + sl::kMaxLights);
}
} // namespace

void vtkShadingLabOpenGLPolyDataMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  if (!program)
  {
    return;
  }
  const sl::Material<double> m = this->DrawnMaterial();
  vtkCamera* camera = ren->GetActiveCamera();
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();

  // The uniform block, flattened so a change can be detected cheaply.
  std::vector<float> block;
  // The lights (the one vtkLight conversion, render::LightingFromVtk) in
  // view coordinates.
  const sl::render::Settings& settings = this->Internal->Settings;
  const sl::Lighting<double> lighting =
    sl::render::LightingFromVtk(ren, settings.lightIntensity, settings.lightSolidAngle);
  AppendLights(block, lighting, view, settings.render.lightPolarizer);
  const double ia[3] = { lighting.ambientIntensity.x, lighting.ambientIntensity.y,
    lighting.ambientIntensity.z };
  vtkProperty* prop = act->GetProperty();
  const double diffuseCoefficient = prop->GetDiffuse();
  const double* dc = this->BlockColorSet ? this->BlockColor : prop->GetDiffuseColor();
  const float values[] = { static_cast<float>(m.ambient.x * ia[0]), static_cast<float>(m.ambient.y * ia[1]),
    static_cast<float>(m.ambient.z * ia[2]), static_cast<float>(m.specularColor.x),
    static_cast<float>(m.specularColor.y), static_cast<float>(m.specularColor.z),
    static_cast<float>(m.kd), static_cast<float>(m.ks), static_cast<float>(m.shininess),
    static_cast<float>(m.eta.x), static_cast<float>(m.eta.y), static_cast<float>(m.eta.z),
    static_cast<float>(m.k.x), static_cast<float>(m.k.y), static_cast<float>(m.k.z),
    m.variant == sl::SpecularVariant::Walter2007 ? 4.0f : 1.0f,
    // rho: VTK's diffuseColor divided by the property's Diffuse coefficient.
    diffuseCoefficient > 0 ? static_cast<float>(1.0 / diffuseCoefficient) : 1.0f,
    static_cast<float>(dc[0]), static_cast<float>(dc[1]), static_cast<float>(dc[2]),
    camera->GetParallelProjection() ? 1.0f : 0.0f,
    static_cast<float>(std::cos(settings.render.fastPhongMaxSpread * sl::kPi<double> / 180.0)) };
  block.insert(block.end(), std::begin(values), std::end(values));
  float weights[sl::kMaxLobes], ms[sl::kMaxLobes];
  for (int k = 0; k < sl::kMaxLobes; ++k)
  {
    weights[k] = static_cast<float>(m.lobes[k].weight);
    ms[k] = static_cast<float>(m.lobes[k].m);
  }
  block.insert(block.end(), weights, weights + sl::kMaxLobes);
  block.insert(block.end(), ms, ms + sl::kMaxLobes);
  int vx, vy, vw, vh;
  ren->GetTiledSizeAndOrigin(&vw, &vh, &vx, &vy);
  const float viewport[4] = { static_cast<float>(vx), static_cast<float>(vy), static_cast<float>(vw),
    static_cast<float>(vh) };
  block.insert(block.end(), viewport, viewport + 4);
  float spectralEta[sl::kSpectralSamples] = {}, spectralK[sl::kSpectralSamples] = {},
    spectralWeight[3 * sl::kSpectralSamples] = {};
  for (int i = 0; i < m.spectralCount && i < sl::kSpectralSamples; ++i)
  {
    spectralEta[i] = static_cast<float>(m.spectralEta[i]);
    spectralK[i] = static_cast<float>(m.spectralK[i]);
    for (int c = 0; c < 3; ++c)
    {
      spectralWeight[3 * i + c] = static_cast<float>(m.spectralWeight[i][c]);
    }
  }
  // The analyser's row and the lights' polarizer axis in view coordinates
  // (x right, y up: the image's axes; Shading.h Analyser, LightPolarizer).
  const auto row =
    sl::Analyser<float>::At(settings.render.polarizer, settings.render.circularAnalyser);
  const float analyser[3] = { row.cos2Theta, row.sin2Theta, row.circular };
  block.insert(block.end(), analyser, analyser + 3);
  const double psi = settings.render.lightPolarizer * sl::kPi<double> / 180.0;
  const float lightPolarizer[3] = { static_cast<float>(std::cos(psi)),
    static_cast<float>(std::sin(psi)), 0.0f };
  block.insert(block.end(), lightPolarizer, lightPolarizer + 3);
  if (m.spectralCount > 0)
  {
    block.insert(block.end(), spectralEta, spectralEta + sl::kSpectralSamples);
    block.insert(block.end(), spectralK, spectralK + sl::kSpectralSamples);
    block.insert(block.end(), spectralWeight, spectralWeight + 3 * sl::kSpectralSamples);
  }

  std::vector<float>& last = this->Internal->LastUniforms[program];
  if (last == block)
  {
    return; // unchanged: nothing to send
  }
  last = block;
  ++this->UniformUploads;
  // The lights lead the block (AppendLights): 4 + 3 + 3 + 4 + 1 floats a light.
  float* lights = block.data();
  constexpr int K = sl::kMaxLights;
  program->SetUniform4fv("slLightVectorVC", K, reinterpret_cast<float(*)[4]>(lights));
  program->SetUniform3fv("slLightIrradiance", K, reinterpret_cast<float(*)[3]>(lights + 4 * K));
  program->SetUniform3fv("slLightAttenuation", K, reinterpret_cast<float(*)[3]>(lights + 7 * K));
  program->SetUniform4fv("slLightSpot", K, reinterpret_cast<float(*)[4]>(lights + 10 * K));
  program->SetUniform1fv("slLightSpotExponent", K, lights + 14 * K);
  program->SetUniform3f("slAmbient", values);
  program->SetUniform3f("slSpecularColor", values + 3);
  program->SetUniformf("slKd", values[6]);
  program->SetUniformf("slKs", values[7]);
  program->SetUniformf("slShininess", values[8]);
  program->SetUniform3f("slEta", values + 9);
  program->SetUniform3f("slK", values + 12);
  program->SetUniformf("slJacobian", values[15]);
  program->SetUniformf("slInvDiffuseIntensity", values[16]);
  program->SetUniform3f("slDiffuseColor", values + 17);
  program->SetUniformi("slCameraParallel", camera->GetParallelProjection() ? 1 : 0);
  program->SetUniformf("slFastPhongMinCos", values[21]);
  program->SetUniform1fv("slLobeWeight", sl::kMaxLobes, weights);
  program->SetUniform1fv("slLobeM", sl::kMaxLobes, ms);
  program->SetUniform4f("slViewport", viewport);
  if (settings.render.polarizer >= 0)
  {
    program->SetUniform3f("slAnalyser", analyser);
  }
  if (settings.render.lightPolarizer >= 0)
  {
    program->SetUniform3f("slLightPolarizer", lightPolarizer);
  }
  if (m.spectralCount > 0)
  {
    program->SetUniform1fv("slSpectralEta", sl::kSpectralSamples, spectralEta);
    program->SetUniform1fv("slSpectralK", sl::kSpectralSamples, spectralK);
    program->SetUniform3fv(
      "slSpectralWeight", sl::kSpectralSamples, reinterpret_cast<float(*)[3]>(spectralWeight));
  }
}

void vtkShadingLabOpenGLPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const sl::render::Settings& settings = this->Internal->Settings;
  for (const auto& row : sl::render::SettingsTable())
  {
    if (row.frontEnds & sl::render::kMapper)
    {
      os << indent << row.property << ": " << sl::render::FormatSetting(row, row.get(settings))
         << "\n";
    }
  }
  os << indent << "ShaderBuildCount: " << this->ShaderBuildCount << "\n";
}
