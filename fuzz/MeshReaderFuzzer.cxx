// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the one mesh entry point (ReadMesh) on arbitrary bytes,
// in the format of SHADINGLAB_FUZZ_EXTENSION. Any outcome but a value or a
// MeshError (a crash, a hang, a sanitizer report, another exception) is a
// finding.
#include "MeshIO.h"

#include <vtkObject.h>
#include <vtkPolyData.h>

#include <cstdint>
#include <cstdio>
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
  try
  {
    vtkPolyData* mesh = shadinglab::ReadMesh(path);
    // A mesh that was accepted must be usable: valid by the same check.
    shadinglab::ValidateMesh(mesh, "fuzzed mesh");
    mesh->Delete();
  }
  catch (const shadinglab::MeshError&)
  {
    // The expected answer to bad input: a one-line error.
  }
  return 0;
}
