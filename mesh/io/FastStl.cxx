// SPDX-License-Identifier: BSD-3-Clause
// The fast STL reader (FastReaders.h): binary files whose size matches
// their triangle count, and ASCII files of one solid written in the
// format's plain form, read as vtkSTLReader reads them with its default
// merging: the corners welded where their coordinates are equal (as
// vtkMergePoints merges them: exactly, -0 equal to +0), points numbered in
// order of first use, triangles whose welded corners coincide dropped.
#include "FastReadCommon.h"
#include "MeshIO.h"
#include "PrecheckCommon.h"

#include <vtkFloatArray.h>
#include <vtkPolyData.h>

#include <cstring>
#include <vector>

namespace shadinglab
{

namespace
{

using fastread::MappedFile;
using fastread::Polygons;

/// Longest ASCII line VTK's reader takes whole (it reads with fgets into
/// 256 bytes); a longer one goes to the checked path.
constexpr size_t kMaxAsciiLine = 254;

/// Corners welded by a hash of their coordinates' bits, in order of first
/// use. Open addressing, at most half full; lookups are made a batch at a
/// time, their slots and then the points those name fetched ahead (the
/// table is larger than the caches, so each lookup would otherwise wait
/// for memory twice).
class Welder
{
public:
  /// Corners looked up together: enough loads in flight to hide memory
  /// latency, few enough that their slots stay cached until probed.
  static constexpr int kBatch = 32;

  explicit Welder(int64_t expectedPoints)
  {
    size_t capacity = 1024;
    while (capacity < 2 * static_cast<size_t>(expectedPoints))
    {
      capacity *= 2;
    }
    this->slots.assign(capacity, -1);
    this->points.reserve(3 * static_cast<size_t>(expectedPoints));
  }

  /// The ids of `n` (<= kBatch) corners given as 3 floats each.
  void Weld(const float* corners, int n, int64_t* ids)
  {
    uint64_t hashes[kBatch];
    const size_t mask = this->slots.size() - 1;
    for (int i = 0; i < n; ++i)
    {
      hashes[i] = Hash(corners + 3 * i);
      __builtin_prefetch(&this->slots[hashes[i] & mask]);
    }
    // The point each first slot names, fetched too: comparing with it was
    // the lookup's second miss (the points are as large as the table, and
    // a scan of 64M triangles made every lookup wait for both). A slot
    // filled by an earlier corner of this batch is probed in Insert all
    // the same: this only fetches.
    for (int i = 0; i < n; ++i)
    {
      const int64_t id = this->slots[hashes[i] & mask];
      if (id >= 0)
      {
        __builtin_prefetch(&this->points[3 * static_cast<size_t>(id)]);
      }
    }
    for (int i = 0; i < n; ++i)
    {
      ids[i] = this->Insert(corners + 3 * i, hashes[i]);
    }
  }

  std::vector<float> points;

private:
  std::vector<int64_t> slots;

  /// The bits of a coordinate with -0 as +0 (they compare equal).
  static uint32_t Bits(float v)
  {
    uint32_t b;
    std::memcpy(&b, &v, 4);
    return b == 0x80000000u ? 0u : b;
  }
  static uint64_t Hash(const float* p)
  {
    uint64_t h = Bits(p[0]) * 0x9E3779B97F4A7C15ull;
    h ^= Bits(p[1]) * 0xC2B2AE3D27D4EB4Full + (h >> 29);
    h ^= Bits(p[2]) * 0x165667B19E3779F9ull + (h >> 32);
    return h ^ (h >> 31);
  }

  int64_t Insert(const float* p, uint64_t hash)
  {
    size_t mask = this->slots.size() - 1;
    for (size_t s = hash & mask;; s = (s + 1) & mask)
    {
      const int64_t id = this->slots[s];
      if (id < 0)
      {
        const int64_t added = static_cast<int64_t>(this->points.size() / 3);
        this->slots[s] = added;
        this->points.insert(this->points.end(), p, p + 3);
        if (2 * static_cast<size_t>(added + 1) > this->slots.size())
        {
          this->Grow();
        }
        return added;
      }
      const float* q = &this->points[3 * static_cast<size_t>(id)];
      if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2])
      {
        return id;
      }
    }
  }

  void Grow()
  {
    std::vector<int64_t> old(2 * this->slots.size(), -1);
    old.swap(this->slots);
    const size_t mask = this->slots.size() - 1;
    for (int64_t id : old)
    {
      if (id >= 0)
      {
        size_t s = Hash(&this->points[3 * static_cast<size_t>(id)]) & mask;
        while (this->slots[s] >= 0)
        {
          s = (s + 1) & mask;
        }
        this->slots[s] = id;
      }
    }
  }
};

/// Welds `n` triangles' corners (9 floats each) and appends those whose
/// three welded corners differ.
void AddTriangles(Welder& welder, const float* corners, int n, Polygons& out, int64_t& polygons)
{
  int64_t ids[Welder::kBatch];
  welder.Weld(corners, 3 * n, ids);
  for (int t = 0; t < n; ++t)
  {
    const int64_t* c = ids + 3 * t;
    if (c[0] != c[1] && c[0] != c[2] && c[1] != c[2])
    {
      out.ids[out.used++] = c[0];
      out.ids[out.used++] = c[1];
      out.ids[out.used++] = c[2];
      out.offset[++polygons] = out.used;
    }
  }
}

