// SPDX-License-Identifier: BSD-3-Clause
#include "MeshArrays.h"
#include "Orientation.h"
#include "PolygonTriangulation.h"

#include <vtkAOSDataArrayTemplate.h>
#include <vtkCellData.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>
#include <vtkTypeInt32Array.h>

#include <algorithm>
#include <type_traits>

namespace shadinglab::mesh
{

namespace
{

/// A cell array of `IdsArray` storage (vtkIdTypeArray or vtkTypeInt32Array,
/// every id fitting) from flat offsets and connectivity, copied.
template <typename IdsArray, typename Offset>
vtkSmartPointer<vtkCellArray> CellArrayOf(
  const Offset* offsets, int64_t numberOfPolygons, const int64_t* connectivity)
{
  using Value = typename IdsArray::ValueType;
  vtkNew<IdsArray> offsetArray, connectivityArray;
  offsetArray->SetNumberOfValues(numberOfPolygons + 1);
  const int64_t size = numberOfPolygons > 0 ? offsets[numberOfPolygons] : 0;
  connectivityArray->SetNumberOfValues(size);
  if (numberOfPolygons > 0)
  {
    std::copy(offsets, offsets + numberOfPolygons + 1, offsetArray->GetPointer(0));
    std::transform(connectivity, connectivity + size, connectivityArray->GetPointer(0),
      [](int64_t id) { return static_cast<Value>(id); });
  }
  else
  {
    offsetArray->SetValue(0, 0); // an empty cell array still has its first offset
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsetArray, connectivityArray);
  return cells;
}

} // namespace

vtkSmartPointer<vtkCellArray> CellArrayFromFlat(const int64_t* offsets,
  int64_t numberOfPolygons, const int64_t* connectivity)
{
  return CellArrayOf<vtkIdTypeArray>(offsets, numberOfPolygons, connectivity);
}

vtkSmartPointer<vtkCellArray> CellArrayFromFlat(const int32_t* offsets,
  int64_t numberOfPolygons, const int64_t* connectivity)
{
  return CellArrayOf<vtkTypeInt32Array>(offsets, numberOfPolygons, connectivity);
}

namespace
{
using Int32Array = vtkAOSDataArrayTemplate<vtkTypeInt32>;
}

bool NarrowPolygonsOf(vtkPolyData* input, NarrowMeshView& out)
{
  vtkCellArray* polys = input->GetPolys();
  auto* offsets = polys ? Int32Array::SafeDownCast(polys->GetOffsetsArray()) : nullptr;
  auto* connectivity = polys ? Int32Array::SafeDownCast(polys->GetConnectivityArray()) : nullptr;
  if (!offsets || !connectivity)
  {
    return false;
  }
  static_assert(sizeof(vtkTypeInt32) == sizeof(int32_t), "32-bit ids");
  out.points = nullptr;
  out.numberOfPoints = input->GetNumberOfPoints();
  out.offsets = reinterpret_cast<const int32_t*>(offsets->GetPointer(0));
  out.connectivity = reinterpret_cast<const int32_t*>(connectivity->GetPointer(0));
  out.numberOfPolygons = polys->GetNumberOfCells();
  return true;
}

void FlatPolygonsFromPolyData(vtkPolyData* input, FlatPolygons& out, bool withPoints)
{
  out.numberOfPoints = input->GetNumberOfPoints();
  auto* doubles = vtkDoubleArray::SafeDownCast(input->GetPoints() ? input->GetPoints()->GetData() : nullptr);
  if (!withPoints)
  {
    out.points = nullptr;
  }
  else if (doubles)
  {
    out.points = doubles->GetPointer(0);
  }
  else
  {
    out.pointStorage.resize(static_cast<size_t>(3 * out.numberOfPoints));
    auto* floats = vtkFloatArray::SafeDownCast(input->GetPoints() ? input->GetPoints()->GetData() : nullptr);
    if (floats) // every reader's points: widened in one loop, no call per point
    {
      std::copy(floats->GetPointer(0), floats->GetPointer(0) + 3 * out.numberOfPoints, out.pointStorage.begin());
    }
    else
    {
      for (vtkIdType i = 0; i < out.numberOfPoints; ++i)
      {
        input->GetPoint(i, &out.pointStorage[3 * i]);
      }
    }
    out.points = out.pointStorage.data();
  }
  vtkCellArray* polys = input->GetPolys();
  out.numberOfPolygons = polys->GetNumberOfCells();
  // 64-bit storage is read in place: an AOS array of vtkTypeInt64 in every
  // VTK from 9.2 to 9.6 (GetOffsetsArray64, its typed getter, is deprecated
  // in 9.6, whose array may not be a vtkTypeInt64Array).
  using Int64Array = vtkAOSDataArrayTemplate<vtkTypeInt64>;
  auto* offsets64 = Int64Array::SafeDownCast(polys->GetOffsetsArray());
  auto* connectivity64 = Int64Array::SafeDownCast(polys->GetConnectivityArray());
  if (offsets64 && connectivity64)
  {
    static_assert(sizeof(vtkTypeInt64) == sizeof(int64_t), "64-bit ids");
    out.offsets = reinterpret_cast<const int64_t*>(offsets64->GetPointer(0));
    out.connectivity = reinterpret_cast<const int64_t*>(connectivity64->GetPointer(0));
    return;
  }
  NarrowMeshView narrow;
  if (NarrowPolygonsOf(input, narrow)) // widened in two loops, no call per cell
  {
    const int64_t n = narrow.numberOfPolygons;
    out.offsetStorage.assign(narrow.offsets, narrow.offsets + n + 1);
    out.connectivityStorage.assign(narrow.connectivity, narrow.connectivity + narrow.offsets[n]);
    out.offsets = out.offsetStorage.data();
    out.connectivity = out.connectivityStorage.data();
    return;
  }
  vtkNew<vtkIdList> ids;
  out.offsetStorage.assign(1, 0);
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    polys->GetCellAtId(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      out.connectivityStorage.push_back(ids->GetId(k));
    }
    out.offsetStorage.push_back(static_cast<int64_t>(out.connectivityStorage.size()));
  }
  out.offsets = out.offsetStorage.data();
  out.connectivity = out.connectivityStorage.data();
}

