// SPDX-License-Identifier: BSD-3-Clause
// Consistent orientation (mesh/core/Orientation.h) and the normals filter
// that uses it: inconsistently oriented faces are turned back, closed
// components face outward, open ones keep their lowest face's side, a
// consistent mesh is left alone, and the input is never modified.
#include "AnalyticMeshes.h"
#include "MeshArrays.h"
#include "Orientation.h"
#include "RepairCheck.h"
#include "VertexBuckets.h"
#include "vtkWeightedPolyDataNormals.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace slm = shadinglab::mesh;
using namespace shadinglab::datasets;

namespace
{

/// A copy of `mesh` with every `every`-th polygon (from `first`) reversed.
vtkSmartPointer<vtkPolyData> WithReversedFaces(vtkPolyData* mesh, int every, int first = 0)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(mesh);
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfPolys(); ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, ids);
    if (c >= first && (c - first) % every == 0)
    {
      std::vector<vtkIdType> r(ids->begin(), ids->end());
      std::reverse(r.begin(), r.end());
      cells->InsertNextCell(static_cast<vtkIdType>(r.size()), r.data());
    }
    else
    {
      cells->InsertNextCell(ids);
    }
  }
  out->SetPolys(cells);
  return out;
}

std::vector<int64_t> Connectivity(vtkPolyData* mesh)
{
  slm::FlatPolygons flat;
  slm::FlatPolygonsFromPolyData(mesh, flat);
  return { flat.connectivity, flat.connectivity + flat.offsets[flat.numberOfPolygons] };
}

std::vector<int64_t> Turned(vtkPolyData* mesh)
{
  slm::FlatPolygons flat;
  slm::FlatPolygonsFromPolyData(mesh, flat);
  std::vector<int64_t> out;
  slm::FlipFaces(flat, slm::ConsistentOrientationFlips(flat), out);
  return out;
}

bool Inconsistent(vtkPolyData* mesh)
{
  slm::FlatPolygons flat;
  slm::FlatPolygonsFromPolyData(mesh, flat);
  return slm::HasInconsistentOrientation(flat);
}

} // namespace

TEST(OrientationTest, ConsistentMeshesAreLeftAlone)
{
  vtkSmartPointer<vtkPolyData> sphere;
  sphere.TakeReference(MakeIcosphere(3));
  vtkSmartPointer<vtkPolyData> terrain;
  terrain.TakeReference(MakeTerrain(20));
  for (vtkPolyData* mesh : { sphere.Get(), terrain.Get() })
  {
    EXPECT_FALSE(Inconsistent(mesh));
    EXPECT_EQ(Turned(mesh), Connectivity(mesh));
  }
}

TEST(OrientationTest, ReversedFacesAreTurnedBackAndClosedSurfacesFaceOutward)
{
  vtkSmartPointer<vtkPolyData> sphere;
  sphere.TakeReference(MakeIcosphere(3));
  // Every third face reversed, and (first = 0) the component's lowest face
  // among them: the closed sphere still ends up outward as it was.
  auto scrambled = WithReversedFaces(sphere, 3);
  const auto before = Connectivity(scrambled);
  EXPECT_TRUE(Inconsistent(scrambled));
  EXPECT_EQ(Turned(scrambled), Connectivity(sphere));
  EXPECT_EQ(Connectivity(scrambled), before); // the input is not modified
  // Everything reversed (consistent, inward): not an inconsistency.
  EXPECT_FALSE(Inconsistent(WithReversedFaces(sphere, 1)));
}

TEST(OrientationTest, AnOpenSurfaceKeepsItsLowestFacesSide)
{
  vtkSmartPointer<vtkPolyData> terrain;
  terrain.TakeReference(MakeTerrain(20));
  // Faces 1, 4, 7, ... reversed: face 0 keeps its side, so the rest turn back.
  EXPECT_EQ(Turned(WithReversedFaces(terrain, 3, 1)), Connectivity(terrain));
  // Faces 0, 3, 6, ... reversed: face 0's side wins, so every face ends up
  // reversed relative to the original.
  EXPECT_EQ(Turned(WithReversedFaces(terrain, 3, 0)), Connectivity(WithReversedFaces(terrain, 1)));
}

