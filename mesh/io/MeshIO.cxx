// SPDX-License-Identifier: BSD-3-Clause
#include "MeshIO.h"

#include "VtkCompat.h"

#include "FastReaders.h"
#include "MeshPrecheck.h"
#include "CompositeIO.h"

#include "Geometry.h"

#include <vtkCellArray.h>
#include <vtkCleanPolyData.h>
#include <vtkCellData.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkIdList.h>
#include <vtkUnsignedCharArray.h>
#include <vtkPointData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkOBJWriter.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLReader.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkDataSetReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLRectilinearGridReader.h>
#include <vtkXMLStructuredGridReader.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <sys/stat.h>
#include <vector>

namespace shadinglab
{

namespace
{

std::string Extension(const std::string& path)
{
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos)
  {
    return {};
  }
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// Upper bounds on OFF header counts: a mesh beyond 2^31 elements is beyond
/// vtkIdType-safe allocation on this machine (24 GiB) and signals a corrupt
/// header rather than a real mesh.
constexpr long long kMaxOffElements = 1LL << 31;

/// The OFF file's non-empty lines split into tokens, '#' comments removed.
/// OFF is line-oriented for faces: tokens after a face's indices are its
/// colour, which is ignored.
std::vector<std::vector<std::string>> OffLines(std::istream& in)
{
  std::vector<std::vector<std::string>> lines;
  std::string line;
  while (std::getline(in, line))
  {
    const auto hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.resize(hash);
    }
    std::istringstream ls(line);
    std::vector<std::string> tokens;
    std::string t;
    while (ls >> t)
    {
      tokens.push_back(t);
    }
    if (!tokens.empty())
    {
      lines.push_back(std::move(tokens));
    }
  }
  return lines;
}

/// A token of an OFF file as a number, or MeshError naming what it was.
double OffNumber(const std::string& t, const char* what, const std::string& bad)
{
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (end == t.c_str() || *end != '\0')
  {
    throw MeshError(bad + "'" + t + "' is not a number (" + what + ")");
  }
  return v;
}

/// Vertex colours as 8-bit RGB: 0..255 integers or 0..1 reals, the largest
/// value tells which.
vtkSmartPointer<vtkUnsignedCharArray> OffColours(const std::vector<double>& values, vtkIdType n)
{
  const double largest = *std::max_element(values.begin(), values.end());
  const double scale = largest > 1.0 ? 1.0 : 255.0;
  auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
  rgb->SetName("Colors");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(n);
  for (size_t k = 0; k < values.size(); ++k)
  {
    const double v = std::clamp(values[k] * scale, 0.0, 255.0);
    rgb->SetValue(static_cast<vtkIdType>(k), static_cast<unsigned char>(std::lround(v)));
  }
  return rgb;
}

vtkSmartPointer<vtkPolyData> ReadOff(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
  {
    throw MeshError("cannot open '" + path + "'");
  }
  const std::vector<std::vector<std::string>> lines = OffLines(in);
  const std::string bad = "malformed OFF file '" + path + "': ";
  auto number = [&](const std::string& t, const char* what) { return OffNumber(t, what, bad); };
  if (lines.empty())
  {
    throw MeshError("empty file '" + path + "'");
  }
  size_t row = 0;
  std::vector<std::string> counts = lines[0];
  // Geomview's header prefixes: C (vertex colours) and N (vertex normals),
  // read as point scalars and normals; in each vertex line the normal comes
  // before the colour. Other prefixes (ST, 4, n) are refused below.
  bool colours = false, normals = false;
  if (counts[0] == "COFF" || counts[0] == "NOFF" || counts[0] == "CNOFF")
  {
    colours = counts[0][0] == 'C';
    normals = counts[0].find('N') != std::string::npos;
    counts[0] = "OFF";
  }
  if (counts[0] == "OFF")
  {
    counts.erase(counts.begin());
    if (counts.empty())
    {
      if (lines.size() < 2)
      {
        throw MeshError(bad + "missing vertex and face counts");
      }
      counts = lines[++row];
    }
  }
  else if (counts[0].size() > 3 && counts[0].compare(counts[0].size() - 3, 3, "OFF") == 0)
  {
    throw MeshError("unsupported OFF variant '" + counts[0] + "' in '" + path + "'");
  }
  ++row;
  if (counts.size() < 2)
  {
    throw MeshError(bad + "missing vertex and face counts");
  }
  const double nv = number(counts[0], "vertex count");
  const double nf = number(counts[1], "face count");
  if (nv < 0 || nf < 0 || nv != std::floor(nv) || nf != std::floor(nf) || nv > kMaxOffElements ||
    nf > kMaxOffElements)
  {
    throw MeshError(bad + "bad vertex/face counts");
  }
  if (lines.size() < row + static_cast<size_t>(nv) + static_cast<size_t>(nf))
  {
    throw MeshError(bad + "fewer lines than the header's " + counts[0] + " vertices and " +
      counts[1] + " faces");
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(nv));
  vtkNew<vtkDoubleArray> normalArray;
  normalArray->SetName("Normals");
  normalArray->SetNumberOfComponents(3);
  std::vector<double> colourValues;
  const size_t needed = 3 + (normals ? 3 : 0) + (colours ? 3 : 0);
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(nv); ++i, ++row)
  {
    const auto& tokens = lines[row];
    if (tokens.size() < needed)
    {
      throw MeshError(bad + "vertex " + std::to_string(i) + " has fewer than " +
        std::to_string(needed) + " numbers");
    }
    double p[3];
    for (int c = 0; c < 3; ++c)
    {
      p[c] = number(tokens[c], "vertex coordinate");
    }
    points->SetPoint(i, p);
    size_t at = 3;
    if (normals)
    {
      double n[3];
      for (int c = 0; c < 3; ++c)
      {
        n[c] = number(tokens[at++], "vertex normal");
      }
      normalArray->InsertNextTuple(n);
    }
    if (colours)
    {
      for (int c = 0; c < 3; ++c)
      {
        colourValues.push_back(number(tokens[at++], "vertex colour"));
      }
    }
  }
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  std::vector<vtkIdType> ids;
  for (vtkIdType f = 0; f < static_cast<vtkIdType>(nf); ++f, ++row)
  {
    const auto& tokens = lines[row];
    const double n = number(tokens[0], "face size");
    if (n < 1 || n != std::floor(n) || n + 1 > static_cast<double>(tokens.size()))
    {
      throw MeshError(bad + "bad vertex count in face " + std::to_string(f));
    }
    ids.resize(static_cast<size_t>(n));
    for (size_t k = 0; k < ids.size(); ++k)
    {
      const double v = number(tokens[k + 1], "face index");
      if (v < 0 || v >= nv || v != std::floor(v))
      {
        throw MeshError(bad + "vertex index out of range in face " + std::to_string(f));
      }
      ids[k] = static_cast<vtkIdType>(v);
    }
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  if (normals)
  {
    mesh->GetPointData()->SetNormals(normalArray);
  }
  if (colours && !colourValues.empty()) // no vertices, no colours (UBSan: fuzz finding)
  {
    mesh->GetPointData()->SetScalars(OffColours(colourValues, static_cast<vtkIdType>(nv)));
  }
  return mesh;
}

void WriteOff(vtkPolyData* mesh, const std::string& path)
{
  std::ofstream out(path);
  if (!out)
  {
    throw MeshError("cannot write '" + path + "'");
  }
  out.precision(17);
  out << "OFF\n" << mesh->GetNumberOfPoints() << " " << mesh->GetNumberOfPolys() << " 0\n";
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    out << p[0] << " " << p[1] << " " << p[2] << "\n";
  }
  vtkNew<vtkIdList> ids;
  vtkCellArray* polys = mesh->GetPolys();
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    polys->GetCellAtId(c, ids);
    out << ids->GetNumberOfIds();
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      out << " " << ids->GetId(k);
    }
    out << "\n";
  }
  if (!out)
  {
    throw MeshError("cannot write '" + path + "' (missing directory, no permission or disk full?)");
  }
}

