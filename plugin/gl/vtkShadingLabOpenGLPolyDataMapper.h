// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadingLabOpenGLPolyDataMapper
 * @brief   the four ShadingLab shading modes on the GPU, by shader replacement
 *
 * The GL renderer's mapper. Applications use its subclass
 * vtkShadingLabPolyDataMapper (plugin/vtk), which can also hand the drawing
 * to the CPU renderer (its Backend setting); this class draws with OpenGL
 * only and ignores that setting.
 *
 * A vtkOpenGLPolyDataMapper whose shaders evaluate the ShadingLab model (the
 * GLSL twin of plugin/model, in plugin/gl/glsl/) in one of four shading
 * modes: FLAT (face normal, lit once per triangle at its provoking vertex),
 * GOURAUD (the model per vertex in the vertex shader, colour interpolated;
 * VTK's own Gouraud lights per fragment), PHONG (normals interpolated and
 * renormalized, model per fragment) and FAST_PHONG (Bishop & Weimer's
 * quadratic about the triangle's provoking vertex). The reflectance model
 * (Lambert, Phong, Blinn-Phong, Cook-Torrance) is the material's: any mode
 * evaluates any model, except FAST_PHONG with Cook-Torrance. Interpolation is
 * perspective-correct or, with PerspectiveCorrect off, screen-linear
 * (GLSL noperspective).
 *
 * Lights are the renderer's vtkLights (headlight, camera and scene lights;
 * positional lights with attenuation and spot cones; intensity I_L = intensity x diffuse
 * colour, solid angle pi as in plugin/model). The ambient intensity Ia is
 * the renderer's ambient. The albedo rho is the property's diffuse colour (or
 * the point scalars' colours), divided by the property's Diffuse coefficient
 * (kd comes from the material).
 *
 * Shader variants are built from #defines (mode, model, light count, point
 * lights, specular, mixture size, conductor, interpolation space); a change
 * of any of them regenerates the shader source (counted by
 * GetShaderBuildCount) and VTK's shader cache reuses a program compiled for
 * that variant before. Material changes that do not change the variant only
 * update uniforms, and uniforms are re-sent only when they changed.
 *
 * @warning FAST_PHONG with a Cook-Torrance material (no quadratic form)
 * evaluates it per fragment as PHONG and says so (vtkWarningMacro). Gouraud mode takes rho from the property, not from point
 * scalars. Meshes without point normals get area-weighted normals computed
 * once per input change; flat mode uploads no point normals.
 */
#ifndef vtkShadingLabOpenGLPolyDataMapper_h
#define vtkShadingLabOpenGLPolyDataMapper_h

#include "shadinglab/model/Shading.h"
#include "shadinglab/render/Settings.h"

#include "shadinglabGLModule.h" // for export macro

#include <vtkOpenGLPolyDataMapper.h>

class vtkShadingLabSettings;

#include <memory>
#include <string>

