// SPDX-License-Identifier: BSD-3-Clause
// ReadMesh on scientists' files: multiblock (.vtm, every block) and
// collections (.pvd, the first time step), structured grids and images
// (their outer surface), higher-order cells (tessellated as ParaView does),
// and the listing files' own failure modes, each one line.
#include "AnalyticMeshes.h"
#include "MeshIO.h"

#include <vtkAppendFilter.h>
#include <vtkCellArray.h>
#include <vtkExodusIIWriter.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkImageData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredGrid.h>
#include <vtkDoubleArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLRectilinearGridWriter.h>
#include <vtkXMLStructuredGridWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

namespace
{
std::string Temp(const std::string& name)
{
  return ::testing::TempDir() + "/shadinglab_formats_" + name;
}

vtkSmartPointer<vtkPolyData> Read(const std::string& path, const shadinglab::ReadOptions& options = {})
{
  vtkSmartPointer<vtkPolyData> mesh;
  mesh.TakeReference(shadinglab::ReadMesh(path, options));
  return mesh;
}

std::string ErrorOf(const std::string& path, const shadinglab::ReadOptions& options = {})
{
  try
  {
    Read(path, options);
  }
  catch (const shadinglab::MeshError& e)
  {
    return e.what();
  }
  return {};
}

template <typename Writer>
void Write(vtkDataObject* data, const std::string& path)
{
  vtkNew<Writer> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1) << path;
}
} // namespace

TEST(ScientificFormatsTest, MultiblockReadsEveryBlock)
{
  vtkSmartPointer<vtkPolyData> sphere, torus;
  sphere.TakeReference(shadinglab::datasets::MakeUVSphere(16, 8));
  torus.TakeReference(shadinglab::datasets::MakeTorus(1.0, 0.3, 12, 6));
  vtkNew<vtkMultiBlockDataSet> inner;
  inner->SetBlock(0, torus);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, sphere);
  blocks->SetBlock(1, inner); // nested blocks too
  const std::string path = Temp("blocks.vtm");
  Write<vtkXMLMultiBlockDataWriter>(blocks, path);
  const auto mesh = Read(path);
  EXPECT_EQ(mesh->GetNumberOfPolys(), sphere->GetNumberOfPolys() + torus->GetNumberOfPolys());
}

TEST(ScientificFormatsTest, CollectionReadsItsFirstTimeStep)
{
  vtkSmartPointer<vtkPolyData> sphere, torus;
  sphere.TakeReference(shadinglab::datasets::MakeUVSphere(16, 8));
  torus.TakeReference(shadinglab::datasets::MakeTorus(1.0, 0.3, 12, 6));
  Write<vtkXMLPolyDataWriter>(sphere, Temp("t1.vtp"));
  Write<vtkXMLPolyDataWriter>(torus, Temp("t0.vtp"));
  const std::string path = Temp("series.pvd");
  std::ofstream(path) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
                         "<Collection>\n"
                         "<DataSet timestep=\"2.5\" part=\"0\" file=\"shadinglab_formats_t1.vtp\"/>\n"
                         "<DataSet timestep=\"0.5\" part=\"0\" file=\"shadinglab_formats_t0.vtp\"/>\n"
                         "</Collection>\n</VTKFile>\n";
  EXPECT_EQ(Read(path)->GetNumberOfPolys(), torus->GetNumberOfPolys());

  // --time-step N and --time T (the last step at or before T, as ParaView
  // snaps), and what is refused, in one line each.
  shadinglab::ReadOptions step;
  step.timeStep = 1;
  EXPECT_EQ(Read(path, step)->GetNumberOfPolys(), sphere->GetNumberOfPolys());
  shadinglab::ReadOptions at;
  for (const auto& [time, polys] : { std::pair{ 2.5, sphere->GetNumberOfPolys() },
         std::pair{ 1.0, torus->GetNumberOfPolys() }, std::pair{ 0.5, torus->GetNumberOfPolys() } })
  {
    at.time = time;
    EXPECT_EQ(Read(path, at)->GetNumberOfPolys(), polys) << "--time " << time;
  }
  at.time = 3.0;
  EXPECT_NE(ErrorOf(path, at).find("outside"), std::string::npos) << ErrorOf(path, at);
  EXPECT_NE(ErrorOf(path, at).find("2 step(s), times 0.5 .. 2.5"), std::string::npos);
  step.timeStep = 2;
  EXPECT_NE(ErrorOf(path, step).find("steps 0..1"), std::string::npos) << ErrorOf(path, step);
  step.time = 1.0;
  EXPECT_NE(ErrorOf(path, step).find("give one"), std::string::npos) << ErrorOf(path, step);
  shadinglab::ReadOptions plain;
  plain.time = 0.5;
  EXPECT_NE(ErrorOf(Temp("t0.vtp"), plain).find("has no time steps"), std::string::npos);
}

