// SPDX-License-Identifier: BSD-3-Clause
// The structural check of a legacy .vtk file made before vtkDataSetReader
// sees it. VTK 9.2's legacy reader trusts the file: a count the file cannot
// hold makes it allocate gigabytes, a value that fails to parse in the
// middle of POINTS leaves a half-built dataset that ReadMeshSimple then
// dereferences (a null read found by fuzz/MeshReaderFuzzer in CI), and cell
// indices beyond the points crash vtkDataSetSurfaceFilter later. So the
// whole file is walked here the way vtkDataReader reads it, token by token
// (binary blocks by their size), and accepted only if every section is
// complete and consistent: counts within the file, every value of its
// type, cell lists well formed with indices within the points, attribute
// arrays exactly as long as the points or cells they belong to. What the
// walk does not know (string arrays, polyhedra, higher-order cells) is
// refused by name rather than passed on.
#include "MeshPrecheck.h"

#include "LegacyVtkWalker.h"
#include "MeshIO.h"

#include <vtkInformationDoubleKey.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkInformationIdTypeKey.h>
#include <vtkInformationIntegerKey.h>
#include <vtkInformationIntegerVectorKey.h>
#include <vtkInformationKeyLookup.h>
#include <vtkInformationStringKey.h>
#include <vtkInformationStringVectorKey.h>
#include <vtkInformationUnsignedLongKey.h>

#include <algorithm>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

namespace shadinglab
{

namespace
{

using namespace legacy_vtk;

using precheck::kMaxImplicitPoints;

using precheck::kMaxComponents;

/// Keys in one METADATA INFORMATION block, and values of one vector key:
/// VTK's writer stores a handful of keys with a few values each (the
/// L2_NORM_RANGE pair); more is a corrupt count VTK would reserve for.
constexpr long long kMaxInformationKeys = 1000;
constexpr long long kMaxInformationLength = 1 << 20;

/// Arrays in one FIELD block (a corrupt count would loop for long).
constexpr long long kMaxFieldArrays = 100000;

/// The keys of a METADATA INFORMATION block, as vtkDataReader::ReadInformation
/// reads them: each key is a "NAME n LOCATION l" line whose DATA layout
/// depends on the type of the key VTK finds under that name (looked up here
/// the same way). Where VTK would warn and go on with its stream in a failed
/// state, or reserve a vector of a negative or huge length, the file is
/// refused instead.
void WalkInformation(Walker& in, long long keys)
{
  for (long long k = 0; k < keys; ++k)
  {
    std::string line;
    do
    {
      if (in.Peek() == EOF)
      {
        in.Fail("the file ends in a METADATA INFORMATION block (truncated?)");
      }
      line = in.RestOfLine();
    } while (line.empty());
    char name[256] = {}, location[256] = {};
    if (line.rfind("NAME ", 0) != 0)
    {
      continue; // VTK ignores the line, and it counts as a key
    }
    if (std::sscanf(line.c_str(), "NAME %255s LOCATION %255s", name, location) != 2)
    {
      in.Fail("INFORMATION line '" + line + "' (NAME key LOCATION class expected)");
    }
    vtkInformationKey* key = vtkInformationKeyLookup::Find(name, location);
    if (!key)
    {
      continue; // unknown to VTK too: it skips the name line only
    }
    const std::string what = std::string("INFORMATION ") + location + "::" + name;
    auto data = [&]()
    {
      if (in.Expect(what.c_str()).rfind("DATA", 0) != 0)
      {
        in.Fail(what + ": no DATA after the NAME line");
      }
    };
    auto number = [&](bool integer)
    {
      const std::string value = in.Expect(what.c_str());
      long long ignored = 0;
      if (integer ? !ParseInteger(value, ignored) : !Walker::IsReal(value))
      {
        in.Fail(what + ": '" + value + "' is not a number of the key's type");
      }
    };
    auto length = [&]()
    {
      const long long n = in.Count(what + " length", 0, kMaxInformationLength);
      return n;
    };
    const bool integerKey = vtkInformationIdTypeKey::SafeDownCast(key) ||
      vtkInformationIntegerKey::SafeDownCast(key) ||
      vtkInformationUnsignedLongKey::SafeDownCast(key);
    if (vtkInformationDoubleKey::SafeDownCast(key) || integerKey)
    {
      data();
      number(integerKey);
      in.RestOfLine();
    }
    else if (vtkInformationDoubleVectorKey::SafeDownCast(key) ||
      vtkInformationIntegerVectorKey::SafeDownCast(key))
    {
      data();
      const long long n = length();
      if (n == 0)
      {
        continue; // VTK leaves the rest of the line unread
      }
      for (long long i = 0; i < n; ++i)
      {
        number(vtkInformationIntegerVectorKey::SafeDownCast(key) != nullptr);
      }
      in.RestOfLine();
    }
    else if (vtkInformationStringKey::SafeDownCast(key))
    {
      const std::string value = in.RestOfLine();
      char token[256] = {};
      if (std::sscanf(value.c_str(), "DATA %255s", token) != 1)
      {
        in.Fail(what + ": no DATA after the NAME line");
      }
    }
    else if (vtkInformationStringVectorKey::SafeDownCast(key))
    {
      data();
      const long long n = length();
      in.RestOfLine();
      for (long long i = 0; i < n; ++i)
      {
        if (in.Peek() == EOF)
        {
          in.Fail(what + ": the file ends in its strings (truncated?)");
        }
        in.RestOfLine();
      }
    }
    // Other key types are not serialized: VTK skips the name line only.
  }
}

/// The dataset's walk: sections in any order VTK accepts, with the counts
/// each later section must agree with.
class LegacyVtkFile
{
public:
  explicit LegacyVtkFile(const std::string& path)
    : In(path)
  {
    std::FILE* f = this->In.File;
    std::fseek(f, 0, SEEK_END);
    this->In.FileSize = std::ftell(f);
    std::fseek(f, 0, SEEK_SET);
  }

