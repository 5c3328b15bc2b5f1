// SPDX-License-Identifier: BSD-3-Clause
// vtkMeshRepair: welding (with seams), degenerate removal, orientation,
// non-manifold resolution through OpenMesh, T-junction repair.
#include "AnalyticMeshes.h"
#include "MeshIO.h"
#include "MeshArrays.h"
#include "RepairCheck.h"
#include "vtkMeshRepair.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "MeshTestUtil.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

namespace
{

/// Every polygon gets its own copies of its vertices: an STL-like soup.
vtkSmartPointer<vtkPolyData> Soup(vtkPolyData* mesh)
{
  auto soup = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfPolys(); ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, ids);
    std::vector<vtkIdType> face;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      face.push_back(points->InsertNextPoint(mesh->GetPoint(ids->GetId(k))));
    }
    polys->InsertNextCell(static_cast<vtkIdType>(face.size()), face.data());
  }
  soup->SetPoints(points);
  soup->SetPolys(polys);
  return soup;
}


vtkSmartPointer<vtkPolyData> Icosphere(int level)
{
  vtkSmartPointer<vtkPolyData> m;
  m.TakeReference(shadinglab::datasets::MakeIcosphere(level));
  return m;
}

} // namespace

TEST(RepairTest, WeldsATriangleSoup)
{
  auto soup = Soup(Icosphere(1));
  ASSERT_EQ(soup->GetNumberOfPoints(), 240);
  vtkNew<vtkMeshRepair> repair;
  repair->SetInputData(soup);
  repair->WeldOn();
  repair->Update();
  EXPECT_EQ(repair->GetOutput()->GetNumberOfPoints(), 42);
  EXPECT_EQ(repair->GetNumberOfWeldedPoints(), 240 - 42);
  EXPECT_EQ(repair->GetOutput()->GetNumberOfPolys(), 80);
  EXPECT_EQ(repair->GetNumberOfFlippedCells(), 0);
  EXPECT_EQ(repair->GetNumberOfDuplicatedPoints(), 0);
  EXPECT_EQ(soup->GetNumberOfPoints(), 240); // input untouched
}

