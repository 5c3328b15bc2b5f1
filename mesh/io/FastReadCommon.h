// SPDX-License-Identifier: BSD-3-Clause
// What the fast readers (FastReaders.h) share: the mapped file, the output
// arrays, number parsing. Internal to mesh/io.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include <vtkSmartPointer.h>
#include <vtkType.h>

class vtkFloatArray;
class vtkPolyData;

namespace shadinglab::fastread
{

/// A file mapped read-only for one sequential walk. The pages walked are
/// handed back as the walk goes (Release), so that a 300 MB file adds at
/// most kReleaseStep to the process's resident memory, not its size.
class MappedFile
{
public:
  /// Bytes walked between two releases: large enough that the madvise
  /// calls cost nothing (~20 per 300 MB file), small beside the arrays
  /// the file becomes.
  static constexpr size_t kReleaseStep = size_t(16) << 20;

  explicit MappedFile(const std::string& path); ///< throws MeshError
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  const char* Data() const { return this->data_; }
  size_t Size() const { return this->size_; }
  /// Drops the pages before `walked` (bytes from the start) from this
  /// process's memory (they stay in the page cache): a call per byte
  /// walked is cheap, it acts every kReleaseStep bytes.
  void Release(size_t walked);
  /// Drops the whole pages inside bytes [begin, end): for a walk split
  /// between threads, each releasing what it walked (safe at once for
  /// disjoint ranges; the page two ranges share stays).
  void ReleaseRange(size_t begin, size_t end) const;

private:
  const char* data_ = nullptr;
  size_t size_ = 0;
  size_t released_ = 0;
};

/// The arrays a reader fills: float points, 64-bit offsets and
/// connectivity while reading; Finish hands them to VTK, in 32-bit storage
/// when every id fits (half the memory: 256 MB less on 16M triangles; VTK
/// reads either storage), else in 64-bit (vtkCellArray's default). The id
/// buffers are the reader's own (malloc) until Finish, so that they can be
/// narrowed in place and handed over without a copy.
struct Polygons
{
  vtkSmartPointer<vtkFloatArray> points;
  float* xyz = nullptr;
  vtkTypeInt64* offset = nullptr; ///< numberOfPolygons + 1 entries
  vtkTypeInt64* ids = nullptr;
  int64_t capacity = 0; ///< of `ids`
  int64_t used = 0;
  int64_t polygonCapacity = 0; ///< of `offset`, less its first entry
  /// `offset` and `ids` hold 32-bit values already (a reader that knew
  /// every id fits wrote them so); Finish hands them over as they are.
  bool idsNarrow = false;

  Polygons(const Polygons&) = delete;
  Polygons& operator=(const Polygons&) = delete;
  ~Polygons();
  /// Sizes points and offsets; connectivity for `idsEstimate` ids, grown
  /// as needed (Reserve).
  Polygons(int64_t numberOfPoints, int64_t numberOfPolygons, int64_t idsEstimate);
  /// Room for `more` ids after the `used` ones.
  void Reserve(int64_t more);
  /// Room for polygons up to `count` (offsets grown by half at least).
  void ReservePolygons(int64_t count);
  /// One polygon from text: its vertex count (3 to `maxCount`) and its
  /// ids (each below `numberOfPoints`), appended; false otherwise.
  template <typename Text>
  bool AddPolygon(Text& text, int64_t numberOfPoints, long long maxCount)
  {
    long long count = 0;
    if (!text.Integer(count) || count < 3 || count > maxCount)
    {
      return false;
    }
    this->Reserve(count);
    for (long long k = 0; k < count; ++k)
    {
      long long id = -1;
      if (!text.Integer(id) || id < 0 || id >= numberOfPoints)
      {
        return false;
      }
      this->ids[this->used++] = id;
    }
    return true;
  }
  /// The polydata of these arrays: `numberOfPolygons` (default: all the
  /// offsets sized for) polygons of the `used` ids.
  vtkSmartPointer<vtkPolyData> Finish(int64_t numberOfPolygons = -1);
};

/// Whether every coordinate is finite: a non-finite one goes to the
/// checked path, whose ValidateMesh names the point.
inline bool AllFinite(const float* xyz, int64_t count)
{
  bool finite = true;
  for (int64_t i = 0; i < count; ++i)
  {
    finite &= std::isfinite(xyz[i]);
  }
  return finite;
}

/// Text: a cursor over [at, end) that skips blanks within a line.
struct Text
{
  const char* at;
  const char* end;

  void SkipBlanks()
  {
    while (this->at < this->end && (*this->at == ' ' || *this->at == '\t' || *this->at == '\r'))
    {
      ++this->at;
    }
  }
  bool AtLineEnd()
  {
    this->SkipBlanks();
    return this->at == this->end || *this->at == '\n';
  }
  /// Past the next newline (or to the end).
  void NextLine()
  {
    const void* nl = std::memchr(this->at, '\n', static_cast<size_t>(this->end - this->at));
    this->at = nl ? static_cast<const char*>(nl) + 1 : this->end;
  }
  /// A whole token as a number: for reals what strtod/atof gives (both
  /// are correctly rounded), then the caller's cast. False when the token
  /// is not entirely a number (the checked path then reads the file).
  template <typename T>
  bool Number(T& value)
  {
    this->SkipBlanks();
    const auto r = std::from_chars(this->at, this->end, value);
    if (r.ec != std::errc() || (r.ptr < this->end && !IsSeparator(*r.ptr)))
    {
      return false;
    }
    this->at = r.ptr;
    return true;
  }
  bool Real(double& value) { return this->Number(value); }
  bool Integer(long long& value) { return this->Number(value); }
  /// The next token equals `word` (then skipped).
  bool Word(const char* word)
  {
    this->SkipBlanks();
    const size_t n = std::strlen(word);
    if (static_cast<size_t>(this->end - this->at) < n || std::memcmp(this->at, word, n) != 0 ||
      (this->at + n < this->end && !IsSeparator(this->at[n])))
    {
      return false;
    }
    this->at += n;
    return true;
  }
  static bool IsSeparator(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
};

} // namespace shadinglab::fastread
