// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabRepair.h"

#include "InnerFilter.h"
#include "vtkMeshRepair.h"

#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>

vtkStandardNewMacro(vtkShadingLabRepair);

int vtkShadingLabRepair::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkNew<vtkMeshRepair> inner;
  inner->SetWeld(this->Weld);
  inner->SetWeldTolerance(this->WeldTolerance);
  inner->SetKeepAttributeSeams(this->KeepAttributeSeams);
  inner->SetFixOrientation(this->FixOrientation);
  inner->SetFixTJunctions(this->FixTJunctions);
  inner->SetTJunctionTolerance(this->TJunctionTolerance);
  return shadinglab::paraview::RunInnerFilter(this, inner, input, output) ? 1 : 0;
}

void vtkShadingLabRepair::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weld: " << this->Weld << "\n";
  os << indent << "WeldTolerance: " << this->WeldTolerance << "\n";
  os << indent << "KeepAttributeSeams: " << this->KeepAttributeSeams << "\n";
  os << indent << "FixOrientation: " << this->FixOrientation << "\n";
  os << indent << "FixTJunctions: " << this->FixTJunctions << "\n";
  os << indent << "TJunctionTolerance: " << this->TJunctionTolerance << "\n";
}
