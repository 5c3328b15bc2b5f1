// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabCompositePolyDataMapper.h"

#include "vtkShadingLabPolyDataMapper.h"

#include <vtkActor.h>
#include <vtkBoundingBox.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkCompositeDataDisplayAttributes.h>
#include <vtkCompositeDataPipeline.h>
#include <vtkDataObjectTree.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkExecutive.h>
#include <vtkInformation.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>

#include <functional>

vtkStandardNewMacro(vtkShadingLabCompositePolyDataMapper);

namespace
{
/// Whether a block mapper has anything to draw. A block without points (a
/// ParaView client's share of data drawn elsewhere) is skipped: VTK 9.6's
/// vtkOpenGLPolyDataMapper dereferences the missing vtkPoints.
bool Drawable(vtkShadingLabPolyDataMapper* mapper)
{
  vtkPolyData* input = mapper ? mapper->GetInput() : nullptr;
  return input && input->GetPoints() && input->GetNumberOfPoints() > 0;
}
}

void vtkShadingLabCompositePolyDataMapper::SetSettings(const shadinglab::render::Settings& settings)
{
  if (!shadinglab::render::SameSettings(this->Settings, settings))
  {
    this->Settings = settings;
    this->Modified();
  }
}

void vtkShadingLabCompositePolyDataMapper::SetMaterial(const shadinglab::Material<double>& material)
{
  shadinglab::render::Settings settings = this->Settings;
  settings.material = material;
  this->SetSettings(settings);
}

std::string vtkShadingLabCompositePolyDataMapper::GetAutoChoices()
{
  std::string out;
  for (auto& m : this->BlockMappers)
  {
    vtkShadingLabPolyDataMapper* sm = m;
    if (sm && !sm->GetAutoChoice().empty())
    {
      out += sm->GetAutoChoice() + "\n";
    }
  }
  return out;
}

std::string vtkShadingLabCompositePolyDataMapper::GetBackendChoices()
{
  std::string out;
  for (auto& m : this->BlockMappers)
  {
    vtkShadingLabPolyDataMapper* sm = m;
    if (sm && sm->GetInput() && sm->GetInput()->GetNumberOfCells() > 0)
    {
      out += sm->GetBackendChoice() + "\n";
    }
  }
  return out;
}

void vtkShadingLabCompositePolyDataMapper::SetBlockAttributes(
  vtkCompositeDataDisplayAttributes* attributes)
{
  this->BlockAttributes = attributes;
  this->Modified();
}

int vtkShadingLabCompositePolyDataMapper::FillInputPortInformation(
  int vtkNotUsed(port), vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  return 1;
}

vtkExecutive* vtkShadingLabCompositePolyDataMapper::CreateDefaultExecutive()
{
  return vtkCompositeDataPipeline::New();
}

void vtkShadingLabCompositePolyDataMapper::BuildIfNeeded()
{
  auto* executive = vtkCompositeDataPipeline::SafeDownCast(this->GetExecutive());
  if (executive && executive->GetPipelineMTime() > this->BuildTime.GetMTime())
  {
    this->BuildBlockMappers();
  }
}

std::vector<vtkPolyData*> vtkShadingLabCompositePolyDataMapper::PolyDataLeaves(bool report)
{
  // The composite iterator's order (leaves only, empty nodes skipped), the
  // order BlockLooks follows too.
  std::vector<vtkPolyData*> leaves;
  vtkDataObject* input = this->GetExecutive()->GetInputData(0, 0);
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* pd = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      {
        leaves.push_back(pd);
      }
      else if (report)
      {
        vtkErrorMacro("every leaf of the composite input must be vtkPolyData; "
          << it->GetCurrentDataObject()->GetClassName() << " is not drawn");
        report = false; // once per build
      }
    }
  }
  else if (auto* pd = vtkPolyData::SafeDownCast(input))
  {
    leaves.push_back(pd);
  }
  else if (input && report)
  {
    vtkErrorMacro("this mapper cannot draw input of type " << input->GetClassName());
  }
  return leaves;
}

