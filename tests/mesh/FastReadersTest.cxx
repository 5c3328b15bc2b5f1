// SPDX-License-Identifier: BSD-3-Clause
// The fast readers (mesh/io/FastReaders.h) against VTK's readers (and the
// checked OFF reader) on generated meshes of every format they take: the
// same points, cells and arrays bit for bit, and the fast path really
// taken. The bad-input corpus is compared by FastReadersCorpusCheck.
#include "FastReaders.h"
#include "MeshIO.h"
#include "SameMesh.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkPLYWriter.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

namespace
{

using shadinglab::MeshError;

std::string Scratch(const std::string& name)
{
  return (testing::TempDir().empty() ? std::string("/tmp/") : testing::TempDir()) + "fastread_" +
    std::to_string(::getpid()) + "_" + name;
}

/// ReadMesh through the checked VTK path.
vtkSmartPointer<vtkPolyData> ReadChecked(const std::string& path)
{
  ::setenv("SHADINGLAB_VTK_READERS", "1", 1);
  vtkSmartPointer<vtkPolyData> mesh;
  mesh.TakeReference(shadinglab::ReadMesh(path));
  ::unsetenv("SHADINGLAB_VTK_READERS");
  return mesh;
}

/// Reads `path` both ways; expects the fast path to take it and both to
/// give the same mesh.
void ExpectSameAsVtk(const std::string& path, const std::string& ext)
{
  SCOPED_TRACE(path);
  ASSERT_TRUE(shadinglab::FastReadersEnabled());
  ASSERT_NE(shadinglab::ReadFast(path, ext), nullptr) << "the fast path left this file to VTK";
  vtkSmartPointer<vtkPolyData> fast;
  fast.TakeReference(shadinglab::ReadMesh(path));
  const vtkSmartPointer<vtkPolyData> checked = ReadChecked(path);
  ASSERT_GT(fast->GetNumberOfPolys(), 0);
  EXPECT_EQ(shadinglab::test::MeshDifference(fast, checked), "");
  // Ids that fit in 32 bits are held in 32-bit storage (half the memory).
  EXPECT_FALSE(fast->GetPolys()->IsStorage64Bit());
}

vtkSmartPointer<vtkPolyData> Sphere(bool withArrays)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(23);
  sphere->SetRadius(1.7);
  sphere->SetCenter(0.25, -3.5, 1e3); // coordinates whose float rounding shows
  sphere->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(sphere->GetOutput());
  if (!withArrays)
  {
    mesh->GetPointData()->Initialize();
    return mesh;
  }
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    rgb->SetTuple3(i, static_cast<double>(i % 256), static_cast<double>((7 * i) % 256), 200);
  }
  mesh->GetPointData()->SetScalars(rgb);
  return mesh;
}

/// A plane of quads, each quad a polygon of four vertices.
vtkSmartPointer<vtkPolyData> Quads()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(9, 6);
  plane->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(plane->GetOutput());
  mesh->GetPointData()->Initialize();
  return mesh;
}

void WritePly(vtkPolyData* mesh, const std::string& path, int type, bool colours)
{
  vtkNew<vtkPLYWriter> w;
  w->SetInputData(mesh);
  w->SetFileName(path.c_str());
  w->SetFileType(type == 0 ? VTK_ASCII : VTK_BINARY);
  if (type == 2)
  {
    w->SetDataByteOrderToBigEndian();
  }
  else
  {
    w->SetDataByteOrderToLittleEndian();
  }
  if (colours)
  {
    w->SetArrayName("RGB");
    w->SetColorModeToDefault();
  }
  ASSERT_EQ(w->Write(), 1);
}

void WriteText(const std::string& path, const std::string& text)
{
  std::ofstream out(path, std::ios::binary);
  out << text;
}

TEST(FastReadersTest, PlyOfEveryEncodingEqualsVtks)
{
  const char* names[] = { "ascii", "le", "be" };
  for (int type = 0; type < 3; ++type)
  {
    for (bool arrays : { false, true })
    {
      const std::string path = Scratch(std::string("sphere_") + names[type] + (arrays ? "_rgb" : "") + ".ply");
      WritePly(Sphere(arrays), path, type, arrays);
      ExpectSameAsVtk(path, "ply");
    }
    const std::string quads = Scratch(std::string("quads_") + names[type] + ".ply");
    WritePly(Quads(), quads, type, false);
    ExpectSameAsVtk(quads, "ply");
  }
}