/// The welded mesh: points from the welder, polygons `polygons` of `out`.
vtkSmartPointer<vtkPolyData> Finish(Welder& welder, Polygons& out, int64_t polygons)
{
  if (polygons == 0 || !fastread::AllFinite(welder.points.data(), static_cast<int64_t>(welder.points.size())))
  {
    return nullptr;
  }
  out.points->SetNumberOfTuples(static_cast<vtkIdType>(welder.points.size() / 3));
  std::memcpy(out.points->GetPointer(0), welder.points.data(), welder.points.size() * sizeof(float));
  return out.Finish(polygons);
}

/// Triangles per batch of the welder (3 corners each).
constexpr int kTrianglesPerBatch = Welder::kBatch / 3;

vtkSmartPointer<vtkPolyData> ReadBinary(MappedFile& file)
{
  const auto* bytes = reinterpret_cast<const unsigned char*>(file.Data());
  const long long n = precheck::ReadInteger(bytes + 80, 4, false, false);
  if (n <= 0 || 84 + 50 * static_cast<unsigned long long>(n) != file.Size())
  {
    return nullptr;
  }
  Polygons out(0, n, 3 * n);
  Welder welder(n / 2 + 1);
  int64_t polygons = 0;
  float corners[9 * kTrianglesPerBatch];
  for (long long t = 0; t < n; t += kTrianglesPerBatch)
  {
    const int count = static_cast<int>(std::min<long long>(kTrianglesPerBatch, n - t));
    for (int k = 0; k < count; ++k)
    {
      // 12 bytes of normal, then the corners (little-endian floats).
      std::memcpy(corners + 9 * k, bytes + 84 + 50 * (t + k) + 12, 36);
    }
    AddTriangles(welder, corners, count, out, polygons);
    if ((t & 0xffff) == 0)
    {
      file.Release(static_cast<size_t>(84 + 50 * t));
    }
  }
  return Finish(welder, out, polygons);
}

/// Reads one line's first token and checks it is `word` (lines longer
/// than VTK reads whole go to the checked path).
bool Line(fastread::Text& text, const char* word, const char*& lineEnd)
{
  const char* start = text.at;
  const void* nl = std::memchr(start, '\n', static_cast<size_t>(text.end - start));
  lineEnd = nl ? static_cast<const char*>(nl) : text.end;
  if (static_cast<size_t>(lineEnd - start) > kMaxAsciiLine)
  {
    return false;
  }
  fastread::Text line{ start, lineEnd };
  if (!line.Word(word))
  {
    return false;
  }
  text.at = line.at;
  return true;
}

vtkSmartPointer<vtkPolyData> ReadAscii(MappedFile& file)
{
  fastread::Text text{ file.Data(), file.Data() + file.Size() };
  const char* lineEnd = nullptr;
  if (!Line(text, "solid", lineEnd))
  {
    return nullptr;
  }
  text.at = lineEnd;
  // A facet is about 250 bytes: the estimate sizes the arrays, which grow
  // when it is short.
  const int64_t estimate = static_cast<int64_t>(file.Size() / 250) + 1;
  Polygons out(0, estimate, 3 * estimate);
  Welder welder(estimate / 2 + 1);
  int64_t polygons = 0;
  float corners[9 * kTrianglesPerBatch];
  int pending = 0;
  auto skipEmpty = [&]() {
    while (text.at < text.end && fastread::Text::IsSeparator(*text.at))
    {
      ++text.at;
    }
  };
  for (;;)
  {
    skipEmpty();
    if (Line(text, "endsolid", lineEnd))
    {
      text.at = lineEnd;
      skipEmpty();
      if (text.at != text.end)
      {
        return nullptr; // another solid: VTK's reader numbers them
      }
      break;
    }
    if (!Line(text, "facet", lineEnd))
    {
      return nullptr;
    }
    text.at = lineEnd;
    skipEmpty();
    if (!Line(text, "outer", lineEnd))
    {
      return nullptr;
    }
    text.at = lineEnd;
    for (int k = 0; k < 3; ++k)
    {
      skipEmpty();
      if (!Line(text, "vertex", lineEnd))
      {
        return nullptr;
      }
      fastread::Text values{ text.at, lineEnd };
      for (int c = 0; c < 3; ++c)
      {
        double v = 0;
        if (!values.Real(v))
        {
          return nullptr;
        }
        corners[9 * pending + 3 * k + c] = static_cast<float>(v);
      }
      if (!values.AtLineEnd())
      {
        return nullptr;
      }
      text.at = lineEnd;
    }
    skipEmpty();
    if (!Line(text, "endloop", lineEnd))
    {
      return nullptr;
    }
    text.at = lineEnd;
    skipEmpty();
    if (!Line(text, "endfacet", lineEnd))
    {
      return nullptr;
    }
    text.at = lineEnd;
    if (++pending == kTrianglesPerBatch)
    {
      out.ReservePolygons(polygons + pending);
      out.Reserve(3 * pending);
      AddTriangles(welder, corners, pending, out, polygons);
      pending = 0;
      file.Release(static_cast<size_t>(text.at - file.Data()));
    }
  }
  out.ReservePolygons(polygons + pending);
  out.Reserve(3 * pending);
  AddTriangles(welder, corners, pending, out, polygons);
  return Finish(welder, out, polygons);
}

} // namespace

vtkSmartPointer<vtkPolyData> ReadFastStl(MappedFile& file)
{
  const size_t head = std::min<size_t>(file.Size(), 256);
  if (precheck::LooksBinaryStl(reinterpret_cast<const unsigned char*>(file.Data()), head))
  {
    return ReadBinary(file);
  }
  return ReadAscii(file);
}

} // namespace shadinglab