  void Walk()
  {
    this->Header();
    std::string token;
    while (this->In.Token(token))
    {
      this->Section(Lower(token), token);
    }
    if (this->Points < 0 && this->Kind != "structured_points" && this->Kind != "rectilinear_grid")
    {
      this->In.Fail("no POINTS section");
    }
    if (this->Kind == "unstructured_grid" && this->Cells > 0 && !this->TypesRead)
    {
      this->In.Fail("CELLS without CELL_TYPES");
    }
    // vtkDataSetSurfaceFilter reads the geometry of a structured dataset
    // without checking it is there (a rectilinear grid without Y and Z
    // coordinates was a null read: fuzz/MeshReaderFuzzer).
    if (this->Kind != "polydata" && this->Kind != "unstructured_grid" && this->Dimensions < 0)
    {
      this->In.Fail("a " + this->Kind + " without DIMENSIONS");
    }
    if (this->Kind == "rectilinear_grid" &&
      !(this->Coordinates[0] && this->Coordinates[1] && this->Coordinates[2]))
    {
      this->In.Fail("a rectilinear grid without all of X_, Y_ and Z_COORDINATES");
    }
  }

private:
  void Header()
  {
    const std::string first = this->In.RestOfLine(false);
    int major = 0, minor = 0;
    if (first.rfind("# vtk DataFile Version", 0) != 0 ||
      std::sscanf(first.c_str() + 22, "%d.%d", &major, &minor) != 2)
    {
      this->In.Fail("the first line is not '# vtk DataFile Version X.Y'");
    }
    this->Major = major;
    this->In.RestOfLine(false); // the title; VTK keeps its first 255 characters
    const std::string format = Lower(this->In.Expect("ASCII or BINARY"));
    if (format != "ascii" && format != "binary")
    {
      this->In.Fail("the third line is '" + format + "', not ASCII or BINARY");
    }
    this->In.Binary = format == "binary";
    if (Lower(this->In.Expect("DATASET")) != "dataset")
    {
      this->In.Fail("no DATASET line after the header");
    }
    this->Kind = Lower(this->In.Expect("the dataset type"));
    if (this->Kind != "polydata" && this->Kind != "unstructured_grid" &&
      this->Kind != "structured_grid" && this->Kind != "structured_points" &&
      this->Kind != "rectilinear_grid")
    {
      this->In.Fail("dataset type '" + this->Kind + "' is not a mesh VTK reads here");
    }
  }

