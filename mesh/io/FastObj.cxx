// SPDX-License-Identifier: BSD-3-Clause
// The fast OBJ reader (FastReaders.h): files of vertices (`v x y z`),
// faces of plain vertex indices (`f 1 2 3`, each a vertex already read)
// and groups (`g`), with comments and empty lines, read as vtkOBJReader
// reads them (VTK 9.2 to 9.6): double points, one polygon per face and a
// float "GroupIds" cell array. A group id is the number of `g` lines
// before the face less one, or that number when the first face comes
// before any `g` (VTK's reader raises its group from -1 to 0 there). Any
// other line (texture coordinates, normals, materials, lines, points,
// relative, slashed or zero-led indices) goes to the checked path.
#include "FastReadCommon.h"
#include "MeshIO.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <vector>

namespace shadinglab
{

namespace
{

/// Bytes of file per polygon the arrays are first sized for: a scan's OBJ
/// spends ~40 bytes per triangle (a vertex line of ~30 for every two faces
/// of ~25); 32 over-sizes that a little, the arrays grow past it when a
/// file is denser and are trimmed at the end.
constexpr size_t kBytesPerPolygonEstimate = 32;

} // namespace

vtkSmartPointer<vtkPolyData> ReadFastObj(fastread::MappedFile& file)
{
  fastread::Text text{ file.Data(), file.Data() + file.Size() };
  std::vector<double> xyz;
  std::vector<int64_t> groupsBefore; // per face: the `g` lines before it
  int64_t groups = 0;
  const int64_t estimate = static_cast<int64_t>(file.Size() / kBytesPerPolygonEstimate) + 1;
  fastread::Polygons out(0, estimate, 3 * estimate);
  int64_t polygons = 0;
  while (text.at < text.end)
  {
    text.SkipBlanks();
    if (text.at == text.end)
    {
      break;
    }
    const char c = *text.at;
    if (c == '\n' || c == '#')
    {
      text.NextLine();
      continue;
    }
    if (text.Word("v"))
    {
      double p[3];
      if (!text.Real(p[0]) || !text.Real(p[1]) || !text.Real(p[2]) || !text.AtLineEnd() ||
        !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        return nullptr;
      }
      xyz.insert(xyz.end(), p, p + 3);
    }
    else if (text.Word("f"))
    {
      const int64_t points = static_cast<int64_t>(xyz.size() / 3);
      int64_t count = 0;
      while (!text.AtLineEnd())
      {
        // An index with a leading zero ("032") is decimal 32 to the OBJ
        // format and to VTK 9.2's reader, but VTK 9.4 on reads "0" as the
        // start of a 0x/0o/0b prefix, finds index 0 and refuses the file:
        // the checked path reads it as the VTK in use does.
        text.SkipBlanks();
        if (text.at < text.end && *text.at == '0')
        {
          return nullptr;
        }
        long long index = 0;
        if (!text.Integer(index) || index < 1 || index > points)
        {
          return nullptr; // relative, slashed, zero or forward: the checked path
        }
        out.Reserve(1);
        out.ids[out.used++] = index - 1;
        ++count;
      }
      if (count < 3)
      {
        return nullptr;
      }
      out.ReservePolygons(polygons + 1);
      out.offset[++polygons] = out.used;
      groupsBefore.push_back(groups);
    }
    else if (text.Word("g"))
    {
      ++groups;
    }
    else
    {
      return nullptr;
    }
    text.NextLine();
    if ((polygons & 0xffff) == 0)
    {
      file.Release(static_cast<size_t>(text.at - file.Data()));
    }
  }
  if (polygons == 0)
  {
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> mesh = out.Finish(polygons);
  auto points = vtkSmartPointer<vtkDoubleArray>::New();
  points->SetNumberOfComponents(3);
  points->SetNumberOfTuples(static_cast<vtkIdType>(xyz.size() / 3));
  std::copy(xyz.begin(), xyz.end(), points->GetPointer(0));
  auto pts = vtkSmartPointer<vtkPoints>::New();
  pts->SetData(points);
  mesh->SetPoints(pts);
  auto ids = vtkSmartPointer<vtkFloatArray>::New();
  ids->SetName("GroupIds");
  ids->SetNumberOfTuples(polygons);
  const int64_t raise = groupsBefore[0] == 0 ? 1 : 0; // VTK's -1 -> 0 at the first face
  for (int64_t f = 0; f < polygons; ++f)
  {
    ids->SetValue(f, static_cast<float>(groupsBefore[static_cast<size_t>(f)] - 1 + raise));
  }
  mesh->GetCellData()->AddArray(ids);
  return mesh;
}

} // namespace shadinglab
