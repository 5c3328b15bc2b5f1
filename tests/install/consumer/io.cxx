// SPDX-License-Identifier: BSD-3-Clause
// The IO component: reads the mesh named on the command line and prints its
// triangle count.
#include "MeshIO.h"

#include <vtkPolyData.h>

#include <iostream>

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::cerr << "usage: consumer MESH\n";
    return 2;
  }
  vtkPolyData* mesh = shadinglab::ReadMesh(argv[1]);
  std::cout << "shadinglab read " << mesh->GetNumberOfPolys() << " polygons\n";
  const bool ok = mesh->GetNumberOfPolys() > 0;
  mesh->Delete();
  return ok ? 0 : 1;
}