  void Section(const std::string& key, const std::string& token)
  {
    const bool poly = this->Kind == "polydata";
    if (key == "points")
    {
      this->Require(this->Points < 0, "a second POINTS section");
      this->Points = this->In.Count("POINTS count");
      if (this->Dimensions >= 0 && this->Points != this->Dimensions)
      {
        this->In.Fail("POINTS " + std::to_string(this->Points) + " differs from DIMENSIONS' " +
          std::to_string(this->Dimensions) + " points");
      }
      this->In.Values("POINTS", 3 * this->Points, this->In.Type("POINTS"));
      this->MetaData(3);
    }
    else if (poly &&
      (key == "vertices" || key == "lines" || key == "polygons" || key == "triangle_strips"))
    {
      this->Require(this->Blocks.insert(key).second, "a second " + token + " section");
      this->Cells += this->CellBlock(token, nullptr);
    }
    else if (key == "cells" && this->Kind == "unstructured_grid")
    {
      this->Require(this->CellSizes.empty() && this->Cells == 0, "a second CELLS section");
      this->Cells = this->CellBlock(token, &this->CellSizes);
    }
    else if (key == "cell_types" && this->Kind == "unstructured_grid")
    {
      this->CellTypes();
    }
    else if (key == "dimensions" && !poly && this->Kind != "unstructured_grid")
    {
      this->DimensionsLine();
    }
    else if ((key == "spacing" || key == "aspect_ratio" || key == "origin") &&
      this->Kind == "structured_points")
    {
      this->In.TextReals(token, 3);
    }
    else if ((key == "x_coordinates" || key == "y_coordinates" || key == "z_coordinates") &&
      this->Kind == "rectilinear_grid")
    {
      const int axis = key[0] - 'x';
      this->Require(this->Dimensions >= 0, token + " before DIMENSIONS");
      this->Require(!this->Coordinates[axis], "a second " + token);
      this->Coordinates[axis] = true;
      const long long n = this->In.Count(token + " count");
      if (n != this->Axes[axis])
      {
        this->In.Fail(token + " " + std::to_string(n) + " differs from DIMENSIONS' " +
          std::to_string(this->Axes[axis]));
      }
      this->In.Values(token, n, this->In.Type(token));
    }
    else if (key == "field")
    {
      this->Field(this->Tuples); // inside POINT_DATA/CELL_DATA: an attribute field
    }
    else if (key == "point_data" || key == "cell_data")
    {
      const bool points = key == "point_data";
      const long long n = this->In.Count(token + " count");
      const long long expected = points ? this->PointCount() : this->CellCount();
      if (n != expected)
      {
        this->In.Fail(token + " " + std::to_string(n) + " but the dataset has " +
          std::to_string(expected) + (points ? " points" : " cells"));
      }
      this->Tuples = n;
    }
    else if (this->Tuples >= 0)
    {
      this->Attribute(key, token);
    }
    else
    {
      this->In.Fail("unknown keyword '" + token + "' in a " + this->Kind + " dataset");
    }
  }

  void Require(bool ok, const std::string& what) const
  {
    if (!ok)
    {
      this->In.Fail(what);
    }
  }

  long long PointCount() const
  {
    return this->Points >= 0 ? this->Points : std::max(this->Dimensions, 0LL);
  }

  long long CellCount() const
  {
    if (this->Kind == "polydata" || this->Kind == "unstructured_grid")
    {
      return this->Cells;
    }
    long long cells = 1;
    for (long long d : this->Axes)
    {
      cells *= std::max(d - 1, 1LL);
    }
    return this->Dimensions >= 0 ? cells : 0;
  }

  void DimensionsLine()
  {
    this->Require(this->Dimensions < 0, "a second DIMENSIONS line");
    long long points = 1;
    for (int axis = 0; axis < 3; ++axis)
    {
      this->Axes[axis] = this->In.Count("DIMENSIONS", 1, kMaxElementCount);
      points *= this->Axes[axis];
      if (points > kMaxElementCount)
      {
        this->In.Fail("DIMENSIONS give more than 2^31 points");
      }
    }
    if (this->Points >= 0 && points != this->Points)
    {
      this->In.Fail("DIMENSIONS give " + std::to_string(points) + " points but POINTS has " +
        std::to_string(this->Points));
    }
    const bool implicit = this->Kind != "structured_grid";
    if (implicit && points > kMaxImplicitPoints)
    {
      this->In.Fail("DIMENSIONS give " + std::to_string(points) + " points, more than the " +
        std::to_string(kMaxImplicitPoints) + " read from a file that does not store them");
    }
    this->Dimensions = points;
  }

