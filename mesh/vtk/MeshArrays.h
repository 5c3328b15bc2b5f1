// SPDX-License-Identifier: BSD-3-Clause
// vtkPolyData polygons <-> flat arrays for the mesh/core algorithms.
#pragma once

#include <cstdint>
#include <vector>

class vtkPolyData;

namespace shadinglab::mesh
{

struct FlatPolygons
{
  std::vector<double> points;
  std::vector<int64_t> offsets{ 0 };
  std::vector<int64_t> connectivity;
  int64_t NumberOfPolygons() const { return static_cast<int64_t>(offsets.size()) - 1; }
};

/// Points and polygons (strips triangulated) of a polydata.
FlatPolygons FlatPolygonsFromPolyData(vtkPolyData* input);

/// Point id pairs of the input's line cells (each segment of a polyline).
std::vector<int64_t> LineSegments(vtkPolyData* input);

} // namespace shadinglab::mesh