void vtkShadingLabCompositePolyDataMapper::BuildBlockMappers()
{
  // One block mapper per polydata leaf, each on a shallow copy (the pipeline
  // is broken here, as the mapper is the pipeline's end).
  this->BlockMappers.clear();
  for (vtkPolyData* leaf : this->PolyDataLeaves(true))
  {
    auto mapper = vtkSmartPointer<vtkShadingLabPolyDataMapper>::New();
    mapper->SetSettings(this->Settings);
    vtkNew<vtkPolyData> copy;
    copy->ShallowCopy(leaf);
    mapper->SetInputData(copy);
    this->BlockMappers.push_back(mapper);
  }
  this->BuildTime.Modified();
}

double* vtkShadingLabCompositePolyDataMapper::GetBounds()
{
  if (!this->GetExecutive()->GetInputData(0, 0))
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  this->Update();
  auto* executive = vtkCompositeDataPipeline::SafeDownCast(this->GetExecutive());
  if (executive->GetPipelineMTime() <= this->BoundsTime.GetMTime())
  {
    return this->Bounds;
  }
  vtkBoundingBox box;
  for (vtkPolyData* leaf : this->PolyDataLeaves(false))
  {
    double b[6];
    leaf->GetCellsBounds(b);
    if (vtkMath::AreBoundsInitialized(b))
    {
      box.AddBounds(b);
    }
  }
  if (box.IsValid())
  {
    box.GetBounds(this->Bounds);
  }
  else
  {
    vtkMath::UninitializeBounds(this->Bounds);
  }
  this->BoundsTime.Modified();
  return this->Bounds;
}

void vtkShadingLabCompositePolyDataMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& mapper : this->BlockMappers)
  {
    mapper->ReleaseGraphicsResources(window);
  }
}

std::vector<vtkShadingLabCompositePolyDataMapper::BlockLook>
vtkShadingLabCompositePolyDataMapper::BlockLooks(double actorOpacity)
{
  // Each polydata leaf in the superclass's traversal order (depth first,
  // children in order, empty nodes skipped), with the attributes of its
  // nearest ancestor (itself included) that sets them, as
  // vtkCompositePolyDataMapper2 inherits them; the actor's otherwise.
  std::vector<BlockLook> looks;
  BlockLook root;
  root.opacity = actorOpacity;
  vtkCompositeDataDisplayAttributes* attrs = this->BlockAttributes;
  std::function<void(vtkDataObject*, BlockLook)> visit = [&](vtkDataObject* node, BlockLook look) {
    if (!node)
    {
      return;
    }
    if (attrs && attrs->HasBlockVisibility(node))
    {
      look.visible = attrs->GetBlockVisibility(node);
    }
    if (attrs && attrs->HasBlockColor(node))
    {
      attrs->GetBlockColor(node, look.color);
      look.colorSet = true;
    }
    if (attrs && attrs->HasBlockOpacity(node))
    {
      look.opacity = attrs->GetBlockOpacity(node);
    }
    if (auto* tree = vtkDataObjectTree::SafeDownCast(node))
    {
      vtkSmartPointer<vtkDataObjectTreeIterator> it;
      it.TakeReference(tree->NewTreeIterator());
      it->VisitOnlyLeavesOff();
      it->TraverseSubTreeOff();
      it->SkipEmptyNodesOn();
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      {
        visit(it->GetCurrentDataObject(), look);
      }
    }
    else if (vtkPolyData::SafeDownCast(node))
    {
      looks.push_back(look);
    }
  };
  visit(this->GetInputDataObject(0, 0), root);
  if (looks.size() != this->BlockMappers.size())
  {
    looks.assign(this->BlockMappers.size(), root); // unknown layout: the actor's look
  }
  return looks;
}

bool vtkShadingLabCompositePolyDataMapper::DrawnTranslucent(
  const BlockLook& look, vtkShadingLabPolyDataMapper* block, double actorOpacity)
{
  // Translucent when the block's opacity (its own, inherited, or the
  // actor's) is below 1, the actor is translucent (a block set to 1 is then
  // drawn with it, in the one pass that runs), or its colours are
  // translucent. (VTK 9.2's vtkCompositePolyDataMapper looked at the
  // colours only, so a translucent actor drew nothing.)
  return look.opacity < 1.0 || actorOpacity < 1.0 || !block->HasOpaqueGeometry();
}