// A scan's body of triangle records, 2^16 faces or more, is parsed by two
// threads (FastPly.cxx, ReadTriangleRecords): the same mesh as VTK's
// reader; a quad in the second half, or an index beyond the vertices,
// sends it to the serial loop, which reads the quad and refuses the index.
TEST(FastReadersTest, BigTriangleBodiesReadOnTwoThreadsAsVtkDoes)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(300);
  sphere->SetPhiResolution(150); // 89,400 triangles
  sphere->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(sphere->GetOutput());
  mesh->GetPointData()->Initialize();
  ASSERT_GT(mesh->GetNumberOfPolys(), 1 << 16);
  const std::string triangles = Scratch("big_triangles.ply");
  WritePly(mesh, triangles, 1, false);
  ExpectSameAsVtk(triangles, "ply");

  // The last triangle replaced by a quad over its three vertices and one more.
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> ids;
  const vtkIdType n = mesh->GetNumberOfPolys();
  for (vtkIdType c = 0; c < n; ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, ids);
    if (c == n - 1)
    {
      ids->InsertNextId(0);
    }
    polys->InsertNextCell(ids);
  }
  auto withQuad = vtkSmartPointer<vtkPolyData>::New();
  withQuad->SetPoints(mesh->GetPoints());
  withQuad->SetPolys(polys);
  const std::string quad = Scratch("big_with_quad.ply");
  WritePly(withQuad, quad, 1, false);
  ExpectSameAsVtk(quad, "ply");

  // An index beyond the vertices in the second half: refused with its line.
  std::ifstream in(triangles, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const int32_t beyond = static_cast<int32_t>(mesh->GetNumberOfPoints());
  std::memcpy(&bytes[bytes.size() - 13 * 10 + 1], &beyond, 4); // 10th face from the end
  const std::string bad = Scratch("big_bad_index.ply");
  WriteText(bad, bytes);
  EXPECT_EQ(shadinglab::ReadFast(bad, "ply"), nullptr);
  try
  {
    vtkSmartPointer<vtkPolyData> read;
    read.TakeReference(shadinglab::ReadMesh(bad));
    ADD_FAILURE() << "read a face with an index outside the vertices";
  }
  catch (const MeshError& e)
  {
    EXPECT_NE(std::string(e.what()).find("outside"), std::string::npos) << e.what();
  }
}

TEST(FastReadersTest, PlyWithOtherTypesElementsAndPropertiesEqualsVtks)
{
  // double coordinates after an extra property, normals, uint counts and
  // ushort indices, a face property VTK skips, an element it skips, a
  // pentagon and a quad.
  std::string body;
  auto put = [&body](const auto& v) { body.append(reinterpret_cast<const char*>(&v), sizeof v); };
  const double xyz[6][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1.5, 1, 0 }, { 0.5, 1.7, 0.1 }, { -0.5, 1, 0 }, { 0.1, 0.1, 1 } };
  for (int i = 0; i < 6; ++i)
  {
    put(static_cast<float>(0.25 * i)); // confidence
    put(xyz[i][0]);
    put(xyz[i][1]);
    put(xyz[i][2]);
    put(static_cast<float>(0.0f));
    put(static_cast<float>(0.6f));
    put(static_cast<float>(0.8f));
  }
  put(static_cast<uint8_t>(9));
  put(static_cast<uint32_t>(5));
  for (uint16_t v : { 0, 1, 2, 3, 4 })
  {
    put(v);
  }
  put(static_cast<uint8_t>(3));
  put(static_cast<uint32_t>(4));
  for (uint16_t v : { 0, 1, 5, 4 })
  {
    put(v);
  }
  put(static_cast<int32_t>(42)); // the edge element's row
  const std::string header = "ply\nformat binary_little_endian 1.0\ncomment made by FastReadersTest\n"
                             "element vertex 6\nproperty float confidence\nproperty double x\n"
                             "property double y\nproperty double z\nproperty float nx\nproperty float ny\n"
                             "property float nz\nelement face 2\nproperty uchar flags\n"
                             "property list uint ushort vertex_indices\nelement edge 1\nproperty int id\n"
                             "end_header\n";
  const std::string path = Scratch("mixed.ply");
  WriteText(path, header + body);
  ExpectSameAsVtk(path, "ply");
}

TEST(FastReadersTest, StlBinaryAndAsciiWeldAsVtkDoes)
{
  for (int type : { VTK_BINARY, VTK_ASCII })
  {
    const std::string path = Scratch(type == VTK_BINARY ? "sphere_bin.stl" : "sphere_ascii.stl");
    vtkNew<vtkSTLWriter> w;
    w->SetInputData(Sphere(false));
    w->SetFileName(path.c_str());
    w->SetFileType(type);
    ASSERT_EQ(w->Write(), 1);
    ExpectSameAsVtk(path, "stl");
  }
  // -0 welds with +0; triangles whose corners weld into two are dropped.
  const std::string path = Scratch("weld.stl");
  WriteText(path,
    "solid weld\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"
    "  endloop\n endfacet\n facet normal 0 0 1\n  outer loop\n   vertex -0 1 0\n   vertex 1 0 0\n"
    "   vertex 1 1 -0.0\n  endloop\n endfacet\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
    "   vertex -0.0 0 0\n   vertex 0 1 0\n  endloop\n endfacet\n facet normal 0 0 1\n  outer loop\n"
    "   vertex 0 0 0\n   vertex 1 0 0\n   vertex 1 0 -0\n  endloop\n endfacet\nendsolid weld\n");
  ExpectSameAsVtk(path, "stl");
  vtkSmartPointer<vtkPolyData> mesh;
  mesh.TakeReference(shadinglab::ReadMesh(path));
  EXPECT_EQ(mesh->GetNumberOfPoints(), 4);
  EXPECT_EQ(mesh->GetNumberOfPolys(), 2);
}

