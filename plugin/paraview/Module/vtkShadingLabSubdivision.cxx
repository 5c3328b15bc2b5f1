// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabSubdivision.h"

#include "InnerFilter.h"
#include "vtkOpenSubdivRefine.h"

#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>

vtkStandardNewMacro(vtkShadingLabSubdivision);

int vtkShadingLabSubdivision::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkNew<vtkOpenSubdivRefine> inner;
  inner->SetScheme(this->Scheme);
  inner->SetLevels(this->Levels);
  inner->SetUseFeatureAngle(this->UseFeatureAngle);
  inner->SetFeatureAngle(this->FeatureAngle);
  inner->SetCreaseSharpness(this->CreaseSharpness);
  inner->SetProjectToLimit(this->ProjectToLimit);
  return shadinglab::paraview::RunInnerFilter(this, inner, input, output) ? 1 : 0;
}

void vtkShadingLabSubdivision::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scheme: " << this->Scheme << "\n";
  os << indent << "Levels: " << this->Levels << "\n";
  os << indent << "UseFeatureAngle: " << this->UseFeatureAngle << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "CreaseSharpness: " << this->CreaseSharpness << "\n";
  os << indent << "ProjectToLimit: " << this->ProjectToLimit << "\n";
}
