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
#include <vector>
#include <string>

class SHADINGLABPARAVIEW_EXPORT vtkShadingLabSurfaceRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkShadingLabSurfaceRepresentation* New();
  vtkTypeMacro(vtkShadingLabSurfaceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Every ShadingLab property of the representation, by the setting's key
   * (shadinglab/render/Settings.h; the ServerManager XML is generated from
   * that table and passes the key first): SetIntSetting for choices (the
   * choice's index), flags and integers, SetRealSettingN for N reals,
   * SetTextSetting for names (a choice's key or Title Case label). A value
   * out of range or unknown is reported with vtkErrorMacro and ignored.
   */
  void SetIntSetting(const char* key, int value);
  void SetRealSetting1(const char* key, double v0);
  void SetRealSetting3(const char* key, double v0, double v1, double v2);
  void SetRealSetting4(const char* key, double v0, double v1, double v2, double v3);
  void SetTextSetting(const char* key, const char* value);
  ///@}

  /// Auto: the last render's choice per block, and why ("" in other modes).
  const char* GetAutoChoice();
  /// The last render's backend per block and, for Auto, why (the context's
  /// renderer and the polygon count against the crossover).
  const char* GetBackendChoice();

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

  /// The superclass's geometry, then normals made across partition
  /// boundaries (MakeDistributedNormals).
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  /// On several ranks, the blocks without normals get them here, from
  /// every face around each vertex, the neighbouring ranks' included
  /// (vtkShadingLabNormals: borrowed boundary faces). The mappers would
  /// make them from their own rank's faces only, and smooth shading would
  /// show each partition boundary as a seam. Collective.
  void MakeDistributedNormals();

  /// Pushes the settings to both mappers after validating the material.
  void UpdateSettings();
  /// Hands ParaView's block colours, opacities and visibility to both
  /// mappers (the superclass gives them to vtkCompositePolyDataMapper2 only).
  void UpdateBlockAttributes();

private:
  vtkShadingLabSurfaceRepresentation(const vtkShadingLabSurfaceRepresentation&) = delete;
  void operator=(const vtkShadingLabSurfaceRepresentation&) = delete;

  void SetSetting(const char* key, const std::vector<double>& numbers, const char* text);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
