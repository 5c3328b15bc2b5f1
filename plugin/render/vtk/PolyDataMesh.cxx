// SPDX-License-Identifier: BSD-3-Clause
#include "PolyDataMesh.h"

#include "PolygonTriangulation.h"

#include "Geometry.h"

#include <vtkCellArray.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolygon.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>

namespace shadinglab::render
{

namespace
{

Mesh Convert(vtkPolyData* input, WorldFrame& frame, bool normalize,
  const ScalarField* field = nullptr, double* range = nullptr,
  PolygonHandling polygons = PolygonHandling::Triangulate, bool release = false);

/// Largest polygon handed to the renderers whole: the CPU renderer clips a
/// polygon at the near plane into at most one more vertex than it has, in a
/// fixed buffer of 64 (Raster.h kMaxPolygonVertices).
constexpr vtkIdType kMaxWholePolygon = 63;

/// A field whose values span at most this many float ulps of their
/// magnitude is constant: the renderers carry scalars as floats and
/// interpolate them with perspective (value / w over 1 / w), which moves
/// a constant by one to three ulps from pixel to pixel; stretched over the
/// whole colour map, that rounding noise speckled a constant field (a unit
/// vector's magnitude, 1 +- 2e-16 in double) with both of the map's ends.
/// 16 ulps (a relative spread of 2e-6) is above that noise, and a real
/// field of so few float steps cannot be told from its own rounding.
constexpr double kConstantFieldUlps = 16.0;

} // namespace

Mesh MeshFromPolyData(vtkPolyData* input)
{
  WorldFrame identity;
  return Convert(input, identity, false);
}

Mesh MeshFromPolyData(vtkPolyData* input, WorldFrame& frame, PolygonHandling polygons)
{
  return Convert(input, frame, true, nullptr, nullptr, polygons);
}

Mesh MeshFromPolyData(vtkPolyData* input, WorldFrame& frame, const ScalarField& field,
  double range[2], PolygonHandling polygons)
{
  return Convert(input, frame, true, &field, range, polygons);
}

Mesh MeshFromPolyDataReleasing(
  vtkSmartPointer<vtkPolyData> input, WorldFrame& frame, PolygonHandling polygons)
{
  return Convert(input, frame, true, nullptr, nullptr, polygons, true);
}

std::string ParseScalarField(const std::string& spec, ScalarField& field)
{
  field = ScalarField();
  std::string rest = spec;
  auto strip = [&](const char* prefix, ScalarField::Association a) {
    const std::string p(prefix);
    if (rest.size() >= p.size() && rest.compare(0, p.size(), p) == 0)
    {
      rest = rest.substr(p.size());
      field.association = a;
    }
  };
  strip("POINTS:", ScalarField::Association::Points);
  strip("CELLS:", ScalarField::Association::Cells);
  const size_t colon = rest.rfind(':');
  if (colon != std::string::npos)
  {
    const std::string c = rest.substr(colon + 1);
    if (c == "Magnitude" || c == "magnitude")
    {
      rest = rest.substr(0, colon);
    }
    else if (!c.empty() && c.size() <= 2 && std::all_of(c.begin(), c.end(), ::isdigit))
    {
      field.component = std::stoi(c);
      rest = rest.substr(0, colon);
    }
  }
  if (rest.empty())
  {
    return "--color-by '" + spec + "': no array name ([POINTS:|CELLS:]NAME[:COMPONENT|Magnitude])";
  }
  field.name = rest;
  return {};
}

namespace
{

/// The names of an attribute's arrays, for error messages.
std::string ArrayNames(vtkDataSetAttributes* data)
{
  std::string names;
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    if (vtkDataArray* array = data->GetArray(a); array && array->GetName())
    {
      names += (names.empty() ? "" : ", ") + std::string(array->GetName());
    }
  }
  return names.empty() ? "none" : names;
}

/// Component `component` of tuple i, or the tuple's magnitude (-1; a
/// one-component array's value itself, sign kept, as VTK maps it).
double ValueOf(vtkDataArray* array, vtkIdType i, int component)
{
  if (component >= 0 || array->GetNumberOfComponents() == 1)
  {
    return array->GetComponent(i, std::max(component, 0));
  }
  double sum = 0;
  for (int c = 0; c < array->GetNumberOfComponents(); ++c)
  {
    const double v = array->GetComponent(i, c);
    sum += v * v;
  }
  return std::sqrt(sum);
}

/// The field's array in `pd` (throws one line when missing); `cells` says
/// where it was found.
vtkDataArray* FindField(vtkPolyData* pd, const ScalarField& field, bool& cells)
{
  using A = ScalarField::Association;
  vtkDataArray* array = nullptr;
  cells = false;
  if (field.association != A::Cells)
  {
    array = pd->GetPointData()->GetArray(field.name.c_str());
  }
  if (!array && field.association != A::Points)
  {
    array = pd->GetCellData()->GetArray(field.name.c_str());
    cells = array != nullptr;
  }
  if (!array)
  {
    throw std::invalid_argument("no " +
      std::string(field.association == A::Points ? "point" : field.association == A::Cells ? "cell" : "point or cell") +
      " array '" + field.name + "' (point arrays: " + ArrayNames(pd->GetPointData()) +
      "; cell arrays: " + ArrayNames(pd->GetCellData()) + ")");
  }
  if (field.component >= array->GetNumberOfComponents())
  {
    throw std::invalid_argument("'" + field.name + "' has " +
      std::to_string(array->GetNumberOfComponents()) + " component(s): use 0.." +
      std::to_string(array->GetNumberOfComponents() - 1) + " or Magnitude");
  }
  return array;
}

/// The input polygon the conversion's polygon i came from (`polygonOf`
/// empty: each is its own).
vtkIdType PolygonOf(const std::vector<vtkIdType>& polygonOf, size_t i)
{
  return polygonOf.empty() ? static_cast<vtkIdType>(i) : polygonOf[i];
}

/// The points' box read in place from float or double points (as
/// vtkPoints::GetBounds gives it, without its per-call dispatch); false
/// for points of another type.
bool BoxInPlace(vtkPoints* points, double box[6])
{
  if (auto* f = vtkFloatArray::SafeDownCast(points->GetData()))
  {
    mesh::PointBox(f->GetPointer(0), points->GetNumberOfPoints(), box);
    return true;
  }
  if (auto* d = vtkDoubleArray::SafeDownCast(points->GetData()))
  {
    mesh::PointBox(d->GetPointer(0), points->GetNumberOfPoints(), box);
    return true;
  }
  return false;
}

/// The points in the local frame as floats, read in place from float or
/// double points; false for points of another type.
bool LocalPointsInPlace(vtkPoints* points, const WorldFrame& frame, std::vector<float>& out)
{
  const vtkIdType n = points->GetNumberOfPoints();
  auto convert = [&](const auto* xyz) {
    for (vtkIdType i = 0; i < n; ++i)
    {
      const Vec3<double> local = frame.ToLocal(
        Vec3<double>(static_cast<double>(xyz[3 * i]), static_cast<double>(xyz[3 * i + 1]), static_cast<double>(xyz[3 * i + 2])));
      out[3 * i] = static_cast<float>(local.x);
      out[3 * i + 1] = static_cast<float>(local.y);
      out[3 * i + 2] = static_cast<float>(local.z);
    }
    return true;
  };
  if (auto* f = vtkFloatArray::SafeDownCast(points->GetData()))
  {
    return convert(f->GetPointer(0));
  }
  if (auto* d = vtkDoubleArray::SafeDownCast(points->GetData()))
  {
    return convert(d->GetPointer(0));
  }
  return false;
}

/// Keeps a VTK object alive as long as the pointer is (IdArray::Shared's owner).
std::shared_ptr<const void> Keep(vtkObjectBase* object)
{
  object->Register(nullptr);
  return std::shared_ptr<const void>(object, [](vtkObjectBase* o) { o->UnRegister(nullptr); });
}

/// TrianglesInPlace for one storage width (vtkTypeInt64 or vtkTypeInt32).
template <typename VtkId>
bool TrianglesOfWidth(vtkCellArray* polys, bool share, Mesh& mesh)
{
  using IdArrayOfWidth = vtkAOSDataArrayTemplate<VtkId>;
  auto* offsets = IdArrayOfWidth::SafeDownCast(polys->GetOffsetsArray());
  auto* connectivity = IdArrayOfWidth::SafeDownCast(polys->GetConnectivityArray());
  const vtkIdType n = polys->GetNumberOfCells();
  if (!offsets || !connectivity || n == 0)
  {
    return false;
  }
  const VtkId* o = offsets->GetPointer(0);
  bool triangles = true;
  for (vtkIdType c = 0; c <= n; ++c)
  {
    triangles &= static_cast<int64_t>(o[c]) == 3 * c;
  }
  if (!triangles)
  {
    return false;
  }
  const VtkId* ids = connectivity->GetPointer(0);
  if (share)
  {
    // vtkTypeInt64 is long long, int64_t long on LP64: the same bits.
    static_assert(sizeof(vtkTypeInt64) == sizeof(int64_t) && sizeof(vtkTypeInt32) == sizeof(int32_t));
    if constexpr (sizeof(VtkId) == 8)
    {
      mesh.offsets = IdArray::Shared(
        reinterpret_cast<const int64_t*>(o), static_cast<size_t>(n + 1), Keep(offsets));
      mesh.connectivity = IdArray::Shared(
        reinterpret_cast<const int64_t*>(ids), static_cast<size_t>(3 * n), Keep(connectivity));
    }
    else
    {
      mesh.offsets = IdArray::SharedNarrow(
        reinterpret_cast<const int32_t*>(o), static_cast<size_t>(n + 1), Keep(offsets));
      mesh.connectivity = IdArray::SharedNarrow(
        reinterpret_cast<const int32_t*>(ids), static_cast<size_t>(3 * n), Keep(connectivity));
    }
    return true;
  }
  mesh.offsets.resize(static_cast<size_t>(n + 1));
  for (vtkIdType c = 0; c <= n; ++c)
  {
    mesh.offsets[static_cast<size_t>(c)] = 3 * c;
  }
  mesh.connectivity.assign(ids, ids + 3 * n);
  return true;
}

/// When every polygon is a triangle held in 64-bit storage (VTK's readers'
/// default) or 32-bit storage (the fast readers' when ids fit): its offsets
/// and connectivity copied as they are, or with `share` shared
/// (IdArray::Shared or SharedNarrow, the arrays kept alive by the mesh),
/// true; otherwise false and nothing done.
bool TrianglesInPlace(vtkCellArray* polys, bool share, Mesh& mesh)
{
  return TrianglesOfWidth<vtkTypeInt64>(polys, share, mesh) ||
    TrianglesOfWidth<vtkTypeInt32>(polys, share, mesh);
}

/// `field`'s values into mesh.scalars (point data) or mesh.cellScalars
/// (cell data, following the polygons the conversion made: `polygonOf`),
/// and its finite values' range (see MeshFromPolyData).
void CopyField(vtkPolyData* pd, const ScalarField& field, const std::vector<vtkIdType>& polygonOf,
  Mesh& mesh, double* range)
{
  const vtkIdType np = pd->GetNumberOfPoints();
  bool cells = false;
  vtkDataArray* array = FindField(pd, field, cells);
  std::vector<float>& out = cells ? mesh.cellScalars : mesh.scalars;
  // Cell data counts verts and lines before the polygons.
  const vtkIdType firstPolygon = pd->GetNumberOfVerts() + pd->GetNumberOfLines();
  const size_t n = cells ? static_cast<size_t>(mesh.NumberOfPolygons()) : static_cast<size_t>(np);
  out.resize(n);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (size_t i = 0; i < n; ++i)
  {
    const vtkIdType tuple = cells ? firstPolygon + PolygonOf(polygonOf, i) : static_cast<vtkIdType>(i);
    const double v = ValueOf(array, tuple, field.component);
    out[i] = static_cast<float>(v);
    if (std::isfinite(v))
    {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  range[0] = lo <= hi ? lo : 0.0;
  range[1] = lo <= hi ? hi : 1.0;
  const double ulp = std::numeric_limits<float>::epsilon() *
    std::max(std::abs(range[0]), std::abs(range[1]));
  if (range[1] - range[0] <= kConstantFieldUlps * ulp)
  {
    // Constant up to rounding: one value, drawn as a constant field is.
    range[0] = range[1] = 0.5 * (range[0] + range[1]);
  }
}

/// Polygons the renderers cannot take whole (concave ones, which a fan
/// would fill over their notches, unless `polygons` is Direct: the CPU
/// renderer's even-odd scan draws them exactly; and ones with more than
/// kMaxWholePolygon vertices) are triangulated by ear clipping
/// (mesh::TriangulatePolygon: keyholes, stars, combs, collinear runs); the
/// triangles keep their polygon's cell normal. `polygonOf` maps back.
void ConvertPolygons(
  vtkPolyData* pd, PolygonHandling polygons, Mesh& mesh, std::vector<vtkIdType>& polygonOf)
{
  vtkCellArray* polys = pd->GetPolys();
  mesh.offsets.reserve(static_cast<size_t>(polys->GetNumberOfCells() + 1));
  mesh.offsets.push_back(0);
  mesh.connectivity.reserve(static_cast<size_t>(polys->GetNumberOfConnectivityIds()));
  polygonOf.reserve(static_cast<size_t>(polys->GetNumberOfCells()));
  vtkNew<vtkIdList> ids;
  std::vector<int64_t> triangles;
  vtkPoints* points = pd->GetPoints();
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    polys->GetCellAtId(c, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    auto pointAt = [&](int64_t k) {
      double p[3];
      points->GetPoint(ids->GetId(k), p);
      return Vec3<double>(p[0], p[1], p[2]);
    };
    if (n > 3 &&
      (n > kMaxWholePolygon ||
        !(polygons == PolygonHandling::Direct || mesh::IsConvexPolygon(n, pointAt))))
    {
      triangles.clear();
      const bool split = mesh::TriangulatePolygon(n, pointAt, triangles);
      if (split)
      {
        for (size_t t = 0; t + 2 < triangles.size(); t += 3)
        {
          for (int k = 0; k < 3; ++k)
          {
            mesh.connectivity.push_back(ids->GetId(triangles[t + k]));
          }
          mesh.offsets.push_back(static_cast<int64_t>(mesh.connectivity.size()));
          polygonOf.push_back(c);
        }
        continue;
      }
    }
    for (vtkIdType k = 0; k < n; ++k)
    {
      mesh.connectivity.push_back(ids->GetId(k));
    }
    mesh.offsets.push_back(static_cast<int64_t>(mesh.connectivity.size()));
    polygonOf.push_back(c);
  }
}

Mesh Convert(vtkPolyData* input, WorldFrame& frame, bool normalize, const ScalarField* field,
  double* range, PolygonHandling polygons, bool release)
{
  vtkSmartPointer<vtkPolyData> pd = input;
  if (input->GetNumberOfStrips() > 0)
  {
    vtkNew<vtkTriangleFilter> tri;
    tri->SetInputData(input);
    tri->PassLinesOff();
    tri->PassVertsOff();
    tri->Update();
    pd = tri->GetOutput();
  }
  Mesh mesh;
  const vtkIdType np = pd->GetNumberOfPoints();
  frame = WorldFrame();
  if (normalize && np > 0)
  {
    double b[6];
    if (!BoxInPlace(pd->GetPoints(), b))
    {
      pd->GetBounds(b);
    }
    const Vec3<double> lo(b[0], b[2], b[4]), hi(b[1], b[3], b[5]);
    const double radius = 0.5 * Length(hi - lo);
    frame.center = (lo + hi) * 0.5;
    // A mesh of one point has no extent: keep its scale.
    frame.scale = radius > 0 && std::isfinite(radius) ? radius : 1.0;
  }
  // The polygons first: releasing, triangles are shared (no copy) and
  // other polygons' arrays (the largest) go before the points and normals
  // are copied.
  vtkCellArray* polys = pd->GetPolys();
  const vtkIdType numberOfPolys = polys->GetNumberOfCells();
  std::vector<vtkIdType> polygonOf; // empty: polygon i is input polygon i
  if (!TrianglesInPlace(polys, release, mesh))
  {
    ConvertPolygons(pd, polygons, mesh, polygonOf);
  }
  if (release)
  {
    vtkNew<vtkCellArray> none;
    pd->SetPolys(none);
    polys = nullptr;
  }
  mesh.points.resize(static_cast<size_t>(3 * np));
  for (vtkIdType i = np > 0 && LocalPointsInPlace(pd->GetPoints(), frame, mesh.points) ? np : 0; i < np; ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    const Vec3<double> local = frame.ToLocal(Vec3<double>(p[0], p[1], p[2]));
    mesh.points[3 * i] = static_cast<float>(local.x);
    mesh.points[3 * i + 1] = static_cast<float>(local.y);
    mesh.points[3 * i + 2] = static_cast<float>(local.z);
  }
  if (vtkDataArray* n = pd->GetPointData()->GetNormals())
  {
    if (n->GetNumberOfComponents() == 3 && n->GetNumberOfTuples() == np)
    {
      mesh.normals.resize(static_cast<size_t>(3 * np));
      if (auto* f = vtkFloatArray::SafeDownCast(n))
      {
        std::copy(f->GetPointer(0), f->GetPointer(0) + 3 * np, mesh.normals.begin());
      }
      else
      {
        for (vtkIdType i = 0; i < np; ++i)
        {
          const double* v = n->GetTuple3(i);
          for (int c = 0; c < 3; ++c)
          {
            mesh.normals[3 * i + c] = static_cast<float>(v[c]);
          }
        }
      }
    }
  }
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(pd->GetPointData()->GetScalars());
  if (scalars && (scalars->GetNumberOfComponents() == 3 || scalars->GetNumberOfComponents() == 4) &&
    scalars->GetNumberOfTuples() == np)
  {
    mesh.colors.resize(static_cast<size_t>(3 * np));
    for (vtkIdType i = 0; i < np; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        mesh.colors[3 * i + c] = scalars->GetTypedComponent(i, c) / 255.0f;
      }
    }
  }
  if (field)
  {
    CopyField(pd, *field, polygonOf, mesh, range);
  }
  // Cell normals apply to polygons only when the polydata has no verts or
  // lines before them in cell order.
  vtkDataArray* cn = pd->GetCellData()->GetNormals();
  if (cn && cn->GetNumberOfComponents() == 3 && pd->GetNumberOfVerts() == 0 &&
    pd->GetNumberOfLines() == 0 && cn->GetNumberOfTuples() == numberOfPolys)
  {
    const size_t n = static_cast<size_t>(mesh.NumberOfPolygons());
    mesh.faceNormals.resize(3 * n);
    for (size_t i = 0; i < n; ++i)
    {
      const double* v = cn->GetTuple3(PolygonOf(polygonOf, i));
      for (int c = 0; c < 3; ++c)
      {
        mesh.faceNormals[3 * i + c] = static_cast<float>(v[c]);
      }
    }
  }
  return mesh;
}

} // namespace

namespace
{

vtkSmartPointer<vtkFloatArray> FloatArray(const std::vector<float>& values, const char* name)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / 3));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  return array;
}

} // namespace

