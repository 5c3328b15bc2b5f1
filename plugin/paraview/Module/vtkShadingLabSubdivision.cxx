// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabSubdivision.h"

#include "BoundaryGhosts.h"
#include "InnerFilter.h"
#include "vtkOpenSubdivRefine.h"

#include <vtkInformationVector.h>
#include <vtkCommunicator.h>
#include <vtkMultiProcessController.h>
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
  // Distributed data: refine with two rings of the neighbouring ranks'
  // faces around the partition boundary (BoundaryGhosts.h), so that both
  // sides compute the same limit points there, then drop what grew from
  // the borrowed faces. Collective on all ranks.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    int usable = input->GetNumberOfStrips() == 0 ? 1 : 0, everyone = 0;
    controller->AllReduce(&usable, &everyone, 1, vtkCommunicator::MIN_OP);
    if (everyone)
    {
      vtkIdType borrowed = 0;
      vtkSmartPointer<vtkPolyData> augmented =
        shadinglab::paraview::WithNeighbourFaces(input, controller, borrowed, 2);
      vtkNew<vtkPolyData> refined;
      if (!shadinglab::paraview::RunInnerFilter(this, inner, augmented, refined))
      {
        return 0;
      }
      shadinglab::paraview::DropBorrowedFaces(refined, output);
      return 1;
    }
  }
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
