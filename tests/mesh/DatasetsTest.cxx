// SPDX-License-Identifier: BSD-3-Clause
// Every shipped dataset reads back through MeshIO, closed analytic surfaces
// are oriented outwards, and their exact normals are unit and outward.
#include "AnalyticMeshes.h"
#include "MeshIO.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "MeshTestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace
{

const std::string kDatasets = SHADINGLAB_SOURCE_DIR "/datasets/";

vtkSmartPointer<vtkPolyData> Read(const std::string& name)
{
  vtkSmartPointer<vtkPolyData> mesh;
  mesh.TakeReference(shadinglab::ReadMesh(kDatasets + name));
  return mesh;
}


} // namespace

TEST(DatasetsTest, EveryShippedFileReads)
{
  const char* files[] = { "uv_sphere_16x8.vtp", "uv_sphere_32x16.vtp", "uv_sphere_64x32.vtp",
    "ellipsoid_16x8.vtp", "ellipsoid_32x16.vtp", "ellipsoid_64x32.vtp", "icosphere_1.vtp",
    "icosphere_2.vtp", "icosphere_3.vtp", "icosphere_4.vtp", "torus_24x12.vtp", "torus_48x24.vtp",
    "torus_96x48.vtp", "cylinder_8.vtp", "cylinder_8.stl", "sphere_lowpoly.ply",
    "corrugated_plane.obj", "quad_strip.vtk", "t_junctions.off", "metaballs_isosurface.vtp",
    "terrain.vtp", "receding_plane.vtp" };
  for (const char* f : files)
  {
    auto mesh = Read(f);
    EXPECT_GT(mesh->GetNumberOfPolys(), 0) << f;
  }
}

TEST(DatasetsTest, ClosedSurfacesAreOrientedOutwards)
{
  // Volumes: 4/3 pi for the unit sphere (inscribed polyhedra fall short),
  // 2 pi^2 R r^2 for the torus, 4/3 pi abc for the ellipsoid.
  const double pi = 3.14159265358979;
  EXPECT_NEAR(shadinglab::testing::SignedVolume(Read("uv_sphere_64x32.vtp")), 4.0 / 3.0 * pi, 0.02);
  EXPECT_NEAR(shadinglab::testing::SignedVolume(Read("icosphere_4.vtp")), 4.0 / 3.0 * pi, 0.02);
  EXPECT_NEAR(shadinglab::testing::SignedVolume(Read("torus_96x48.vtp")), 2 * pi * pi * 1.0 * 0.16, 0.02);
  EXPECT_NEAR(shadinglab::testing::SignedVolume(Read("ellipsoid_64x32.vtp")), 4.0 / 3.0 * pi * 1.5 * 0.7, 0.03);
  EXPECT_GT(shadinglab::testing::SignedVolume(Read("cylinder_8.stl")), 0.0);
  EXPECT_GT(shadinglab::testing::SignedVolume(Read("sphere_lowpoly.ply")), 0.0);
  EXPECT_GT(shadinglab::testing::SignedVolume(Read("metaballs_isosurface.vtp")), 0.0);
}

TEST(DatasetsTest, ExactNormalsAreUnitAndOutward)
{
  for (const char* f : { "uv_sphere_32x16.vtp", "icosphere_3.vtp", "torus_48x24.vtp",
         "ellipsoid_32x16.vtp", "metaballs_isosurface.vtp", "terrain.vtp" })
  {
    auto mesh = Read(f);
    vtkDataArray* n = mesh->GetPointData()->GetArray(shadinglab::datasets::kExactNormalArray);
    ASSERT_NE(n, nullptr) << f;
    ASSERT_EQ(n->GetNumberOfTuples(), mesh->GetNumberOfPoints()) << f;
    for (vtkIdType i = 0; i < n->GetNumberOfTuples(); ++i)
    {
      const double* v = n->GetTuple3(i);
      ASSERT_NEAR(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), 1.0, 1e-9) << f << " " << i;
    }
  }
  // On the sphere the exact normal is the position.
  auto sphere = Read("uv_sphere_32x16.vtp");
  vtkDataArray* n = sphere->GetPointData()->GetArray(shadinglab::datasets::kExactNormalArray);
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    double p[3];
    sphere->GetPoint(i, p);
    const double* v = n->GetTuple3(i);
    ASSERT_NEAR(p[0] * v[0] + p[1] * v[1] + p[2] * v[2], 1.0, 1e-9);
  }
}

TEST(DatasetsTest, TJunctionPatchHasVerticesOnCoarseEdges)
{
  auto mesh = Read("t_junctions.off");
  // 4x4 coarse + 8x8 fine quads = 16 + 64 cells.
  EXPECT_EQ(mesh->GetNumberOfPolys(), 80);
  // Vertices at x = 0 used by fine quads only (odd fine rows): 4 T-junctions.
  int onSeam = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    onSeam += std::abs(p[0]) < 1e-12;
  }
  EXPECT_EQ(onSeam, 9);
}