TEST(OrientationTest, CoincidentPointsAreOneEvenWithSignedZeroAndNaN)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> points = { 1, 2, 3, 0.0, 0, 0, nan, 0, 0, 1, 2, 3, -0.0, 0, 0, nan, 0,
    0, 1, 2, 4 };
  const auto same = slm::CoincidentPointRepresentatives(points.data(), 7);
  EXPECT_EQ(same, (std::vector<int64_t>{ 0, 1, 2, 0, 1, 2, 6 }));
}

TEST(OrientationTest, NormalsFilterTurnsInconsistentFacesAndKeepsTheInput)
{
  vtkSmartPointer<vtkPolyData> sphere;
  sphere.TakeReference(MakeUVSphere(48, 24));
  auto scrambled = WithReversedFaces(sphere, 3, 1);
  const auto before = Connectivity(scrambled);
  auto normalsOf = [](vtkPolyData* mesh, bool consistency, vtkIdType* flipped) {
    vtkNew<vtkWeightedPolyDataNormals> filter;
    filter->SetInputData(mesh);
    filter->SetConsistency(consistency);
    filter->SplittingOff();
    filter->Update();
    *flipped = filter->GetNumberOfFlippedPolygons();
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->ShallowCopy(filter->GetOutput());
    return out;
  };
  vtkIdType flipped = 0;
  auto reference = normalsOf(sphere, true, &flipped);
  EXPECT_EQ(flipped, 0);
  auto repaired = normalsOf(scrambled, true, &flipped);
  EXPECT_EQ(flipped, (sphere->GetNumberOfPolys() + 1) / 3);
  EXPECT_EQ(Connectivity(scrambled), before);
  EXPECT_EQ(Connectivity(repaired), Connectivity(sphere));
  vtkDataArray* a = reference->GetPointData()->GetNormals();
  vtkDataArray* b = repaired->GetPointData()->GetNormals();
  ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples());
  double worst = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(a->GetComponent(i, c) - b->GetComponent(i, c)));
    }
  }
  EXPECT_LT(worst, 1e-6);
  // Without it the reversed faces cancel their neighbours: some vertex
  // normal strays far from the sphere's radius.
  auto raw = normalsOf(scrambled, false, &flipped);
  EXPECT_EQ(flipped, 0);
  vtkDataArray* n = raw->GetPointData()->GetNormals();
  double smallest = 1;
  for (vtkIdType i = 0; i < n->GetNumberOfTuples(); ++i)
  {
    const double* p = raw->GetPoint(i);
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    double dot = 0;
    for (int c = 0; c < 3; ++c)
    {
      dot += n->GetComponent(i, c) * p[c] / r;
    }
    smallest = std::min(smallest, dot);
  }
  EXPECT_LT(smallest, 0.5);
}

