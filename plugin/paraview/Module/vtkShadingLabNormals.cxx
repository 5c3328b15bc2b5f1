// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabNormals.h"

#include "BoundaryGhosts.h"
#include "DistributedOrientation.h"
#include "InnerFilter.h"
#include "vtkWeightedPolyDataNormals.h"

#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkCommunicator.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkStreamingDemandDrivenPipeline.h>

vtkStandardNewMacro(vtkShadingLabNormals);

namespace
{

/// Whether `holds` is true on every rank (collective).
bool AllRanks(vtkMultiProcessController* controller, bool holds)
{
  int mine = holds ? 1 : 0, everyone = 0;
  controller->AllReduce(&mine, &everyone, 1, vtkCommunicator::MIN_OP);
  return everyone != 0;
}

/// A copy of `mesh` without its ghost polygons (and ghost flags).
vtkSmartPointer<vtkPolyData> WithoutGhostCells(vtkPolyData* mesh)
{
  vtkNew<vtkPolyData> flagged;
  flagged->ShallowCopy(mesh);
  vtkNew<vtkUnsignedCharArray> borrowed;
  borrowed->SetName(shadinglab::paraview::kBorrowedArray);
  borrowed->SetNumberOfTuples(mesh->GetNumberOfCells());
  vtkUnsignedCharArray* ghosts = mesh->GetCellGhostArray();
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    borrowed->SetValue(c, ghosts && ghosts->GetValue(c) != 0 ? 1 : 0);
  }
  flagged->GetCellData()->AddArray(borrowed);
  auto result = vtkSmartPointer<vtkPolyData>::New();
  shadinglab::paraview::DropBorrowedFaces(flagged, result);
  result->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  result->GetPointData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  return result;
}

} // namespace

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
  // sees all of its faces, then drop them again; the orientation is made
  // consistent across the ranks first (DistributedOrientation.h). Data with
  // ghost cells uses them, unless the orientation is inconsistent: then the
  // ghost cells go (turning them to match their owners' would need their
  // owners) and the faces are borrowed instead. Collective on all ranks.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool distributed = controller && controller->GetNumberOfProcesses() > 1;
  vtkSmartPointer<vtkPolyData> work = input;
  vtkIdType borrowed = 0;
  bool orientedAcrossRanks = false;
  if (distributed && AllRanks(controller, input->GetNumberOfStrips() == 0))
  {
    vtkSmartPointer<vtkPolyData> piece = input;
    bool borrow = AllRanks(controller, !input->HasAnyGhostCells());
    if (!borrow && !AllRanks(controller, !shadinglab::mesh::InconsistentlyOriented(input)))
    {
      piece = WithoutGhostCells(input);
      borrow = true;
    }
    if (borrow)
    {
      work = shadinglab::paraview::WithNeighbourFaces(piece, controller, borrowed);
      if (auto turned = shadinglab::paraview::OrientedAcrossRanks(piece, work, controller))
      {
        work = shadinglab::paraview::WithNeighbourFaces(turned, controller, borrowed);
      }
      orientedAcrossRanks = true;
    }
  }
  const bool madeGhosts = borrowed > 0;
  vtkNew<vtkWeightedPolyDataNormals> normals;
  normals->SetWeighting(this->Weighting);
  normals->SetFeatureAngle(this->FeatureAngle);
  normals->SetSplitting(this->Splitting);
  // Oriented across the ranks already: a partition alone must not choose.
  normals->SetConsistency(!orientedAcrossRanks);
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