TEST(FastReadersTest, OffEqualsTheCheckedReader)
{
  const std::string written = Scratch("sphere.off");
  shadinglab::WriteMesh(Sphere(false), written);
  ExpectSameAsVtk(written, "off");
  const std::string path = Scratch("comments.off");
  WriteText(path, "# a comment first\nOFF\n\n5 2 0 # counts\n0 0 0\n1 0 0 \n1 1 0\n0 1 0\n"
                  "# between\n0.5 0.5 1e-1\n4 0 1 2 3 255 0 0\n3 0 1 4\n");
  ExpectSameAsVtk(path, "off");
}

TEST(FastReadersTest, ObjEqualsVtks)
{
  const std::string written = Scratch("sphere.obj");
  vtkNew<vtkOBJWriter> w;
  w->SetInputData(Sphere(false));
  w->SetFileName(written.c_str());
  ASSERT_EQ(w->Write(), 1);
  ExpectSameAsVtk(written, "obj");
  // Groups before the first face, comments, blank lines, a quad.
  const std::string grouped = Scratch("grouped.obj");
  WriteText(grouped, "# made by FastReadersTest\nv 0 0 0\nv 1 0 0\nv 1 1 0.5\n\nv 0 1 1e-3\ng first\n"
                     "f 1 2 3\ng second part\nf 1 3 4\ng\n  f 2 3 4 1 \n");
  ExpectSameAsVtk(grouped, "obj");
  // A face before any group: VTK raises its group id from -1 to 0 there.
  const std::string early = Scratch("early.obj");
  WriteText(early, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\ng later\nf 1 3 4\n");
  ExpectSameAsVtk(early, "obj");
}

TEST(FastReadersTest, LeavesWhatItDoesNotReadToTheCheckedPath)
{
  // Texture coordinates become an array in VTK's reader: not the fast path's.
  const std::string uv = Scratch("uv.ply");
  WriteText(uv, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nproperty float u\nproperty float v\nelement face 1\n"
                "property list uchar int vertex_indices\nend_header\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n");
  EXPECT_EQ(shadinglab::ReadFast(uv, "ply"), nullptr);
  const std::string slashed = Scratch("slashed.obj");
  WriteText(slashed, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n");
  EXPECT_EQ(shadinglab::ReadFast(slashed, "obj"), nullptr);
  // An index with a leading zero: VTK 9.2 reads 032 as 32, VTK 9.4 on as
  // a prefixed number it refuses (found by the OBJ fuzzer on Debian 13).
  // Whatever the VTK, the fast path leaves it to VTK, so both paths agree.
  const std::string zeroLed = Scratch("zero_led.obj");
  WriteText(zeroLed, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 04 3\n");
  EXPECT_EQ(shadinglab::ReadFast(zeroLed, "obj"), nullptr);
  const std::string zeroLedAtEnd = Scratch("zero_led_end.obj");
  WriteText(zeroLedAtEnd, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 03");
  EXPECT_EQ(shadinglab::ReadFast(zeroLedAtEnd, "obj"), nullptr);
  // Bad files too: the checked path names their problem.
  const std::string bad = Scratch("bad_index.ply");
  WriteText(bad, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                 "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  EXPECT_EQ(shadinglab::ReadFast(bad, "ply"), nullptr);
  try
  {
    vtkSmartPointer<vtkPolyData> mesh;
    mesh.TakeReference(shadinglab::ReadMesh(bad));
    ADD_FAILURE() << "read a face with an index outside the vertices";
  }
  catch (const MeshError& e)
  {
    EXPECT_NE(std::string(e.what()).find("vertex index 7 outside 0..2"), std::string::npos) << e.what();
  }
  // Counts beyond the file: refused before any allocation for them.
  const std::string huge = Scratch("huge.ply");
  WriteText(huge, "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\n"
                  "property float y\nproperty float z\nelement face 2000000000\n"
                  "property list uchar int vertex_indices\nend_header\n");
  EXPECT_EQ(shadinglab::ReadFast(huge, "ply"), nullptr);
}

} // namespace
