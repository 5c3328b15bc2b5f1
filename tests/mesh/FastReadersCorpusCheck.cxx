// SPDX-License-Identifier: BSD-3-Clause
// Every .ply, .stl, .off and .obj file of a folder (the bad-input corpus) read
// through the fast readers and through the checked VTK path: both must
// refuse it with the same one line, or give the same mesh bit for bit.
//
//   shadinglab_fastread_corpus DIR   (exit 0: all agree; 1: a difference)
#include "FastReaders.h"
#include "MeshIO.h"
#include "SameMesh.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace
{

/// The mesh, or the error's message (mesh null).
vtkSmartPointer<vtkPolyData> Read(const std::string& path, bool checked, std::string& error)
{
  if (checked)
  {
    ::setenv("SHADINGLAB_VTK_READERS", "1", 1);
  }
  vtkSmartPointer<vtkPolyData> mesh;
  try
  {
    mesh.TakeReference(shadinglab::ReadMesh(path));
  }
  catch (const shadinglab::MeshError& e)
  {
    error = e.what();
  }
  ::unsetenv("SHADINGLAB_VTK_READERS");
  return mesh;
}

} // namespace

int main(int argc, char** argv)
{
  if (argc != 2 || !std::filesystem::is_directory(argv[1]))
  {
    std::fprintf(stderr, "usage: shadinglab_fastread_corpus DIR\n");
    return 2;
  }
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(argv[1]))
  {
    const std::string ext = entry.path().extension().string();
    if (ext == ".ply" || ext == ".stl" || ext == ".off" || ext == ".obj")
    {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  int differences = 0, readFast = 0, refused = 0;
  for (const std::string& path : files)
  {
    std::string fastError, checkedError;
    const auto fast = Read(path, false, fastError);
    const auto checked = Read(path, true, checkedError);
    const std::string ext = path.substr(path.rfind('.') + 1);
    readFast += shadinglab::ReadFast(path, ext) != nullptr;
    std::string d;
    if (!fast || !checked)
    {
      refused += !fast && !checked;
      d = fastError == checkedError ? "" : "fast: '" + fastError + "' checked: '" + checkedError + "'";
    }
    else
    {
      d = shadinglab::test::MeshDifference(fast, checked);
    }
    if (!d.empty())
    {
      std::printf("DIFFERENT %s: %s\n", path.c_str(), d.c_str());
      ++differences;
    }
  }
  std::printf("%zu files: %d read by the fast path, %d refused by both alike, %d different\n",
    files.size(), readFast, refused, differences);
  return files.empty() || differences > 0 ? 1 : 0;
}
