// SPDX-License-Identifier: BSD-3-Clause
// A PLY header as the precheck and the fast reader both read it. Internal
// to mesh/io.
#pragma once

#include <istream>
#include <string>
#include <vector>

namespace shadinglab::ply
{

/// One PLY property: a scalar of `size` bytes, or a list (count, items).
struct PlyProperty
{
  std::string name;
  bool list = false;
  int size = 0;      ///< scalar or item size in bytes
  int countSize = 0; ///< list count size in bytes
  bool integer = true;
  bool isSigned = true;
  bool countSigned = false; ///< list count signedness
};

struct PlyElement
{
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

/// What a PLY header declares.
struct PlyHeader
{
  std::string format;
  std::vector<PlyElement> elements;
};

/// A PLY type name's size in bytes and kind; false for an unknown name.
bool PlyType(const std::string& type, int& size, bool& integer, bool& isSigned);

/// A PLY header's format and elements, read up to end_header (at most
/// 10,000 lines), every line checked; MeshError (`bad` first) otherwise.
PlyHeader ReadPlyHeader(std::istream& in, const std::string& bad);

} // namespace shadinglab::ply
