// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadingLabCompositePolyDataMapper
 * @brief   multiblock input rendered block by block with vtkShadingLabPolyDataMapper
 *
 * A mapper of vtkPolyData or composite data whose per-block mappers are
 * vtkShadingLabPolyDataMapper instances carrying this mapper's mode,
 * interpolation space and material. It holds the properties only; the GLSL
 * work lives in the block mappers (ParaView's advice for composite mappers).
 * It derives from vtkMapper and owns its block mappers, as VTK 9.2's
 * vtkCompositePolyDataMapper did: VTK 9.3 rebuilt that class around
 * delegators that batch the blocks into one vtkOpenGLPolyDataMapper of
 * VTK's, with no place for our shader replacements, so the same source
 * serves VTK 9.2 to 9.6.
 * Per-block visibility, colour and opacity (vtkCompositeDataDisplayAttributes,
 * inherited down the tree as vtkCompositePolyDataMapper2 does) come from
 * SetBlockAttributes: ParaView's Block Colors / Opacities / Selectors.
 */
#ifndef vtkShadingLabCompositePolyDataMapper_h
#define vtkShadingLabCompositePolyDataMapper_h

#include "shadinglab/model/Shading.h"

#include "shadinglabVTKModule.h" // for export macro
#include "vtkShadingLabPolyDataMapper.h" // for Modes

#include <vtkMapper.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>


class vtkCompositeDataDisplayAttributes;
class vtkPolyData;

class SHADINGLABVTK_EXPORT vtkShadingLabCompositePolyDataMapper : public vtkMapper
{
public:
  static vtkShadingLabCompositePolyDataMapper* New();
  vtkTypeMacro(vtkShadingLabCompositePolyDataMapper, vtkMapper);
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
  /// The union of the polydata leaves' cell bounds.
  double* GetBounds() override;
  using vtkAbstractMapper3D::GetBounds;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkShadingLabCompositePolyDataMapper() = default;
  ~vtkShadingLabCompositePolyDataMapper() override = default;
  void Render(vtkRenderer* ren, vtkActor* act) override;
  /// Takes vtkPolyData or a vtkCompositeDataSet of them.
  int FillInputPortInformation(int port, vtkInformation* info) override;
  vtkExecutive* CreateDefaultExecutive() override;

  shadinglab::render::Settings Settings;
  /// The block mappers of the last build, one per polydata leaf in the
  /// composite iterator's order (leaves only, empty ones skipped).
  std::vector<vtkSmartPointer<vtkShadingLabPolyDataMapper>> BlockMappers;
  vtkTimeStamp BuildTime; ///< when BlockMappers were made
  vtkTimeStamp BoundsTime; ///< when Bounds were computed
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
  /// Makes BlockMappers anew when the pipeline changed since BuildTime.
  void BuildIfNeeded();
  void BuildBlockMappers();
  /// The input's vtkPolyData leaves in block-mapper order; `report` logs a
  /// leaf or an input this mapper cannot draw (once).
  std::vector<vtkPolyData*> PolyDataLeaves(bool report);

private:
  vtkShadingLabCompositePolyDataMapper(const vtkShadingLabCompositePolyDataMapper&) = delete;
  void operator=(const vtkShadingLabCompositePolyDataMapper&) = delete;
};

#endif
