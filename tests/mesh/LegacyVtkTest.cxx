// SPDX-License-Identifier: BSD-3-Clause
// Legacy .vtk files through the one mesh entry point: every dataset type,
// both encodings and both cell layouts (file versions 4.2 and 5.1) that
// VTK's own writers produce are read, with their attributes; every prefix
// of those files (a truncation) is refused with a MeshError or read as a
// valid mesh, never a crash (the structural walk of LegacyVtkCheck.cxx).
#include "MeshIO.h"

#include <vtkAppendFilter.h>
#include <vtkCellData.h>
#include <vtkDataSetWriter.h>
#include <vtkDoubleArray.h>
#include <vtkElevationFilter.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkStructuredGrid.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

namespace
{

struct Case
{
  std::string name;
  vtkSmartPointer<vtkDataSet> data;
  vtkIdType polygons; // the surface ReadMesh must return
};

/// A sphere with point scalars and normals and a two-component cell array
/// with named components (written as METADATA COMPONENT_NAMES).
vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(12);
  source->SetPhiResolution(6);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(source->GetOutputPort());
  elevation->Update();
  auto sphere = vtkSmartPointer<vtkPolyData>::New();
  sphere->DeepCopy(elevation->GetOutput());
  vtkNew<vtkDoubleArray> cellValues;
  cellValues->SetName("cell values");
  cellValues->SetNumberOfComponents(2);
  cellValues->SetComponentName(0, "first value");
  cellValues->SetComponentName(1, "second");
  for (vtkIdType i = 0; i < sphere->GetNumberOfCells(); ++i)
  {
    cellValues->InsertNextTuple2(i, -i);
  }
  sphere->GetCellData()->AddArray(cellValues);
  return sphere;
}

std::vector<Case> Cases()
{
  std::vector<Case> cases;
  auto sphere = Sphere();
  cases.push_back({ "polydata", sphere, sphere->GetNumberOfPolys() });
  vtkNew<vtkAppendFilter> append;
  append->SetInputData(sphere);
  append->Update();
  cases.push_back({ "unstructured", append->GetOutput(), sphere->GetNumberOfPolys() });
  // A 4 x 5 x 6 block: its boundary has 2 (3*4 + 3*5 + 4*5) = 94 quads.
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(4, 5, 6);
  image->AllocateScalars(VTK_FLOAT, 1);
  // AllocateScalars leaves the values uninitialized: garbage that was
  // sometimes a NaN, which the reader rightly rejects.
  image->GetPointData()->GetScalars()->Fill(0.0);
  cases.push_back({ "image", image, 94 });
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->SetDimensions(4, 5, 6);
  vtkNew<vtkPoints> points;
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 4; ++i)
        points->InsertNextPoint(i, j + 0.1 * i, k);
  grid->SetPoints(points);
  cases.push_back({ "structured", grid, 94 });
  auto rectilinear = vtkSmartPointer<vtkRectilinearGrid>::New();
  rectilinear->SetDimensions(4, 5, 6);
  vtkNew<vtkFloatArray> x, y, z;
  for (int i = 0; i < 6; ++i)
  {
    x->InsertNextValue(0.5f * i);
    y->InsertNextValue(1.5f * i);
    z->InsertNextValue(0.25f * i * i);
  }
  x->SetNumberOfTuples(4);
  y->SetNumberOfTuples(5);
  rectilinear->SetXCoordinates(x);
  rectilinear->SetYCoordinates(y);
  rectilinear->SetZCoordinates(z);
  cases.push_back({ "rectilinear", rectilinear, 94 });
  return cases;
}

/// A file name of its own per test and process: ctest runs the tests of
/// this suite in parallel processes, which must not share a file.
std::string Write(const Case& c, bool binary, int version)
{
  const std::string path = ::testing::TempDir() + "/shadinglab_legacy_" +
    ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
    std::to_string(getpid()) + "_" + c.name + (binary ? "_binary_" : "_ascii_") +
    std::to_string(version) + ".vtk";
  vtkNew<vtkDataSetWriter> writer;
  writer->SetInputData(c.data);
  writer->SetFileName(path.c_str());
  writer->SetFileType(binary ? VTK_BINARY : VTK_ASCII);
  if (version == 42)
  {
    writer->SetFileVersion(vtkDataSetWriter::VTK_LEGACY_READER_VERSION_4_2);
  }
  EXPECT_EQ(writer->Write(), 1) << path;
  return path;
}

std::string Contents(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return { std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
}

} // namespace

