// SPDX-License-Identifier: BSD-3-Clause
// Consistent orientation (mesh/core/Orientation.h) and the normals filter
// that uses it: inconsistently oriented faces are turned back, closed
// components face outward, open ones keep their lowest face's side, a
// consistent mesh is left alone, and the input is never modified.
#include "AnalyticMeshes.h"
#include "MeshArrays.h"
#include "Orientation.h"
#include "vtkWeightedPolyDataNormals.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
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
