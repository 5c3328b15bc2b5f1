// SPDX-License-Identifier: BSD-3-Clause
#include "vtkWeightedPolyDataNormals.h"

#include "MeshArrays.h"
#include "Orientation.h"
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

#include <algorithm>
#include <cstdint>
#include <functional>
#include <numeric>

vtkStandardNewMacro(vtkWeightedPolyDataNormals);

namespace
{

/// The normals of a mesh of float or double points: split at creases, or
/// crease-free (one pass over the arrays, no adjacency: edge counts stay
/// 0, every point its own original).
template <typename View>
shadinglab::mesh::NormalResult NormalsOf(const View& mesh, const shadinglab::mesh::NormalOptions& options)
{
  if (options.splitting)
  {
    return shadinglab::mesh::ComputeVertexNormals(mesh, options);
  }
  shadinglab::mesh::NormalResult result;
  shadinglab::mesh::ComputeVertexNormalsNoSplit(mesh, options.weighting, result.normals);
  result.originalPointIds.resize(static_cast<size_t>(mesh.numberOfPoints));
  std::iota(result.originalPointIds.begin(), result.originalPointIds.end(), int64_t(0));
  return result;
}

} // namespace

int vtkWeightedPolyDataNormals::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->NumberOfCreaseEdges = this->NumberOfSplitPoints = 0;
  this->NumberOfNonManifoldEdges = this->NumberOfBoundaryEdges = 0;
  this->NumberOfFlippedPolygons = 0;
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return 1;
  }
  vtkSmartPointer<vtkPolyData> source = shadinglab::mesh::WithoutStrips(input, true);
  namespace slm = shadinglab::mesh;
  // Float points (every reader's) are read in place by the normals, not
  // copied to double (192 MB on 16M triangles): the orientation test reads
  // the connectivity alone, and only turning faces needs double points.
  auto* floats = vtkFloatArray::SafeDownCast(source->GetPoints()->GetData());
  auto* doubles = vtkDoubleArray::SafeDownCast(source->GetPoints()->GetData());
  slm::NormalOptions options;
  options.weighting = static_cast<slm::NormalWeighting>(this->Weighting);
  options.splitting = this->Splitting;
  options.featureAngle = this->FeatureAngle;
  if (this->UseLinesAsFeatureEdges)
  {
    options.featureEdges = slm::LineSegments(source);
  }
  // 32-bit cells (the fast readers') are read in place, not widened (256 MB
  // on 16M triangles), unless faces must be turned: then the widened path.
  // The orientation test runs once: on the 32-bit cells in place when
  // there are some, else on the widened copy below.
  slm::NarrowMeshView narrow;
  const bool narrowIds = slm::NarrowPolygonsOf(source, narrow);
  const bool turnNarrow = narrowIds && this->Consistency && slm::HasInconsistentOrientation(narrow);
  if ((floats || doubles) && narrowIds && !turnNarrow)
  {
    this->UpdateProgress(0.1);
    slm::NormalResult result;
    if (floats)
    {
      const slm::FloatNarrowMeshView floatMesh{ floats->GetPointer(0), narrow.numberOfPoints,
        narrow.offsets, narrow.connectivity, narrow.numberOfPolygons };
      result = NormalsOf(floatMesh, options);
    }
    else
    {
      narrow.points = doubles->GetPointer(0);
      result = NormalsOf(narrow, options);
    }
    // Split copies can take the point count past 2^31: then 64-bit storage.
    const bool fits = result.originalPointIds.size() < static_cast<size_t>(INT32_MAX);
    const std::vector<int64_t>& moved = result.connectivity;
    this->MakeOutput(source, output, result, [&] {
      if (fits)
      {
        return slm::CellArrayFromFlat(narrow.offsets, narrow.numberOfPolygons, moved.data());
      }
      const std::vector<int64_t> offsets(narrow.offsets, narrow.offsets + narrow.numberOfPolygons + 1);
      return slm::CellArrayFromFlat(offsets.data(), narrow.numberOfPolygons, moved.data());
    });
    return 1;
  }
  slm::FlatPolygons flat;
  slm::FlatPolygonsFromPolyData(source, flat, floats == nullptr);
  slm::MeshView mesh;
  mesh.points = flat.points;
  mesh.numberOfPoints = flat.numberOfPoints;
  mesh.offsets = flat.offsets;
  mesh.connectivity = flat.connectivity;
  mesh.numberOfPolygons = flat.numberOfPolygons;
  std::vector<int64_t> turned; // the connectivity with inconsistent faces reversed
  slm::FlatPolygons withPoints;
  if (this->Consistency && (narrowIds ? turnNarrow : slm::HasInconsistentOrientation(mesh)))
  {
    if (!mesh.points)
    {
      slm::FlatPolygonsFromPolyData(source, withPoints);
      mesh.points = withPoints.points;
    }
    this->NumberOfFlippedPolygons =
      slm::FlipFaces(mesh, slm::ConsistentOrientationFlips(mesh), turned);
    mesh.connectivity = turned.data();
  }
  const slm::FloatMeshView floatMesh{ floats ? floats->GetPointer(0) : nullptr,
    mesh.numberOfPoints, mesh.offsets, mesh.connectivity, mesh.numberOfPolygons };
  this->UpdateProgress(0.1);
  slm::NormalResult result = floats ? NormalsOf(floatMesh, options) : NormalsOf(mesh, options);
  const std::vector<int64_t>& moved = result.connectivity;
  this->MakeOutput(source, output, result, [&] {
    return slm::CellArrayFromFlat(mesh.offsets, mesh.numberOfPolygons,
      moved.empty() ? turned.data() : moved.data());
  }, !turned.empty());
  return 1;
}