// 32-bit cells (the fast readers' storage whenever ids fit) are read in
// place and give what 64-bit cells give: the orientation test, the repair
// check, and the normals filter's output bit for bit, split, turned or
// left alone; the filter keeps 32-bit storage and leaves its input as it was.
TEST(OrientationTest, NarrowCellsGiveTheWideCellsResults)
{
  vtkSmartPointer<vtkPolyData> sphere;
  sphere.TakeReference(MakeUVSphere(48, 24));
  // Float points, as a file's.
  vtkNew<vtkPoints> floats;
  floats->SetDataTypeToFloat();
  floats->SetNumberOfPoints(sphere->GetNumberOfPoints());
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    floats->SetPoint(i, sphere->GetPoint(i));
  }
  sphere->SetPoints(floats);
  auto narrowOf = [](vtkPolyData* mesh) {
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->DeepCopy(mesh);
    EXPECT_TRUE(out->GetPolys()->ConvertTo32BitStorage());
    return out;
  };
  for (const bool scramble : { false, true })
  {
    SCOPED_TRACE(scramble ? "scrambled" : "consistent");
    auto wide = scramble ? WithReversedFaces(sphere, 3, 1) : sphere;
    ASSERT_TRUE(wide->GetPolys()->IsStorage64Bit());
    auto narrow = narrowOf(wide);
    slm::NarrowMeshView view;
    ASSERT_TRUE(slm::NarrowPolygonsOf(narrow, view));
    slm::NarrowMeshView none;
    EXPECT_FALSE(slm::NarrowPolygonsOf(wide, none)); // 64-bit cells: not viewed as 32
    EXPECT_EQ(slm::InconsistentlyOriented(narrow), scramble);
    EXPECT_EQ(slm::InconsistentlyOriented(narrow), slm::InconsistentlyOriented(wide));
    EXPECT_EQ(Connectivity(narrow), Connectivity(wide)); // the widened copy
    slm::FlatPolygons flat;
    slm::FlatPolygonsFromPolyData(wide, flat);
    const slm::RepairNeeds a = slm::CheckRepairNeeds(flat);
    const slm::RepairNeeds b = slm::CheckRepairNeeds(slm::FloatNarrowMeshView{
      vtkFloatArray::SafeDownCast(narrow->GetPoints()->GetData())->GetPointer(0), view.numberOfPoints,
      view.offsets, view.connectivity, view.numberOfPolygons });
    EXPECT_EQ(a.inconsistentEdges, b.inconsistentEdges);
    EXPECT_EQ(a.inconsistentEdges > 0, scramble);
    EXPECT_EQ(a.degenerate, b.degenerate);
    EXPECT_EQ(a.nonManifoldEdges, b.nonManifoldEdges);
    EXPECT_EQ(a.inwardComponents, b.inwardComponents);
    for (const double angle : { 5.0, 180.0 }) // split (faces meet at 7.5 degrees), or not
    {
      auto normalsOf = [angle](vtkPolyData* mesh) {
        vtkNew<vtkWeightedPolyDataNormals> filter;
        filter->SetInputData(mesh);
        filter->SetFeatureAngle(angle);
        filter->Update();
        auto out = vtkSmartPointer<vtkPolyData>::New();
        out->ShallowCopy(filter->GetOutput());
        return std::make_pair(out, filter->GetNumberOfSplitPoints());
      };
      const auto before = Connectivity(narrow);
      const auto [fromWide, splitWide] = normalsOf(wide);
      const auto [fromNarrow, splitNarrow] = normalsOf(narrow);
      EXPECT_EQ(splitWide, splitNarrow);
      EXPECT_EQ(splitWide > 0, angle < 90) << angle;
      EXPECT_EQ(Connectivity(narrow), before); // the input is not modified
      EXPECT_FALSE(narrow->GetPolys()->IsStorage64Bit());
      // Turned faces take the widened path and its 64-bit storage.
      EXPECT_EQ(fromNarrow->GetPolys()->IsStorage64Bit(), scramble) << angle;
      EXPECT_EQ(Connectivity(fromNarrow), Connectivity(fromWide)) << angle;
      vtkDataArray* na = fromWide->GetPointData()->GetNormals();
      vtkDataArray* nb = fromNarrow->GetPointData()->GetNormals();
      ASSERT_EQ(na->GetNumberOfTuples(), nb->GetNumberOfTuples());
      for (vtkIdType i = 0; i < na->GetNumberOfValues(); ++i)
      {
        ASSERT_EQ(vtkFloatArray::SafeDownCast(na)->GetValue(i),
          vtkFloatArray::SafeDownCast(nb)->GetValue(i)) << i;
      }
    }
  }
}