template <typename Reader>
vtkSmartPointer<vtkPolyData> ReadWith(const std::string& path)
{
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  if (reader->GetErrorCode() != 0)
  {
    throw MeshError("cannot read '" + path + "': malformed or unsupported file");
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(reader->GetOutput());
  return out;
}

/// CheckCellsInPlace for one storage width (vtkTypeInt64 or vtkTypeInt32).
template <typename VtkId>
bool CheckCellsOfWidth(vtkCellArray* cells, bool polys, vtkIdType np, bool& checked)
{
  using IdArrayOfWidth = vtkAOSDataArrayTemplate<VtkId>;
  auto* offsets = IdArrayOfWidth::SafeDownCast(cells->GetOffsetsArray());
  auto* connectivity = IdArrayOfWidth::SafeDownCast(cells->GetConnectivityArray());
  checked = offsets && connectivity;
  if (!checked)
  {
    return false;
  }
  const VtkId* o = offsets->GetPointer(0);
  const VtkId* ids = connectivity->GetPointer(0);
  const vtkIdType n = cells->GetNumberOfCells();
  for (vtkIdType c = 0; c < n; ++c)
  {
    const vtkTypeInt64 size = static_cast<vtkTypeInt64>(o[c + 1]) - o[c];
    bool inRange = true;
    for (vtkTypeInt64 k = o[c]; k < o[c + 1]; ++k)
    {
      inRange &= ids[k] >= 0 && ids[k] < np;
    }
    if ((polys && size < 3) || !inRange)
    {
      return false; // the general loop names the cell
    }
  }
  return true;
}

/// The cell checks of ValidateMesh on 64-bit storage (VTK's readers'
/// default) or 32-bit storage (the fast readers' when ids fit) read in
/// place: false when the storage is another, or a cell fails, for the
/// general loop to check and name.
bool CheckCellsInPlace(vtkCellArray* cells, bool polys, vtkIdType np)
{
  bool checked = false;
  const bool wide = CheckCellsOfWidth<vtkTypeInt64>(cells, polys, np, checked);
  return checked ? wide : CheckCellsOfWidth<vtkTypeInt32>(cells, polys, np, checked);
}

/// The first point with a non-finite coordinate, read in place from float
/// or double points, and their box; the number of points when there is
/// none. Points of another type: 0 and false, for the caller's loop to
/// check each and VTK to bound them.
bool ScanPoints(vtkPoints* points, vtkIdType& firstNonFinite, double box[6])
{
  const vtkIdType n = points->GetNumberOfPoints();
  auto scan = [&](const auto* xyz) {
    firstNonFinite = n;
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (!std::isfinite(xyz[3 * i]) || !std::isfinite(xyz[3 * i + 1]) || !std::isfinite(xyz[3 * i + 2]))
      {
        firstNonFinite = i;
        break;
      }
    }
    mesh::PointBox(xyz, n, box);
    return true;
  };
  if (auto* f = vtkFloatArray::SafeDownCast(points->GetData()))
  {
    return scan(f->GetPointer(0));
  }
  if (auto* d = vtkDoubleArray::SafeDownCast(points->GetData()))
  {
    return scan(d->GetPointer(0));
  }
  firstNonFinite = 0;
  return false;
}

} // namespace

