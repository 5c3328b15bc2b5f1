// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMeshRepair.h"

#include "MeshArrays.h"
#include "MeshRepair.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <cstring>
#include <functional>

vtkStandardNewMacro(vtkMeshRepair);

namespace
{
/// A hash of all point-data values of each point (FNV-1a over the bytes of
/// the double values): equal attributes give equal keys.
std::vector<uint64_t> SeamKeys(vtkPointData* pd, vtkIdType n)
{
  std::vector<uint64_t> keys(static_cast<size_t>(n), 1469598103934665603ULL);
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array)
    {
      continue;
    }
    const int nc = array->GetNumberOfComponents();
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int c = 0; c < nc; ++c)
      {
        const double v = array->GetComponent(i, c);
        unsigned char bytes[sizeof(double)];
        std::memcpy(bytes, &v, sizeof(double));
        for (unsigned char b : bytes)
        {
          keys[i] = (keys[i] ^ b) * 1099511628211ULL;
        }
      }
    }
  }
  return keys;
}
} // namespace

int vtkMeshRepair::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->NumberOfWeldedPoints = this->NumberOfDegenerateCellsRemoved = 0;
  this->NumberOfFlippedCells = this->NumberOfNonManifoldEdges = 0;
  this->NumberOfDuplicatedPoints = this->NumberOfTJunctionsFixed = 0;
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return 1;
  }
  vtkSmartPointer<vtkPolyData> source = shadinglab::mesh::WithoutStrips(input, false);
  namespace slm = shadinglab::mesh;
  slm::FlatPolygons flat;
  slm::FlatPolygonsFromPolyData(source, flat);
  slm::RepairOptions options;
  options.weld = this->Weld;
  options.weldTolerance = this->WeldTolerance;
  std::vector<uint64_t> keys;
  if (this->KeepAttributeSeams)
  {
    keys = SeamKeys(source->GetPointData(), source->GetNumberOfPoints());
    options.seamKeys = &keys;
  }
  options.fixOrientation = this->FixOrientation;
  slm::RepairReport report;
  this->UpdateProgress(0.05);
  slm::OwnedMesh mesh = slm::RepairMesh(flat.points, flat.numberOfPoints, flat.offsets,
    flat.connectivity, flat.numberOfPolygons, options, report);
  this->UpdateProgress(0.7);
  if (this->FixTJunctions)
  {
    this->NumberOfTJunctionsFixed = slm::FixTJunctions(mesh, this->TJunctionTolerance);
  }
  this->NumberOfWeldedPoints = report.welded;
  this->NumberOfDegenerateCellsRemoved = report.degenerateRemoved;
  this->NumberOfFlippedCells = report.flipped;
  this->NumberOfNonManifoldEdges = report.nonManifoldEdges;
  this->NumberOfDuplicatedPoints = report.duplicatedVertices;

  const vtkIdType nOut = mesh.NumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataType(source->GetPoints()->GetDataType());
  points->SetNumberOfPoints(nOut);
  vtkPointData* inPD = source->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyAllocate(inPD, nOut);
  vtkNew<vtkIdTypeArray> originalIds;
  originalIds->SetName("OriginalPointIds");
  originalIds->SetNumberOfTuples(nOut);
  for (vtkIdType i = 0; i < nOut; ++i)
  {
    points->SetPoint(i, &mesh.points[3 * i]);
    outPD->CopyData(inPD, mesh.pointIds[i], i);
    originalIds->SetValue(i, mesh.pointIds[i]);
  }
  outPD->AddArray(originalIds);
  output->SetPoints(points);
  output->SetPolys(slm::CellArrayFromFlat(
    mesh.offsets.data(), mesh.NumberOfPolygons(), mesh.connectivity.data()));
  vtkCellData* inCD = source->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(inCD, static_cast<vtkIdType>(mesh.cellIds.size()));
  // Input cell ids of polygons: polys follow verts and lines in VTK's order.
  const vtkIdType polyBase = source->GetNumberOfVerts() + source->GetNumberOfLines();
  for (size_t c = 0; c < mesh.cellIds.size(); ++c)
  {
    outCD->CopyData(inCD, polyBase + mesh.cellIds[c], static_cast<vtkIdType>(c));
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMeshRepair::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weld: " << this->Weld << " (tolerance " << this->WeldTolerance << ")\n";
  os << indent << "KeepAttributeSeams: " << this->KeepAttributeSeams << "\n";
  os << indent << "FixOrientation: " << this->FixOrientation << "\n";
  os << indent << "FixTJunctions: " << this->FixTJunctions << " (tolerance "
     << this->TJunctionTolerance << ")\n";
}
