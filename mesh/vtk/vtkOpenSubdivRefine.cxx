// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenSubdivRefine.h"

#include "Geometry.h"
#include "MeshArrays.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
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
#include <cmath>
#include <array>
#include <map>
#include <memory>

vtkStandardNewMacro(vtkOpenSubdivRefine);

namespace
{

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

/// One vertex's values in a flat buffer of `width` doubles per vertex: the
/// primvar interface OpenSubdiv's PrimvarRefiner expects.
struct Row
{
  double* data;
  int width;
  void Clear()
  {
    std::fill(this->data, this->data + this->width, 0.0);
  }
  void AddWithWeight(const Row& src, float weight)
  {
    for (int i = 0; i < this->width; ++i)
    {
      this->data[i] += static_cast<double>(weight) * src.data[i];
    }
  }
  Row& operator=(const Row& src)
  {
    std::copy(src.data, src.data + this->width, this->data);
    return *this;
  }
  Row(double* d, int w)
    : data(d)
    , width(w)
  {
  }
  Row(const Row&) = default;
};

struct Buffer
{
  double* base;
  int width;
  Row operator[](int i) const { return Row(this->base + static_cast<size_t>(i) * this->width, this->width); }
};

/// Marks as creases (of `sharpness`) the edges between two faces whose
/// normals differ by more than `featureAngle` degrees.
void AddFeatureCreases(const shadinglab::mesh::FlatPolygons& flat, double featureAngle,
  float sharpness, std::map<std::pair<int64_t, int64_t>, float>& creases)
{
  std::map<std::pair<int64_t, int64_t>, std::vector<int64_t>> edgeFaces;
  std::vector<std::array<double, 3>> normals(static_cast<size_t>(flat.numberOfPolygons));
  for (int64_t f = 0; f < flat.numberOfPolygons; ++f)
  {
    const int64_t b = flat.offsets[f], e = flat.offsets[f + 1];
    for (int64_t k = b; k < e; ++k)
    {
      const int64_t u = flat.connectivity[k], v = flat.connectivity[k + 1 < e ? k + 1 : b];
      edgeFaces[{ std::min(u, v), std::max(u, v) }].push_back(f);
    }
    const shadinglab::Vec3d area = shadinglab::mesh::NewellAreaVector<double>(
      e - b, [&](int64_t k) { return shadinglab::mesh::PointOf(flat.points, flat.connectivity[b + k]); });
    std::array<double, 3> n{ area.x, area.y, area.z };
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n)
    {
      x = l > 0 ? x / l : 0.0;
    }
    normals[f] = n;
  }
  const double cosFeature = std::cos(featureAngle * 3.14159265358979323846 / 180.0);
  for (const auto& [edge, faces] : edgeFaces)
  {
    if (faces.size() == 2)
    {
      const auto& a = normals[faces[0]];
      const auto& b = normals[faces[1]];
      if (a[0] * b[0] + a[1] * b[1] + a[2] * b[2] < cosFeature)
      {
        creases[edge] = sharpness;
      }
    }
  }
}

/// The refined points (the last level's, or their limit when `limit` is
/// given), their limit normals (du x dv, normalized; +z where the tangents
/// degenerate) and the refined point-data arrays onto `output`.
void WriteRefinedPoints(const double* src, int width, int nv, const double* limit,
  const std::vector<double>& du, const std::vector<double>& dv,
  const std::vector<vtkDataArray*>& arrays, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nv);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(nv);
  for (int v = 0; v < nv; ++v)
  {
    const double* pos =
      limit ? limit + 3 * static_cast<size_t>(v) : src + static_cast<size_t>(v) * width;
    points->SetPoint(v, pos);
    const double* a = &du[3 * static_cast<size_t>(v)];
    const double* b = &dv[3 * static_cast<size_t>(v)];
    double n[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (l > 0 && std::isfinite(l))
    {
      n[0] /= l, n[1] /= l, n[2] /= l;
    }
    else
    {
      n[0] = 0, n[1] = 0, n[2] = 1; // degenerate tangents (e.g. at a cone point)
    }
    normals->SetTuple(v, n);
  }
  output->SetPoints(points);
  vtkPointData* outPD = output->GetPointData();
  int col = 3;
  for (vtkDataArray* array : arrays)
  {
    vtkSmartPointer<vtkDataArray> refined;
    refined.TakeReference(array->NewInstance());
    refined->SetName(array->GetName());
    refined->SetNumberOfComponents(array->GetNumberOfComponents());
    refined->SetNumberOfTuples(nv);
    for (int v = 0; v < nv; ++v)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        refined->SetComponent(v, c, src[static_cast<size_t>(v) * width + col + c]);
      }
    }
    col += array->GetNumberOfComponents();
    outPD->AddArray(refined);
  }
  outPD->SetNormals(normals);
}

