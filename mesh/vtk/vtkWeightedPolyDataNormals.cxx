// SPDX-License-Identifier: BSD-3-Clause
#include "vtkWeightedPolyDataNormals.h"

#include "MeshArrays.h"
#include "VertexNormals.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
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

vtkStandardNewMacro(vtkWeightedPolyDataNormals);

int vtkWeightedPolyDataNormals::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->NumberOfCreaseEdges = this->NumberOfSplitPoints = 0;
  this->NumberOfNonManifoldEdges = this->NumberOfBoundaryEdges = 0;
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return 1;
  }
  vtkSmartPointer<vtkPolyData> source = input;
  if (input->GetNumberOfStrips() > 0)
  {
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(input);
    triangles->PassLinesOn();
    triangles->PassVertsOn();
    triangles->Update();
    source = triangles->GetOutput();
  }
  namespace slm = shadinglab::mesh;
  const slm::FlatPolygons flat = slm::FlatPolygonsFromPolyData(source);
  slm::PolygonMesh mesh;
  mesh.points = flat.points.data();
  mesh.numberOfPoints = source->GetNumberOfPoints();
  mesh.offsets = flat.offsets.data();
  mesh.connectivity = flat.connectivity.data();
  mesh.numberOfPolygons = flat.NumberOfPolygons();
  slm::NormalOptions options;
  options.weighting = static_cast<slm::NormalWeighting>(this->Weighting);
  options.splitting = this->Splitting;
  options.featureAngle = this->FeatureAngle;
  if (this->UseLinesAsFeatureEdges)
  {
    options.featureEdges = slm::LineSegments(source);
  }
  this->UpdateProgress(0.1);
  const slm::NormalResult result = slm::ComputeVertexNormals(mesh, options);
  this->UpdateProgress(0.8);
  this->NumberOfCreaseEdges = result.creaseEdges;
  this->NumberOfSplitPoints = result.splitPoints;
  this->NumberOfNonManifoldEdges = result.nonManifoldEdges;
  this->NumberOfBoundaryEdges = result.boundaryEdges;

  const vtkIdType nOut = static_cast<vtkIdType>(result.originalPointIds.size());
  vtkNew<vtkPoints> points;
  points->SetDataType(source->GetPoints()->GetDataType());
  points->SetNumberOfPoints(nOut);
  vtkPointData* inPD = source->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyNormalsOff();
  outPD->CopyAllocate(inPD, nOut);
  vtkNew<vtkIdTypeArray> originalIds;
  originalIds->SetName("OriginalPointIds");
  originalIds->SetNumberOfTuples(nOut);
  for (vtkIdType i = 0; i < nOut; ++i)
  {
    const vtkIdType src = result.originalPointIds[i];
    points->SetPoint(i, source->GetPoint(src));
    outPD->CopyData(inPD, src, i);
    originalIds->SetValue(i, src);
  }
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(nOut);
  for (vtkIdType i = 0; i < nOut; ++i)
  {
    normals->SetTuple(i, &result.normals[3 * i]);
  }
  outPD->SetNormals(normals);
  outPD->AddArray(originalIds);

  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(flat.offsets.size()));
  for (size_t i = 0; i < flat.offsets.size(); ++i)
  {
    offsets->SetValue(static_cast<vtkIdType>(i), flat.offsets[i]);
  }
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(result.connectivity.size()));
  for (size_t i = 0; i < result.connectivity.size(); ++i)
  {
    connectivity->SetValue(static_cast<vtkIdType>(i), result.connectivity[i]);
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetPolys(polys);
  output->SetVerts(source->GetVerts());
  output->SetLines(source->GetLines());
  // Cell data: verts and lines come before polys in VTK's cell order, so
  // passing the arrays keeps their correspondence.
  output->GetCellData()->PassData(source->GetCellData());
  this->UpdateProgress(1.0);
  return 1;
}

void vtkWeightedPolyDataNormals::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* names[] = { "Uniform", "Area", "Angle", "Max" };
  os << indent << "Weighting: " << names[this->Weighting] << "\n";
  os << indent << "Splitting: " << this->Splitting << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "UseLinesAsFeatureEdges: " << this->UseLinesAsFeatureEdges << "\n";
}
