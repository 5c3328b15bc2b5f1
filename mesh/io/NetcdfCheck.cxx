// SPDX-License-Identifier: BSD-3-Clause
// The check of an Exodus II file's netCDF header, made before VTK's Exodus
// reader (and the netCDF library under it) sees the file. Mutated headers
// found by fuzz/MeshReaderFuzzer made that stack spend 16 s rejecting a
// 4.6 KB file (dimensions and variables sized far beyond the file). The
// classic format (CDF-1, CDF-2 64-bit offsets, CDF-5 64-bit data; the
// netCDF "Classic Format Specification") is walked here: every count and
// name within the file, dimensions within kMaxElementCount, every fixed-size
// variable's data inside the file. netCDF-4 (HDF5) files are not read.
#include "MeshPrecheck.h"

#include "MeshIO.h"
#include "PrecheckCommon.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace shadinglab
{

namespace
{

using precheck::kMaxElementCount;

/// The header's tags (netCDF classic format).
constexpr uint32_t kTagDimension = 0x0A;
constexpr uint32_t kTagVariable = 0x0B;
constexpr uint32_t kTagAttribute = 0x0C;
/// Exodus II's default maximum name length (ex_opts' EX_MAX_NAME_LENGTH,
/// 32 characters): the buffers VTK's reader gets names in.
constexpr uint64_t kMaxExodusName = 32;

class NetcdfHeader
{
public:
  NetcdfHeader(const std::string& path, std::vector<unsigned char> bytes)
    : Path(path)
    , Bytes(std::move(bytes))
  {
  }

  void Run()
  {
    const int version = this->Bytes.size() >= 4 ? this->Bytes[3] : 0;
    this->Wide = version == 5;               // CDF-5: 64-bit counts
    this->WideOffsets = version == 2 || version == 5;
    this->At = 4;
    const uint64_t records = this->Count();
    this->Dimensions();
    this->Attributes();
    this->Variables();
    this->Records(records);
    this->NamesOfResults();
  }

private:
  [[noreturn]] void Fail(const std::string& what) const
  {
    throw MeshError("malformed Exodus II file '" + this->Path + "': " + what);
  }

  uint64_t Big(int size)
  {
    if (this->At + size > this->Bytes.size())
    {
      this->Fail("the netCDF header is cut short");
    }
    uint64_t v = 0;
    for (int k = 0; k < size; ++k)
    {
      v = (v << 8) | this->Bytes[this->At + k];
    }
    this->At += size;
    return v;
  }
  uint32_t Tag() { return static_cast<uint32_t>(this->Big(4)); }
  /// A count: 4 bytes (8 in CDF-5), at most kMaxElementCount.
  uint64_t Count()
  {
    const uint64_t n = this->Big(this->Wide ? 8 : 4);
    if (n > static_cast<uint64_t>(kMaxElementCount))
    {
      this->Fail("a count of " + std::to_string(n) + " in the netCDF header");
    }
    return n;
  }
  /// A list's element count: each element takes at least `minBytes`.
  uint64_t ListCount(uint32_t expected, uint64_t minBytes)
  {
    const uint32_t tag = this->Tag();
    const uint64_t n = this->Count();
    if (tag == 0 && n == 0)
    {
      return 0; // ABSENT
    }
    if (tag != expected)
    {
      this->Fail("an unexpected tag in the netCDF header");
    }
    if (n * minBytes > this->Bytes.size() - this->At)
    {
      this->Fail(std::to_string(n) + " header entries in a " + std::to_string(this->Bytes.size()) +
        "-byte file");
    }
    return n;
  }
  void Skip(uint64_t n)
  {
    const uint64_t padded = (n + 3) / 4 * 4;
    if (padded > this->Bytes.size() - this->At)
    {
      this->Fail("the netCDF header is cut short");
    }
    this->At += padded;
  }
  std::string Name()
  {
    const uint64_t n = this->Count();
    const size_t at = this->At;
    this->Skip(n);
    return std::string(reinterpret_cast<const char*>(this->Bytes.data()) + at, n);
  }

  static int TypeSize(uint32_t type)
  {
    switch (type)
    {
      case 1: case 2: case 7: return 1; // byte, char, ubyte
      case 3: case 8: return 2;         // short, ushort
      case 4: case 5: case 9: return 4; // int, float, uint
      case 6: case 10: case 11: return 8; // double, int64, uint64
      default: return 0;
    }
  }

  void Dimensions()
  {
    const uint64_t n = this->ListCount(kTagDimension, 8);
    for (uint64_t d = 0; d < n; ++d)
    {
      const std::string name = this->Name();
      this->DimensionLengths.push_back(this->Count()); // 0: the record dimension
      this->DimensionNames.push_back(name);
      if (name == "num_nodes")
      {
        this->Nodes = this->DimensionLengths.back();
      }
    }
  }

  void Attributes()
  {
    const uint64_t n = this->ListCount(kTagAttribute, 12);
    for (uint64_t a = 0; a < n; ++a)
    {
      this->Name();
      const int size = TypeSize(this->Tag());
      if (size == 0)
      {
        this->Fail("an attribute of unknown type");
      }
      this->Skip(this->Count() * static_cast<uint64_t>(size));
    }
  }

  void Variables()
  {
    const uint64_t n = this->ListCount(kTagVariable, 16);
    for (uint64_t v = 0; v < n; ++v)
    {
      const std::string name = this->Name();
      this->VariableNames.push_back(name);
      const uint64_t rank = this->Count();
      uint64_t values = 1;
      bool record = false;
      for (uint64_t r = 0; r < rank; ++r)
      {
        const uint64_t id = this->Count();
        if (id >= this->DimensionLengths.size())
        {
          this->Fail("a variable over dimension " + std::to_string(id) + " of " +
            std::to_string(this->DimensionLengths.size()));
        }
        const uint64_t length = this->DimensionLengths[id];
        this->LastDimension = length;
        record |= length == 0;
        values *= length == 0 ? 1 : length;
        if (values > static_cast<uint64_t>(kMaxElementCount))
        {
          this->Fail("a variable of more than " + std::to_string(kMaxElementCount) + " values");
        }
      }
      this->Attributes();
      const uint32_t type = this->Tag();
      const int size = TypeSize(type);
      if (size == 0)
      {
        this->Fail("a variable of unknown type");
      }
      this->Big(this->Wide ? 8 : 4); // vsize (informative; recomputed above)
      const uint64_t begin = this->Big(this->WideOffsets ? 8 : 4);
      // A fixed-size variable's data lies inside the file; a record
      // variable's first record starts inside it.
      const uint64_t bytes = record ? 0 : values * static_cast<uint64_t>(size);
      if (record)
      {
        this->RecordBytes += (values * static_cast<uint64_t>(size) + 3) / 4 * 4;
        this->FirstRecord = std::min(this->FirstRecord, begin);
      }
      if (begin > this->Bytes.size() || bytes > this->Bytes.size() - begin)
      {
        this->Fail("a variable's data (" + std::to_string(bytes) + " bytes at " + std::to_string(begin) +
          ") beyond the file's end");
      }
      // Names (eb_names, coor_names, ...: char rows of len_name or
      // len_string): every row holds its terminating NUL (VTK's reader
      // runs strlen over them).
      if (type == 2 && rank >= 2 && !record)
      {
        const uint64_t row = this->LastDimension;
        for (uint64_t r = 0; row > 0 && r < values / row; ++r)
        {
          // Within Exodus's name length: VTK's reader copies at most
          // kMaxExodusName characters and expects the terminator there.
          const unsigned char* first = this->Bytes.data() + begin + r * row;
          const uint64_t reach = std::min<uint64_t>(row, kMaxExodusName + 1);
          if (std::find(first, first + reach, 0) == first + reach)
          {
            this->Fail("name " + std::to_string(r) + " of '" + name + "' is not terminated");
          }
        }
      }
      // Exodus II element connectivity (connect1, connect2, ...): 1-based
      // node numbers, each within num_nodes (VTK's reader indexes its
      // points with them unchecked).
      if (name.rfind("connect", 0) == 0 && !record)
      {
        if (type != 4 && type != 10)
        {
          this->Fail("connectivity '" + name + "' is not of integers");
        }
        for (uint64_t k = 0; k < values; ++k)
        {
          uint64_t raw = 0;
          for (int b = 0; b < size; ++b)
          {
            raw = (raw << 8) | this->Bytes[begin + k * size + b];
          }
          const int64_t node = size == 4 ? static_cast<int32_t>(raw) : static_cast<int64_t>(raw);
          if (node < 1 || static_cast<uint64_t>(node) > this->Nodes)
          {
            this->Fail("'" + name + "' names node " + std::to_string(node) + " of " +
              std::to_string(this->Nodes));
          }
        }
      }
    }
  }

  /// The records (time steps) lie inside the file: a header claiming
  /// millions of them made the Exodus library read (and VTK allocate) for
  /// minutes. Without record variables, at most one per byte of the file.
  void Records(uint64_t records) const
  {
    const uint64_t size = this->Bytes.size();
    const bool inside = this->RecordBytes == 0
      ? records <= size
      : records == 0 ||
        (this->FirstRecord <= size && records - 1 <= (size - this->FirstRecord) / this->RecordBytes);
    if (!inside)
    {
      this->Fail(std::to_string(records) + " records (time steps) in a " + std::to_string(size) +
        "-byte file");
    }
  }

  /// Every count of result variables (num_nod_var, num_elem_var,
  /// num_glo_var, ...) comes with their names (name_nod_var, ...): the
  /// Exodus library leaves the caller's name buffers untouched when the
  /// names are missing, and VTK's reader then runs strlen over them.
  void NamesOfResults() const
  {
    const std::string prefix = "num_", suffix = "_var";
    for (size_t d = 0; d < this->DimensionNames.size(); ++d)
    {
      const std::string& dim = this->DimensionNames[d];
      if (dim.size() <= prefix.size() + suffix.size() || dim.rfind(prefix, 0) != 0 ||
        dim.compare(dim.size() - suffix.size(), suffix.size(), suffix) != 0 ||
        this->DimensionLengths[d] == 0)
      {
        continue;
      }
      const std::string names = "name_" + dim.substr(prefix.size());
      if (std::find(this->VariableNames.begin(), this->VariableNames.end(), names) ==
        this->VariableNames.end())
      {
        this->Fail("'" + dim + "' without '" + names + "'");
      }
    }
  }

  std::string Path;
  std::vector<unsigned char> Bytes;
  size_t At = 0;
  bool Wide = false, WideOffsets = false;
  std::vector<uint64_t> DimensionLengths;
  std::vector<std::string> DimensionNames, VariableNames;
  uint64_t Nodes = 0;         ///< the num_nodes dimension
  uint64_t RecordBytes = 0;   ///< one record of every record variable
  uint64_t FirstRecord = UINT64_MAX; ///< where the record data starts
  uint64_t LastDimension = 0; ///< the last dimension of the variable being read
};

} // namespace

void PrecheckNetcdfClassic(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> bytes(
    (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  NetcdfHeader(path, std::move(bytes)).Run();
}

} // namespace shadinglab
