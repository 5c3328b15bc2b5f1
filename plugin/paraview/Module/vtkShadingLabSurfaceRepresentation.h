// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadingLabSurfaceRepresentation
 * @brief   ParaView's Surface representation drawn by the ShadingLab mapper
 *
 * A vtkGeometryRepresentationWithFaces whose mappers are
 * vtkShadingLabCompositePolyDataMapper: the shading mode (where the model is
 * evaluated: flat, Gouraud, Phong, fast Phong) and the reflectance model
 * (what is evaluated: Lambert, Phong, Blinn-Phong, Cook-Torrance) are
 * independent properties, as are the material's parameters. Colouring by a
 * data array works as in the Surface representation: the mapped colour is
 * the diffuse albedo rho. ParaView's lights (light kit, headlight, extra
 * lights) are the lights of the model.
 *
 * Material parameters are plain numbers here (the ServerManager XML sets
 * them one by one); a named preset, when set, replaces them all.
 */
#ifndef vtkShadingLabSurfaceRepresentation_h
#define vtkShadingLabSurfaceRepresentation_h

#include "shadinglabParaViewModule.h" // for export macro

#include <vtkGeometryRepresentationWithFaces.h>

#include <memory>
#include <string>

class SHADINGLABPARAVIEW_EXPORT vtkShadingLabSurfaceRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkShadingLabSurfaceRepresentation* New();
  vtkTypeMacro(vtkShadingLabSurfaceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// vtkShadingLabPolyDataMapper::Modes: 0 flat, 1 Gouraud, 2 Phong (default), 3 fast Phong,
  /// 4 auto (per block and render, the cheapest mode predicted under MaxError).
  void SetShadingMode(int mode);
  /// Auto's error budget, mean error in 1/255 (default 1, [0.01, 255]).
  void SetMaxError(double maxError);
  /// Auto: the last render's choice per block, and why ("" in other modes).
  const char* GetAutoChoice();
  /// shadinglab::ReflectanceModel: 0 Lambert, 1 Phong, 2 Blinn-Phong (default), 3 Cook-Torrance.
  void SetReflectanceModel(int model);
  /// 0 perspective-correct (default), 1 screen-space interpolation.
  void SetInterpolationSpace(int space);
  /// Fast Phong's spread limit in degrees (default 30, [0, 180]).
  void SetFastPhongMaxSpread(double degrees);

  ///@{
  /// Vertex normals made when the data has none (or always, with
  /// RecomputeNormals): weighting 0 uniform, 1 area (default), 2 angle,
  /// 3 Max; creases split above FeatureAngle degrees (default 180: none).
  void SetNormalWeighting(int weighting);
  void SetFeatureAngle(double degrees);
  void SetRecomputeNormals(int recompute);
  ///@}

  ///@{
  /// The material (docs/model.md): kd, ks (kd + ks <= 1), shininess n,
  /// ambient reflectance Ra, specular colour, Beckmann roughnesses m_k and
  /// weights w_k (up to 4 lobes), eta and k per RGB channel, and the
  /// specular variant (0: Cook & Torrance 1982, 1: Walter et al. 2007).
  void SetKd(double kd);
  void SetKs(double ks);
  void SetShininess(double n);
  void SetAmbientReflectance(double ra);
  void SetSpecularTint(double r, double g, double b);
  void SetBeckmannRoughness(double m0, double m1, double m2, double m3);
  void SetBeckmannWeights(double w0, double w1, double w2, double w3);
  void SetEta(double r, double g, double b);
  void SetExtinction(double r, double g, double b);
  void SetSpecularVariant(int variant);
  ///@}

  /// A named preset (plastic, glass, gold, copper, silver, aluminium), or
  /// "Custom" / empty (default): the parameters above.
  void SetMaterialPreset(const char* name);

  /// The last material problem ("" when valid). An invalid material keeps
  /// the last valid one and reports the problem with vtkErrorMacro.
  const char* GetMaterialProblem();

  /// Applies material changes (validated as a whole, after every property
  /// of an Apply has arrived), then the superclass's request handling.
  int ProcessViewRequest(
    vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;

protected:
  vtkShadingLabSurfaceRepresentation();
  ~vtkShadingLabSurfaceRepresentation() override;

  /// Pushes the material to both mappers after validating it.
  void UpdateMaterial();
  /// Hands ParaView's block colours, opacities and visibility to both
  /// mappers (the superclass gives them to vtkCompositePolyDataMapper2 only).
  void UpdateBlockAttributes();

private:
  vtkShadingLabSurfaceRepresentation(const vtkShadingLabSurfaceRepresentation&) = delete;
  void operator=(const vtkShadingLabSurfaceRepresentation&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
