// SPDX-License-Identifier: BSD-3-Clause
#include "MeshPrecheck.h"

#include "MeshIO.h"
#include "PlyHeader.h"
#include "PrecheckCommon.h"

#include <cerrno>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace shadinglab
{

namespace
{

using precheck::kMaxElementCount;
using precheck::ParseInteger;
using precheck::ReadInteger;
using ply::PlyElement;
using ply::PlyHeader;
using ply::PlyProperty;
using ply::ReadPlyHeader;


/// Largest polygon accepted in a PLY face list: 1e6 vertices per face is
/// far beyond any real polygon and keeps a corrupt count from allocating.
constexpr long long kMaxListLength = 1000000;

std::string Where(const std::string& path, long long line)
{
  return "'" + path + "' line " + std::to_string(line);
}

bool ParseReal(const std::string& token, double& value)
{
  if (token.empty())
  {
    return false;
  }
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size() && end != token.c_str();
}

/// An OBJ element vertex split at its slashes: v, v/vt, v//vn or v/vt/vn.
struct ObjVertexRef
{
  std::string parts[3]; ///< vertex, texture coordinate, normal (may be empty)
  int slashes = 0;

  /// "v", "v/t", "v//n" or "v/t/n": every vertex of an element has one form.
  std::string Form() const
  {
    if (this->slashes == 0)
    {
      return "v";
    }
    return this->parts[1].empty() ? "v//n" : (this->parts[2].empty() ? "v/t" : "v/t/n");
  }
};

ObjVertexRef SplitObjVertex(const std::string& token, const std::string& path, long long line)
{
  ObjVertexRef ref;
  size_t begin = 0;
  for (size_t slash = token.find('/'); slash != std::string::npos; slash = token.find('/', begin))
  {
    if (ref.slashes == 2)
    {
      ref.slashes = 3; // too many
      break;
    }
    ref.parts[ref.slashes++] = token.substr(begin, slash - begin);
    begin = slash + 1;
  }
  if (ref.slashes < 3)
  {
    ref.parts[ref.slashes] = token.substr(begin);
  }
  // A slash must be followed by an index: "2/" and "2/1/" are not OBJ
  // ("2/" made VTK's reader dereference a null texture-coordinate array:
  // fuzz/MeshReaderFuzzer); "2//" names neither.
  const bool ok = ref.slashes <= 2 && !ref.parts[ref.slashes].empty() &&
    !(ref.slashes == 2 && ref.parts[1].empty() && ref.parts[2].empty());
  if (!ok)
  {
    throw MeshError(Where(path, line) + ": '" + token + "' is not v, v/vt, v//vn or v/vt/vn");
  }
  return ref;
}

std::ifstream Open(const std::string& path, std::ios::openmode mode = std::ios::in)
{
  std::ifstream in(path, mode);
  if (!in)
  {
    throw MeshError("cannot open '" + path + "' (no permission?)");
  }
  return in;
}

/// The numbers of an OBJ "v" line after its keyword (at least three finite
/// coordinates; trailing text after the numbers is allowed), or MeshError
/// at `where`.
int ObjVertexNumbers(std::istringstream& tokens, const std::string& where)
{
  int count = 0;
  std::string token;
  while (tokens >> token)
  {
    double value = 0;
    if (!ParseReal(token, value))
    {
      if (count < 3)
      {
        throw MeshError(where + ": a vertex needs three numbers");
      }
      break; // a comment or trailing text after the numbers
    }
    if (count < 3 && !std::isfinite(value))
    {
      throw MeshError(where + ": non-finite (NaN or Inf) vertex coordinate");
    }
    ++count;
  }
  if (count < 3)
  {
    throw MeshError(where + ": a vertex needs three numbers");
  }
  return count;
}

} // namespace

void PrecheckObj(const std::string& path)
{
  std::ifstream in = Open(path);
  std::string line;
  long long number = 0, vertices = 0;
  long long largestIndex = 0, largestIndexLine = 0;
  long long textureCoordinates = 0, normals = 0;
  long long largestTexture = 0, largestNormal = 0; // largest positive vt, vn indices
  bool firstHasColour = false;
  while (std::getline(in, line))
  {
    ++number;
    if (number == 1 && line.size() >= 3 && static_cast<unsigned char>(line[0]) == 0xEF &&
      static_cast<unsigned char>(line[1]) == 0xBB && static_cast<unsigned char>(line[2]) == 0xBF)
    {
      throw MeshError("'" + path + "' starts with a UTF-8 byte-order mark, which VTK's OBJ reader "
                                   "mistakes for data: remove it");
    }
    // UTF-16 (a byte-order mark, or the NUL bytes of its ASCII characters):
    // every keyword would be unknown, and the file read as an empty mesh.
    const bool utf16Mark = number == 1 && line.size() >= 2 &&
      ((static_cast<unsigned char>(line[0]) == 0xFF && static_cast<unsigned char>(line[1]) == 0xFE) ||
        (static_cast<unsigned char>(line[0]) == 0xFE && static_cast<unsigned char>(line[1]) == 0xFF));
    if (utf16Mark || (number <= 2 && line.find('\0') != std::string::npos))
    {
      throw MeshError("'" + path + "' is UTF-16 text (NUL bytes between its characters): OBJ is "
                                   "ASCII or UTF-8; save it as UTF-8");
    }
    std::istringstream tokens(line);
    std::string keyword;
    tokens >> keyword;
    if (keyword == "v")
    {
      const int count = ObjVertexNumbers(tokens, Where(path, number));
      // x y z, x y z w, or x y z r g b: VTK's reader takes six numbers as a
      // colour and crashes when only some vertices have one (found by
      // fuzz/MeshReaderFuzzer).
      const bool colour = count >= 6;
      if (count == 5 || count > 7)
      {
        throw MeshError(Where(path, number) + ": a vertex has " + std::to_string(count) +
          " numbers (expected x y z [w] or x y z r g b)");
      }
      if (vertices == 0)
      {
        firstHasColour = colour;
      }
      else if (colour != firstHasColour)
      {
        throw MeshError(Where(path, number) + ": vertex colours on some vertices only (VTK's "
                                              "OBJ reader needs them on all or none)");
      }
      ++vertices;
    }
    else if (keyword == "vt" || keyword == "vn")
    {
      // VTK reads two texture coordinates or three normal components.
      const int needed = keyword == "vt" ? 2 : 3;
      std::string token;
      for (int c = 0; c < needed; ++c)
      {
        double value = 0;
        if (!(tokens >> token) || !ParseReal(token, value) || !std::isfinite(value))
        {
          throw MeshError(Where(path, number) + ": a '" + keyword + "' needs " +
            std::to_string(needed) + " finite numbers");
        }
      }
      ++(keyword == "vt" ? textureCoordinates : normals);
    }
    else if (keyword == "f" || keyword == "l" || keyword == "p")
    {
      int count = 0;
      std::string token, form;
      while (tokens >> token)
      {
        const ObjVertexRef ref = SplitObjVertex(token, path, number);
        if (count > 0 && ref.Form() != form)
        {
          throw MeshError(Where(path, number) + ": '" + token +
            "' mixes index forms within one element");
        }
        form = ref.Form();
        // vt and vn indices: non-zero, relative ones within the lines read
        // so far; positive ones against the totals at the end (OBJ allows
        // forward references).
        for (int k = 1; k <= 2; ++k)
        {
          long long index = 0;
          const long long lines = k == 1 ? textureCoordinates : normals;
          if (ref.parts[k].empty())
          {
            continue;
          }
          if (!ParseInteger(ref.parts[k], index) || index == 0 || (index < 0 && -index > lines))
          {
            throw MeshError(Where(path, number) + ": " +
              (k == 1 ? "texture coordinate" : "normal") + " index '" + ref.parts[k] +
              "' out of range");
          }
          (k == 1 ? largestTexture : largestNormal) =
            std::max(k == 1 ? largestTexture : largestNormal, index);
        }
        long long index = 0;
        if (!ParseInteger(ref.parts[0], index))
        {
          throw MeshError(Where(path, number) + ": '" + token + "' is not a vertex index");
        }
        if (index == 0)
        {
          throw MeshError(Where(path, number) + ": vertex index 0 (OBJ indices start at 1)");
        }
        if (index < 0 && -index > vertices)
        {
          throw MeshError(Where(path, number) + ": relative index " + std::to_string(index) +
            " points before the first vertex");
        }
        if (index > largestIndex)
        {
          largestIndex = index;
          largestIndexLine = number;
        }
        ++count;
      }
      const int needed = keyword == "f" ? 3 : (keyword == "l" ? 2 : 1);
      if (count < needed)
      {
        throw MeshError(Where(path, number) + ": a '" + keyword + "' element needs at least " +
          std::to_string(needed) + " vertices (has " + std::to_string(count) + ")");
      }
    }
  }
  if (largestTexture > textureCoordinates || largestNormal > normals)
  {
    throw MeshError("'" + path + "': a face refers to texture coordinate " +
      std::to_string(largestTexture) + " or normal " + std::to_string(largestNormal) + " beyond the file's " +
      std::to_string(textureCoordinates) + " vt and " + std::to_string(normals) + " vn lines");
  }
  if (largestIndex > vertices)
  {
    throw MeshError(Where(path, largestIndexLine) + ": vertex index " +
      std::to_string(largestIndex) + " beyond the file's " + std::to_string(vertices) +
      " vertices");
  }
}

namespace
{

/// The vertex element's row count, after checking that it has x, y and z
/// and that a non-empty face element has its index list.
long long PlyVertexCount(const std::vector<PlyElement>& elements, const std::string& bad)
{
  long long vertexCount = -1;
  for (const PlyElement& e : elements)
  {
    if (e.name == "vertex")
    {
      int xyz = 0;
      for (const PlyProperty& p : e.properties)
      {
        xyz += !p.list && (p.name == "x" || p.name == "y" || p.name == "z");
      }
      if (xyz != 3)
      {
        throw MeshError(bad + "the vertex element has no x, y and z properties");
      }
      vertexCount = e.count;
    }
  }
  if (vertexCount < 0)
  {
    throw MeshError(bad + "no vertex element");
  }
  for (const PlyElement& e : elements)
  {
    if (e.name == "face" && e.count > 0 &&
      std::none_of(e.properties.begin(), e.properties.end(), [](const PlyProperty& p) {
        return p.list && (p.name == "vertex_indices" || p.name == "vertex_index");
      }))
    {
      throw MeshError(bad + "the face element has no 'vertex_indices' list");
    }
  }
  return vertexCount;
}

/// Whether `p` of `e` is the face element's vertex index list.
bool IsPlyFaceList(const PlyElement& e, const PlyProperty& p)
{
  return e.name == "face" && p.list && (p.name == "vertex_indices" || p.name == "vertex_index");
}

/// A face's vertex index, checked against the vertex count.
void CheckPlyIndex(long long index, long long row, long long vertexCount, const std::string& bad)
{
  if (index < 0 || index >= vertexCount)
  {
    throw MeshError(bad + "face " + std::to_string(row) + " has vertex index " +
      std::to_string(index) + " outside 0.." + std::to_string(vertexCount - 1));
  }
}

/// The rows of an ASCII PLY body: every value a finite number, every list
/// as long as it says, every face index a vertex.
void CheckPlyAscii(std::istream& in, const std::vector<PlyElement>& elements,
  long long vertexCount, const std::string& bad)
{
  std::string line;
  for (const PlyElement& e : elements)
  {
    for (long long row = 0; row < e.count; ++row)
    {
      // A row without its end of line is cut off (VTK's reader asserts
      // on it: found by fuzz/MeshReaderFuzzer).
      if (!std::getline(in, line) || in.eof())
      {
        throw MeshError(bad + "data ends in element '" + e.name + "' at row " +
          std::to_string(row) + " of " + std::to_string(e.count) + " (truncated?)");
      }
      std::istringstream tokens(line);
      for (const PlyProperty& p : e.properties)
      {
        std::string token;
        double value = 0;
        if (!(tokens >> token) || !ParseReal(token, value))
        {
          throw MeshError(bad + "element '" + e.name + "' row " + std::to_string(row) +
            ": missing or non-numeric '" + p.name + "'");
        }
        if (!p.list)
        {
          if (!std::isfinite(value))
          {
            throw MeshError(bad + "non-finite (NaN or Inf) '" + p.name + "' in element '" +
              e.name + "' row " + std::to_string(row));
          }
          continue;
        }
        // Range first: converting NaN or 1e300 to an integer is undefined
        // (UBSan, fuzz/MeshReaderFuzzer).
        if (!(value >= 0 && value <= static_cast<double>(kMaxListLength)) ||
          value != std::floor(value))
        {
          throw MeshError(bad + "element '" + e.name + "' row " + std::to_string(row) +
            ": list length '" + token + "'");
        }
        const long long n = static_cast<long long>(value);
        if (n < 0)
        {
          throw MeshError(bad + "element '" + e.name + "' row " + std::to_string(row) +
            ": list length '" + token + "'");
        }
        for (long long k = 0; k < n; ++k)
        {
          long long index = 0;
          if (!(tokens >> token) || !ParseInteger(token, index))
          {
            throw MeshError(bad + "element '" + e.name + "' row " + std::to_string(row) +
              ": the list is shorter than its length " + std::to_string(n));
          }
          if (IsPlyFaceList(e, p))
          {
            CheckPlyIndex(index, row, vertexCount, bad);
          }
        }
      }
    }
  }
}

/// The rows of a binary PLY body: the bytes the fixed-size rows need are
/// present before any is read, every list length in range, every face
/// index a vertex.
void CheckPlyBinary(std::istream& in, const std::vector<PlyElement>& elements, bool bigEndian,
  long long vertexCount, const std::string& bad)
{
  // Scalar-only rows have a fixed size: check the bytes they need before
  // reading anything (a 244-byte file must not claim 2e9 vertices).
  const std::streamoff start = in.tellg();
  in.seekg(0, std::ios::end);
  const long long available = static_cast<long long>(in.tellg() - start);
  in.seekg(start);
  long long needed = 0;
  for (const PlyElement& e : elements)
  {
    long long row = 0;
    for (const PlyProperty& p : e.properties)
    {
      row += p.list ? p.countSize : p.size;
    }
    needed += e.count * row;
    if (needed > available)
    {
      throw MeshError(bad + "the header declares " + std::to_string(e.count) + " '" + e.name +
        "' rows but the file has only " + std::to_string(available) + " bytes of data");
    }
  }
  std::vector<unsigned char> buffer(8 * 1024 * 1024);
  long long buffered = 0, position = 0;
  auto take = [&](long long bytes, const PlyElement& e, long long row) -> const unsigned char* {
    if (position + bytes > buffered)
    {
      const long long keep = buffered - position;
      std::memmove(buffer.data(), buffer.data() + position, static_cast<size_t>(keep));
      in.read(reinterpret_cast<char*>(buffer.data() + keep),
        static_cast<std::streamsize>(buffer.size() - keep));
      buffered = keep + in.gcount();
      position = 0;
      if (bytes > buffered)
      {
        throw MeshError(bad + "data ends in element '" + e.name + "' at row " +
          std::to_string(row) + " of " + std::to_string(e.count) + " (truncated?)");
      }
    }
    const unsigned char* p = buffer.data() + position;
    position += bytes;
    return p;
  };
  for (const PlyElement& e : elements)
  {
    for (long long row = 0; row < e.count; ++row)
    {
      for (const PlyProperty& p : e.properties)
      {
        if (!p.list)
        {
          take(p.size, e, row);
          continue;
        }
        const long long n = ReadInteger(take(p.countSize, e, row), p.countSize, true, bigEndian);
        if (n < 0 || n > kMaxListLength)
        {
          throw MeshError(bad + "element '" + e.name + "' row " + std::to_string(row) +
            ": list length " + std::to_string(n));
        }
        if (IsPlyFaceList(e, p) && !p.integer)
        {
          throw MeshError(bad + "face indices are not integers");
        }
        for (long long k = 0; k < n; ++k)
        {
          const unsigned char* item = take(p.size, e, row);
          if (IsPlyFaceList(e, p))
          {
            CheckPlyIndex(ReadInteger(item, p.size, p.isSigned, bigEndian), row, vertexCount, bad);
          }
        }
      }
    }
  }
}

} // namespace

void PrecheckPly(const std::string& path)
{
  std::ifstream in = Open(path, std::ios::in | std::ios::binary);
  const std::string bad = "malformed PLY '" + path + "': ";
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0)
  {
    throw MeshError(bad + "does not start with 'ply'");
  }
  const PlyHeader header = ReadPlyHeader(in, bad);
  const long long vertexCount = PlyVertexCount(header.elements, bad);
  if (header.format == "ascii")
  {
    CheckPlyAscii(in, header.elements, vertexCount, bad);
    return;
  }
  if (header.format != "binary_little_endian" && header.format != "binary_big_endian")
  {
    throw MeshError(bad + "unknown format '" + header.format + "'");
  }
  CheckPlyBinary(in, header.elements, header.format == "binary_big_endian", vertexCount, bad);
}