TEST(LegacyVtkTest, EveryWriterFlavourIsRead)
{
  for (const Case& c : Cases())
  {
    for (bool binary : { false, true })
    {
      for (int version : { 42, 51 })
      {
        const std::string path = Write(c, binary, version);
        SCOPED_TRACE(path);
        vtkSmartPointer<vtkPolyData> mesh;
        ASSERT_NO_THROW(mesh.TakeReference(shadinglab::ReadMesh(path)));
        EXPECT_EQ(mesh->GetNumberOfPolys(), c.polygons);
        if (c.name == "polydata" || c.name == "unstructured")
        {
          EXPECT_NE(mesh->GetPointData()->GetArray("Elevation"), nullptr);
          vtkDataArray* cellValues = mesh->GetCellData()->GetArray("cell values");
          ASSERT_NE(cellValues, nullptr);
          EXPECT_STREQ(cellValues->GetComponentName(0), "first value");
        }
        std::remove(path.c_str());
      }
    }
  }
}

TEST(LegacyVtkTest, EveryTruncationIsRefusedOrValid)
{
  // Cut each flavour of the sphere at 64 places: a cut inside the header or
  // a binary block must be an error; a cut that happens to end on a value
  // boundary may read as a smaller valid mesh. Either way, no crash.
  const Case sphere = Cases()[0];
  for (bool binary : { false, true })
  {
    for (int version : { 42, 51 })
    {
      const std::string path = Write(sphere, binary, version);
      const std::string whole = Contents(path);
      int refused = 0;
      for (int cut = 0; cut < 64; ++cut)
      {
        const size_t length = whole.size() * static_cast<size_t>(cut) / 64;
        std::ofstream(path, std::ios::binary | std::ios::trunc)
          .write(whole.data(), static_cast<std::streamsize>(length));
        try
        {
          vtkSmartPointer<vtkPolyData> mesh;
          mesh.TakeReference(shadinglab::ReadMesh(path));
          shadinglab::ValidateMesh(mesh, "truncated");
          // Accepted: the cut must fall between two sections, where a
          // shorter file is indeed complete.
          const size_t next = whole.find_first_not_of(" \n", length);
          EXPECT_TRUE(next < whole.size() &&
            std::isupper(static_cast<unsigned char>(whole[next])) &&
            (length == 0 || whole[length - 1] == '\n' || whole[length] == '\n'))
            << path << " cut at " << length << ": '" << whole.substr(length, 40) << "'";
        }
        catch (const shadinglab::MeshError& e)
        {
          ++refused;
          EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        }
      }
      EXPECT_GE(refused, 60) << path;
      std::remove(path.c_str());
    }
  }
}

TEST(LegacyVtkTest, InconsistentSectionsAreNamed)
{
  const std::string head = "# vtk DataFile Version 4.2\nt\nASCII\nDATASET POLYDATA\n"
                           "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\n";
  const struct
  {
    std::string tail, expected;
  } cases[] = {
    { "POINT_DATA 2\nSCALARS s float\nLOOKUP_TABLE default\n0 1\n", "POINT_DATA 2 but" },
    { "POINT_DATA 3\nSCALARS s float 7\nLOOKUP_TABLE default\n0 1 2\n", "component count" },
    { "POINT_DATA 3\nSCALARS s float\n0 1 2\n", "without its LOOKUP_TABLE" },
    { "POINT_DATA 3\nNORMALS n float\n0 0 1 0 0 1 0 0\n", "ends after 8 of 9" },
    { "POINT_DATA 3\nNORMALS n float\n0 0 1 0 0 1 0 0 1 0 0\n", "unknown keyword '0'" },
    { "CELL_DATA 1\nFIELD f 1\na 1 2 float\n0 1\n", "has 2 tuples, not 1" },
    { "LINES 1 3\n2 0 5\n", "point index 5" },
    { "POLYGONS 1 4\n3 0 1 2\n", "a second POLYGONS" },
  };
  for (const auto& c : cases)
  {
    const std::string path =
      ::testing::TempDir() + "/shadinglab_legacy_bad_" + std::to_string(getpid()) + ".vtk";
    std::ofstream(path, std::ios::binary | std::ios::trunc) << head << c.tail;
    std::string error;
    try
    {
      vtkSmartPointer<vtkPolyData> mesh;
      mesh.TakeReference(shadinglab::ReadMesh(path));
    }
    catch (const shadinglab::MeshError& e)
    {
      error = e.what();
    }
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.tail << " -> " << error;
    std::remove(path.c_str());
  }
}
