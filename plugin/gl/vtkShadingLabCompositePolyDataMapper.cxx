// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabCompositePolyDataMapper.h"

#include "vtkShadingLabPolyDataMapper.h"

#include <vtkObjectFactory.h>

vtkStandardNewMacro(vtkShadingLabCompositePolyDataMapper);

void vtkShadingLabCompositePolyDataMapper::SetMaterial(const shadinglab::Material<double>& material)
{
  this->Material = material;
  this->Modified();
}

vtkPolyDataMapper* vtkShadingLabCompositePolyDataMapper::MakeAMapper()
{
  auto* mapper = vtkShadingLabPolyDataMapper::New();
  mapper->SetShadingMode(this->ShadingMode);
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
      sm->SetPerspectiveCorrect(this->PerspectiveCorrect);
      sm->SetFastPhongMaxSpread(this->FastPhongMaxSpread);
      sm->SetNormalWeighting(this->NormalWeighting);
      sm->SetFeatureAngle(this->FeatureAngle);
      sm->SetRecomputeNormals(this->RecomputeNormals);
      sm->SetMaterial(this->Material);
    }
  }
  this->Superclass::Render(ren, act);
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
  os << indent << "PerspectiveCorrect: " << this->PerspectiveCorrect << "\n";
}