vtkSmartPointer<vtkPolyData> WithoutStrips(vtkPolyData* input, bool keepLinesAndVerts)
{
  if (input->GetNumberOfStrips() == 0 &&
    (keepLinesAndVerts || (input->GetNumberOfLines() == 0 && input->GetNumberOfVerts() == 0)))
  {
    return input;
  }
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(input);
  triangles->SetPassLines(keepLinesAndVerts);
  triangles->SetPassVerts(keepLinesAndVerts);
  triangles->Update();
  return triangles->GetOutput();
}

bool InconsistentlyOriented(vtkPolyData* input)
{
  NarrowMeshView narrow;
  if (NarrowPolygonsOf(input, narrow)) // 32-bit cells read in place
  {
    return HasInconsistentOrientation(narrow);
  }
  FlatPolygons flat;
  FlatPolygonsFromPolyData(input, flat, false);
  return HasInconsistentOrientation(flat);
}

vtkSmartPointer<vtkPolyData> WithPolygonsTurned(vtkPolyData* input, const std::vector<uint8_t>& flips)
{
  FlatPolygons flat;
  FlatPolygonsFromPolyData(input, flat);
  std::vector<int64_t> turned;
  FlipFaces(flat, flips, turned);
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(input);
  out->SetPolys(CellArrayFromFlat(flat.offsets, flat.numberOfPolygons, turned.data()));
  return out;
}

vtkSmartPointer<vtkPolyData> ConsistentlyOriented(vtkPolyData* input)
{
  FlatPolygons flat;
  FlatPolygonsFromPolyData(input, flat);
  if (!HasInconsistentOrientation(flat))
  {
    return input;
  }
  return WithPolygonsTurned(input, ConsistentOrientationFlips(flat));
}

std::vector<int64_t> LineSegments(vtkPolyData* input)
{
  std::vector<int64_t> segments;
  vtkNew<vtkIdList> ids;
  vtkCellArray* lines = input->GetLines();
  for (vtkIdType c = 0; c < lines->GetNumberOfCells(); ++c)
  {
    lines->GetCellAtId(c, ids);
    for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      segments.push_back(ids->GetId(k));
      segments.push_back(ids->GetId(k + 1));
    }
  }
  return segments;
}

vtkSmartPointer<vtkPolyData> WithConcavePolygonsSplit(vtkPolyData* input, int64_t* split)
{
  if (split)
  {
    *split = 0;
  }
  vtkCellArray* polys = input ? input->GetPolys() : nullptr;
  vtkPoints* points = input ? input->GetPoints() : nullptr;
  if (!polys || !points || polys->GetNumberOfCells() == 0 || polys->GetMaxCellSize() <= 3)
  {
    return input; // triangles only (scans, isosurfaces): no pass over the cells
  }
  auto pointOf = [points](vtkIdType id) {
    double p[3];
    points->GetPoint(id, p);
    return Vec3<double>(p[0], p[1], p[2]);
  };
  // First pass: is any polygon concave? (Most meshes: none, nothing copied.)
  vtkNew<vtkIdList> ids;
  std::vector<char> concave(static_cast<size_t>(polys->GetNumberOfCells()), 0);
  int64_t count = 0;
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    polys->GetCellAtId(c, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    if (n > 3 && !IsConvexPolygon(n, [&](int64_t k) { return pointOf(ids->GetId(k)); }))
    {
      concave[static_cast<size_t>(c)] = 1;
      ++count;
    }
  }
  if (count == 0)
  {
    return input;
  }
  // Cell data is indexed verts, lines, polys, strips: the polygons' part
  // is rebuilt, the other cells keep theirs (copied first, in order).
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(input);
  vtkNew<vtkCellArray> cells;
  vtkCellData* from = input->GetCellData();
  vtkNew<vtkCellData> data;
  data->CopyAllocate(from, polys->GetNumberOfCells() + count);
  const vtkIdType before = input->GetNumberOfVerts() + input->GetNumberOfLines();
  vtkIdType next = 0;
  for (vtkIdType c = 0; c < before; ++c)
  {
    data->CopyData(from, c, next++);
  }
  std::vector<int64_t> triangles;
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    polys->GetCellAtId(c, ids);
    triangles.clear();
    if (concave[static_cast<size_t>(c)] &&
      TriangulatePolygon(ids->GetNumberOfIds(), [&](int64_t k) { return pointOf(ids->GetId(k)); },
        triangles))
    {
      for (size_t t = 0; t + 2 < triangles.size(); t += 3)
      {
        const vtkIdType tri[3] = { ids->GetId(triangles[t]), ids->GetId(triangles[t + 1]),
          ids->GetId(triangles[t + 2]) };
        cells->InsertNextCell(3, tri);
        data->CopyData(from, before + c, next++);
      }
      if (split)
      {
        ++*split;
      }
      continue;
    }
    cells->InsertNextCell(ids);
    data->CopyData(from, before + c, next++);
  }
  for (vtkIdType c = 0; c < input->GetNumberOfStrips(); ++c)
  {
    data->CopyData(from, before + polys->GetNumberOfCells() + c, next++);
  }
  out->SetPolys(cells);
  out->GetCellData()->ShallowCopy(data);
  return out;
}

} // namespace shadinglab::mesh