TEST(ScientificFormatsTest, StructuredGridsAndImagesGiveTheirOuterSurface)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(3, 4, 5);
  Write<vtkXMLImageDataWriter>(image, Temp("box.vti"));
  // A 3 x 4 x 5 point box: 2x3 + 2x4 + 3x4 quads on opposite faces.
  EXPECT_EQ(Read(Temp("box.vti"))->GetNumberOfPolys(), 2 * (2 * 3 + 2 * 4 + 3 * 4));
  vtkNew<vtkRectilinearGrid> rect;
  rect->SetDimensions(3, 4, 5);
  vtkNew<vtkDoubleArray> x, y, z;
  for (int i = 0; i < 5; ++i)
  {
    (i < 3 ? x->InsertNextValue(i * i) : 0);
    (i < 4 ? y->InsertNextValue(0.5 * i) : 0);
    z->InsertNextValue(std::sqrt(i));
  }
  rect->SetXCoordinates(x);
  rect->SetYCoordinates(y);
  rect->SetZCoordinates(z);
  Write<vtkXMLRectilinearGridWriter>(rect, Temp("rect.vtr"));
  EXPECT_EQ(Read(Temp("rect.vtr"))->GetNumberOfPolys(), 2 * (2 * 3 + 2 * 4 + 3 * 4));
  vtkNew<vtkStructuredGrid> grid;
  grid->SetDimensions(4, 4, 1); // a curved sheet
  vtkNew<vtkPoints> points;
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      points->InsertNextPoint(i, j, 0.1 * i * j);
    }
  }
  grid->SetPoints(points);
  Write<vtkXMLStructuredGridWriter>(grid, Temp("sheet.vts"));
  EXPECT_EQ(Read(Temp("sheet.vts"))->GetNumberOfPolys(), 9);
}

TEST(ScientificFormatsTest, QuadraticCellsAreTessellatedAsParaViewDoes)
{
  // One quadratic triangle (corner points, then edge midpoints lifted out of
  // the plane): ParaView's level-1 subdivision draws it as 4 triangles.
  vtkNew<vtkPoints> points;
  const double p[6][3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 1, 0, 0.3 }, { 1, 1, 0.3 },
    { 0, 1, 0.3 } };
  for (const auto& q : p)
  {
    points->InsertNextPoint(q);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  const vtkIdType ids[6] = { 0, 1, 2, 3, 4, 5 };
  grid->InsertNextCell(VTK_QUADRATIC_TRIANGLE, 6, ids);
  Write<vtkXMLUnstructuredGridWriter>(grid, Temp("quadratic.vtu"));
  const auto mesh = Read(Temp("quadratic.vtu"));
  EXPECT_GE(mesh->GetNumberOfPolys(), 4);
  double bounds[6];
  mesh->GetBounds(bounds);
  EXPECT_NEAR(bounds[5], 0.3, 1e-6) << "the curved edges are kept"; // float points
  // The level is a setting: 0 draws the corner nodes' flat triangle, each
  // level splits every triangle in four (ParaView's property, 0..4).
  // The top rises towards the quadratic surface's own (its value at the
  // centroid, 4/3 of the edge midpoints' 0.3 = 0.4).
  double previousTop = -1.0;
  for (int level = 0; level <= shadinglab::kMaxNonlinearSubdivisionLevel; ++level)
  {
    shadinglab::ReadOptions options;
    options.nonlinearSubdivisionLevel = level;
    const auto at = Read(Temp("quadratic.vtu"), options);
    EXPECT_EQ(at->GetNumberOfPolys(), 1 << (2 * level)) << "level " << level;
    at->GetBounds(bounds);
    if (level <= 1)
    {
      EXPECT_NEAR(bounds[5], level == 0 ? 0.0 : 0.3, 1e-6) << "level " << level;
    }
    EXPECT_GT(bounds[5], previousTop) << "level " << level;
    EXPECT_LE(bounds[5], 0.4 + 1e-6) << "level " << level;
    previousTop = bounds[5];
  }
  shadinglab::ReadOptions absurd;
  absurd.nonlinearSubdivisionLevel = shadinglab::kMaxNonlinearSubdivisionLevel + 1;
  const std::string error = ErrorOf(Temp("quadratic.vtu"), absurd);
  EXPECT_NE(error.find("nonlinear subdivision level must be 0..4"), std::string::npos) << error;
}