std::string CheckColorArray(
  vtkPolyData* polydata, const ColorBySettings& color, const std::string& prefix)
{
  ScalarField field;
  std::string problem = ParseScalarField(color.array, field);
  if (!problem.empty())
  {
    return problem;
  }
  try
  {
    bool cells = false;
    FindField(polydata, field, cells);
  }
  catch (const std::invalid_argument& e)
  {
    return prefix + "color-by: " + e.what();
  }
  return "";
}

std::string MeshColoredBy(vtkPolyData* polydata, WorldFrame& frame, const ColorBySettings& color,
  const std::string& prefix, Mesh& mesh, ColorMap& map, std::string& title,
  PolygonHandling polygons)
{
  ScalarField field;
  std::string problem = ParseScalarField(color.array, field);
  if (!problem.empty())
  {
    return problem;
  }
  double range[2] = { 0, 1 };
  try
  {
    mesh = MeshFromPolyData(polydata, frame, field, range, polygons);
  }
  catch (const std::invalid_argument& e)
  {
    return prefix + "color-by: " + e.what();
  }
  if (!FindColorMap(color.colormap, map))
  {
    return "unknown " + prefix + "colormap '" + color.colormap + "'";
  }
  if (color.range != "auto")
  {
    // MIN,MAX: two finite numbers, MIN < MAX.
    const std::string& text = color.range;
    const size_t comma = text.find(',');
    char* end = nullptr;
    double lo = 0, hi = 0;
    bool ok = comma != std::string::npos;
    if (ok)
    {
      const std::string a = text.substr(0, comma), b = text.substr(comma + 1);
      lo = std::strtod(a.c_str(), &end);
      ok = !a.empty() && *end == '\0';
      hi = std::strtod(b.c_str(), &end);
      ok = ok && !b.empty() && *end == '\0';
    }
    if (!ok || !std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    {
      return prefix + "range must be MIN,MAX with MIN < MAX (or auto), not '" + text + "'";
    }
    range[0] = lo;
    range[1] = hi;
  }
  map.rangeMin = range[0];
  map.rangeMax = range[1];
  title = field.name;
  if (field.component >= 0)
  {
    title += " " + std::to_string(field.component);
  }
  return "";
}

vtkPolyData* PolyDataFromMesh(const Mesh& mesh)
{
  vtkPolyData* pd = vtkPolyData::New();
  vtkNew<vtkPoints> points;
  points->SetData(FloatArray(mesh.points, "Points"));
  pd->SetPoints(points);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(mesh.offsets.size()));
  std::copy(mesh.offsets.begin(), mesh.offsets.end(), offsets->GetPointer(0));
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(mesh.connectivity.size()));
  std::copy(mesh.connectivity.begin(), mesh.connectivity.end(), connectivity->GetPointer(0));
  vtkNew<vtkCellArray> polys;
  if (mesh.offsets.empty())
  {
    offsets->InsertNextValue(0);
  }
  polys->SetData(offsets, connectivity);
  pd->SetPolys(polys);
  if (!mesh.normals.empty())
  {
    pd->GetPointData()->SetNormals(FloatArray(mesh.normals, "Normals"));
  }
  if (!mesh.colors.empty())
  {
    pd->GetPointData()->SetScalars(FloatArray(mesh.colors, "Colors"));
  }
  if (!mesh.faceNormals.empty())
  {
    pd->GetCellData()->SetNormals(FloatArray(mesh.faceNormals, "Normals"));
  }
  for (const std::vector<float>* values : { &mesh.scalars, &mesh.cellScalars })
  {
    if (!values->empty())
    {
      vtkNew<vtkFloatArray> array;
      array->SetName("Scalars");
      array->SetNumberOfTuples(static_cast<vtkIdType>(values->size()));
      std::copy(values->begin(), values->end(), array->GetPointer(0));
      (values == &mesh.scalars ? static_cast<vtkDataSetAttributes*>(pd->GetPointData())
                               : pd->GetCellData())
        ->AddArray(array);
    }
  }
  return pd;
}

} // namespace shadinglab::render