class SHADINGLABGL_EXPORT vtkShadingLabOpenGLPolyDataMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkShadingLabOpenGLPolyDataMapper* New();
  vtkTypeMacro(vtkShadingLabOpenGLPolyDataMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Where the model is evaluated: shadinglab::render::ShadingMode's values
  /// (plain numbers for VTK's wrappers; static_asserts in the .cxx tie them).
  enum Modes
  {
    FLAT = 0,
    GOURAUD = 1,
    PHONG = 2,
    FAST_PHONG = 3,
    /// Not a render::ShadingMode: chosen per render among FLAT, GOURAUD and
    /// PHONG as the cheapest predicted to keep the mean error under
    /// MaxError (render::ChooseMode, docs/model.md eq. 4.1-4.5), from this
    /// mapper's input, the renderer's camera, size and lights, and the
    /// material.
    AUTO = 4
  };

  ///@{
  /**
   * Every setting at once (shadinglab/render/Settings.h, the table every
   * front end reads): mode (or auto with its error budget), interpolation
   * space, fast Phong's spread limit, the normals made for inputs without
   * them, the light-intensity scale and the material. Only what the shaders
   * are built from (mode, model, specular on/off, lobe count, conductor,
   * interpolation) rebuilds them; the rest are uniforms.
   */
  void SetSettings(const shadinglab::render::Settings& settings);
  const shadinglab::render::Settings& GetSettings() const;
  ///@}

  /// The same from a vtkShadingLabSettings (VTK's wrappers, Python): its
  /// settings are copied; later changes to it need another call.
  void SetSettingsFrom(vtkShadingLabSettings* settings);

  /**
   * One setting by its table key and text, as on the command line:
   * SetSetting("mode", "gouraud"), SetSetting("eta", "1.5,1.5,1.5").
   * Returns false (and reports with vtkErrorMacro) on an unknown key or a
   * value out of range; the mapper is then unchanged.
   */
  bool SetSetting(const char* key, const char* value);

  /// Per-block overrides from a composite mapper (ParaView's block colours
  /// and opacities): `color` (nullptr: the property's) is the albedo rho of
  /// a block drawn without scalar colours, `opacity` (< 0: the property's)
  /// its opacity. Uniforms only: no shader rebuild.
  void SetBlockOverrides(const double* color, double opacity);

  /// The mode the last render drew: ShadingMode, or AUTO's choice.
  int GetDrawnMode() const;
  /// AUTO: the last choice's reasons (predictors, each mode's predicted
  /// error and cost; render::ModeChoice::why); "" otherwise.
  const std::string& GetAutoChoice() const;

  /// The material alone (the settings' `material`).
  void SetMaterial(const shadinglab::Material<double>& material);
  const shadinglab::Material<double>& GetMaterial() const;

  /// Shader sources generated so far (one per variant change).
  int GetShaderBuildCount() const { return this->ShaderBuildCount; }
  /// Substitutions that did not find their tag (must stay 0).
  int GetFailedSubstitutionCount() const { return this->FailedSubstitutions; }
  /// Times the uniform block was (re)sent to a program.
  int GetUniformUploadCount() const { return this->UniformUploads; }
  /// The variant #defines of the last build.
  const std::string& GetLastVariant() const { return this->LastVariant; }
  ///@{
  /// Colours (or colour texture coordinates) are mapped from the data
  /// drawn: the input with the normals made in RenderPieceStart, whose
  /// crease split adds points. VTK 9.2's buffer building maps GetInput()
  /// (without them), and the split points took whatever colour lay past
  /// the array's end.
  using Superclass::MapScalars;
  vtkUnsignedCharArray* MapScalars(double alpha) override;
  vtkUnsignedCharArray* MapScalars(double alpha, int& cellFlag) override;
  ///@}

protected:
  vtkShadingLabOpenGLPolyDataMapper();
  ~vtkShadingLabOpenGLPolyDataMapper() override;

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void SetPropertyShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  /// The input with the normals the settings ask for (made here when it
  /// has none, or on request; none in flat mode) and its concave polygons
  /// split into ear-clipped triangles: what both backends draw.
  vtkPolyData* PrepareInput(vtkPolyData* input);
  /// The normals' part of PrepareInput.
  vtkPolyData* PrepareNormals(vtkPolyData* input);
  /// A subclass that drew the input another way (the CPU backend) reports
  /// the mode it drew and, for AUTO, why (GetDrawnMode, GetAutoChoice).
  void SetDrawnElsewhere(int mode, const std::string& autoChoice);

  bool BlockColorSet = false;
  double BlockColor[3] = { 1, 1, 1 };
  double BlockOpacity = -1.0;
  int ShaderBuildCount = 0;
  int FailedSubstitutions = 0;
  int UniformUploads = 0;
  std::string LastVariant;

private:
  vtkShadingLabOpenGLPolyDataMapper(const vtkShadingLabOpenGLPolyDataMapper&) = delete;
  void operator=(const vtkShadingLabOpenGLPolyDataMapper&) = delete;

  std::string Variant(vtkRenderer* ren) const;
  /// The mode the shaders evaluate: the drawn mode, or PHONG where the
  /// material's model has no form in it (render::SupportsModel).
  int EffectiveMode() const;
  /// The settings' material as drawn on this input: without highlights on
  /// colours from data (render::MaterialForData), once MapScalars has run.
  shadinglab::Material<double> DrawnMaterial() const;
  /// AUTO: chooses the drawn mode for `input` seen by `ren`.
  void ChooseAutoMode(vtkRenderer* ren, vtkPolyData* input);
  bool Substitute(vtkShader* shader, const std::string& tag, const std::string& code);
  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
