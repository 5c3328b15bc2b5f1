// SPDX-License-Identifier: BSD-3-Clause
// Reading and writing surface meshes in every format VTK reads, plus OFF.
#pragma once

#include <stdexcept>
#include <limits>
#include <string>
#include <vector>

class vtkPolyData;

namespace shadinglab
{

/// A mesh file that cannot be used; what() is one line naming the problem.
struct MeshError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Most tessellation levels of a higher-order face: ParaView's Nonlinear
/// Subdivision Level stops at 4 too (a quadratic triangle becomes 4^4 = 256
/// triangles there; more only multiplies the memory).
constexpr int kMaxNonlinearSubdivisionLevel = 4;

/// How files are turned into surfaces.
struct ReadOptions
{
  /// Each higher-order (quadratic) face is split this many times, as
  /// ParaView's Surface does with its Nonlinear Subdivision Level (default
  /// 1 there too); 0 draws the corner nodes' linear face.
  int nonlinearSubdivisionLevel = 1;
  /// A time series (.pvd, Exodus II): the step to read, by its time value
  /// (the last step at or before it, as ParaView snaps a requested time;
  /// NaN: not asked) or by its index from 0 (-1: not asked). At most one;
  /// neither reads the first step. A time outside the file's span, an index
  /// past its last step, or either on a file without time steps is refused.
  double time = std::numeric_limits<double>::quiet_NaN();
  int timeStep = -1;
};

/// The step `options` asks of a series with `times` (sorted ascending):
/// its index, or a MeshError naming the span for `what`.
size_t ChooseTimeStep(const std::vector<double>& times, const ReadOptions& options,
  const std::string& what);

/**
 * Reads INPUT by extension: .vtp, .vtk (any legacy data set), .vtu, .vts,
 * .vtr, .vti (the outer surface; higher-order cells tessellated as ParaView
 * does), .vtm (every block) and .pvd (the first time step's parts),
 * appended into one mesh, Exodus II (.e .exo .ex2, classic netCDF), .ply,
 * .obj, .stl, .off. Triangle strips are
 * converted to triangles; lines and vertices are dropped.
 * Throws MeshError when the file is missing, unreadable, malformed, empty (no
 * polygon), or has non-finite coordinates, or when `options` are out of
 * range. The caller owns the result.
 */
vtkPolyData* ReadMesh(const std::string& path, const ReadOptions& options = {});

/// The extensions ReadMesh reads, without the dot, in the order help lists
/// them: the one list of the CLI's help, its error for an unknown
/// extension and the explorer's File > Open filter.
const std::vector<std::string>& ReadableExtensions();
/// ReadableExtensions as ".vtp .vtk ...".
std::string ReadableExtensionsText();

/// Writes by extension: .vtp, .vtk, .ply, .obj, .stl, .off. Throws MeshError.
void WriteMesh(vtkPolyData* mesh, const std::string& path);

/// Checks a mesh for use (at least one polygon, finite points); throws MeshError.
void ValidateMesh(vtkPolyData* mesh, const std::string& what);

/// ValidateMesh, its walk over every cell's ids left out when `checkCells`
/// is false: for the fast readers' meshes, whose cells were checked as
/// they were parsed (the walk is ~0.1 s of a 16M-triangle mesh).
void ValidateMeshCells(vtkPolyData* mesh, const std::string& what, bool checkCells);

} // namespace shadinglab
