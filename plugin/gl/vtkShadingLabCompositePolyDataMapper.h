// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadingLabCompositePolyDataMapper
 * @brief   multiblock input rendered block by block with vtkShadingLabPolyDataMapper
 *
 * A vtkCompositePolyDataMapper whose per-block mappers are
 * vtkShadingLabPolyDataMapper instances carrying this mapper's mode,
 * interpolation space and material. It holds the properties only; the GLSL
 * work lives in the delegate (ParaView's advice for composite mappers).
 * Per-block visibility, colour and opacity (vtkCompositeDataDisplayAttributes,
 * inherited down the tree as vtkCompositePolyDataMapper2 does) come from
 * SetBlockAttributes: ParaView's Block Colors / Opacities / Selectors.
 */
#ifndef vtkShadingLabCompositePolyDataMapper_h
#define vtkShadingLabCompositePolyDataMapper_h

#include "shadinglab/model/Shading.h"

#include "shadinglabGLModule.h" // for export macro
#include "vtkShadingLabPolyDataMapper.h" // for Modes

#include <vtkCompositePolyDataMapper.h>
#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

#include <string>
#include <vector>


class vtkCompositeDataDisplayAttributes;

class SHADINGLABGL_EXPORT vtkShadingLabCompositePolyDataMapper : public vtkCompositePolyDataMapper
{
public:
  static vtkShadingLabCompositePolyDataMapper* New();
  vtkTypeMacro(vtkShadingLabCompositePolyDataMapper, vtkCompositePolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The block mappers' settings (vtkShadingLabPolyDataMapper::SetSettings);
  /// with auto each block chooses its own mode (per object and view).
  void SetSettings(const shadinglab::render::Settings& settings);
  const shadinglab::render::Settings& GetSettings() const { return this->Settings; }
  void SetMaterial(const shadinglab::Material<double>& material);
  ///@}
  /// AUTO: each drawn block's choice, one line per block ("" otherwise).
  std::string GetAutoChoices();
  /// Each drawn block's backend and, for Auto, why: one line per block.
  std::string GetBackendChoices();

  /// Sum of the block mappers' shader builds.
  int GetShaderBuildCount();

  /// Per-block visibility, colour and opacity, keyed by the input's data
  /// objects (any node: a setting applies to the subtree below it). nullptr:
  /// every block as the actor.
  void SetBlockAttributes(vtkCompositeDataDisplayAttributes* attributes);

  bool HasOpaqueGeometry() override;
  bool HasTranslucentPolygonalGeometry() override;

protected:
  vtkShadingLabCompositePolyDataMapper() = default;
  ~vtkShadingLabCompositePolyDataMapper() override = default;
  vtkPolyDataMapper* MakeAMapper() override;
  void Render(vtkRenderer* ren, vtkActor* act) override;

  shadinglab::render::Settings Settings;
  /// The block mappers of the last build, in leaf order (the superclass
  /// owns them; weak here).
  std::vector<vtkWeakPointer<vtkShadingLabPolyDataMapper>> BlockMappers;
  vtkMTimeType BuildSeen = ~vtkMTimeType(0); ///< build stamp of BlockMappers' first
  vtkSmartPointer<vtkCompositeDataDisplayAttributes> BlockAttributes;

  /// How one leaf is drawn: visibility, colour (when set) and opacity.
  struct BlockLook
  {
    bool visible = true;
    bool colorSet = false;
    double color[3] = { 1, 1, 1 };
    double opacity = 1.0;
  };
  /// One BlockLook per block mapper (per polydata leaf, in order), the
  /// root's opacity `actorOpacity`.
  std::vector<BlockLook> BlockLooks(double actorOpacity);
  /// Whether Render draws `block` in the translucent pass.
  static bool DrawnTranslucent(
    const BlockLook& look, vtkShadingLabPolyDataMapper* block, double actorOpacity);
  bool HasBlocks(bool translucent);
  void BuildIfNeeded();

private:
  vtkShadingLabCompositePolyDataMapper(const vtkShadingLabCompositePolyDataMapper&) = delete;
  void operator=(const vtkShadingLabCompositePolyDataMapper&) = delete;
};

#endif