void ValidateMesh(vtkPolyData* mesh, const std::string& what)
{
  ValidateMeshCells(mesh, what, true);
}

void ValidateMeshCells(vtkPolyData* mesh, const std::string& what, bool checkCells)
{
  if (!mesh || mesh->GetNumberOfPoints() == 0 || mesh->GetNumberOfPolys() == 0)
  {
    throw MeshError("empty mesh: '" + what + "' has no polygons");
  }
  // Every cell's point ids in range and every polygon with >= 3 of them:
  // no algorithm downstream checks indices again.
  const vtkIdType np = mesh->GetNumberOfPoints();
  vtkNew<vtkIdList> ids;
  for (vtkCellArray* cells : { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
  {
    if (!checkCells)
    {
      break; // a fast reader checked them as it parsed
    }
    const bool polys = cells == mesh->GetPolys();
    // Offsets that do not fit the connectivity (a legacy file declaring
    // more cells than it lists) would make every cell access overflow:
    // found by fuzz/MeshReaderFuzzer.
    if (cells->GetNumberOfCells() > 0 && !cells->IsValid())
    {
      throw MeshError("malformed cells in '" + what + "': their offsets do not match their "
                      "connectivity (truncated or corrupt)");
    }
    if (CheckCellsInPlace(cells, polys, np))
    {
      continue;
    }
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
    {
      cells->GetCellAtId(c, ids);
      if (polys && ids->GetNumberOfIds() < 3)
      {
        throw MeshError("polygon " + std::to_string(c) + " of '" + what + "' has " +
          std::to_string(ids->GetNumberOfIds()) + " vertices (at least 3 needed)");
      }
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        if (ids->GetId(k) < 0 || ids->GetId(k) >= np)
        {
          throw MeshError("cell " + std::to_string(c) + " of '" + what + "' refers to point " +
            std::to_string(ids->GetId(k)) + ", outside 0.." + std::to_string(np - 1));
        }
      }
    }
  }
  vtkPoints* pts = mesh->GetPoints();
  vtkIdType firstNonFinite = 0;
  double bounds[6];
  const bool boxed = ScanPoints(pts, firstNonFinite, bounds);
  for (vtkIdType i = firstNonFinite; i < pts->GetNumberOfPoints(); ++i)
  {
    double p[3];
    pts->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      throw MeshError("non-finite (NaN or Inf) coordinates at point " + std::to_string(i) +
        " of '" + what + "'");
    }
  }
  // At least one polygon with an area: a mesh of degenerate faces only
  // (collinear or repeated points) has nothing to draw or to give normals
  // to, and every command says so alike.
  if (!boxed)
  {
    mesh->GetBounds(bounds);
  }
  const double diagonal2 = (bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) + (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]);
  bool anyArea = false;
  vtkCellArray* polys = mesh->GetPolys();
  for (vtkIdType c = 0; c < polys->GetNumberOfCells() && !anyArea; ++c)
  {
    polys->GetCellAtId(c, ids);
    const Vec3<double> area = mesh::NewellAreaVector<double>(ids->GetNumberOfIds(), [&](int64_t k) {
      double p[3];
      pts->GetPoint(ids->GetId(k), p);
      return Vec3<double>(p[0], p[1], p[2]);
    });
    anyArea = Length(area) > mesh::kDegenerateRelativeArea * diagonal2;
  }
  if (!anyArea)
  {
    throw MeshError("every polygon of '" + what + "' is degenerate (zero area): nothing to draw");
  }
}