TEST(ScientificFormatsTest, ListingFilesFailInOneLine)
{
  const std::string self = Temp("self.vtm");
  std::ofstream(self) << "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\"><vtkMultiBlockDataSet>"
                         "<DataSet index=\"0\" file=\"shadinglab_formats_self.vtm\"/>"
                         "</vtkMultiBlockDataSet></VTKFile>\n";
  const std::string missing = Temp("missing.vtm");
  std::ofstream(missing) << "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\"><vtkMultiBlockDataSet>"
                            "<DataSet index=\"0\" file=\"nowhere.vtp\"/>"
                            "</vtkMultiBlockDataSet></VTKFile>\n";
  const std::string none = Temp("none.pvd");
  std::ofstream(none) << "<VTKFile type=\"Collection\"><Collection></Collection></VTKFile>\n";
  const std::string truncated = Temp("truncated.vtm");
  std::ofstream(truncated) << "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\"><vtkMulti";
  const std::string badStep = Temp("badstep.pvd");
  std::ofstream(badStep) << "<VTKFile type=\"Collection\"><Collection>"
                            "<DataSet timestep=\"soon\" file=\"x.vtp\"/></Collection></VTKFile>\n";
  const std::string badExtent = Temp("extent.vti");
  std::ofstream(badExtent) << "<VTKFile type=\"ImageData\" version=\"1.0\"><ImageData WholeExtent=\"0 9 0 9 0 9\">"
                              "<Piece Extent=\"0 9 0 -9 0 9\"></Piece></ImageData></VTKFile>\n";
  const struct
  {
    std::string path;
    const char* says;
  } cases[] = { { self, "nested more than" }, { missing, "block 'nowhere.vtp'" },
    { none, "lists no data set" }, { truncated, "not a VTKFile" }, { badStep, "timestep" },
    { badExtent, "Extent" } };
  for (const auto& c : cases)
  {
    const std::string err = ErrorOf(c.path);
    EXPECT_NE(err.find(c.says), std::string::npos) << c.path << ": " << err;
    EXPECT_EQ(err.find('\n'), std::string::npos) << err;
  }
}

