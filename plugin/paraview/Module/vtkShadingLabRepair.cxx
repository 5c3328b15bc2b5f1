// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabRepair.h"

#include "GatheredPolyData.h"
#include "InnerFilter.h"
#include "vtkMeshRepair.h"

#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkPointData.h>
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
  // Distributed data: repaired as a whole on rank 0 (GatheredPolyData.h),
  // so that welds, T-junctions and orientation across partition boundaries
  // come out as on one rank. Collective on all ranks.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    namespace pv = shadinglab::paraview;
    vtkSmartPointer<vtkPolyData> whole = pv::GatherWithOwner(input, controller);
    vtkNew<vtkPolyData> repaired;
    const bool ok = !whole || pv::RunInnerFilter(this, inner, whole, repaired);
    if (!pv::ScatterByOwner(repaired, ok, controller, output))
    {
      return 0;
    }
    // Point ids of the gathered mesh mean nothing on a rank.
    output->GetPointData()->RemoveArray("OriginalPointIds");
    return 1;
  }
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