namespace
{

/// The corner point ids of a face, sorted: a key that a linear and a
/// quadratic face over the same corners share (VTK lists corners first).
std::vector<vtkIdType> CornerKey(vtkCell* face)
{
  const int corners = face->GetNumberOfEdges(); // a polygon has as many corners as edges
  std::vector<vtkIdType> key;
  for (int k = 0; k < corners && k < face->GetNumberOfPoints(); ++k)
  {
    key.push_back(face->GetPointId(k));
  }
  std::sort(key.begin(), key.end());
  return key;
}

/// A volume mesh as FE codes and gmsh write it also lists its boundary as
/// 2D cells: dropped here where they cover a boundary face of the 3D cells
/// (both would be drawn, coincident, as z-fighting facets); 2D cells
/// elsewhere (shells) are kept, 1D and 0D cells are not drawn anyway.
vtkSmartPointer<vtkDataSet> WithoutBoundaryCopies(vtkDataSet* data)
{
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid)
  {
    return data;
  }
  std::map<std::vector<vtkIdType>, int> faces; // corner key -> 3D cells sharing it
  bool anyVolume = false, anySurface = false;
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const int dimension = shadinglab::vtkcompat::CellDimension(static_cast<unsigned char>(grid->GetCellType(c)));
    anySurface |= dimension == 2;
    if (dimension != 3)
    {
      continue;
    }
    anyVolume = true;
    grid->GetCell(c, cell);
    for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
    {
      ++faces[CornerKey(cell->GetFace(f))];
    }
  }
  if (!anyVolume || !anySurface)
  {
    return data;
  }
  vtkNew<vtkIdList> kept;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const int dimension = shadinglab::vtkcompat::CellDimension(static_cast<unsigned char>(grid->GetCellType(c)));
    if (dimension == 2)
    {
      grid->GetCell(c, cell);
      const auto it = faces.find(CornerKey(cell));
      if (it != faces.end() && it->second == 1)
      {
        continue; // a copy of a boundary face
      }
    }
    if (dimension >= 2)
    {
      kept->InsertNextId(c);
    }
  }
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->SetPoints(grid->GetPoints());
  out->GetPointData()->PassData(grid->GetPointData());
  out->GetCellData()->CopyAllocate(grid->GetCellData(), kept->GetNumberOfIds());
  out->Allocate(kept->GetNumberOfIds());
  vtkNew<vtkIdList> ids;
  for (vtkIdType k = 0; k < kept->GetNumberOfIds(); ++k)
  {
    const vtkIdType c = kept->GetId(k);
    grid->GetCellPoints(c, ids);
    const vtkIdType n = out->InsertNextCell(grid->GetCellType(c), ids);
    out->GetCellData()->CopyData(grid->GetCellData(), c, n);
  }
  return out;
}

} // namespace

