// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabNormals.h"

#include "BoundaryGhosts.h"
#include "InnerFilter.h"
#include "vtkWeightedPolyDataNormals.h"

#include <vtkCellData.h>
#include <vtkDataSetAttributes.h>
#include <vtkCommunicator.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkStreamingDemandDrivenPipeline.h>

vtkStandardNewMacro(vtkShadingLabNormals);

int vtkShadingLabNormals::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // One more ghost level than asked: a boundary vertex's normal needs every
  // face around it, some of which live on the neighbouring partition.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  const int ghosts =
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS());
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), ghosts + 1);
  return 1;
}

int vtkShadingLabNormals::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  // Distributed data without ghost cells (e.g. after RedistributeDataSet
  // and Extract Surface): borrow the neighbouring ranks' faces around the
  // partition boundary (BoundaryGhosts.h), so that every boundary vertex
  // sees all of its faces, then drop them again. Collective on all ranks.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool distributed = controller && controller->GetNumberOfProcesses() > 1;
  vtkSmartPointer<vtkPolyData> work = input;
  vtkIdType borrowed = 0;
  if (distributed)
  {
    int needsGhosts = !input->HasAnyGhostCells() && input->GetNumberOfStrips() == 0 ? 1 : 0;
    int everyone = 0;
    controller->AllReduce(&needsGhosts, &everyone, 1, vtkCommunicator::MIN_OP);
    if (everyone)
    {
      work = shadinglab::paraview::WithNeighbourFaces(input, controller, borrowed);
    }
  }
  const bool madeGhosts = borrowed > 0;
  vtkNew<vtkWeightedPolyDataNormals> normals;
  normals->SetWeighting(this->Weighting);
  normals->SetFeatureAngle(this->FeatureAngle);
  normals->SetSplitting(this->Splitting);
  if (!madeGhosts)
  {
    return shadinglab::paraview::RunInnerFilter(this, normals, work, output) ? 1 : 0;
  }
  vtkNew<vtkPolyData> withGhosts;
  if (!shadinglab::paraview::RunInnerFilter(this, normals, work, withGhosts))
  {
    return 0;
  }
  shadinglab::paraview::DropBorrowedFaces(withGhosts, output);
  return 1;
}

void vtkShadingLabNormals::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weighting: " << this->Weighting << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "Splitting: " << this->Splitting << "\n";
}