void vtkWeightedPolyDataNormals::MakeOutput(vtkPolyData* source, vtkPolyData* output,
  shadinglab::mesh::NormalResult& result,
  const std::function<vtkSmartPointer<vtkCellArray>()>& newPolygons, bool turned)
{
  namespace slm = shadinglab::mesh;
  this->UpdateProgress(0.8);
  this->NumberOfCreaseEdges = result.creaseEdges;
  this->NumberOfSplitPoints = result.splitPoints;
  this->NumberOfNonManifoldEdges = result.nonManifoldEdges;
  this->NumberOfBoundaryEdges = result.boundaryEdges;

  const vtkIdType nIn = source->GetNumberOfPoints();
  const vtkIdType nOut = static_cast<vtkIdType>(result.originalPointIds.size());
  vtkSmartPointer<vtkPoints> points;
  vtkPointData* inPD = source->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  if (nOut == nIn)
  {
    // No split: the input's points object and point data shared as they are
    // (the vtkPoints itself: a new one ShallowCopy'd from it calls Modified,
    // which vtkPoints passes to the shared data array, and the input's
    // modification time moved).
    points = source->GetPoints();
    outPD->PassData(inPD);
    outPD->SetNormals(nullptr);
  }
  else
  {
    // The first nIn output points are the input points in order; split
    // copies follow.
    points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataType(source->GetPoints()->GetDataType());
    points->SetNumberOfPoints(nOut);
    points->GetData()->InsertTuples(0, nIn, 0, source->GetPoints()->GetData());
    outPD->CopyNormalsOff();
    outPD->CopyAllocate(inPD, nOut);
    for (vtkIdType i = 0; i < nIn; ++i)
    {
      outPD->CopyData(inPD, i, i);
    }
    for (vtkIdType i = nIn; i < nOut; ++i)
    {
      const vtkIdType src = result.originalPointIds[i];
      points->SetPoint(i, source->GetPoint(src));
      outPD->CopyData(inPD, src, i);
    }
  }
  // Each result array freed as soon as it is copied: on a big mesh the
  // double normals and the ids are 0.25 GB (16M triangles).
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(nOut);
  float* nf = normals->GetPointer(0);
  for (size_t i = 0; i < result.normals.size(); ++i)
  {
    nf[i] = static_cast<float>(result.normals[i]);
  }
  std::vector<double>().swap(result.normals);
  vtkNew<vtkIdTypeArray> originalIds;
  originalIds->SetName("OriginalPointIds");
  originalIds->SetNumberOfTuples(nOut);
  std::copy(result.originalPointIds.begin(), result.originalPointIds.end(), originalIds->GetPointer(0));
  std::vector<int64_t>().swap(result.originalPointIds);
  outPD->SetNormals(normals);
  outPD->AddArray(originalIds);

  output->SetPoints(points);
  if ((nOut != nIn && !result.connectivity.empty()) || turned)
  {
    // Corners moved to split points, or faces turned.
    output->SetPolys(newPolygons());
  }
  else
  {
    output->SetPolys(source->GetPolys()); // the input's polygons as they are
  }
  output->SetVerts(source->GetVerts());
  output->SetLines(source->GetLines());
  // Cell data: verts and lines come before polys in VTK's cell order, so
  // passing the arrays keeps their correspondence.
  output->GetCellData()->PassData(source->GetCellData());
  this->UpdateProgress(1.0);
}

void vtkWeightedPolyDataNormals::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* names[] = { "Uniform", "Area", "Angle", "Max" };
  os << indent << "Weighting: " << names[this->Weighting] << "\n";
  os << indent << "Splitting: " << this->Splitting << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "UseLinesAsFeatureEdges: " << this->UseLinesAsFeatureEdges << "\n";
  os << indent << "Consistency: " << this->Consistency << "\n";
}