vtkSmartPointer<vtkPolyData> SurfaceOf(vtkDataSet* data, const ReadOptions& options)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    mesh->ShallowCopy(poly);
    return mesh;
  }
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(WithoutBoundaryCopies(data));
  surface->SetNonlinearSubdivisionLevel(options.nonlinearSubdivisionLevel);
  surface->Update();
  mesh->ShallowCopy(surface->GetOutput());
  // The subdivision gives each higher-order face its own points: merge the
  // coincident ones, so vertex normals and orientation see the surface
  // whole (and smooth shading does not show every original face).
  bool nonlinear = false;
  for (vtkIdType c = 0; c < data->GetNumberOfCells() && !nonlinear; ++c)
  {
    nonlinear = !shadinglab::vtkcompat::CellIsLinear(static_cast<unsigned char>(data->GetCellType(c)));
  }
  if (nonlinear)
  {
    vtkNew<vtkCleanPolyData> merge; // (vtkStaticCleanPolyData leaks a byte per instance in VTK 9.2)
    merge->SetInputData(mesh);
    merge->PointMergingOn();
    merge->SetTolerance(0.0);
    merge->ConvertLinesToPointsOff();
    merge->ConvertPolysToLinesOff();
    merge->ConvertStripsToPolysOff();
    merge->Update();
    mesh->ShallowCopy(merge->GetOutput());
  }
  return mesh;
}

namespace
{

/// A structured VTK XML file (.vts, .vtr, .vti), pre-checked like .vtp.
vtkSmartPointer<vtkDataSet> ReadStructured(const std::string& path, const std::string& ext)
{
  vtkSmartPointer<vtkXMLReader> reader;
  std::string type;
  if (ext == "vts")
  {
    reader = vtkSmartPointer<vtkXMLStructuredGridReader>::New();
    type = "StructuredGrid";
  }
  else if (ext == "vtr")
  {
    reader = vtkSmartPointer<vtkXMLRectilinearGridReader>::New();
    type = "RectilinearGrid";
  }
  else
  {
    reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
    type = "ImageData";
  }
  if (!reader->CanReadFile(path.c_str()))
  {
    throw MeshError("cannot read '" + path + "': not a VTK XML " + type +
      " file (malformed, truncated or another type)");
  }
  PrecheckXmlVtk(path, type);
  reader->SetFileName(path.c_str());
  reader->Update();
  auto* data = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (reader->GetErrorCode() != 0 || !data)
  {
    throw MeshError("cannot read '" + path + "': malformed ." + ext + " file");
  }
  return data;
}

} // namespace

const std::vector<std::string>& ReadableExtensions()
{
  static const std::vector<std::string> extensions = { "vtp", "vtk", "vtu", "vts", "vtr", "vti",
    "vtm", "pvd", "e", "exo", "ex2", "exii", "ply", "obj", "stl", "off" };
  return extensions;
}

std::string ReadableExtensionsText()
{
  std::string text;
  for (const std::string& ext : ReadableExtensions())
  {
    text += (text.empty() ? "." : " .") + ext;
  }
  return text;
}

