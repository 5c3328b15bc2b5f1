// SPDX-License-Identifier: BSD-3-Clause
// Checks of a mesh file made before a VTK reader sees it: VTK 9.2's OBJ,
// PLY and STL readers crash, hang or silently drop data on some malformed
// files (indices out of range, a byte-order mark, truncated data, element
// counts far beyond the file's size, missing coordinates). Each function
// reads the file once, allocates nothing proportional to the counts its
// header claims, and throws MeshError with one line naming the problem.
#pragma once

#include <string>

namespace shadinglab
{

/// OBJ: no byte-order mark; every `v` has three finite numbers; every
/// `f`/`l`/`p` index is an integer, not 0, within the vertices (negative
/// ones relative to the vertices read so far); faces have >= 3 vertices.
void PrecheckObj(const std::string& path);

/// PLY (ASCII and binary): a complete header with element counts in range,
/// a vertex element with x, y and z, data present for every row, list
/// counts in range, face indices within the vertices.
void PrecheckPly(const std::string& path);

/// STL: binary files hold exactly 84 + 50 n bytes for their n triangles;
/// ASCII files have complete facets and end with `endsolid`.
void PrecheckStl(const std::string& path);
/// Legacy .vtk (LegacyVtkCheck.cxx): the whole file walked the way
/// vtkDataReader reads it; every section complete, every value of its type,
/// cells well formed with indices within the points, attribute arrays as
/// long as the points or cells they describe (VTK's reader crashed on a
/// value that failed to parse and allocated gigabytes for an 84-byte file
/// claiming 2e9 points: both found by fuzz/MeshReaderFuzzer).
void PrecheckLegacyVtk(const std::string& path);

/// VTK XML .vtp/.vtu (XmlVtkCheck.cxx): well-formed XML of the `type`
/// ("PolyData", "UnstructuredGrid"); every DataArray's header (size or
/// compression blocks) matches its piece and the bytes present; offsets,
/// connectivity and cell types decoded and consistent.
void PrecheckXmlVtk(const std::string& path, const std::string& type);

/// Exodus II (NetcdfCheck.cxx): a netCDF classic header (CDF-1, -2, -5)
/// whose counts, names and fixed-size variables all lie within the file.
void PrecheckNetcdfClassic(const std::string& path);


} // namespace shadinglab