TEST(RepairTest, SeamsWithDifferentAttributesStayOpen)
{
  // Two triangles sharing an edge geometrically; the shared positions carry
  // different texture-like values on each side.
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  const double p[6][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { 1, 1, 0 },
    { 0, 1, 0 } };
  for (auto& q : p)
  {
    points->InsertNextPoint(q);
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType a[3] = { 0, 1, 2 }, b[3] = { 3, 4, 5 };
  polys->InsertNextCell(3, a);
  polys->InsertNextCell(3, b);
  vtkNew<vtkFloatArray> u;
  u->SetName("u");
  for (float v : { 0.f, 1.f, 0.f, 0.5f, 1.f, 0.25f })
  {
    u->InsertNextValue(v);
  }
  pd->SetPoints(points);
  pd->SetPolys(polys);
  pd->GetPointData()->AddArray(u);
  vtkNew<vtkMeshRepair> repair;
  repair->SetInputData(pd);
  repair->WeldOn();
  repair->Update();
  EXPECT_EQ(repair->GetNumberOfWeldedPoints(), 2);
  repair->KeepAttributeSeamsOn();
  repair->Update();
  EXPECT_EQ(repair->GetNumberOfWeldedPoints(), 0);
  EXPECT_EQ(repair->GetOutput()->GetNumberOfPoints(), 6);
}

TEST(RepairTest, RemovesDegenerateFacesAndCountsThem)
{
  auto pd = Icosphere(1);
  vtkNew<vtkCellArray> polys;
  polys->DeepCopy(pd->GetPolys());
  const vtkIdType repeated[3] = { 0, 0, 1 };
  const vtkIdType pinched[4] = { 0, 1, 0, 2 };
  polys->InsertNextCell(3, repeated);
  polys->InsertNextCell(4, pinched);
  pd->SetPolys(polys);
  vtkNew<vtkIntArray> tag;
  tag->SetName("tag");
  for (int i = 0; i < 82; ++i)
  {
    tag->InsertNextValue(i);
  }
  pd->GetCellData()->AddArray(tag);
  vtkNew<vtkMeshRepair> repair;
  repair->SetInputData(pd);
  repair->Update();
  EXPECT_EQ(repair->GetNumberOfDegenerateCellsRemoved(), 2);
  EXPECT_EQ(repair->GetOutput()->GetNumberOfPolys(), 80);
  auto* outTag = repair->GetOutput()->GetCellData()->GetArray("tag");
  ASSERT_NE(outTag, nullptr);
  EXPECT_EQ(outTag->GetTuple1(79), 79.0);
}

TEST(RepairTest, OrientationIsMadeConsistentAndOutward)
{
  auto pd = Icosphere(2);
  const double volume = shadinglab::testing::SignedVolume(pd);
  // Flip a random third of the faces, then the whole sphere inside out.
  std::mt19937 rng(5);
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> ids;
  int flippedByUs = 0;
  for (vtkIdType c = 0; c < pd->GetNumberOfPolys(); ++c)
  {
    pd->GetPolys()->GetCellAtId(c, ids);
    std::vector<vtkIdType> f(ids->begin(), ids->end());
    if (rng() % 3 == 0)
    {
      std::reverse(f.begin(), f.end());
      ++flippedByUs;
    }
    polys->InsertNextCell(3, f.data());
  }
  pd->SetPolys(polys);
  vtkNew<vtkMeshRepair> repair;
  repair->SetInputData(pd);
  repair->Update();
  EXPECT_EQ(repair->GetNumberOfFlippedCells(), flippedByUs);
  EXPECT_NEAR(shadinglab::testing::SignedVolume(repair->GetOutput()), volume, 1e-9);
  EXPECT_EQ(repair->GetNumberOfDuplicatedPoints(), 0);
}

TEST(RepairTest, NonManifoldEdgesKeepEveryFace)
{
  // Three triangles on one edge: OpenMesh refuses the third; it gets its own
  // vertex copies instead of being dropped.
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  for (const auto& q : std::vector<std::array<double, 3>>{
         { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, -1, 0.2 }, { 0.5, 0, 1 } })
  {
    points->InsertNextPoint(q.data());
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType f1[3] = { 0, 1, 2 }, f2[3] = { 1, 0, 3 }, f3[3] = { 0, 1, 4 };
  polys->InsertNextCell(3, f1);
  polys->InsertNextCell(3, f2);
  polys->InsertNextCell(3, f3);
  pd->SetPoints(points);
  pd->SetPolys(polys);
  vtkNew<vtkMeshRepair> repair;
  repair->SetInputData(pd);
  repair->Update();
  EXPECT_EQ(repair->GetNumberOfNonManifoldEdges(), 1);
  EXPECT_EQ(repair->GetOutput()->GetNumberOfPolys(), 3);
  EXPECT_GE(repair->GetNumberOfDuplicatedPoints(), 2);
  auto* ids2 = repair->GetOutput()->GetPointData()->GetArray("OriginalPointIds");
  ASSERT_NE(ids2, nullptr);
}

TEST(RepairTest, TJunctionsAreSplit)
{
  vtkSmartPointer<vtkPolyData> patch;
  patch.TakeReference(shadinglab::ReadMesh(SHADINGLAB_SOURCE_DIR "/datasets/t_junctions.off"));
  vtkNew<vtkMeshRepair> repair;
  repair->SetInputData(patch);
  repair->FixTJunctionsOn();
  repair->Update();
  EXPECT_EQ(repair->GetNumberOfTJunctionsFixed(), 4);
  // The four coarse quads on the seam became pentagons.
  int pentagons = 0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < repair->GetOutput()->GetNumberOfPolys(); ++c)
  {
    repair->GetOutput()->GetPolys()->GetCellAtId(c, ids);
    pentagons += ids->GetNumberOfIds() == 5;
  }
  EXPECT_EQ(pentagons, 4);
  // A clean mesh has none.
  repair->SetInputData(Icosphere(2));
  repair->Update();
  EXPECT_EQ(repair->GetNumberOfTJunctionsFixed(), 0);
}

TEST(RepairCheckTest, FindsWhatTheRepairWouldChangeAndNothingOnCleanMeshes)
{
  namespace slm = shadinglab::mesh;
  // An octahedron: closed, outward, manifold.
  std::vector<double> points = { 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1 };
  std::vector<int64_t> faces = { 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0,
    3, 5 };
  auto check = [&](const std::vector<int64_t>& conn) {
    std::vector<int64_t> offsets;
    for (size_t k = 0; k <= conn.size(); k += 3)
    {
      offsets.push_back(static_cast<int64_t>(k));
    }
    const slm::MeshView view{ points.data(), static_cast<int64_t>(points.size() / 3),
      offsets.data(), conn.data(), static_cast<int64_t>(offsets.size() - 1) };
    return slm::CheckRepairNeeds(view);
  };
  EXPECT_FALSE(check(faces).Any());
  auto oneFlipped = faces;
  std::swap(oneFlipped[1], oneFlipped[2]);
  EXPECT_EQ(check(oneFlipped).inconsistentEdges, 3);
  auto allFlipped = faces;
  for (size_t k = 0; k < allFlipped.size(); k += 3)
  {
    std::swap(allFlipped[k + 1], allFlipped[k + 2]);
  }
  const auto inward = check(allFlipped);
  EXPECT_EQ(inward.inconsistentEdges, 0);
  EXPECT_EQ(inward.inwardComponents, 1);
  auto degenerate = faces;
  degenerate.insert(degenerate.end(), { 0, 0, 1 });
  EXPECT_EQ(check(degenerate).degenerate, 1);
  auto fin = faces; // a third face on edge 0-2: non-manifold (and the octahedron open no more)
  points.insert(points.end(), { 2, 2, 0 });
  fin.insert(fin.end(), { 0, 6, 2 });
  EXPECT_EQ(check(fin).nonManifoldEdges, 1);
  // The shipped datasets that the repair leaves alone pass the check.
  for (const char* name : { "icosphere_3.vtp", "torus_48x24.vtp" })
  {
    vtkSmartPointer<vtkPolyData> pd;
    pd.TakeReference(shadinglab::ReadMesh(std::string(SHADINGLAB_SOURCE_DIR) + "/datasets/" + name));
    shadinglab::mesh::FlatPolygons flat;
    shadinglab::mesh::FlatPolygonsFromPolyData(pd, flat);
    EXPECT_FALSE(slm::CheckRepairNeeds(flat).Any()) << name;
  }
}