size_t ChooseTimeStep(
  const std::vector<double>& times, const ReadOptions& options, const std::string& what)
{
  if (times.empty())
  {
    throw MeshError("'" + what + "' has no time steps");
  }
  auto span = [&] {
    char text[160];
    std::snprintf(text, sizeof text, "%zu step(s), times %g .. %g", times.size(), times.front(),
      times.back());
    return std::string(text);
  };
  if (options.timeStep >= 0)
  {
    if (static_cast<size_t>(options.timeStep) >= times.size())
    {
      throw MeshError("--time-step " + std::to_string(options.timeStep) + ": '" + what + "' has " +
        span() + " (steps 0.." + std::to_string(times.size() - 1) + ")");
    }
    return static_cast<size_t>(options.timeStep);
  }
  if (std::isnan(options.time))
  {
    return 0;
  }
  // The last step at or before the time (ParaView snaps so); a rounding
  // hair below the first step still reads it.
  const double slack = 1e-9 * std::max(1.0, std::abs(times.back() - times.front()));
  if (!(options.time >= times.front() - slack && options.time <= times.back() + slack))
  {
    char t[32];
    std::snprintf(t, sizeof t, "%g", options.time);
    throw MeshError(std::string("--time ") + t + ": outside '" + what + "': " + span());
  }
  size_t step = 0;
  while (step + 1 < times.size() && times[step + 1] <= options.time + slack)
  {
    ++step;
  }
  return step;
}

vtkPolyData* ReadMesh(const std::string& path, const ReadOptions& options)
{
  if (!std::isnan(options.time) && options.timeStep >= 0)
  {
    throw MeshError("--time and --time-step: give one");
  }
  if (std::isinf(options.time) || options.timeStep < -1)
  {
    throw MeshError("--time must be finite, --time-step 0 or more");
  }
  const std::string ext = Extension(path);
  const bool series = ext == "pvd" || ext == "e" || ext == "exo" || ext == "ex2" || ext == "exii";
  if ((!std::isnan(options.time) || options.timeStep >= 0) && !series)
  {
    throw MeshError(std::string(options.timeStep >= 0 ? "--time-step" : "--time") + ": '" + path +
      "' has no time steps (.pvd and Exodus II series do)");
  }
  if (options.nonlinearSubdivisionLevel < 0 ||
    options.nonlinearSubdivisionLevel > kMaxNonlinearSubdivisionLevel)
  {
    throw MeshError("the nonlinear subdivision level must be 0.." +
      std::to_string(kMaxNonlinearSubdivisionLevel) + " (got " +
      std::to_string(options.nonlinearSubdivisionLevel) + ")");
  }
  return ReadMeshAt(path, options, 0);
}

vtkPolyData* ReadMeshAt(const std::string& path, const ReadOptions& options, int depth)
{
  struct stat st;
  if (stat(path.c_str(), &st) != 0)
  {
    throw MeshError("cannot read '" + path + "': no such file");
  }
  if (!S_ISREG(st.st_mode))
  {
    throw MeshError("cannot read '" + path + "': not a regular file");
  }
  if (st.st_size == 0)
  {
    throw MeshError("cannot read '" + path + "': empty file");
  }
  const std::string ext = Extension(path);
  vtkSmartPointer<vtkPolyData> mesh;
  bool readFast = false;
  // VTK readers report problems through vtkErrorMacro and vtkLogger to
  // stderr; silence both so the user sees our one-line message only.
  const int warnings = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOff();
  const vtkLogger::Verbosity verbosity = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  struct RestoreLogging
  {
    int warnings;
    vtkLogger::Verbosity verbosity;
    ~RestoreLogging()
    {
      vtkObject::SetGlobalWarningDisplay(this->warnings);
      vtkLogger::SetStderrVerbosity(this->verbosity);
    }
  } restore{ warnings, verbosity };
  if (ext == "vtp")
  {
    vtkNew<vtkXMLPolyDataReader> probe;
    if (!probe->CanReadFile(path.c_str()))
    {
      throw MeshError("cannot read '" + path + "': not a VTK XML PolyData file (malformed, "
                                               "truncated or another type)");
    }
    PrecheckXmlVtk(path, "PolyData");
    mesh = ReadWith<vtkXMLPolyDataReader>(path);
  }
  else if ((ext == "ply" || ext == "stl" || ext == "off" || ext == "obj") && FastReadersEnabled() &&
    (mesh = ReadFast(path, ext)))
  {
    readFast = true; // read at memory speed, its cells checked on the way (FastReaders.h)
  }
  else if (ext == "ply")
  {
    PrecheckPly(path);
    mesh = ReadWith<vtkPLYReader>(path);
  }
  else if (ext == "obj")
  {
    PrecheckObj(path);
    mesh = ReadWith<vtkOBJReader>(path);
  }
  else if (ext == "stl")
  {
    PrecheckStl(path);
    mesh = ReadWith<vtkSTLReader>(path);
  }
  else if (ext == "off")
  {
    mesh = ReadOff(path);
  }
  else if (ext == "e" || ext == "exo" || ext == "ex2" || ext == "exii")
  {
    mesh = ReadExodus(path, options);
  }
  else if (ext == "vtm" || ext == "pvd")
  {
    mesh = ReadListing(path, ext == "pvd", options, depth);
  }
  else if (ext == "vts" || ext == "vtr" || ext == "vti")
  {
    mesh = SurfaceOf(ReadStructured(path, ext), options);
  }
  else if (ext == "vtk" || ext == "vtu")
  {
    vtkSmartPointer<vtkDataSet> data;
    if (ext == "vtk")
    {
      PrecheckLegacyVtk(path);
      auto reader = vtkSmartPointer<vtkDataSetReader>::New();
      reader->SetFileName(path.c_str());
      reader->Update();
      if (reader->GetErrorCode() != 0 || !reader->GetOutput())
      {
        throw MeshError("cannot read '" + path + "': malformed or unsupported legacy VTK file");
      }
      data = reader->GetOutput();
    }
    else
    {
      auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
      if (!reader->CanReadFile(path.c_str()))
      {
        throw MeshError("cannot read '" + path + "': not a VTK XML UnstructuredGrid file "
                                                 "(malformed, truncated or another type)");
      }
      PrecheckXmlVtk(path, "UnstructuredGrid");
      reader->SetFileName(path.c_str());
      reader->Update();
      if (reader->GetErrorCode() != 0)
      {
        throw MeshError("cannot read '" + path + "': malformed .vtu file");
      }
      data = reader->GetOutput();
    }
    mesh = SurfaceOf(data, options);
  }
  else
  {
    throw MeshError("cannot read '" + path +
      "': unknown extension (expected " + ReadableExtensionsText() + ")");
  }
  if (!mesh)
  {
    throw MeshError("cannot read '" + path + "'");
  }
  if (mesh->GetNumberOfStrips() > 0)
  {
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(mesh);
    triangles->PassVertsOff();
    triangles->PassLinesOff();
    triangles->Update();
    mesh->ShallowCopy(triangles->GetOutput());
  }
  ValidateMeshCells(mesh, path, !readFast);
  mesh->Register(nullptr);
  return mesh;
}

