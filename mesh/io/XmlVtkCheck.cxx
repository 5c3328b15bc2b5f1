// SPDX-License-Identifier: BSD-3-Clause
// The check of a VTK XML file (.vtp, .vtu) made before vtkXMLPolyDataReader
// or vtkXMLUnstructuredGridReader reads its data. VTK 9.2's XML readers
// trust the block headers of binary data: a corrupt compression header
// (block count, block sizes) makes them read past their buffers or
// allocate without bound, and a corrupt last offset sizes the connectivity
// they allocate. So the XML is parsed here with VTK's own parser (expat),
// every DataArray's header is read and held against the bytes the file
// has and the values its piece declares, and the arrays that give the
// cells their shape (offsets, connectivity, types) are decoded, with VTK's
// own decompressors, and checked: offsets never decrease and end at the
// connectivity's length, indices lie within the points.
#include "MeshPrecheck.h"

#include "MeshIO.h"
#include "PrecheckCommon.h"

#include <vtkBase64Utilities.h>
#include <vtkDataCompressor.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkZLibDataCompressor.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace shadinglab
{

namespace
{

using precheck::kMaxComponents;
using precheck::kMaxElementCount;
using precheck::kMaxImplicitPoints;

/// Largest uncompressed block of a compressed array: VTK's writer uses
/// 32 KiB blocks by default and at most 2^31 - 1 bytes (int sizes inside).
constexpr long long kMaxBlockSize = (1LL << 31) - 1;

struct WordType
{
  const char* name;
  int size;
  bool integer;
  bool isSigned;
};

constexpr WordType kWordTypes[] = { { "Int8", 1, true, true },
  { "UInt8", 1, true, false },
  { "Int16", 2, true, true },
  { "UInt16", 2, true, false },
  { "Int32", 4, true, true },
  { "UInt32", 4, true, false },
  { "Int64", 8, true, true },
  { "UInt64", 8, true, false },
  { "Float32", 4, false, true },
  { "Float64", 8, false, true } };

class XmlCheck
{
public:
  XmlCheck(const std::string& path, const std::string& type)
    : Path(path)
    , Type(type)
  {
  }

  void Run()
  {
    this->Parser->SetFileName(this->Path.c_str());
    if (!this->Parser->Parse() || !this->Parser->GetRootElement())
    {
      this->Fail("not well-formed XML (truncated or corrupt?)");
    }
    vtkXMLDataElement* root = this->Parser->GetRootElement();
    if (std::strcmp(root->GetName(), "VTKFile") != 0 || !root->GetAttribute("type") ||
      this->Type != root->GetAttribute("type"))
    {
      this->Fail("not a VTKFile of type " + this->Type);
    }
    this->Header(root);
    vtkXMLDataElement* data = root->FindNestedElementWithName(this->Type.c_str());
    if (!data)
    {
      this->Fail("no <" + this->Type + "> element");
    }
    // The whole extent sizes the reader's output (its update extent): an
    // image's or rectilinear grid's points are not in the file, so the
    // file's size does not bound them (fuzzing found a 2e9^3 WholeExtent
    // over a small Piece make the surface filter ask for exabytes).
    if (const char* whole = data->GetAttribute("WholeExtent"))
    {
      long long points = 0, cells = 0;
      this->ExtentCounts(whole, points, cells, "WholeExtent");
      if (this->Type != "StructuredGrid" && points > kMaxImplicitPoints)
      {
        this->Fail("WholeExtent=\"" + std::string(whole) + "\" has " + std::to_string(points) +
          " implicit points, more than " + std::to_string(kMaxImplicitPoints));
      }
    }
    this->FindAppendedData();
    for (int i = 0; i < data->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* child = data->GetNestedElement(i);
      if (std::strcmp(child->GetName(), "Piece") == 0)
      {
        this->Piece(child);
      }
      else if (std::strcmp(child->GetName(), "FieldData") == 0)
      {
        this->Arrays(child, -1);
      }
    }
  }

private:
  [[noreturn]] void Fail(const std::string& what) const
  {
    throw MeshError("malformed VTK XML file '" + this->Path + "': " + what);
  }

  long long Attribute(vtkXMLDataElement* e, const char* name, long long fallback) const
  {
    const char* text = e->GetAttribute(name);
    if (!text)
    {
      return fallback;
    }
    long long value = 0;
    if (!precheck::ParseInteger(text, value) || value < 0 || value > kMaxElementCount)
    {
      this->Fail(std::string(e->GetName()) + " " + name + "=\"" + text + "\"");
    }
    return value;
  }

  void Header(vtkXMLDataElement* root)
  {
    const char* order = root->GetAttribute("byte_order");
    this->BigEndian = order && std::strcmp(order, "BigEndian") == 0;
    const char* header = root->GetAttribute("header_type");
    this->HeaderSize = header && std::strcmp(header, "UInt64") == 0 ? 8 : 4;
    if (header && this->HeaderSize == 4 && std::strcmp(header, "UInt32") != 0)
    {
      this->Fail(std::string("header_type \"") + header + "\"");
    }
    if (const char* compressor = root->GetAttribute("compressor"))
    {
      const std::string name = compressor;
      if (name == "vtkZLibDataCompressor")
      {
        this->Compressor = vtkSmartPointer<vtkZLibDataCompressor>::New();
      }
      else if (name == "vtkLZ4DataCompressor")
      {
        this->Compressor = vtkSmartPointer<vtkLZ4DataCompressor>::New();
      }
      else if (name == "vtkLZMADataCompressor")
      {
        this->Compressor = vtkSmartPointer<vtkLZMADataCompressor>::New();
      }
      else
      {
        this->Fail("unknown compressor \"" + name + "\"");
      }
    }
  }

  /// Where the appended section's bytes start (past its '_') and how many
  /// the file has from there.
  void FindAppendedData()
  {
    this->File.open(this->Path, std::ios::binary);
    this->File.seekg(0, std::ios::end);
    const long long size = static_cast<long long>(this->File.tellg());
    vtkXMLDataElement* appended =
      this->Parser->GetRootElement()->FindNestedElementWithName("AppendedData");
    if (!appended)
    {
      return;
    }
    const char* encoding = appended->GetAttribute("encoding");
    this->AppendedBase64 = !encoding || std::strcmp(encoding, "raw") != 0;
    this->AppendedStart = this->Parser->GetAppendedDataPosition();
    if (this->AppendedStart <= 0 || this->AppendedStart > size)
    {
      this->Fail("AppendedData without its data");
    }
    this->AppendedSize = size - this->AppendedStart;
    // Raw data ends where the closing tag begins (its last occurrence: the
    // data may hold the same bytes by chance); without this, a truncated
    // block would be filled from the tags.
    const long long tail = std::min<long long>(this->AppendedSize, 4096);
    std::string end(static_cast<size_t>(tail), '\0');
    this->File.seekg(size - tail);
    this->File.read(end.data(), tail);
    const size_t close = end.rfind("</AppendedData>");
    if (close != std::string::npos)
    {
      this->AppendedSize -= tail - static_cast<long long>(close);
    }
  }

  /// A structured piece's Extent="x0 x1 y0 y1 z0 z1": its point and cell
  /// counts, each at most kMaxElementCount.
  void ExtentCounts(const char* extent, long long& points, long long& cells,
    const char* what = "Piece Extent") const
  {
    long long e[6];
    const char* p = extent;
    for (long long& v : e)
    {
      char* end = nullptr;
      errno = 0;
      v = std::strtoll(p, &end, 10);
      if (end == p || errno != 0 || v < -kMaxElementCount || v > kMaxElementCount)
      {
        this->Fail(std::string(what) + "=\"" + extent + "\"");
      }
      p = end;
    }
    points = 1;
    cells = 1;
    for (int a = 0; a < 3; ++a)
    {
      const long long d = e[2 * a + 1] - e[2 * a];
      if (d < 0 || points > kMaxElementCount / (d + 1))
      {
        this->Fail(std::string(what) + "=\"" + extent + "\": " +
          (d < 0 ? "decreasing" : "more than " + std::to_string(kMaxElementCount) + " points"));
      }
      points *= d + 1;
      cells *= std::max(d, 1LL);
    }
  }

  void Piece(vtkXMLDataElement* piece)
  {
    long long points = this->Attribute(piece, "NumberOfPoints", 0);
    long long cells = 0;
    // Structured pieces (ImageData, RectilinearGrid, StructuredGrid) give
    // an Extent instead of counts and cell sections.
    if (const char* extent = piece->GetAttribute("Extent"))
    {
      long long structuredCells = 0;
      this->ExtentCounts(extent, points, structuredCells);
      if (this->Type != "StructuredGrid" && points > kMaxImplicitPoints)
      {
        this->Fail("Piece Extent=\"" + std::string(extent) + "\" has " + std::to_string(points) +
          " implicit points, more than " + std::to_string(kMaxImplicitPoints));
      }
      cells = structuredCells;
      if (vtkXMLDataElement* e = piece->FindNestedElementWithName("Coordinates"))
      {
        // RectilinearGrid: one array per axis, as long as the extent says.
        long long e6[6] = {};
        std::sscanf(extent, "%lld %lld %lld %lld %lld %lld", &e6[0], &e6[1], &e6[2], &e6[3],
          &e6[4], &e6[5]);
        int axis = 0;
        for (int i = 0; i < e->GetNumberOfNestedElements() && axis < 3; ++i)
        {
          vtkXMLDataElement* array = e->GetNestedElement(i);
          if (std::strcmp(array->GetName(), "DataArray") == 0)
          {
            this->Values(array, e6[2 * axis + 1] - e6[2 * axis] + 1, false, [](long long, long long) {});
            ++axis;
          }
        }
      }
    }
    for (const char* section : { "Verts", "Lines", "Strips", "Polys", "Cells" })
    {
      const std::string count =
        section == std::string("Cells") ? "NumberOfCells" : std::string("NumberOf") + section;
      const long long n = this->Attribute(piece, count.c_str(), 0);
      cells += n;
      if (vtkXMLDataElement* e = piece->FindNestedElementWithName(section))
      {
        this->CellSection(e, section, n, points);
      }
      else if (n > 0)
      {
        this->Fail(std::string("a piece with ") + count.c_str() + "=" + std::to_string(n) +
          " but no <" + section + ">");
      }
    }
    if (vtkXMLDataElement* e = piece->FindNestedElementWithName("Points"))
    {
      this->Arrays(e, points, 3);
    }
    else if (points > 0 && (!piece->GetAttribute("Extent") || this->Type == "StructuredGrid"))
    {
      // ImageData and RectilinearGrid pieces have implicit points.
      this->Fail("a piece with points but no <Points>");
    }
    if (vtkXMLDataElement* e = piece->FindNestedElementWithName("PointData"))
    {
      this->Arrays(e, points);
    }
    if (vtkXMLDataElement* e = piece->FindNestedElementWithName("CellData"))
    {
      this->Arrays(e, cells);
    }
  }

  /// Every DataArray of a PointData/CellData/Points/FieldData element: its
  /// bytes present and as many as `tuples` of its components (FieldData:
  /// its own NumberOfTuples).
  void Arrays(vtkXMLDataElement* parent, long long tuples, int components = 0)
  {
    for (int i = 0; i < parent->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* array = parent->GetNestedElement(i);
      if (std::strcmp(array->GetName(), "DataArray") != 0)
      {
        continue;
      }
      const long long n = tuples >= 0 ? tuples : this->Attribute(array, "NumberOfTuples", 0);
      const long long c = this->Attribute(array, "NumberOfComponents", 1);
      if (c < 1 || c > kMaxComponents || (components && c != components))
      {
        this->Fail(this->Name(array) + ": NumberOfComponents " + std::to_string(c));
      }
      this->Values(array, n * c, false, [](long long, long long) {});
    }
  }

  /// Verts/Lines/Strips/Polys/Cells: offsets (one end offset per cell),
  /// connectivity (indices within the points) and, for cells, types.
  void CellSection(vtkXMLDataElement* section, const char* name, long long cells, long long points)
  {
    std::map<std::string, vtkXMLDataElement*> arrays;
    for (int i = 0; i < section->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* array = section->GetNestedElement(i);
      if (const char* n = array->GetAttribute("Name"))
      {
        arrays[n] = array;
      }
    }
    if (arrays.count("faces") || arrays.count("faceoffsets"))
    {
      this->Fail("polyhedron cells are not read");
    }
    if (!arrays.count("offsets") || !arrays.count("connectivity"))
    {
      this->Fail(std::string("<") + name + "> without its offsets and connectivity");
    }
    long long previous = 0;
    std::vector<long long> sizes;
    const bool typed = std::strcmp(name, "Cells") == 0;
    this->Values(arrays["offsets"],
      cells,
      true,
      [&](long long i, long long offset)
      {
        if (offset < previous || offset > kMaxElementCount)
        {
          this->Fail(std::string(name) + " offset " + std::to_string(offset) + " at cell " +
            std::to_string(i) + " (offsets never decrease)");
        }
        if (typed)
        {
          sizes.push_back(offset - previous);
        }
        previous = offset;
      });
    this->Values(arrays["connectivity"],
      previous,
      true,
      [&](long long, long long index)
      {
        if (index < 0 || index >= points)
        {
          this->Fail(std::string(name) + ": point index " + std::to_string(index) +
            " outside [0, " + std::to_string(points) + ")");
        }
      });
    if (typed)
    {
      if (!arrays.count("types"))
      {
        this->Fail("<Cells> without types");
      }
      this->Values(arrays["types"],
        cells,
        true,
        [&](long long i, long long type)
        {
          const std::string problem = precheck::CheckCellType(type, sizes[static_cast<size_t>(i)]);
          if (!problem.empty())
          {
            this->Fail("cell " + std::to_string(i) + ": " + problem);
          }
        });
    }
  }

  std::string Name(vtkXMLDataElement* array) const
  {
    const char* name = array->GetAttribute("Name");
    if (!name && array->GetParent())
    {
      return std::string("the ") + array->GetParent()->GetName() + " DataArray";
    }
    return std::string("DataArray '") + (name ? name : "") + "'";
  }

  const WordType& Word(vtkXMLDataElement* array) const
  {
    const char* type = array->GetAttribute("type");
    for (const WordType& t : kWordTypes)
    {
      if (type && std::strcmp(type, t.name) == 0)
      {
        return t;
      }
    }
    this->Fail(
      this->Name(array) + ": type \"" + (type ? type : "") + "\" is not read (numeric types only)");
  }

  long long Decode(const unsigned char* p, int size, bool isSigned) const
  {
    return precheck::ReadInteger(p, size, isSigned, this->BigEndian);
  }

  /// The bytes of a binary array, from the inline base64 text or the
  /// appended section, after its header: the header words are checked
  /// against `expected` bytes and against the bytes present; when `visit`
  /// is given the values are decoded (decompressed) and visited.
  template<typename Visit>
  void Values(vtkXMLDataElement* array, long long count, bool decode, Visit visit)
  {
    const WordType& word = this->Word(array);
    const char* format = array->GetAttribute("format");
    const std::string what = this->Name(array);
    if (decode && !word.integer)
    {
      this->Fail(what + " is not integer");
    }
    if (format && std::strcmp(format, "ascii") == 0)
    {
      this->Ascii(array, count, word, visit);
      return;
    }
    Source source;
    if (format && std::strcmp(format, "appended") == 0)
    {
      const long long offset = this->Attribute(array, "offset", -1);
      if (offset < 0 || offset >= this->AppendedSize)
      {
        this->Fail(what + ": offset outside the appended data");
      }
      source = {
        nullptr, this->AppendedSize - offset, this->AppendedBase64, this->AppendedStart + offset
      };
    }
    else if (format && std::strcmp(format, "binary") == 0)
    {
      source = this->InlineSource(array);
    }
    else
    {
      this->Fail(what + ": format \"" + (format ? format : "") + "\"");
    }
    const long long expected = count * word.size;
    std::vector<unsigned char> bytes = this->Block(source, expected, what, decode);
    if (decode)
    {
      for (long long i = 0; i < count; ++i)
      {
        visit(i, this->Decode(bytes.data() + i * word.size, word.size, word.isSigned));
      }
    }
  }

  /// Encoded bytes: in memory (inline data) or in the file from `start`
  /// (appended data, read on demand rather than held whole).
  struct Source
  {
    const char* data = nullptr;
    long long size = 0;
    bool base64 = false;
    long long start = 0;
  };

  /// The parser keeps no character data of a DataArray: like
  /// vtkXMLDataParser::SeekInlineDataPosition, start after the element's
  /// '>' and its white space; the data runs to the next '<'.
  Source InlineSource(vtkXMLDataElement* array)
  {
    this->File.clear();
    this->File.seekg(array->GetXMLByteIndex());
    char c = 0;
    while (this->File.get(c) && c != '>')
    {
    }
    while (this->File.get(c) && std::isspace(static_cast<unsigned char>(c)))
    {
    }
    // The data ends at its last non-space character before the '<' (base64
    // text is followed by white space and the closing tag).
    const long long start = static_cast<long long>(this->File.tellg()) - 1;
    long long size = 0, read = 0;
    while (this->File && c != '<')
    {
      ++read;
      size = std::isspace(static_cast<unsigned char>(c)) ? size : read;
      this->File.get(c);
    }
    if (!this->File)
    {
      this->Fail(this->Name(array) + ": its inline data does not end (truncated?)");
    }
    return { nullptr, size, true, start };
  }

  void Read(const Source& s, long long at, long long n, char* out)
  {
    if (s.data)
    {
      std::memcpy(out, s.data + at, static_cast<size_t>(n));
      return;
    }
    this->File.clear();
    this->File.seekg(s.start + at);
    if (!this->File.read(out, static_cast<std::streamsize>(n)))
    {
      this->Fail("cannot read its appended data");
    }
  }

  /// `bytes` bytes of a source from `at` (in encoded characters for
  /// base64), decoded; advances `at`.
  std::vector<unsigned char> Take(const Source& s,
    long long& at,
    long long bytes,
    const std::string& what)
  {
    const long long characters = s.base64 ? (bytes + 2) / 3 * 4 : bytes;
    if (bytes == 0)
    {
      return {};
    }
    if (bytes < 0 || characters > s.size - at)
    {
      this->Fail(what + ": its data needs " + std::to_string(characters) + " bytes, the file has " +
        std::to_string(s.size - at) + " (truncated or corrupt header?)");
    }
    std::vector<unsigned char> out(static_cast<size_t>(bytes));
    if (s.base64)
    {
      // Decoded straight into `out`: DecodeSafely stops when it is full.
      std::vector<char> text(static_cast<size_t>(characters));
      this->Read(s, at, characters, text.data());
      const size_t n = vtkBase64Utilities::DecodeSafely(
        reinterpret_cast<const unsigned char*>(text.data()), text.size(), out.data(), out.size());
      if (static_cast<long long>(n) < bytes)
      {
        this->Fail(what + ": corrupt base64 data");
      }
    }
    else
    {
      this->Read(s, at, bytes, reinterpret_cast<char*>(out.data()));
    }
    at += characters;
    return out;
  }

  std::vector<unsigned char> Block(const Source& s,
    long long expected,
    const std::string& what,
    bool decode)
  {
    long long at = 0;
    const int h = this->HeaderSize;
    auto word = [&](const std::vector<unsigned char>& b, size_t k)
    { return this->Decode(b.data() + k * static_cast<size_t>(h), h, false); };
    if (!this->Compressor)
    {
      // Uncompressed: the size word and the data are one (base64) run.
      long long peek = 0;
      const long long size = word(this->Take(s, peek, h, what), 0);
      if (size != expected)
      {
        this->Fail(what + ": its header says " + std::to_string(size) + " bytes, the piece " +
          std::to_string(expected));
      }
      const long long characters = s.base64 ? (h + size + 2) / 3 * 4 : h + size;
      if (characters > s.size)
      {
        this->Fail(what + ": its data needs " + std::to_string(characters) +
          " bytes, the file has " + std::to_string(s.size) + " (truncated?)");
      }
      if (!decode)
      {
        return {};
      }
      std::vector<unsigned char> run = this->Take(s, at, h + size, what);
      run.erase(run.begin(), run.begin() + h);
      return run;
    }
    // Compressed: [blocks, block size, last block size, compressed sizes].
    const std::vector<unsigned char> head = this->Take(s, at, 3LL * h, what);
    const long long blocks = word(head, 0), blockSize = word(head, 1), last = word(head, 2);
    // Ranges first, then the product (a corrupt header overflowed it:
    // UBSan, fuzz/MeshReaderFuzzer).
    const bool sane = blocks >= 0 && blocks <= s.size && blockSize >= 0 &&
      blockSize <= kMaxBlockSize && last >= 0 && last <= blockSize &&
      (blocks <= 1 || blocks - 1 <= expected / std::max(blockSize, 1LL));
    const long long total =
      !sane || blocks == 0 ? 0 : (blocks - 1) * blockSize + (last ? last : blockSize);
    if (!sane || total != expected)
    {
      this->Fail(what + ": compression header (" + std::to_string(blocks) + " blocks of " +
        std::to_string(blockSize) + " bytes, last " + std::to_string(last) +
        ") does not hold the piece's " + std::to_string(expected) + " bytes");
    }
    // The sizes follow the first three words in the same base64 run.
    long long headerAt = 0;
    const std::vector<unsigned char> sizes = this->Take(s, headerAt, (3 + blocks) * h, what);
    at = headerAt;
    long long compressed = 0;
    for (long long b = 0; b < blocks; ++b)
    {
      const long long size = word(sizes, static_cast<size_t>(3 + b));
      if (size < 0 || size > s.size)
      {
        this->Fail(what + ": compressed block " + std::to_string(b) + " of " +
          std::to_string(size) + " bytes");
      }
      compressed += size;
      if (compressed > s.size)
      {
        break; // refused below, before the sum can overflow
      }
    }
    const long long characters = s.base64 ? (compressed + 2) / 3 * 4 : compressed;
    if (characters > s.size - at)
    {
      this->Fail(what + ": its compressed blocks need " + std::to_string(characters) +
        " bytes, the file has " + std::to_string(s.size - at) + " (truncated?)");
    }
    // Every block must decompress to its size (VTK's reader reports a
    // failed block but goes on with the array half filled); the values
    // are kept only when asked for, otherwise one block at a time.
    const std::vector<unsigned char> packed = this->Take(s, at, compressed, what);
    std::vector<unsigned char> out(
      static_cast<size_t>(decode ? total : std::min(total, blockSize)));
    long long in = 0;
    for (long long b = 0; b < blocks; ++b)
    {
      const long long size = word(sizes, static_cast<size_t>(3 + b));
      const long long want = b + 1 == blocks && last ? last : blockSize;
      unsigned char* target = out.data() + (decode ? b * blockSize : 0);
      const size_t got = this->Compressor->Uncompress(
        packed.data() + in, static_cast<size_t>(size), target, static_cast<size_t>(want));
      if (static_cast<long long>(got) != want)
      {
        this->Fail(what + ": compressed block " + std::to_string(b) + " does not decompress");
      }
      in += size;
    }
    if (!decode)
    {
      return {};
    }
    return out;
  }

  template<typename Visit>
  void Ascii(vtkXMLDataElement* array, long long count, const WordType& word, Visit visit)
  {
    const Source source = this->InlineSource(array);
    std::string buffer(static_cast<size_t>(source.size), '\0');
    this->Read(source, 0, source.size, buffer.data());
    const char* text = buffer.c_str();
    long long i = 0;
    const char* p = text;
    while (i < count)
    {
      while (*p && std::isspace(static_cast<unsigned char>(*p)))
      {
        ++p;
      }
      if (!*p)
      {
        break;
      }
      char* end = nullptr;
      if (word.integer)
      {
        errno = 0;
        const long long v = std::strtoll(p, &end, 10);
        if (end == p || errno != 0 || (*end && !std::isspace(static_cast<unsigned char>(*end))))
        {
          this->Fail(
            this->Name(array) + ": ascii value " + std::to_string(i) + " is not an integer");
        }
        visit(i, v);
      }
      else
      {
        std::strtod(p, &end);
        if (end == p || (*end && !std::isspace(static_cast<unsigned char>(*end))))
        {
          this->Fail(this->Name(array) + ": ascii value " + std::to_string(i) + " is not a number");
        }
      }
      p = end;
      ++i;
    }
    if (i < count)
    {
      this->Fail(
        this->Name(array) + ": " + std::to_string(i) + " ascii values of " + std::to_string(count));
    }
  }

  std::string Path, Type;
  vtkNew<vtkXMLDataParser> Parser;
  vtkSmartPointer<vtkDataCompressor> Compressor;
  std::ifstream File;
  long long AppendedStart = 0, AppendedSize = 0;
  bool AppendedBase64 = false;
  bool BigEndian = false;
  int HeaderSize = 4;
};

} // namespace

void PrecheckXmlVtk(const std::string& path, const std::string& type)
{
  XmlCheck(path, type).Run();
}

} // namespace shadinglab
