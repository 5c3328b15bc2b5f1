// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the one mesh entry point (ReadMesh) on arbitrary bytes,
// in the format of SHADINGLAB_FUZZ_EXTENSION. Any outcome but a value or a
// MeshError (a crash, a hang, a sanitizer report, another exception) is a
// finding. For the formats of the fast readers (PLY, STL, OFF, OBJ) the input is
// also read through the checked VTK path: the two must agree, the same
// mesh bit for bit or both a MeshError (differential fuzzing).
#include "FastReaders.h"
#include "MeshIO.h"
#include "../tests/mesh/SameMesh.h"

#include <vtkObject.h>
#include <vtkPolyData.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  static const std::string path = "/tmp/shadinglab-fuzz-" + std::to_string(getpid()) + "." +
    SHADINGLAB_FUZZ_EXTENSION;
  static bool quiet = [] {
    vtkObject::GlobalWarningDisplayOff();
    return true;
  }();
  (void)quiet;
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  auto read = [](bool checked) -> vtkPolyData* {
    if (checked)
    {
      setenv("SHADINGLAB_VTK_READERS", "1", 1);
    }
    vtkPolyData* mesh = nullptr;
    try
    {
      mesh = shadinglab::ReadMesh(path);
      // A mesh that was accepted must be usable: valid by the same check.
      shadinglab::ValidateMesh(mesh, "fuzzed mesh");
    }
    catch (const shadinglab::MeshError&)
    {
      // The expected answer to bad input: a one-line error.
    }
    unsetenv("SHADINGLAB_VTK_READERS");
    return mesh;
  };
  vtkPolyData* fast = read(false);
  const std::string ext = SHADINGLAB_FUZZ_EXTENSION;
  if (ext == "ply" || ext == "stl" || ext == "off" || ext == "obj")
  {
    vtkPolyData* checked = read(true);
    const std::string difference = fast && checked ? shadinglab::test::MeshDifference(fast, checked)
      : (!fast) != (!checked)                      ? "one path read it, the other refused it"
                                                   : "";
    if (!difference.empty())
    {
      std::fprintf(stderr, "fast and checked readers differ: %s\n", difference.c_str());
      std::abort();
    }
    if (checked)
    {
      checked->Delete();
    }
  }
  if (fast)
  {
    fast->Delete();
  }
  return 0;
}