/// Each child face of the last level inherits its ancestor polygon's cell
/// data (polygons after the source's verts and lines).
void CopyCellDataToChildren(const Far::TopologyRefiner& refiner,
  const Far::PrimvarRefiner& primvars, int levels, vtkPolyData* source, int64_t polygons,
  vtkPolyData* output)
{
  vtkCellData* inCD = source->GetCellData();
  if (inCD->GetNumberOfArrays() > 0)
  {
    std::vector<int> parent(static_cast<size_t>(polygons));
    for (int f = 0; f < static_cast<int>(polygons); ++f)
    {
      parent[f] = f;
    }
    for (int level = 1; level <= levels; ++level)
    {
      const Far::TopologyLevel& l = refiner.GetLevel(level);
      std::vector<int> next(static_cast<size_t>(l.GetNumFaces()));
      // Refinement::getChildFaceParentFace is not public; uniform refinement
      // numbers child faces parent by parent, so map through the face-uniform
      // interpolation of the parent index.
      struct IndexRow
      {
        int* p;
        void operator=(const IndexRow& o) { *this->p = *o.p; }
      };
      struct IndexBuffer
      {
        int* base;
        IndexRow operator[](int i) const { return IndexRow{ this->base + i }; }
      };
      IndexBuffer s{ parent.data() }, d{ next.data() };
      primvars.InterpolateFaceUniform(level, s, d);
      parent.swap(next);
    }
    const int nf = refiner.GetLevel(levels).GetNumFaces();
    vtkCellData* outCD = output->GetCellData();
    outCD->CopyAllocate(inCD, nf);
    const vtkIdType polyBase = source->GetNumberOfVerts() + source->GetNumberOfLines();
    for (int f = 0; f < nf; ++f)
    {
      outCD->CopyData(inCD, polyBase + parent[f], f);
    }
  }
}

/// The last level's faces (of `corners` corners each) as the output's polygons.
void WriteRefinedFaces(const Far::TopologyLevel& last, int corners, vtkPolyData* output)
{
  vtkNew<vtkCellArray> polys;
  const int nf = last.GetNumFaces();
  polys->AllocateExact(nf, static_cast<vtkIdType>(nf) * corners);
  for (int f = 0; f < nf; ++f)
  {
    const Far::ConstIndexArray fv = last.GetFaceVertices(f);
    std::vector<vtkIdType> ids(fv.begin(), fv.end());
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  output->SetPolys(polys);
}

} // namespace

