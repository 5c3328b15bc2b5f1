// SPDX-License-Identifier: BSD-3-Clause
// Files that list other files: a multiblock .vtm (every data set, nested
// blocks included) and a ParaView collection .pvd (the data sets of its
// first time step). Each listed file is read by ReadMesh's own path, with
// its pre-checks, and the surfaces are appended into one mesh.
#pragma once

#include <string>

#include "MeshIO.h"

#include <vtkSmartPointer.h>

class vtkDataSet;
class vtkPolyData;

namespace shadinglab
{

/// Deepest nesting of listing files (a .vtm naming a .vtm ...): a file
/// that names itself stops here instead of recursing without end.
constexpr int kMaxListingDepth = 4;
/// Most files one listing may name (ParaView's largest multiblock
/// examples have hundreds of blocks; a million-line listing is an attack).
constexpr int kMaxListedFiles = 100000;

/// ReadMesh at nesting depth `depth` (0 for the user's file).
vtkPolyData* ReadMeshAt(const std::string& path, const ReadOptions& options, int depth);

/// Reads a .vtm (`collection` false) or .pvd (true); throws MeshError.
vtkSmartPointer<vtkPolyData> ReadListing(
  const std::string& path, bool collection, const ReadOptions& options, int depth);

/// Reads an Exodus II file (.e, .exo, .ex2): every element block at the
/// first time step, with every nodal and element variable, as ParaView
/// opens it; the outer surface of each block, appended. Classic netCDF
/// files only, their header checked first (PrecheckNetcdfClassic).
/// Throws MeshError.
vtkSmartPointer<vtkPolyData> ReadExodus(const std::string& path, const ReadOptions& options);

/// The outer surface of a data set (polydata as is), as ParaView's Surface
/// representation shows it: higher-order cells tessellated
/// `options.nonlinearSubdivisionLevel` times (defined with ReadMesh; shared
/// with the listing and Exodus readers).
vtkSmartPointer<vtkPolyData> SurfaceOf(vtkDataSet* data, const ReadOptions& options);

} // namespace shadinglab