void WriteMesh(vtkPolyData* mesh, const std::string& path)
{
  // Each writer: input, file name, the format's binary switch, write.
  // VTK writers may return success on an unopenable file and report it only
  // through their error code and multi-line log output: check the code and
  // keep the log quiet, so the caller gets one MeshError line.
  auto write = [&](auto writer, auto configure) {
    writer->SetInputData(mesh);
    writer->SetFileName(path.c_str());
    configure(writer.GetPointer());
    const int warnings = vtkObject::GetGlobalWarningDisplay();
    vtkObject::GlobalWarningDisplayOff();
    const int written = writer->Write();
    vtkObject::SetGlobalWarningDisplay(warnings);
    return written && writer->GetErrorCode() == 0;
  };
  auto none = [](auto*) {};
  const std::string ext = Extension(path);
  int ok = 0;
  if (ext == "vtp")
  {
    ok = write(vtkSmartPointer<vtkXMLPolyDataWriter>::New(), [](auto* w) { w->SetDataModeToBinary(); });
  }
  else if (ext == "vtk")
  {
    ok = write(vtkSmartPointer<vtkPolyDataWriter>::New(), none);
  }
  else if (ext == "ply")
  {
    ok = write(vtkSmartPointer<vtkPLYWriter>::New(), [](auto* w) { w->SetFileTypeToBinary(); });
  }
  else if (ext == "stl")
  {
    ok = write(vtkSmartPointer<vtkSTLWriter>::New(), [](auto* w) { w->SetFileTypeToBinary(); });
  }
  else if (ext == "obj")
  {
    ok = write(vtkSmartPointer<vtkOBJWriter>::New(), none);
  }
  else if (ext == "off")
  {
    WriteOff(mesh, path);
    ok = 1;
  }
  else
  {
    throw MeshError("cannot write '" + path + "': unknown extension (expected .vtp .vtk .ply .obj .stl .off)");
  }
  if (!ok)
  {
    throw MeshError("cannot write '" + path + "' (missing directory, no permission or disk full?)");
  }
}

} // namespace shadinglab
