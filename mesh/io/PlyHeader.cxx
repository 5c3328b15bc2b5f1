// SPDX-License-Identifier: BSD-3-Clause
#include "PlyHeader.h"

#include "MeshIO.h"
#include "PrecheckCommon.h"

#include <algorithm>
#include <sstream>

namespace shadinglab::ply
{

using precheck::kMaxElementCount;
using precheck::ParseInteger;

bool PlyType(const std::string& type, int& size, bool& integer, bool& isSigned)
{
  static const struct
  {
    const char* name;
    int size;
    bool integer, isSigned;
  } types[] = { { "char", 1, true, true }, { "int8", 1, true, true }, { "uchar", 1, true, false },
    { "uint8", 1, true, false }, { "short", 2, true, true }, { "int16", 2, true, true },
    { "ushort", 2, true, false }, { "uint16", 2, true, false }, { "int", 4, true, true },
    { "int32", 4, true, true }, { "uint", 4, true, false }, { "uint32", 4, true, false },
    { "float", 4, false, true }, { "float32", 4, false, true }, { "double", 8, false, true },
    { "float64", 8, false, true } };
  for (const auto& t : types)
  {
    if (type == t.name)
    {
      size = t.size;
      integer = t.integer;
      isSigned = t.isSigned;
      return true;
    }
  }
  return false;
}

PlyHeader ReadPlyHeader(std::istream& in, const std::string& bad)
{
  std::string line;
  PlyHeader header;
  std::string& format = header.format;
  std::vector<PlyElement>& elements = header.elements;
  bool ended = false;
  for (int lines = 0; lines < 10000 && std::getline(in, line); ++lines)
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    if (std::any_of(line.begin(), line.end(), [](char c) {
          return static_cast<unsigned char>(c) < 0x20 && c != '\t';
        }))
    {
      // VTK's header parser stops at a NUL and reads what follows as the
      // data's shape (a double free found by fuzz/MeshReaderFuzzer).
      throw MeshError(bad + "a control character in the header (line '" +
        line.substr(0, line.find('\0')) + "')");
    }
    std::istringstream tokens(line);
    std::string keyword;
    tokens >> keyword;
    if (keyword == "end_header")
    {
      ended = true;
      break;
    }
    if (keyword == "format")
    {
      tokens >> format;
    }
    else if (keyword == "element")
    {
      PlyElement e;
      std::string count;
      tokens >> e.name >> count;
      if (!ParseInteger(count, e.count) || e.count < 0 || e.count > kMaxElementCount)
      {
        throw MeshError(bad + "element '" + e.name + "' has count '" + count +
          "' (expected 0 to 2^31-1)");
      }
      elements.push_back(e);
    }
    else if (keyword == "property")
    {
      if (elements.empty())
      {
        throw MeshError(bad + "a property before any element");
      }
      PlyProperty p;
      std::string type;
      tokens >> type;
      if (type == "list")
      {
        std::string countType, itemType;
        tokens >> countType >> itemType >> p.name;
        bool countInteger = true;
        p.list = true;
        if (!PlyType(countType, p.countSize, countInteger, p.countSigned) || !countInteger ||
          !PlyType(itemType, p.size, p.integer, p.isSigned))
        {
          throw MeshError(bad + "unknown list types '" + countType + " " + itemType + "'");
        }
      }
      else
      {
        tokens >> p.name;
        if (!PlyType(type, p.size, p.integer, p.isSigned))
        {
          throw MeshError(bad + "unknown property type '" + type + "'");
        }
      }
      elements.back().properties.push_back(p);
    }
    else if (!keyword.empty() && keyword != "comment" && keyword != "obj_info")
    {
      // VTK's reader skips a line it does not know and then misreads the
      // data (a crash found by fuzz/MeshReaderFuzzer): refuse it.
      throw MeshError(bad + "unknown header line '" + line.substr(0, 40) + "'");
    }
  }
  if (!ended)
  {
    throw MeshError(bad + "the header has no 'end_header' (truncated?)");
  }
  return header;
}

} // namespace shadinglab::ply
