// SPDX-License-Identifier: BSD-3-Clause
// The fast PLY reader (FastReaders.h): binary (either byte order) and ASCII
// files whose vertices hold x, y, z and optionally nx, ny, nz and uchar
// red, green, blue (alpha), and whose faces hold one index list, as VTK's
// vtkPLYReader reads them: float points, "Normals" (float) and "RGB" or
// "RGBA" (uchar) point arrays, one polygon per face. Other elements and
// other scalar properties are skipped, as VTK skips them. Anything else
// VTK would turn into an array (texture coordinates, face colours or
// intensity) or that needs a check goes to the checked path.
#include "FastReadCommon.h"
#include "MeshIO.h"
#include "PlyHeader.h"
#include "TwoThreads.h"

#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <cstring>
#include <sstream>
#include <string_view>
#include <vector>

namespace shadinglab
{

namespace
{

using fastread::MappedFile;
using fastread::Polygons;
using ply::PlyElement;
using ply::PlyProperty;

/// Longest header searched for end_header: ReadPlyHeader reads at most
/// 10,000 lines; 4 MB is 400 bytes a line, beyond any real header.
constexpr size_t kMaxHeaderBytes = size_t(4) << 20;

/// Most vertices of a face VTK's reader takes: it copies a face's indices
/// into a 256-entry array.
constexpr long long kMaxFaceVertices = 256;

/// A face record of a scan's body: uchar 3, then three int indices.
constexpr size_t kTriangleRecord = 13;
/// Faces from which a body of triangle records is parsed by two threads:
/// a thread's start (~50 us) is ~2 % of 2^16 faces' parse.
constexpr int64_t kTwoThreadFaces = int64_t(1) << 16;
/// Faces between two releases of the pages a thread has parsed.
constexpr int64_t kReleaseFaces = int64_t(1) << 16;

/**
 * A body of `nf` triangle records at `at` (little-endian, as the host),
 * parsed by two threads, each its half of the faces, each handing back
 * the file's pages behind it. True when every record is a triangle of
 * indices in [0, nv); false leaves the element to the serial loop (which
 * overwrites what this wrote and finds the first problem, as it always
 * has). The records are independent, so the halves need no join: the
 * arrays are the serial loop's, bit for bit.
 */
template <typename Id>
bool ReadTriangleRecordsAs(const MappedFile& file, size_t at, int64_t nf, int64_t nv, Polygons& out)
{
  const char* body = file.Data() + at;
  Id* ids = reinterpret_cast<Id*>(out.ids);
  Id* offset = reinterpret_cast<Id*>(out.offset);
  bool good[2] = { true, true };
  auto half = [&](int h, int64_t f0, int64_t f1)
  {
    bool ok = true;
    for (int64_t chunk = f0; chunk < f1 && ok; chunk += kReleaseFaces)
    {
      const int64_t end = std::min(f1, chunk + kReleaseFaces);
      for (int64_t f = chunk; f < end; ++f)
      {
        const char* r = body + kTriangleRecord * static_cast<size_t>(f);
        int32_t v[3];
        std::memcpy(v, r + 1, sizeof v);
        ok &= r[0] == 3;
        for (int k = 0; k < 3; ++k)
        {
          ok &= v[k] >= 0 && v[k] < nv;
          ids[3 * f + k] = static_cast<Id>(v[k]);
        }
        offset[f + 1] = static_cast<Id>(3 * (f + 1));
      }
      file.ReleaseRange(at + kTriangleRecord * static_cast<size_t>(f0),
        at + kTriangleRecord * static_cast<size_t>(end));
    }
    good[h] = ok;
  };
  const int64_t middle = nf / 2;
  mesh::RunBoth(true, [&] { half(0, 0, middle); }, [&] { half(1, middle, nf); });
  return good[0] && good[1];
}

/**
 * ReadTriangleRecordsAs with the ids written in 32 bits straight away when
 * they fit (out.idsNarrow: Finish then has nothing to narrow, and half the
 * id pages are ever touched), else in 64. When it fails, the serial loop
 * writes every id again in 64 bits.
 */
bool ReadTriangleRecords(const MappedFile& file, size_t at, int64_t nf, int64_t nv, Polygons& out)
{
  if (nv < INT32_MAX && 3 * nf < INT32_MAX)
  {
    out.idsNarrow = ReadTriangleRecordsAs<vtkTypeInt32>(file, at, nf, nv, out);
    return out.idsNarrow;
  }
  return ReadTriangleRecordsAs<vtkTypeInt64>(file, at, nf, nv, out);
}

enum class Kind
{
  I8,
  U8,
  I16,
  U16,
  I32,
  U32,
  F32,
  F64
};

Kind KindOf(int size, bool integer, bool isSigned)
{
  if (!integer)
  {
    return size == 4 ? Kind::F32 : Kind::F64;
  }
  switch (size)
  {
    case 1:
      return isSigned ? Kind::I8 : Kind::U8;
    case 2:
      return isSigned ? Kind::I16 : Kind::U16;
    default:
      return isSigned ? Kind::I32 : Kind::U32;
  }
}

template <typename T>
T Load(const char* p, bool swap)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (swap)
  {
    for (size_t i = 0; i < sizeof(T) / 2; ++i)
    {
      std::swap(b[i], b[sizeof(T) - 1 - i]);
    }
  }
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

/// A binary value as vtkPLY converts it: integers through int (unsigned
/// through unsigned int), then double.
double Value(const char* p, Kind k, bool swap)
{
  switch (k)
  {
    case Kind::I8:
      return static_cast<int8_t>(*p);
    case Kind::U8:
      return static_cast<uint8_t>(*p);
    case Kind::I16:
      return Load<int16_t>(p, swap);
    case Kind::U16:
      return Load<uint16_t>(p, swap);
    case Kind::I32:
      return Load<int32_t>(p, swap);
    case Kind::U32:
      return Load<uint32_t>(p, swap);
    case Kind::F32:
      return Load<float>(p, swap);
    case Kind::F64:
      return Load<double>(p, swap);
  }
  return 0;
}

/// An integer value (list count or index) as vtkPLY keeps it, in an int;
/// -1 for a float-typed one (the checked path names it).
long long Index(const char* p, Kind k, bool swap)
{
  if (k == Kind::F32 || k == Kind::F64)
  {
    return -1;
  }
  return static_cast<int32_t>(static_cast<uint32_t>(static_cast<int64_t>(Value(p, k, swap))));
}

/// Where the values the reader keeps lie in a vertex row: property
/// indices (-1 for absent), and the face row's shape.
struct Layout
{
  const PlyElement* vertex = nullptr;
  const PlyElement* face = nullptr;
  int xyz[3] = { -1, -1, -1 };
  int normal[3] = { -1, -1, -1 };
  int rgba[4] = { -1, -1, -1, -1 };
  bool normals = false;
  int colours = 0; ///< 0, 3 (RGB) or 4 (RGBA)
  int list = -1;   ///< the face's index list property
};

int Find(const PlyElement& e, const char* name)
{
  for (size_t i = 0; i < e.properties.size(); ++i)
  {
    if (e.properties[i].name == name)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

/// The layout, or false when the fast path does not read this file.
bool MakeLayout(const std::vector<PlyElement>& elements, Layout& l)
{
  for (const PlyElement& e : elements)
  {
    if (e.name == "vertex" && !l.vertex && !l.face)
    {
      l.vertex = &e;
    }
    else if (e.name == "face" && l.vertex && !l.face)
    {
      l.face = &e;
    }
    else if (e.name == "vertex" || e.name == "face")
    {
      return false; // a second one, or faces first
    }
  }
  if (!l.vertex || !l.face || l.vertex->count == 0 || l.face->count == 0)
  {
    return false;
  }
  const PlyElement& v = *l.vertex;
  for (const PlyProperty& p : v.properties)
  {
    if (p.list)
    {
      return false;
    }
  }
  const char* names[] = { "x", "y", "z", "nx", "ny", "nz", "red", "green", "blue", "alpha" };
  int* slots[] = { &l.xyz[0], &l.xyz[1], &l.xyz[2], &l.normal[0], &l.normal[1], &l.normal[2],
    &l.rgba[0], &l.rgba[1], &l.rgba[2], &l.rgba[3] };
  for (int i = 0; i < 10; ++i)
  {
    *slots[i] = Find(v, names[i]);
  }
  if (l.xyz[0] < 0 || l.xyz[1] < 0 || l.xyz[2] < 0)
  {
    return false;
  }
  // Texture coordinates and diffuse colours become arrays in VTK's reader.
  for (const char* name : { "u", "v", "texture_u", "texture_v", "diffuse_red" })
  {
    if (Find(v, name) >= 0)
    {
      return false;
    }
  }
  l.normals = l.normal[0] >= 0 && l.normal[1] >= 0 && l.normal[2] >= 0;
  if (l.rgba[0] >= 0 && l.rgba[1] >= 0 && l.rgba[2] >= 0)
  {
    l.colours = l.rgba[3] >= 0 ? 4 : 3;
    for (int c = 0; c < l.colours; ++c)
    {
      const PlyProperty& p = v.properties[static_cast<size_t>(l.rgba[c])];
      if (!p.integer || p.size != 1 || p.isSigned)
      {
        return false; // converted through VTK's rules: its path reads these
      }
    }
  }
  const PlyElement& f = *l.face;
  for (size_t i = 0; i < f.properties.size(); ++i)
  {
    const PlyProperty& p = f.properties[i];
    if (p.list && (p.name == "vertex_indices" || p.name == "vertex_index") && l.list < 0 && p.integer)
    {
      l.list = static_cast<int>(i);
    }
    else if (p.list || p.name == "intensity" || p.name == "red" || p.name == "green" ||
      p.name == "blue" || p.name == "alpha")
    {
      return false;
    }
  }
  return l.list >= 0;
}

/// The optional point arrays of a layout, sized.
struct PointArrays
{
  vtkSmartPointer<vtkFloatArray> normals;
  vtkSmartPointer<vtkUnsignedCharArray> colours;

  PointArrays(const Layout& l, int64_t n)
  {
    if (l.normals)
    {
      this->normals = vtkSmartPointer<vtkFloatArray>::New();
      this->normals->SetName("Normals");
      this->normals->SetNumberOfComponents(3);
      this->normals->SetNumberOfTuples(n);
    }
    if (l.colours)
    {
      this->colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
      this->colours->SetName(l.colours == 4 ? "RGBA" : "RGB");
      this->colours->SetNumberOfComponents(l.colours);
      this->colours->SetNumberOfTuples(n);
    }
  }
  void AttachTo(vtkPolyData* mesh)
  {
    if (this->colours)
    {
      mesh->GetPointData()->SetScalars(this->colours);
    }
    if (this->normals)
    {
      mesh->GetPointData()->SetNormals(this->normals);
    }
  }
};

/// Byte offsets of properties in a fixed-size binary row, and its size;
/// false when a property is a list.
bool RowOffsets(const PlyElement& e, std::vector<size_t>& offsets, size_t& size)
{
  offsets.clear();
  size = 0;
  for (const PlyProperty& p : e.properties)
  {
    if (p.list)
    {
      return false;
    }
    offsets.push_back(size);
    size += static_cast<size_t>(p.size);
  }
  return true;
}

/// Whether the binary body's rows fit in `bytes`: fixed rows whole, faces
/// at their smallest (three indices each).
bool FitsTheFile(const std::vector<PlyElement>& elements, const Layout& l, size_t bytes)
{
  unsigned long long need = 0;
  for (const PlyElement& e : elements)
  {
    unsigned long long row = 0;
    for (const PlyProperty& p : e.properties)
    {
      row += p.list ? static_cast<unsigned long long>(p.countSize) + (&e == l.face ? 3ull * static_cast<unsigned long long>(p.size) : 0)
                    : static_cast<unsigned long long>(p.size);
    }
    need += row * static_cast<unsigned long long>(e.count); // < 2^31 rows of < 2^31 bytes
  }
  return need <= bytes;
}

/// The face element of a binary body at `at` (advanced past it): false
/// for a face the fast path does not read (the checked path then names it).
bool ReadBinaryFaces(MappedFile& file, size_t& at, const PlyElement& e, const Layout& l, bool swap,
  Polygons& out)
{
  const char* data = file.Data();
  const size_t size = file.Size();
  const int64_t nv = l.vertex->count;
  const int64_t nf = l.face->count;
  // before the list, the list, after it: scalars of fixed sizes
  size_t before = 0, after = 0;
  for (size_t i = 0; i < e.properties.size(); ++i)
  {
    if (static_cast<int>(i) != l.list)
    {
      (static_cast<int>(i) < l.list ? before : after) += static_cast<size_t>(e.properties[i].size);
    }
  }
  const PlyProperty& list = e.properties[static_cast<size_t>(l.list)];
  const Kind countKind = KindOf(list.countSize, true, list.countSigned);
  const Kind itemKind = KindOf(list.size, true, list.isSigned);
  const size_t countSize = static_cast<size_t>(list.countSize);
  const size_t item = static_cast<size_t>(list.size);
  const bool fastTriangles = !swap && before == 0 && after == 0 && countSize == 1 && item == 4;
  vtkTypeInt64* offset = out.offset;
  if (fastTriangles && nf >= kTwoThreadFaces &&
    static_cast<size_t>(nf) <= (size - at) / kTriangleRecord &&
    ReadTriangleRecords(file, at, nf, nv, out))
  {
    out.used = 3 * nf;
    at += kTriangleRecord * static_cast<size_t>(nf);
    file.Release(at);
    return true;
  }
  for (int64_t f = 0; f < nf; ++f)
  {
    if (at + before + countSize > size)
    {
      return false;
    }
    at += before;
    const long long count = Index(data + at, countKind, swap);
    at += countSize;
    if (count < 3 || count > kMaxFaceVertices || at + static_cast<size_t>(count) * item + after > size)
    {
      return false;
    }
    out.Reserve(count);
    vtkTypeInt64* ids = out.ids + out.used;
    if (fastTriangles)
    {
      for (long long k = 0; k < count; ++k)
      {
        int32_t v;
        std::memcpy(&v, data + at + 4 * static_cast<size_t>(k), 4);
        ids[k] = v;
      }
    }
    else
    {
      for (long long k = 0; k < count; ++k)
      {
        ids[k] = Index(data + at + static_cast<size_t>(k) * item, itemKind, swap);
      }
    }
    bool inRange = true;
    for (long long k = 0; k < count; ++k)
    {
      inRange &= ids[k] >= 0 && ids[k] < nv;
    }
    if (!inRange)
    {
      return false;
    }
    out.used += count;
    offset[f + 1] = out.used;
    at += static_cast<size_t>(count) * item + after;
    if ((f & 0xffff) == 0)
    {
      file.Release(at);
    }
  }
  return true;
}

vtkSmartPointer<vtkPolyData> ReadBinary(MappedFile& file, size_t at,
  const std::vector<PlyElement>& elements, const Layout& l, bool swap)
{
  const char* data = file.Data();
  const size_t size = file.Size();
  const int64_t nv = l.vertex->count;
  const int64_t nf = l.face->count;
  if (!FitsTheFile(elements, l, size - at))
  {
    return nullptr; // before anything is allocated for the counts
  }
  Polygons out(nv, nf, 3 * nf);
  PointArrays arrays(l, nv);
  std::vector<size_t> offsets;
  for (const PlyElement& e : elements)
  {
    if (&e == l.vertex)
    {
      size_t row = 0;
      RowOffsets(e, offsets, row);
      if (row * static_cast<size_t>(nv) > size - at)
      {
        return nullptr;
      }
      Kind kinds[10];
      const int* slots[] = { &l.xyz[0], &l.xyz[1], &l.xyz[2], &l.normal[0], &l.normal[1], &l.normal[2] };
      for (int c = 0; c < 6; ++c)
      {
        const PlyProperty* p = *slots[c] >= 0 ? &e.properties[static_cast<size_t>(*slots[c])] : nullptr;
        kinds[c] = p ? KindOf(p->size, p->integer, p->isSigned) : Kind::F32;
      }
      const bool plain = !swap && row == 12 && l.xyz[0] == 0 && l.xyz[1] == 1 && l.xyz[2] == 2 &&
        kinds[0] == Kind::F32 && kinds[1] == Kind::F32 && kinds[2] == Kind::F32;
      if (plain)
      {
        std::memcpy(out.xyz, data + at, 12 * static_cast<size_t>(nv));
      }
      else
      {
        float* n = arrays.normals ? arrays.normals->GetPointer(0) : nullptr;
        unsigned char* rgb = arrays.colours ? arrays.colours->GetPointer(0) : nullptr;
        for (int64_t i = 0; i < nv; ++i)
        {
          const char* r = data + at + static_cast<size_t>(i) * row;
          for (int c = 0; c < 3; ++c)
          {
            out.xyz[3 * i + c] = static_cast<float>(Value(r + offsets[static_cast<size_t>(l.xyz[c])], kinds[c], swap));
          }
          if (n)
          {
            for (int c = 0; c < 3; ++c)
            {
              n[3 * i + c] = static_cast<float>(Value(r + offsets[static_cast<size_t>(l.normal[c])], kinds[3 + c], swap));
            }
          }
          for (int c = 0; c < l.colours; ++c)
          {
            rgb[l.colours * i + c] = static_cast<unsigned char>(r[offsets[static_cast<size_t>(l.rgba[c])]]);
          }
        }
      }
      at += row * static_cast<size_t>(nv);
      file.Release(at);
      if (!fastread::AllFinite(out.xyz, 3 * nv))
      {
        return nullptr;
      }
    }
    else if (&e == l.face)
    {
      if (!ReadBinaryFaces(file, at, e, l, swap, out))
      {
        return nullptr;
      }
    }
    else
    {
      size_t row = 0;
      if (!RowOffsets(e, offsets, row) || row * static_cast<size_t>(e.count) > size - at)
      {
        return nullptr; // a list in another element: its rows vary in size
      }
      at += row * static_cast<size_t>(e.count);
    }
  }
  vtkSmartPointer<vtkPolyData> mesh = out.Finish();
  arrays.AttachTo(mesh);
  return mesh;
}

vtkSmartPointer<vtkPolyData> ReadAscii(MappedFile& file, size_t at,
  const std::vector<PlyElement>& elements, const Layout& l)
{
  fastread::Text text{ file.Data() + at, file.Data() + file.Size() };
  const int64_t nv = l.vertex->count;
  const int64_t nf = l.face->count;
  // Each value takes at least 2 bytes (a digit and a separator), a face at
  // least 8 ("3 0 1 2\n"): counts the rest of the file cannot hold are
  // refused before anything is allocated for them.
  const auto values = static_cast<unsigned long long>(l.vertex->properties.size());
  if (2ull * values * static_cast<unsigned long long>(nv) + 8ull * static_cast<unsigned long long>(nf) >
    static_cast<unsigned long long>(file.Size() - at))
  {
    return nullptr;
  }
  Polygons out(nv, nf, 3 * nf);
  PointArrays arrays(l, nv);
  for (const PlyElement& e : elements)
  {
    if (&e == l.vertex)
    {
      float* n = arrays.normals ? arrays.normals->GetPointer(0) : nullptr;
      unsigned char* rgb = arrays.colours ? arrays.colours->GetPointer(0) : nullptr;
      std::vector<double> row(e.properties.size());
      for (int64_t i = 0; i < nv; ++i)
      {
        for (size_t p = 0; p < row.size(); ++p)
        {
          long long integer = 0;
          if (e.properties[p].integer ? !text.Integer(integer) : !text.Real(row[p]))
          {
            return nullptr;
          }
          if (e.properties[p].integer)
          {
            if (integer < INT32_MIN || integer > INT32_MAX)
            {
              return nullptr; // atoi's overflow: the checked path decides
            }
            row[p] = static_cast<double>(integer);
          }
        }
        if (!text.AtLineEnd())
        {
          return nullptr;
        }
        text.NextLine();
        for (int c = 0; c < 3; ++c)
        {
          out.xyz[3 * i + c] = static_cast<float>(row[static_cast<size_t>(l.xyz[c])]);
        }
        for (int c = 0; n && c < 3; ++c)
        {
          n[3 * i + c] = static_cast<float>(row[static_cast<size_t>(l.normal[c])]);
        }
        for (int c = 0; c < l.colours; ++c)
        {
          rgb[l.colours * i + c] =
            static_cast<unsigned char>(static_cast<int>(row[static_cast<size_t>(l.rgba[c])]));
        }
      }
      if (!fastread::AllFinite(out.xyz, 3 * nv))
      {
        return nullptr;
      }
    }
    else if (&e == l.face)
    {
      for (int64_t f = 0; f < nf; ++f)
      {
        for (size_t p = 0; p < e.properties.size(); ++p)
        {
          if (static_cast<int>(p) != l.list)
          {
            double skipped = 0;
            if (!text.Real(skipped))
            {
              return nullptr;
            }
            continue;
          }
          if (!out.AddPolygon(text, nv, kMaxFaceVertices))
          {
            return nullptr;
          }
        }
        out.offset[f + 1] = out.used;
        if (!text.AtLineEnd())
        {
          return nullptr;
        }
        text.NextLine();
      }
    }
    else
    {
      for (long long r = 0; r < e.count; ++r)
      {
        if (text.at == text.end)
        {
          return nullptr;
        }
        text.NextLine();
      }
    }
    file.Release(static_cast<size_t>(text.at - file.Data()));
  }
  vtkSmartPointer<vtkPolyData> mesh = out.Finish();
  arrays.AttachTo(mesh);
  return mesh;
}

} // namespace

vtkSmartPointer<vtkPolyData> ReadFastPly(MappedFile& file)
{
  const std::string_view all(file.Data(), std::min(file.Size(), kMaxHeaderBytes));
  size_t end = all.find("\nend_header");
  if (all.rfind("ply", 0) != 0 || end == std::string_view::npos)
  {
    return nullptr;
  }
  end = all.find('\n', end + 1);
  if (end == std::string_view::npos)
  {
    return nullptr;
  }
  const size_t body = end + 1;
  std::istringstream header(std::string(all.substr(0, body)));
  std::string first;
  std::getline(header, first);
  ply::PlyHeader h;
  try
  {
    h = ply::ReadPlyHeader(header, "");
  }
  catch (const MeshError&)
  {
    return nullptr;
  }
  if (static_cast<size_t>(header.tellg()) != body)
  {
    return nullptr;
  }
  Layout layout;
  if (!MakeLayout(h.elements, layout))
  {
    return nullptr;
  }
  if (h.format == "ascii")
  {
    return ReadAscii(file, body, h.elements, layout);
  }
  if (h.format != "binary_little_endian" && h.format != "binary_big_endian")
  {
    return nullptr;
  }
  return ReadBinary(file, body, h.elements, layout, h.format == "binary_big_endian");
}

} // namespace shadinglab