TEST(ScientificFormatsTest, BoundaryCopiesOfAVolumeMeshAreDrawnOnce)
{
  // One quadratic tetrahedron (corners, then edge midpoints in VTK's order),
  // its face 0-1-3 also listed as a quadratic triangle (as gmsh and FE codes
  // write boundaries), and a shell triangle away from it, which stays.
  vtkNew<vtkPoints> points;
  const double c[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  for (const auto& p : c)
  {
    points->InsertNextPoint(p);
  }
  const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
  for (const auto& e : edges)
  {
    points->InsertNextPoint(0.5 * (c[e[0]][0] + c[e[1]][0]), 0.5 * (c[e[0]][1] + c[e[1]][1]),
      0.5 * (c[e[0]][2] + c[e[1]][2]));
  }
  for (const auto& p : { std::array<double, 3>{ 3, 0, 0 }, { 4, 0, 0 }, { 3, 1, 0 }, { 3.5, 0, 0 },
         { 3.5, 0.5, 0 }, { 3, 0.5, 0 } })
  {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  const vtkIdType tet[10] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 };
  grid->InsertNextCell(VTK_QUADRATIC_TETRA, 10, tet);
  const vtkIdType face[6] = { 0, 1, 3, 4, 8, 7 }; // corners 0 1 3, mids 01 13 30
  grid->InsertNextCell(VTK_QUADRATIC_TRIANGLE, 6, face);
  const vtkIdType shell[6] = { 10, 11, 12, 13, 14, 15 };
  grid->InsertNextCell(VTK_QUADRATIC_TRIANGLE, 6, shell);
  Write<vtkXMLUnstructuredGridWriter>(grid, Temp("volume_with_boundary.vtu"));
  // 4 tetrahedron faces + the shell, each tessellated into 4 triangles.
  EXPECT_EQ(Read(Temp("volume_with_boundary.vtu"))->GetNumberOfPolys(), 5 * 4);
}

TEST(ScientificFormatsTest, ExodusReadsEveryElementBlockWithItsVariables)
{
  vtkSmartPointer<vtkPolyData> sphere;
  sphere.TakeReference(shadinglab::datasets::MakeUVSphere(16, 8));
  vtkNew<vtkFloatArray> temperature;
  temperature->SetName("Temperature");
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    temperature->InsertNextValue(static_cast<float>(sphere->GetPoint(i)[2]));
  }
  sphere->GetPointData()->AddArray(temperature);
  vtkNew<vtkAppendFilter> grid;
  grid->AddInputData(sphere);
  grid->Update();
  const std::string path = Temp("sphere.e");
  vtkNew<vtkExodusIIWriter> writer;
  writer->SetInputConnection(grid->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->WriteAllTimeStepsOff();
  ASSERT_EQ(writer->Write(), 1);
  const auto mesh = Read(path);
  EXPECT_EQ(mesh->GetNumberOfPolys(), sphere->GetNumberOfPolys());
  EXPECT_NE(mesh->GetPointData()->GetArray("Temperature"), nullptr) << "nodal variables come along";
  // One state: step 0 reads it, step 1 is refused naming the count.
  shadinglab::ReadOptions step;
  step.timeStep = 0;
  EXPECT_EQ(Read(path, step)->GetNumberOfPolys(), sphere->GetNumberOfPolys());
  step.timeStep = 1;
  EXPECT_NE(ErrorOf(path, step).find("1 step(s)"), std::string::npos) << ErrorOf(path, step);
  // Not netCDF, or netCDF cut short: one line, no library report.
  std::ofstream(Temp("text.exo")) << "not exodus\n";
  EXPECT_NE(ErrorOf(Temp("text.exo")).find("no netCDF signature"), std::string::npos);
  std::ofstream(Temp("cut.e"), std::ios::binary) << std::string("CDF\x01", 4) << "truncated";
  const std::string cut = ErrorOf(Temp("cut.e"));
  EXPECT_NE(cut.find("cut short"), std::string::npos) << cut;

  // Mutations of the valid file that VTK's reader cannot survive, each
  // refused by the header check in one line: nodal results without their
  // names (the library leaves the names unset), a header claiming millions
  // of time steps (minutes of reading before).
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string unnamed = bytes;
  const size_t at = unnamed.find("name_nod_var");
  ASSERT_NE(at, std::string::npos);
  unnamed.replace(at, 12, "name_xyz_var");
  std::ofstream(Temp("unnamed.e"), std::ios::binary) << unnamed;
  const std::string noNames = ErrorOf(Temp("unnamed.e"));
  EXPECT_NE(noNames.find("'num_nod_var' without 'name_nod_var'"), std::string::npos) << noNames;
  std::string records = bytes;
  records[4] = 2; // numrecs, big-endian: 0x02000001 time steps
  std::ofstream(Temp("records.e"), std::ios::binary) << records;
  const std::string tooMany = ErrorOf(Temp("records.e"));
  EXPECT_NE(tooMany.find("records (time steps) in a"), std::string::npos) << tooMany;
}
