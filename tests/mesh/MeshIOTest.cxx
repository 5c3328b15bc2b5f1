// SPDX-License-Identifier: BSD-3-Clause
// Bad input gets a clear MeshError naming the problem, never a crash.
#include "AnalyticMeshes.h"
#include "MeshIO.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace
{

std::string TempFile(const std::string& name, const std::string& contents)
{
  const std::string path = ::testing::TempDir() + "/shadinglab_meshio_" + name;
  std::ofstream(path) << contents;
  return path;
}

std::string ErrorOf(const std::string& path)
{
  try
  {
    vtkSmartPointer<vtkPolyData> mesh;
    mesh.TakeReference(shadinglab::ReadMesh(path));
  }
  catch (const shadinglab::MeshError& e)
  {
    return e.what();
  }
  return {};
}

} // namespace

TEST(MeshIOTest, MissingFile)
{
  EXPECT_NE(ErrorOf("/nonexistent/x.vtp").find("no such file"), std::string::npos);
}

TEST(MeshIOTest, EmptyFile)
{
  EXPECT_NE(ErrorOf(TempFile("empty.stl", "")).find("empty file"), std::string::npos);
}

TEST(MeshIOTest, UnknownExtension)
{
  EXPECT_NE(ErrorOf(TempFile("mesh.xyz", "1 2 3\n")).find("unknown extension"), std::string::npos);
}

TEST(MeshIOTest, GarbageInEveryFormat)
{
  for (const char* ext : { "vtp", "vtk", "ply", "obj", "stl", "off", "vtu" })
  {
    const std::string err =
      ErrorOf(TempFile(std::string("garbage.") + ext, "this is not a mesh\n\x01\x02garbage\n"));
    EXPECT_FALSE(err.empty()) << ext;
    EXPECT_EQ(err.find('\n'), std::string::npos) << ext << ": " << err;
  }
}

TEST(MeshIOTest, Utf16ObjIsNamedNotEmpty)
{
  // A triangle saved as UTF-16 (little and big endian, with and without the
  // byte-order mark) by an editor: named as such, not "empty mesh".
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (const bool little : { true, false })
  {
    for (const bool mark : { true, false })
    {
      std::string bytes = mark ? (little ? std::string("\xFF\xFE") : std::string("\xFE\xFF")) : "";
      for (const char c : text)
      {
        bytes += little ? std::string{ c, '\0' } : std::string{ '\0', c };
      }
      const std::string err = ErrorOf(TempFile(std::string("utf16_") + (little ? "le" : "be") +
          (mark ? "_bom" : "") + ".obj", bytes));
      EXPECT_NE(err.find("UTF-16"), std::string::npos) << little << mark << ": " << err;
      EXPECT_EQ(err.find('\n'), std::string::npos) << err;
    }
  }
}

TEST(MeshIOTest, NaNCoordinatesAreRejected)
{
  const std::string err =
    ErrorOf(TempFile("nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_NE(err.find("non-finite"), std::string::npos) << err;
  EXPECT_NE(err.find("point 1"), std::string::npos) << err;
}

TEST(MeshIOTest, MeshWithoutPolygonsIsEmpty)
{
  const std::string err = ErrorOf(TempFile("nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"));
  EXPECT_NE(err.find("empty mesh"), std::string::npos) << err;
}

TEST(MeshIOTest, MalformedOff)
{
  EXPECT_NE(ErrorOf(TempFile("short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n")).find("malformed"),
    std::string::npos);
  EXPECT_NE(ErrorOf(TempFile("index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"))
              .find("out of range"),
    std::string::npos);
  EXPECT_NE(ErrorOf(TempFile("count.off", "OFF\n-3 1 0\n")).find("counts"), std::string::npos);
}

TEST(MeshIOTest, OffRoundTripWithFaceColours)
{
  const std::string path =
    TempFile("colour.off", "OFF\n# comment\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                           "3 0 1 2 255 0 0\n3 0 2 3 0 255 0\n");
  vtkSmartPointer<vtkPolyData> mesh;
  mesh.TakeReference(shadinglab::ReadMesh(path));
  EXPECT_EQ(mesh->GetNumberOfPolys(), 2);
  EXPECT_EQ(mesh->GetNumberOfPoints(), 4);
}

TEST(MeshIOTest, EveryWriterRoundTrips)
{
  vtkSmartPointer<vtkPolyData> sphere;
  sphere.TakeReference(shadinglab::datasets::MakeIcosphere(1));
  for (const char* ext : { "vtp", "vtk", "ply", "obj", "stl", "off" })
  {
    const std::string path = ::testing::TempDir() + "/shadinglab_roundtrip." + ext;
    shadinglab::WriteMesh(sphere, path);
    vtkSmartPointer<vtkPolyData> back;
    back.TakeReference(shadinglab::ReadMesh(path));
    EXPECT_EQ(back->GetNumberOfPolys(), 80) << ext;
    std::remove(path.c_str());
  }
}

TEST(MeshIOTest, UnwritablePathIsAnError)
{
  vtkSmartPointer<vtkPolyData> sphere;
  sphere.TakeReference(shadinglab::datasets::MakeIcosphere(1));
  for (const char* ext : { "vtp", "vtk", "ply", "obj", "stl", "off" })
  {
    const std::string path = std::string("/nonexistent-dir/mesh.") + ext;
    try
    {
      shadinglab::WriteMesh(sphere, path);
      ADD_FAILURE() << "no error writing " << path;
    }
    catch (const shadinglab::MeshError& e)
    {
      EXPECT_NE(std::string(e.what()).find("cannot write"), std::string::npos) << e.what();
    }
  }
}

TEST(MeshIOTest, ColouredAndNormalOffVariants)
{
  // COFF: colours as 0..255 integers; NOFF: normals after the coordinates.
  vtkSmartPointer<vtkPolyData> coff;
  coff.TakeReference(shadinglab::ReadMesh(TempFile("c.off",
    "COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n")));
  auto* colours = vtkUnsignedCharArray::SafeDownCast(coff->GetPointData()->GetScalars());
  ASSERT_NE(colours, nullptr);
  EXPECT_EQ(colours->GetValue(0), 255);
  EXPECT_EQ(colours->GetValue(4), 255);
  EXPECT_EQ(colours->GetValue(8), 255);
  EXPECT_EQ(colours->GetValue(1), 0);
  vtkSmartPointer<vtkPolyData> noff;
  noff.TakeReference(shadinglab::ReadMesh(TempFile("n.off",
    "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n")));
  ASSERT_NE(noff->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(noff->GetPointData()->GetNormals()->GetComponent(2, 2), 1.0);
  // A .vtp that is not XML says what it is not.
  EXPECT_NE(ErrorOf(TempFile("g.vtp", "solid this is an STL")).find("not a VTK XML"),
    std::string::npos);
}