int vtkOpenSubdivRefine::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->NumberOfCreaseEdges = 0;
  if (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    return 1;
  }
  vtkSmartPointer<vtkPolyData> source = shadinglab::mesh::WithoutStrips(input, true);
  namespace slm = shadinglab::mesh;
  slm::FlatPolygons flat;
  slm::FlatPolygonsFromPolyData(source, flat);
  bool allTriangles = true;
  std::vector<int> vertsPerFace(static_cast<size_t>(flat.numberOfPolygons));
  for (int64_t f = 0; f < flat.numberOfPolygons; ++f)
  {
    vertsPerFace[f] = static_cast<int>(flat.offsets[f + 1] - flat.offsets[f]);
    allTriangles &= vertsPerFace[f] == 3;
  }
  int scheme = this->Scheme;
  if (scheme == AUTO)
  {
    scheme = allTriangles ? LOOP : CATMULL_CLARK;
  }
  if (scheme == LOOP && !allTriangles)
  {
    vtkErrorMacro("Loop subdivision needs a triangle mesh; use CATMULL_CLARK or AUTO");
    return 0;
  }
  this->SchemeUsed = scheme;
  std::vector<Far::Index> indices(flat.connectivity, flat.connectivity + flat.offsets[flat.numberOfPolygons]);

  // Crease edges: input lines, and dihedral angles above FeatureAngle.
  std::map<std::pair<int64_t, int64_t>, float> creases;
  const std::vector<int64_t> lines = slm::LineSegments(source);
  for (size_t i = 0; i + 1 < lines.size(); i += 2)
  {
    creases[{ std::min(lines[i], lines[i + 1]), std::max(lines[i], lines[i + 1]) }] =
      static_cast<float>(this->CreaseSharpness);
  }
  if (this->UseFeatureAngle)
  {
    AddFeatureCreases(flat, this->FeatureAngle, static_cast<float>(this->CreaseSharpness), creases);
  }
  std::vector<Far::Index> creasePairs;
  std::vector<float> creaseWeights;
  for (const auto& [edge, sharpness] : creases)
  {
    creasePairs.push_back(static_cast<Far::Index>(edge.first));
    creasePairs.push_back(static_cast<Far::Index>(edge.second));
    creaseWeights.push_back(sharpness);
  }
  this->NumberOfCreaseEdges = static_cast<vtkIdType>(creaseWeights.size());

  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(flat.numberOfPoints);
  desc.numFaces = static_cast<int>(flat.numberOfPolygons);
  desc.numVertsPerFace = vertsPerFace.data();
  desc.vertIndicesPerFace = indices.data();
  desc.numCreases = static_cast<int>(creaseWeights.size());
  desc.creaseVertexIndexPairs = creasePairs.empty() ? nullptr : creasePairs.data();
  desc.creaseWeights = creaseWeights.empty() ? nullptr : creaseWeights.data();
  Sdc::Options sdcOptions;
  sdcOptions.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  const Sdc::SchemeType type = scheme == LOOP ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;
  std::unique_ptr<Far::TopologyRefiner> refiner(
    Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Create(
      desc, Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Options(type, sdcOptions)));
  if (!refiner)
  {
    vtkErrorMacro("OpenSubdiv rejected the mesh topology");
    return 0;
  }
  Far::TopologyRefiner::UniformOptions uniform(this->Levels);
  // Limit() needs the last level's full topology (ENVIRONMENT.md).
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);
  this->UpdateProgress(0.3);

  // Vertex primvars: position (3) then every numeric point-data component.
  vtkPointData* inPD = source->GetPointData();
  std::vector<vtkDataArray*> arrays;
  int width = 3;
  for (int a = 0; a < inPD->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = inPD->GetArray(a);
    if (array && array != inPD->GetNormals())
    {
      arrays.push_back(array);
      width += array->GetNumberOfComponents();
    }
  }
  int total = 0;
  for (int level = 0; level <= this->Levels; ++level)
  {
    total += refiner->GetLevel(level).GetNumVertices();
  }
  std::vector<double> values(static_cast<size_t>(total) * width, 0.0);
  for (int64_t v = 0; v < flat.numberOfPoints; ++v)
  {
    double* row = &values[static_cast<size_t>(v) * width];
    std::copy(flat.points + 3 * v, flat.points + 3 * v + 3, row);
    int col = 3;
    for (vtkDataArray* array : arrays)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        row[col++] = array->GetComponent(v, c);
      }
    }
  }
  Far::PrimvarRefiner primvars(*refiner);
  double* src = values.data();
  for (int level = 1; level <= this->Levels; ++level)
  {
    double* dst = src + static_cast<size_t>(refiner->GetLevel(level - 1).GetNumVertices()) * width;
    Buffer s{ src, width }, d{ dst, width };
    primvars.Interpolate(level, s, d);
    src = dst;
  }
  const Far::TopologyLevel& last = refiner->GetLevel(this->Levels);
  const int nv = last.GetNumVertices();
  std::vector<double> limit(static_cast<size_t>(nv) * 3), du(static_cast<size_t>(nv) * 3),
    dv(static_cast<size_t>(nv) * 3);
  {
    // Limit of positions only: a 3-wide view of the last level's rows.
    std::vector<double> positions(static_cast<size_t>(nv) * 3);
    for (int v = 0; v < nv; ++v)
    {
      std::copy(src + static_cast<size_t>(v) * width, src + static_cast<size_t>(v) * width + 3,
        &positions[3 * static_cast<size_t>(v)]);
    }
    Buffer s{ positions.data(), 3 }, p{ limit.data(), 3 }, t1{ du.data(), 3 }, t2{ dv.data(), 3 };
    primvars.Limit(s, p, t1, t2);
  }
  this->UpdateProgress(0.7);

  // Output.
  WriteRefinedPoints(src, width, nv, this->ProjectToLimit ? limit.data() : nullptr, du, dv, arrays,
    output);

  WriteRefinedFaces(last, scheme == LOOP ? 3 : 4, output);

  // Cell data: each child face inherits its ancestor polygon's values.
  CopyCellDataToChildren(*refiner, primvars, this->Levels, source, flat.numberOfPolygons, output);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkOpenSubdivRefine::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* names[] = { "Auto", "Loop", "Catmull-Clark" };
  os << indent << "Scheme: " << names[this->Scheme] << "\n";
  os << indent << "Levels: " << this->Levels << "\n";
  os << indent << "UseFeatureAngle: " << this->UseFeatureAngle << " (" << this->FeatureAngle
     << " degrees)\n";
  os << indent << "CreaseSharpness: " << this->CreaseSharpness << "\n";
  os << indent << "ProjectToLimit: " << this->ProjectToLimit << "\n";
}
