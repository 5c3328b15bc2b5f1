// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadingLabCompositePolyDataMapper
 * @brief   multiblock input rendered block by block with vtkShadingLabPolyDataMapper
 *
 * A vtkCompositePolyDataMapper whose per-block mappers are
 * vtkShadingLabPolyDataMapper instances carrying this mapper's mode,
 * interpolation space and material. It holds the properties only; the GLSL
 * work lives in the delegate (ParaView's advice for composite mappers).
 */
#ifndef vtkShadingLabCompositePolyDataMapper_h
#define vtkShadingLabCompositePolyDataMapper_h

#include "shadinglab/model/Shading.h"

#include "shadinglabGLModule.h" // for export macro
#include "vtkShadingLabPolyDataMapper.h" // for Modes

#include <vtkCompositePolyDataMapper.h>
#include <vtkWeakPointer.h>

#include <string>
#include <vector>


class SHADINGLABGL_EXPORT vtkShadingLabCompositePolyDataMapper : public vtkCompositePolyDataMapper
{
public:
  static vtkShadingLabCompositePolyDataMapper* New();
  vtkTypeMacro(vtkShadingLabCompositePolyDataMapper, vtkCompositePolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// vtkShadingLabPolyDataMapper::Modes (default PHONG); with AUTO each
  /// block chooses its own mode (per object and view).
  vtkSetClampMacro(ShadingMode, int, vtkShadingLabPolyDataMapper::FLAT,
    vtkShadingLabPolyDataMapper::AUTO);
  vtkGetMacro(ShadingMode, int);
  /// AUTO's error budget (vtkShadingLabPolyDataMapper::SetMaxError).
  vtkSetClampMacro(MaxError, double, 0.01, 255.0);
  vtkGetMacro(MaxError, double);
  /// AUTO: each drawn block's choice, one line per block ("" otherwise).
  std::string GetAutoChoices();
  vtkSetMacro(PerspectiveCorrect, bool);
  vtkGetMacro(PerspectiveCorrect, bool);
  /// vtkShadingLabPolyDataMapper's normal settings (see there).
  vtkSetClampMacro(NormalWeighting, int, 0, 3);
  vtkGetMacro(NormalWeighting, int);
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  vtkSetMacro(RecomputeNormals, bool);
  vtkGetMacro(RecomputeNormals, bool);
  /// vtkShadingLabPolyDataMapper::SetFastPhongMaxSpread (default 30 degrees).
  vtkSetClampMacro(FastPhongMaxSpread, double, 0.0, 180.0);
  vtkGetMacro(FastPhongMaxSpread, double);
  void SetMaterial(const shadinglab::Material<double>& material);

  /// Sum of the block mappers' shader builds.
  int GetShaderBuildCount();

protected:
  vtkShadingLabCompositePolyDataMapper() = default;
  ~vtkShadingLabCompositePolyDataMapper() override = default;
  vtkPolyDataMapper* MakeAMapper() override;
  void Render(vtkRenderer* ren, vtkActor* act) override;

  int ShadingMode = vtkShadingLabPolyDataMapper::PHONG;
  double MaxError = 1.0;
  bool PerspectiveCorrect = true;
  double FastPhongMaxSpread = 30.0;
  int NormalWeighting = 1;
  double FeatureAngle = 180.0;
  bool RecomputeNormals = false;
  shadinglab::Material<double> Material;
  /// The block mappers made so far (the superclass owns them; weak here).
  std::vector<vtkWeakPointer<vtkShadingLabPolyDataMapper>> BlockMappers;

private:
  vtkShadingLabCompositePolyDataMapper(const vtkShadingLabCompositePolyDataMapper&) = delete;
  void operator=(const vtkShadingLabCompositePolyDataMapper&) = delete;
};

#endif