void PrecheckStl(const std::string& path)
{
  std::ifstream in = Open(path, std::ios::in | std::ios::binary);
  in.seekg(0, std::ios::end);
  const long long size = static_cast<long long>(in.tellg());
  in.seekg(0);
  {
    char head[256];
    in.read(head, sizeof head);
    const std::streamsize n = in.gcount();
    in.clear();
    in.seekg(0);
    if (precheck::LooksBinaryStl(reinterpret_cast<const unsigned char*>(head), static_cast<size_t>(n)))
    {
      unsigned char header[84];
      if (size < 84 || !in.read(reinterpret_cast<char*>(header), 84) ||
        84 + 50 * ReadInteger(header + 80, 4, false, false) != size)
      {
        throw MeshError("malformed STL '" + path + "': a binary STL of " + std::to_string(size) +
          " bytes whose triangle count does not match its size (truncated or miscounted?)");
      }
      return; // a consistent binary STL
    }
  }
  std::string first;
  in >> first;
  if (first != "solid")
  {
    throw MeshError("malformed STL '" + path + "': a binary STL of " + std::to_string(size) +
      " bytes whose triangle count does not match its size (truncated or miscounted?)");
  }
  // ASCII: complete facets of three vertices, and the closing keyword.
  std::string token;
  long long vertices = 0, facets = 0, ends = 0;
  bool closed = false;
  while (in >> token)
  {
    if (token == "vertex")
    {
      ++vertices;
      for (int c = 0; c < 3; ++c)
      {
        double value = 0;
        if (!(in >> token) || !ParseReal(token, value) || !std::isfinite(value))
        {
          throw MeshError("malformed STL '" + path + "': vertex " + std::to_string(vertices) +
            " lacks three finite coordinates");
        }
      }
    }
    facets += token == "facet";
    ends += token == "endfacet";
    closed |= token == "endsolid";
  }
  if (vertices != 3 * ends || facets != ends || !closed)
  {
    throw MeshError("malformed STL '" + path + "': incomplete facets or no 'endsolid' (truncated?)");
  }
}

} // namespace shadinglab
