// SPDX-License-Identifier: BSD-3-Clause
// VTK XML files (.vtp, .vtu) through the one mesh entry point: every data
// mode (ascii, inline binary, appended raw and base64), compressor (none,
// zlib, LZ4, LZMA) and header type VTK's writers produce is read with its
// arrays; every truncation and every corrupted block header is refused
// with a one-line MeshError (the check of XmlVtkCheck.cxx), never a crash.
#include "MeshIO.h"

#include <vtkAppendFilter.h>
#include <vtkElevationFilter.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

namespace
{

vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(24);
  source->SetPhiResolution(12);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(source->GetOutputPort());
  elevation->Update();
  return vtkPolyData::SafeDownCast(elevation->GetOutputDataObject(0));
}

enum class Mode
{
  Ascii,
  Binary,
  AppendedRaw,
  AppendedBase64
};

/// Writes the sphere (.vtp) or its unstructured copy (.vtu) in one flavour;
/// small blocks so that compressed arrays span several.
template<typename Writer>
std::string Write(vtkDataObject* data,
  const std::string& name,
  Mode mode,
  int compressor,
  bool header64)
{
  // Own names per process: ctest runs these tests in parallel processes.
  const std::string path =
    ::testing::TempDir() + "/shadinglab_xml_" + std::to_string(getpid()) + "_" + name;
  vtkNew<Writer> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  switch (mode)
  {
    case Mode::Ascii:
      writer->SetDataModeToAscii();
      break;
    case Mode::Binary:
      writer->SetDataModeToBinary();
      break;
    case Mode::AppendedRaw:
    case Mode::AppendedBase64:
      writer->SetDataModeToAppended();
      writer->SetEncodeAppendedData(mode == Mode::AppendedBase64);
      break;
  }
  writer->SetCompressorType(compressor);
  header64 ? writer->SetHeaderTypeToUInt64() : writer->SetHeaderTypeToUInt32();
  writer->SetBlockSize(1024);
  EXPECT_EQ(writer->Write(), 1) << path;
  return path;
}

std::string Contents(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return { std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
}

std::string ErrorOf(const std::string& path)
{
  try
  {
    vtkSmartPointer<vtkPolyData> mesh;
    mesh.TakeReference(shadinglab::ReadMesh(path));
    shadinglab::ValidateMesh(mesh, "test");
  }
  catch (const shadinglab::MeshError& e)
  {
    return e.what();
  }
  return {};
}

constexpr int kCompressors[] = { vtkXMLWriterBase::NONE,
  vtkXMLWriterBase::ZLIB,
  vtkXMLWriterBase::LZ4,
  vtkXMLWriterBase::LZMA };

} // namespace

TEST(XmlVtkTest, EveryWriterFlavourIsRead)
{
  auto sphere = Sphere();
  vtkNew<vtkAppendFilter> append;
  append->SetInputData(sphere);
  append->Update();
  int files = 0;
  for (Mode mode : { Mode::Ascii, Mode::Binary, Mode::AppendedRaw, Mode::AppendedBase64 })
  {
    for (int compressor : kCompressors)
    {
      for (bool header64 : { false, true })
      {
        const std::string tag = std::to_string(static_cast<int>(mode)) + "_" +
          std::to_string(compressor) + (header64 ? "_64" : "_32");
        for (const std::string& path :
          { Write<vtkXMLPolyDataWriter>(sphere, tag + ".vtp", mode, compressor, header64),
            Write<vtkXMLUnstructuredGridWriter>(
              append->GetOutput(), tag + ".vtu", mode, compressor, header64) })
        {
          SCOPED_TRACE(path);
          vtkSmartPointer<vtkPolyData> mesh;
          ASSERT_NO_THROW(mesh.TakeReference(shadinglab::ReadMesh(path)));
          EXPECT_EQ(mesh->GetNumberOfPolys(), sphere->GetNumberOfPolys());
          EXPECT_NE(mesh->GetPointData()->GetArray("Elevation"), nullptr);
          std::remove(path.c_str());
          ++files;
        }
      }
    }
  }
  EXPECT_EQ(files, 64);
}

TEST(XmlVtkTest, EveryTruncationIsRefused)
{
  // 48 cuts of a binary flavour of each compressor: the XML cannot close,
  // or a block lacks its bytes; both are one-line errors.
  auto sphere = Sphere();
  for (Mode mode : { Mode::Binary, Mode::AppendedRaw, Mode::AppendedBase64 })
  {
    for (int compressor : kCompressors)
    {
      const std::string path =
        Write<vtkXMLPolyDataWriter>(sphere, "cut.vtp", mode, compressor, false);
      const std::string whole = Contents(path);
      for (int cut = 0; cut < 48; ++cut)
      {
        std::ofstream(path, std::ios::binary | std::ios::trunc)
          .write(whole.data(), static_cast<std::streamsize>(whole.size() * cut / 48));
        const std::string error = ErrorOf(path);
        EXPECT_FALSE(error.empty())
          << "mode " << static_cast<int>(mode) << " compressor " << compressor << " cut " << cut;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
      }
      std::remove(path.c_str());
    }
  }
}

TEST(XmlVtkTest, CorruptBlockHeadersAreNamed)
{
  // Appended raw data: the first array's header sits right after the '_'.
  // Overwrite its first word (the byte count, or the block count when
  // compressed) with a huge value.
  auto sphere = Sphere();
  for (int compressor : kCompressors)
  {
    const std::string path =
      Write<vtkXMLPolyDataWriter>(sphere, "corrupt.vtp", Mode::AppendedRaw, compressor, false);
    std::string bytes = Contents(path);
    const size_t data = bytes.find('_', bytes.find("<AppendedData"));
    ASSERT_NE(data, std::string::npos);
    const unsigned char huge[4] = { 0xff, 0xff, 0xff, 0x7f };
    std::memcpy(&bytes[data + 1], huge, 4);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    const std::string error = ErrorOf(path);
    EXPECT_NE(
      error.find(compressor == vtkXMLWriterBase::NONE ? "its header says" : "compression header"),
      std::string::npos)
      << error;
    std::remove(path.c_str());
  }
}
