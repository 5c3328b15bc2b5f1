// SPDX-License-Identifier: BSD-3-Clause
// Reading and writing surface meshes in every format VTK reads, plus OFF.
#pragma once

#include <stdexcept>
#include <string>

class vtkPolyData;

namespace shadinglab
{

/// A mesh file that cannot be used; what() is one line naming the problem.
struct MeshError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/**
 * Reads INPUT by extension: .vtp, .vtk (any legacy data set), .vtu, .vts,
 * .vtr, .vti (the outer surface; higher-order cells tessellated as ParaView
 * does), .vtm (every block) and .pvd (the first time step's parts),
 * appended into one mesh, .ply, .obj, .stl, .off. Triangle strips are
 * converted to triangles; lines and vertices are dropped.
 * Throws MeshError when the file is missing, unreadable, malformed, empty (no
 * polygon), or has non-finite coordinates. The caller owns the result.
 */
vtkPolyData* ReadMesh(const std::string& path);

/// Writes by extension: .vtp, .vtk, .ply, .obj, .stl, .off. Throws MeshError.
void WriteMesh(vtkPolyData* mesh, const std::string& path);

/// Checks a mesh for use (at least one polygon, finite points); throws MeshError.
void ValidateMesh(vtkPolyData* mesh, const std::string& what);

} // namespace shadinglab
