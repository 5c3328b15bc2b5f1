// SPDX-License-Identifier: BSD-3-Clause
// What the format checks (MeshPrecheck.cxx, LegacyVtkCheck.cxx,
// XmlVtkCheck.cxx) share: the count limits and the parsing of integers,
// from text and from bytes. Internal to mesh/io.
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace shadinglab::precheck
{

/// Largest element count accepted (points, cells, tuples, header counts):
/// 2^31 - 1 is the most VTK's readers address (several keep counts in int),
/// and beyond any mesh this tool renders in its 24 GiB budget; a larger
/// count is a corrupt header.
constexpr long long kMaxElementCount = (1LL << 31) - 1;
/// Largest number of implicit points of an image or rectilinear grid
/// (legacy STRUCTURED_POINTS / RECTILINEAR_GRID, XML ImageData /
/// RectilinearGrid): their points are not stored in the file, so the file's
/// size does not bound them; 2^27 (134M) points is a 512^3 volume, whose
/// boundary surface is already 1.6M quads.
constexpr long long kMaxImplicitPoints = 1LL << 27;

/// Components per tuple of an array: VTK writes at most the 9 of a tensor in
/// practice; 1024 keeps a corrupt count from multiplying a tuple count into
/// an allocation and keeps tuples x components x 8 bytes within 64 bits.
constexpr long long kMaxComponents = 1024;

/// A whole token as a base-10 integer (an embedded NUL, which would end
/// c_str() early, fails: fuzzer find).
inline bool ParseInteger(const std::string& token, long long& value)
{
  if (token.empty())
  {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  value = std::strtoll(token.c_str(), &end, 10);
  return errno == 0 && end == token.c_str() + token.size() && end != token.c_str();
}

/// An integer of `size` bytes (1, 2, 4 or 8) at `p`, little- or big-endian.
inline long long ReadInteger(const unsigned char* p, int size, bool isSigned, bool bigEndian)
{
  uint64_t v = 0;
  for (int i = 0; i < size; ++i)
  {
    const int shift = 8 * (bigEndian ? size - 1 - i : i);
    v |= static_cast<uint64_t>(p[i]) << shift;
  }
  if (isSigned && size < 8 && (v >> (8 * size - 1)) & 1)
  {
    v |= ~uint64_t(0) << (8 * size); // sign extension
  }
  return static_cast<long long>(v);
}

/// Points per cell of the VTK cell types the surface filter handles; -1 for
/// a variable-size type (its least count in `minimum`); -2 for a type
/// refused (polyhedra, higher-order Lagrange and Bezier cells).
inline int FixedPoints(long long type, int& minimum)
{
  minimum = 0;
  switch (type)
  {
    case 0:
      return 0; // VTK_EMPTY_CELL
    case 1:
      return 1; // VTK_VERTEX
    case 2:
      minimum = 1;
      return -1; // VTK_POLY_VERTEX
    case 3:
      return 2; // VTK_LINE
    case 4:
      minimum = 2;
      return -1; // VTK_POLY_LINE
    case 5:
      return 3; // VTK_TRIANGLE
    case 6:
      minimum = 3;
      return -1; // VTK_TRIANGLE_STRIP
    case 7:
      minimum = 3;
      return -1; // VTK_POLYGON
    case 8:
    case 9:
    case 10:
      return 4; // PIXEL, QUAD, TETRA
    case 11:
    case 12:
      return 8; // VOXEL, HEXAHEDRON
    case 13:
      return 6; // WEDGE
    case 14:
      return 5; // PYRAMID
    case 15:
      return 10; // PENTAGONAL_PRISM
    case 16:
      return 12; // HEXAGONAL_PRISM
    case 21:
      return 3; // QUADRATIC_EDGE
    case 22:
      return 6; // QUADRATIC_TRIANGLE
    case 23:
      return 8; // QUADRATIC_QUAD
    case 24:
      return 10; // QUADRATIC_TETRA
    case 25:
      return 20; // QUADRATIC_HEXAHEDRON
    case 26:
      return 15; // QUADRATIC_WEDGE
    case 27:
      return 13; // QUADRATIC_PYRAMID
    default:
      return -2;
  }
}

/// Empty when a VTK cell of `type` may have `points` points; otherwise what
/// is wrong (legacy CELL_TYPES and XML `types` alike).
inline std::string CheckCellType(long long type, long long points)
{
  int minimum = 0;
  const int fixed = FixedPoints(type, minimum);
  if (fixed == -2)
  {
    return "type " + std::to_string(type) + " (polyhedra and higher-order cells are not read)";
  }
  if ((fixed >= 0 && points != fixed) || (fixed == -1 && points < minimum))
  {
    return "type " + std::to_string(type) + " with " + std::to_string(points) + " points";
  }
  return {};
}

/// The share of non-text bytes among the first 256 from which VTK's STL
/// reader takes a file for binary (vtksys::SystemTools::DetectFileType's
/// default percent_bin, 0.05).
constexpr double kStlBinaryFraction = 0.05;

/// Whether VTK's STL reader takes a file starting with these `n` (at most
/// 256) bytes for binary, as vtksys::SystemTools::DetectFileType decides:
/// 5 % or more of them outside 0x20-0x7F, newline, carriage return and tab
/// (a form feed is binary). Decide the same way, or a file checked as ASCII
/// is read as binary with a header count of billions (an 11 GB allocation:
/// fuzz/MeshReaderFuzzer).
inline bool LooksBinaryStl(const unsigned char* head, size_t n)
{
  int binary = 0;
  for (size_t k = 0; k < n; ++k)
  {
    const int c = head[k];
    binary += !((c >= 0x20 && c <= 0x7F) || c == '\n' || c == '\r' || c == '\t');
  }
  return n > 0 && static_cast<double>(binary) / static_cast<double>(n) >= kStlBinaryFraction;
}

} // namespace shadinglab::precheck
