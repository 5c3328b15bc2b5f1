// SPDX-License-Identifier: BSD-3-Clause
// vtkPolyData polygons -> flat arrays for the mesh/core algorithms, without
// copying when the data already has the right layout (double points, 64-bit
// cell array storage).
#pragma once

#include "Geometry.h"

#include <cstdint>
#include <vector>

#include <vtkSmartPointer.h>

class vtkCellArray;
class vtkPolyData;

namespace shadinglab::mesh
{

/// A MeshView of a vtkPolyData, viewing its arrays in place where it can.
struct FlatPolygons : MeshView
{
  // Storage, used only when the input could not be viewed in place.
  std::vector<double> pointStorage;
  std::vector<int64_t> offsetStorage;
  std::vector<int64_t> connectivityStorage;
};

/// Views (or copies) points and polygons of a polydata. Strips must have
/// been triangulated by the caller. The polydata must outlive the result.
/// Without `withPoints` the points are left out (null), for algorithms of
/// the connectivity alone: float points are then not copied to double.
void FlatPolygonsFromPolyData(vtkPolyData* input, FlatPolygons& out, bool withPoints = true);

/// The input itself when it has no triangle strips, else a copy with the
/// strips triangulated (lines and vertices kept when `keepLinesAndVerts`).
vtkSmartPointer<vtkPolyData> WithoutStrips(vtkPolyData* input, bool keepLinesAndVerts);

/// The input itself when every polygon is convex, else a copy whose concave
/// polygons are replaced by their ear-clipped triangles
/// (TriangulatePolygon), each with its polygon's cell data: what a fan
/// triangulation (VTK's OpenGL mapper) draws correctly. `split`: how many
/// polygons were.
vtkSmartPointer<vtkPolyData> WithConcavePolygonsSplit(vtkPolyData* input, int64_t* split = nullptr);

/// The input's polygons viewed in place as 32-bit ids, when its cell array
/// has 32-bit storage (the fast readers' whenever the ids fit): true, with
/// `out`'s points null (the caller sets them); else false, `out` untouched.
bool NarrowPolygonsOf(vtkPolyData* input, NarrowMeshView& out);

/// The inverse: a cell array holding `numberOfPolygons` polygons given as
/// offsets (numberOfPolygons + 1 entries, or none for no polygon) and
/// connectivity, copied.
vtkSmartPointer<vtkCellArray> CellArrayFromFlat(const int64_t* offsets,
  int64_t numberOfPolygons, const int64_t* connectivity);
/// The same from 32-bit offsets, into 32-bit storage (every id must fit).
vtkSmartPointer<vtkCellArray> CellArrayFromFlat(const int32_t* offsets,
  int64_t numberOfPolygons, const int64_t* connectivity);

/// Whether two of the input's polygons run a shared edge the same way
/// (Orientation.h HasInconsistentOrientation).
bool InconsistentlyOriented(vtkPolyData* input);

/// A shallow copy of the input with the polygons flagged in `flips` (one
/// per polygon) reversed.
vtkSmartPointer<vtkPolyData> WithPolygonsTurned(vtkPolyData* input, const std::vector<uint8_t>& flips);

/// The input itself when its polygons are consistently oriented, else a
/// shallow copy whose polygons are turned so that they are
/// (Orientation.h: per component, outward when closed). Strips must have
/// been triangulated by the caller. The input is not modified.
vtkSmartPointer<vtkPolyData> ConsistentlyOriented(vtkPolyData* input);

/// Point id pairs of the input's line cells (each segment of a polyline).
std::vector<int64_t> LineSegments(vtkPolyData* input);

} // namespace shadinglab::mesh