void vtkShadingLabCompositePolyDataMapper::Render(vtkRenderer* ren, vtkActor* act)
{
  this->BuildIfNeeded();
  const double actorOpacity = act->GetProperty()->GetOpacity();
  const std::vector<BlockLook> looks = this->BlockLooks(actorOpacity);
  const bool translucentPass = act->IsRenderingTranslucentPolygonalGeometry() != 0;
  this->TimeToDraw = 0;
  for (size_t i = 0; i < this->BlockMappers.size(); ++i)
  {
    vtkShadingLabPolyDataMapper* sm = this->BlockMappers[i];
    const BlockLook& look = looks[i];
    if (!Drawable(sm) || !look.visible)
    {
      continue;
    }
    sm->SetSettings(this->Settings); // in step with this mapper's settings
    if (sm->GetClippingPlanes() != this->ClippingPlanes)
    {
      sm->SetClippingPlanes(this->ClippingPlanes);
    }
    sm->SetLookupTable(this->GetLookupTable());
    sm->SetScalarVisibility(this->GetScalarVisibility());
    sm->SetUseLookupTableScalarRange(this->GetUseLookupTableScalarRange());
    sm->SetScalarRange(this->GetScalarRange());
    sm->SetColorMode(this->GetColorMode());
    sm->SetInterpolateScalarsBeforeMapping(this->GetInterpolateScalarsBeforeMapping());
    sm->SetScalarMode(this->GetScalarMode());
    if (this->ScalarMode == VTK_SCALAR_MODE_USE_POINT_FIELD_DATA ||
      this->ScalarMode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA)
    {
      if (this->ArrayAccessMode == VTK_GET_ARRAY_BY_ID)
      {
        sm->ColorByArrayComponent(this->ArrayId, this->ArrayComponent);
      }
      else
      {
        sm->ColorByArrayComponent(this->ArrayName, this->ArrayComponent);
      }
    }
    if (DrawnTranslucent(look, sm, actorOpacity) != translucentPass)
    {
      continue;
    }
    sm->SetBlockOverrides(look.colorSet ? look.color : nullptr, look.opacity);
    sm->Render(ren, act);
    this->TimeToDraw += sm->GetTimeToDraw();
  }
}

bool vtkShadingLabCompositePolyDataMapper::HasOpaqueGeometry()
{
  this->BuildIfNeeded();
  return this->HasBlocks(false);
}

bool vtkShadingLabCompositePolyDataMapper::HasTranslucentPolygonalGeometry()
{
  this->BuildIfNeeded();
  return this->HasBlocks(true);
}

bool vtkShadingLabCompositePolyDataMapper::HasBlocks(bool translucent)
{
  // Which passes the visible blocks need, as Render decides (the actor's
  // own opacity is the actor's business: vtkActor asks for it apart).
  const std::vector<BlockLook> looks = this->BlockLooks(1.0);
  for (size_t i = 0; i < this->BlockMappers.size(); ++i)
  {
    vtkShadingLabPolyDataMapper* sm = this->BlockMappers[i];
    if (!Drawable(sm) || !looks[i].visible)
    {
      continue;
    }
    if (DrawnTranslucent(looks[i], sm, 1.0) == translucent)
    {
      return true;
    }
  }
  return false;
}

int vtkShadingLabCompositePolyDataMapper::GetShaderBuildCount()
{
  int count = 0;
  for (auto& m : this->BlockMappers)
  {
    if (vtkShadingLabPolyDataMapper* sm = m)
    {
      count += sm->GetShaderBuildCount();
    }
  }
  return count;
}

void vtkShadingLabCompositePolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const auto& settings = this->Settings;
  for (const auto& row : shadinglab::render::SettingsTable())
  {
    if (row.frontEnds & shadinglab::render::kMapper)
    {
      os << indent << row.property << ": "
         << shadinglab::render::FormatSetting(row, row.get(settings)) << "\n";
    }
  }
}
