// SPDX-License-Identifier: BSD-3-Clause
// shadinglab_make_datasets DIR: writes the synthetic datasets shipped in
// datasets/. Deterministic: the same build writes the same meshes.
#include "AnalyticMeshes.h"
#include "MeshIO.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <functional>
#include <iostream>
#include <string>

using namespace shadinglab;
using namespace shadinglab::datasets;

namespace
{
void Write(vtkPolyData* raw, const std::string& dir, const std::string& name, bool triangulate = false)
{
  vtkSmartPointer<vtkPolyData> mesh;
  mesh.TakeReference(raw);
  if (triangulate)
  {
    vtkNew<vtkTriangleFilter> tri;
    tri->SetInputData(mesh);
    tri->Update();
    mesh = tri->GetOutput();
  }
  const std::string path = dir + "/" + name;
  WriteMesh(mesh, path);
  std::cout << path << ": " << mesh->GetNumberOfPoints() << " points, "
            << mesh->GetNumberOfPolys() << " polygons\n";
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::cerr << "usage: shadinglab_make_datasets DIR\n";
    return 2;
  }
  const std::string dir = argv[1];
  try
  {
    for (int res : { 16, 32, 64 })
    {
      Write(MakeUVSphere(res, res / 2), dir,
        "uv_sphere_" + std::to_string(res) + "x" + std::to_string(res / 2) + ".vtp");
      Write(MakeEllipsoid(1.5, 1.0, 0.7, res, res / 2), dir,
        "ellipsoid_" + std::to_string(res) + "x" + std::to_string(res / 2) + ".vtp");
    }
    for (int level = 1; level <= 4; ++level)
    {
      Write(MakeIcosphere(level), dir, "icosphere_" + std::to_string(level) + ".vtp");
    }
    for (int res : { 24, 48, 96 })
    {
      Write(MakeTorus(1.0, 0.4, res, res / 2), dir,
        "torus_" + std::to_string(res) + "x" + std::to_string(res / 2) + ".vtp");
    }
    Write(MakeLowPolyCylinder(8), dir, "cylinder_8.vtp");
    Write(MakeLowPolyCylinder(8), dir, "cylinder_8.stl", true);
    Write(MakeUVSphere(8, 6), dir, "sphere_lowpoly.ply");
    Write(MakeCorrugatedPlane(8, 4, 0.08), dir, "corrugated_plane.obj");
    Write(MakeQuadStrip(12), dir, "quad_strip.vtk");
    Write(MakeTJunctionPatch(4), dir, "t_junctions.off");
    Write(MakeMetaballIsosurface(48), dir, "metaballs_isosurface.vtp");
    Write(MakeTerrain(96), dir, "terrain.vtp");
    Write(MakeRecedingPlane(8.0), dir, "receding_plane.vtp");
  }
  catch (const MeshError& e)
  {
    std::cerr << "shadinglab_make_datasets: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