TEST(OrientationTest, VertexBucketsListCornersInFaceOrderOnAnyThreads)
{
  // BucketCornersByVertex (the orientation check's and the normals' table),
  // built by two threads above kParallelBucketCorners: every corner once,
  // in the slots of its vertex, in the order one serial pass gives, on
  // meshes of mixed polygon sizes on both sides of the threshold.
  std::mt19937 rng(5);
  for (const int64_t faces : { int64_t(1000), int64_t(40000) })
  {
    const int64_t points = faces / 3 + 7;
    std::uniform_int_distribution<int64_t> vertex(0, points - 1);
    std::uniform_int_distribution<int> corners(3, 6);
    std::vector<int64_t> offsets{ 0 }, connectivity;
    for (int64_t f = 0; f < faces; ++f)
    {
      for (int k = corners(rng); k > 0; --k)
      {
        connectivity.push_back(vertex(rng));
      }
      offsets.push_back(static_cast<int64_t>(connectivity.size()));
    }
    slm::MeshView mesh;
    mesh.numberOfPoints = points;
    mesh.numberOfPolygons = faces;
    mesh.offsets = offsets.data();
    mesh.connectivity = connectivity.data();
    const int64_t nc = offsets.back();
    EXPECT_EQ(nc >= slm::kParallelBucketCorners, faces == 40000);
    std::vector<int64_t> start, slotCorner(static_cast<size_t>(nc), -1);
    slm::BucketCornersByVertex(mesh, start,
      [&](int64_t f, int64_t b, int64_t e, int64_t c, int64_t slot) {
        EXPECT_TRUE(b <= c && c < e && offsets[f] == b && offsets[f + 1] == e);
        slotCorner[static_cast<size_t>(slot)] = c;
      });
    // The serial reference: for each vertex, its corners in increasing order.
    std::vector<std::vector<int64_t>> expected(static_cast<size_t>(points));
    for (int64_t c = 0; c < nc; ++c)
    {
      expected[static_cast<size_t>(connectivity[c])].push_back(c);
    }
    ASSERT_EQ(start.size(), static_cast<size_t>(points + 1));
    EXPECT_EQ(start.front(), 0);
    EXPECT_EQ(start.back(), nc);
    for (int64_t v = 0; v < points; ++v)
    {
      const std::vector<int64_t> got(slotCorner.begin() + start[v], slotCorner.begin() + start[v + 1]);
      ASSERT_EQ(got, expected[static_cast<size_t>(v)]) << "vertex " << v;
    }
  }
}

TEST(OrientationTest, PointBoxIsTheSerialPassOnAnyThreads)
{
  // mesh::PointBox (the readers' check and the conversion's frame): above
  // kParallelBoxPoints two threads, joined first half first, give the one
  // pass's box bit for bit, NaN skipped and of -0 and 0 the first kept.
  const int64_t n = slm::kParallelBoxPoints + 12345;
  std::vector<float> xyz(static_cast<size_t>(3 * n));
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> value(1.0f, 2.0f);
  for (float& v : xyz)
  {
    v = value(rng);
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  xyz[0] = nan;                                  // x: skipped
  xyz[3 * (n / 2) + 1] = -0.0f;                  // y's minimum in the second half...
  xyz[3 * (n / 2 - 5) + 1] = 0.0f;               // ... after an equal one in the first
  xyz[3 * (n - 1) + 2] = 7.0f;                   // z's maximum, the last point
  double box[6];
  slm::PointBox(xyz.data(), n, box);
  float lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
  for (int64_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const float v = xyz[static_cast<size_t>(3 * i + c)];
      lo[c] = v < lo[c] ? v : lo[c];
      hi[c] = v > hi[c] ? v : hi[c];
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(box[2 * c], lo[c]);
    EXPECT_EQ(box[2 * c + 1], hi[c]);
    EXPECT_EQ(std::signbit(box[2 * c]), std::signbit(lo[c])) << "axis " << c;
  }
  EXPECT_EQ(box[2], 0.0);
  EXPECT_FALSE(std::signbit(box[2])) << "the first of the equal minima";
  EXPECT_EQ(box[5], 7.0);
  EXPECT_FALSE(std::isnan(box[0]));
}