  /// VERTICES / LINES / POLYGONS / TRIANGLE_STRIPS / CELLS: the legacy
  /// layout (n cells in `size` integers, each a count then its indices) or,
  /// from file version 5, OFFSETS and CONNECTIVITY. Returns the cell count.
  long long CellBlock(const std::string& token, std::vector<int>* sizes)
  {
    this->Require(this->Points >= 0, token + " before POINTS");
    const long long n = this->In.Count(token + " count");
    const long long size = this->In.Count(token + " size");
    auto index = [&](long long value)
    {
      if (value < 0 || value >= this->Points)
      {
        this->In.Fail(token + ": point index " + std::to_string(value) + " outside [0, " +
          std::to_string(this->Points) + ")");
      }
    };
    if (this->Major >= 5)
    {
      if (Lower(this->In.Expect("OFFSETS")) != "offsets")
      {
        this->In.Fail(token + " without OFFSETS (file version 5)");
      }
      const ValueType& offsetType = this->In.Type("OFFSETS");
      this->Require(offsetType.integer, "OFFSETS are not integers");
      long long previous = 0;
      this->In.Values("OFFSETS",
        n,
        offsetType,
        [&](long long i, long long offset)
        {
          if ((i == 0 && offset != 0) || offset < previous || offset > size)
          {
            this->In.Fail("OFFSETS value " + std::to_string(offset) + " at " + std::to_string(i) +
              " (offsets start at 0, never decrease, and end at the connectivity size " +
              std::to_string(size) + ")");
          }
          if (sizes && i > 0)
          {
            sizes->push_back(static_cast<int>(std::min<long long>(offset - previous, 1 << 30)));
          }
          previous = offset;
        });
      if (n > 0 && previous != size)
      {
        this->In.Fail("OFFSETS end at " + std::to_string(previous) + " but CONNECTIVITY has " +
          std::to_string(size) + " entries");
      }
      this->Require(n > 0 || size == 0, token + " has connectivity but no offsets");
      if (Lower(this->In.Expect("CONNECTIVITY")) != "connectivity")
      {
        this->In.Fail(token + " without CONNECTIVITY (file version 5)");
      }
      const ValueType& connectivityType = this->In.Type("CONNECTIVITY");
      this->Require(connectivityType.integer, "CONNECTIVITY is not integers");
      this->In.Values(
        "CONNECTIVITY", size, connectivityType, [&](long long, long long value) { index(value); });
      return std::max(n - 1, 0LL);
    }
    // Legacy layout: 4-byte ints in a binary file.
    long long cells = 0, remaining = 0;
    this->In.Values(token,
      size,
      kInt,
      [&](long long, long long value)
      {
        if (remaining > 0)
        {
          index(value);
          --remaining;
          return;
        }
        if (value < 0 || value > size || cells == n)
        {
          this->In.Fail(token + ": cell " + std::to_string(cells) + " of " + std::to_string(n) +
            " has point count " + std::to_string(value) + " (counts and indices disagree)");
        }
        remaining = value;
        ++cells;
        if (sizes)
        {
          sizes->push_back(static_cast<int>(value));
        }
      });
    if (cells != n || remaining != 0)
    {
      this->In.Fail(token + " declares " + std::to_string(n) + " cells in " + std::to_string(size) +
        " integers but they hold " + std::to_string(cells) +
        (remaining ? " and the last is cut short" : ""));
    }
    return n;
  }

  void CellTypes()
  {
    const long long n = this->In.Count("CELL_TYPES count");
    if (n != this->Cells || static_cast<long long>(this->CellSizes.size()) != n)
    {
      this->In.Fail("CELL_TYPES " + std::to_string(n) + " but CELLS has " +
        std::to_string(this->Cells) + " cells");
    }
    this->Require(!this->TypesRead, "a second CELL_TYPES section");
    this->TypesRead = true;
    this->In.Values("CELL_TYPES",
      n,
      kInt,
      [&](long long i, long long type)
      {
        const std::string problem =
          precheck::CheckCellType(type, this->CellSizes[static_cast<size_t>(i)]);
        if (!problem.empty())
        {
          this->In.Fail("cell " + std::to_string(i) + ": " + problem);
        }
      });
  }

  /// A FIELD block; inside POINT_DATA/CELL_DATA (`tuples` >= 0) every array
  /// has exactly that many tuples, since its values are copied per point.
  void Field(long long tuples)
  {
    this->In.Expect("the FIELD name");
    const long long arrays = this->In.Count("FIELD array count", 0, kMaxFieldArrays);
    for (long long a = 0; a < arrays; ++a)
    {
      const std::string name = this->In.Expect("a FIELD array name");
      if (name == "NULL_ARRAY")
      {
        continue;
      }
      const long long components =
        this->In.Count("components of '" + name + "'", 1, kMaxComponents);
      const long long n = this->In.Count("tuples of '" + name + "'");
      if (tuples >= 0 && n != tuples)
      {
        this->In.Fail("field array '" + name + "' has " + std::to_string(n) + " tuples, not " +
          std::to_string(tuples));
      }
      this->In.Values("field array '" + name + "'", components * n, this->In.Type(name));
      this->MetaData(components);
    }
  }

