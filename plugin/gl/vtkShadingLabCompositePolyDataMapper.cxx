// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabCompositePolyDataMapper.h"

#include "vtkShadingLabPolyDataMapper.h"

#include <vtkActor.h>
#include <vtkObjectFactory.h>
#include <vtkProperty.h>

vtkStandardNewMacro(vtkShadingLabCompositePolyDataMapper);

void vtkShadingLabCompositePolyDataMapper::SetMaterial(const shadinglab::Material<double>& material)
{
  this->Material = material;
  this->Modified();
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

vtkPolyDataMapper* vtkShadingLabCompositePolyDataMapper::MakeAMapper()
{
  auto* mapper = vtkShadingLabPolyDataMapper::New();
  mapper->SetShadingMode(this->ShadingMode);
  mapper->SetMaxError(this->MaxError);
  mapper->SetPerspectiveCorrect(this->PerspectiveCorrect);
  mapper->SetFastPhongMaxSpread(this->FastPhongMaxSpread);
  mapper->SetNormalWeighting(this->NormalWeighting);
  mapper->SetFeatureAngle(this->FeatureAngle);
  mapper->SetRecomputeNormals(this->RecomputeNormals);
  mapper->SetMaterial(this->Material);
  this->BlockMappers.emplace_back(mapper);
  return mapper;
}

void vtkShadingLabCompositePolyDataMapper::Render(vtkRenderer* ren, vtkActor* act)
{
  // Keep the block mappers in step with this mapper's settings.
  for (auto& m : this->BlockMappers)
  {
    if (vtkShadingLabPolyDataMapper* sm = m)
    {
      sm->SetShadingMode(this->ShadingMode);
      sm->SetMaxError(this->MaxError);
      sm->SetPerspectiveCorrect(this->PerspectiveCorrect);
      sm->SetFastPhongMaxSpread(this->FastPhongMaxSpread);
      sm->SetNormalWeighting(this->NormalWeighting);
      sm->SetFeatureAngle(this->FeatureAngle);
      sm->SetRecomputeNormals(this->RecomputeNormals);
      sm->SetMaterial(this->Material);
    }
  }
  this->Superclass::Render(ren, act);
  // VTK 9.2's vtkCompositePolyDataMapper draws a block in the translucent
  // pass only when the block's own colours are translucent, so an actor made
  // translucent by its opacity drew nothing: draw those blocks here, with
  // the colouring the superclass would have handed them.
  if (act->IsRenderingTranslucentPolygonalGeometry() && act->GetProperty()->GetOpacity() < 1.0)
  {
    for (auto& m : this->BlockMappers)
    {
      vtkShadingLabPolyDataMapper* sm = m;
      if (!sm || !sm->GetInput() || !sm->HasOpaqueGeometry())
      {
        continue; // gone, empty, or already drawn by the superclass
      }
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
      sm->Render(ren, act);
    }
  }
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
  os << indent << "ShadingMode: " << this->ShadingMode << "\n";
  os << indent << "MaxError: " << this->MaxError << "\n";
  os << indent << "PerspectiveCorrect: " << this->PerspectiveCorrect << "\n";
}