  void Attribute(const std::string& key, const std::string& token)
  {
    const long long n = this->Tuples;
    const std::string name = key == "lookup_table" ? "" : this->In.Expect("an array name");
    long long components = 0;
    if (key == "scalars")
    {
      const ValueType& type = this->In.Type(token);
      const std::string rest = this->In.RestOfLine();
      components = 1;
      if (rest.find_first_not_of(" \t") != std::string::npos &&
        (std::sscanf(rest.c_str(), "%lld", &components) != 1 || components < 1 || components > 4))
      {
        this->In.Fail("SCALARS '" + name + "': component count '" + rest + "' (1 to 4)");
      }
      if (Lower(this->In.Expect("LOOKUP_TABLE")) != "lookup_table")
      {
        this->In.Fail("SCALARS '" + name + "' without its LOOKUP_TABLE line");
      }
      this->In.Expect("the lookup table name");
      this->In.Values("SCALARS '" + name + "'", n * components, type);
    }
    else if (key == "color_scalars")
    {
      components = this->In.Count("COLOR_SCALARS components", 1, 4);
      this->In.Values(
        "COLOR_SCALARS '" + name + "'", n * components, this->In.Binary ? kUnsignedChar : kFloat);
    }
    else if (key == "lookup_table")
    {
      this->In.Expect("a lookup table name");
      const long long size = this->In.Count("LOOKUP_TABLE size");
      this->In.Values("LOOKUP_TABLE", 4 * size, this->In.Binary ? kUnsignedChar : kFloat);
      return;
    }
    else if (key == "vectors" || key == "normals" || key == "tensors" || key == "tensors6" ||
      key == "global_ids" || key == "pedigree_ids")
    {
      components = key == "tensors"            ? 9
        : key == "tensors6"                    ? 6
        : key == "vectors" || key == "normals" ? 3
                                               : 1;
      this->In.Values(token + " '" + name + "'", n * components, this->In.Type(token));
    }
    else if (key == "texture_coordinates")
    {
      components = this->In.Count("TEXTURE_COORDINATES dimension", 1, 3);
      this->In.Values("TEXTURE_COORDINATES '" + name + "'", n * components, this->In.Type(token));
    }
    else
    {
      this->In.Fail("unknown keyword '" + token + "' in POINT_DATA or CELL_DATA");
    }
    this->MetaData(components);
  }

  /// VTK looks for METADATA right after an array; its block ends at a
  /// blank line and holds COMPONENT_NAMES (one line per component) and
  /// INFORMATION blocks (VTK's own writer adds L2_NORM_RANGE).
  void MetaData(long long components)
  {
    while (this->In.Peek() != EOF && std::isspace(this->In.Peek()))
    {
      this->In.Get();
    }
    if (std::tolower(this->In.Peek()) != 'm')
    {
      return;
    }
    std::string token;
    this->In.Token(token);
    if (Lower(token) != "metadata")
    {
      this->In.Fail("unknown keyword '" + token + "'");
    }
    this->In.RestOfLine();
    while (this->In.Peek() != EOF)
    {
      const std::string line = Lower(this->In.RestOfLine());
      if (line.empty())
      {
        return;
      }
      if (line.rfind("component_names", 0) == 0)
      {
        for (long long c = 0; c < components; ++c)
        {
          if (this->In.Peek() == EOF)
          {
            this->In.Fail("the file ends in the COMPONENT_NAMES of METADATA (truncated?)");
          }
          this->In.RestOfLine();
        }
        continue;
      }
      long long keys = 0;
      if (std::sscanf(line.c_str(), "information %lld", &keys) == 1)
      {
        if (keys < 0 || keys > kMaxInformationKeys)
        {
          this->In.Fail("METADATA INFORMATION count " + std::to_string(keys));
        }
        WalkInformation(this->In, keys);
        continue;
      }
      this->In.Fail("METADATA line '" + line + "' (COMPONENT_NAMES or INFORMATION expected)");
    }
  }

  Walker In;
  std::string Kind;
  int Major = 0;
  long long Points = -1, Cells = 0, Dimensions = -1, Tuples = -1;
  long long Axes[3] = { -1, -1, -1 };
  bool Coordinates[3] = { false, false, false };
  std::vector<int> CellSizes;
  bool TypesRead = false;
  std::set<std::string> Blocks; // the polydata cell sections read
};

} // namespace

void PrecheckLegacyVtk(const std::string& path)
{
  LegacyVtkFile(path).Walk();
}

} // namespace shadinglab
