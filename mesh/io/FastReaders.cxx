// SPDX-License-Identifier: BSD-3-Clause
#include "FastReaders.h"

#include "FastReadCommon.h"
#include "MeshIO.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>

#include <algorithm>
#include <cstdlib>
#include <new>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace shadinglab
{

// The formats' readers (FastPly.cxx, FastStl.cxx, FastOff.cxx, FastObj.cxx).
vtkSmartPointer<vtkPolyData> ReadFastPly(fastread::MappedFile& file);
vtkSmartPointer<vtkPolyData> ReadFastStl(fastread::MappedFile& file);
vtkSmartPointer<vtkPolyData> ReadFastOff(fastread::MappedFile& file);
vtkSmartPointer<vtkPolyData> ReadFastObj(fastread::MappedFile& file);

namespace fastread
{

MappedFile::MappedFile(const std::string& path)
{
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  struct stat st;
  if (fd < 0 || ::fstat(fd, &st) != 0)
  {
    if (fd >= 0)
    {
      ::close(fd);
    }
    throw MeshError("cannot open '" + path + "'");
  }
  this->size_ = static_cast<size_t>(st.st_size);
  if (this->size_ > 0)
  {
    void* p = ::mmap(nullptr, this->size_, PROT_READ, MAP_PRIVATE, fd, 0);
    if (p == MAP_FAILED)
    {
      ::close(fd);
      throw MeshError("cannot map '" + path + "' into memory");
    }
    ::madvise(p, this->size_, MADV_SEQUENTIAL);
    this->data_ = static_cast<const char*>(p);
  }
  ::close(fd);
}

MappedFile::~MappedFile()
{
  if (this->data_)
  {
    ::munmap(const_cast<char*>(this->data_), this->size_);
  }
}

void MappedFile::Release(size_t walked)
{
  if (walked < this->released_ + kReleaseStep)
  {
    return;
  }
  const size_t page = static_cast<size_t>(::sysconf(_SC_PAGESIZE));
  const size_t upTo = walked / page * page;
  ::madvise(const_cast<char*>(this->data_) + this->released_, upTo - this->released_, MADV_DONTNEED);
  this->released_ = upTo;
}

void MappedFile::ReleaseRange(size_t begin, size_t end) const
{
  const size_t page = static_cast<size_t>(::sysconf(_SC_PAGESIZE));
  const size_t first = (begin + page - 1) / page * page, last = std::min(end, this->size_) / page * page;
  if (last > first)
  {
    ::madvise(const_cast<char*>(this->data_) + first, last - first, MADV_DONTNEED);
  }
}

namespace
{

/// Grows or shrinks a malloc'd id buffer to `count` ids of `bytes` each
/// (at least one, so that null means failure).
vtkTypeInt64* ResizeIds(void* buffer, int64_t count, size_t bytes = sizeof(vtkTypeInt64))
{
  void* grown = std::realloc(buffer, static_cast<size_t>(std::max<int64_t>(count, 1)) * bytes);
  if (!grown)
  {
    throw std::bad_alloc();
  }
  return static_cast<vtkTypeInt64*>(grown);
}

/// `count` int64 ids handed to a new VTK array, which frees them: narrowed
/// to 32 bits in place first when `narrow` (value k moves from byte 8k to
/// byte 4k, never over a value not yet read; skipped when the buffer holds
/// 32-bit values already, `written32`), the buffer then shrunk.
vtkSmartPointer<vtkDataArray> HandOver(vtkTypeInt64* buffer, int64_t count, bool narrow, bool written32)
{
  if (!narrow)
  {
    auto wide = vtkSmartPointer<vtkTypeInt64Array>::New();
    wide->SetArray(ResizeIds(buffer, count), count, 0, vtkAbstractArray::VTK_DATA_ARRAY_FREE);
    return wide;
  }
  auto* narrowed = reinterpret_cast<vtkTypeInt32*>(buffer);
  for (int64_t k = 0; !written32 && k < count; ++k)
  {
    narrowed[k] = static_cast<vtkTypeInt32>(buffer[k]);
  }
  auto ids = vtkSmartPointer<vtkTypeInt32Array>::New();
  ids->SetArray(reinterpret_cast<vtkTypeInt32*>(ResizeIds(buffer, count, sizeof(vtkTypeInt32))),
    count, 0, vtkAbstractArray::VTK_DATA_ARRAY_FREE);
  return ids;
}

} // namespace

Polygons::Polygons(int64_t numberOfPoints, int64_t numberOfPolygons, int64_t idsEstimate)
{
  this->points = vtkSmartPointer<vtkFloatArray>::New();
  this->points->SetNumberOfComponents(3);
  this->points->SetNumberOfTuples(numberOfPoints);
  this->xyz = this->points->GetPointer(0);
  this->polygonCapacity = numberOfPolygons;
  this->offset = ResizeIds(nullptr, numberOfPolygons + 1);
  this->offset[0] = 0;
  this->capacity = std::max<int64_t>(idsEstimate, 1);
  this->ids = ResizeIds(nullptr, this->capacity);
}

Polygons::~Polygons()
{
  std::free(this->offset);
  std::free(this->ids);
}

void Polygons::Reserve(int64_t more)
{
  if (this->used + more <= this->capacity)
  {
    return;
  }
  this->capacity = std::max(this->used + more, this->capacity + this->capacity / 2);
  this->ids = ResizeIds(this->ids, this->capacity);
}

void Polygons::ReservePolygons(int64_t count)
{
  if (count <= this->polygonCapacity)
  {
    return;
  }
  this->polygonCapacity = std::max(count, this->polygonCapacity + this->polygonCapacity / 2);
  this->offset = ResizeIds(this->offset, this->polygonCapacity + 1);
}

vtkSmartPointer<vtkPolyData> Polygons::Finish(int64_t numberOfPolygons)
{
  const int64_t n = numberOfPolygons >= 0 ? numberOfPolygons : this->polygonCapacity;
  // Ids below 2^31 (points and corners both): 32-bit storage.
  const bool narrow =
    this->idsNarrow || (this->points->GetNumberOfTuples() < INT32_MAX && this->used < INT32_MAX);
  vtkSmartPointer<vtkDataArray> offsets = HandOver(this->offset, n + 1, narrow, this->idsNarrow);
  this->offset = nullptr;
  vtkSmartPointer<vtkDataArray> connectivity = HandOver(this->ids, this->used, narrow, this->idsNarrow);
  this->ids = nullptr;
  auto pts = vtkSmartPointer<vtkPoints>::New();
  pts->SetData(this->points);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->SetData(offsets, connectivity);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(pts);
  mesh->SetPolys(polys);
  return mesh;
}

} // namespace fastread

bool FastReadersEnabled()
{
  const char* vtk = std::getenv("SHADINGLAB_VTK_READERS");
  return !(vtk && std::string(vtk) == "1");
}

vtkSmartPointer<vtkPolyData> ReadFast(const std::string& path, const std::string& ext)
{
  if (ext != "ply" && ext != "stl" && ext != "off" && ext != "obj")
  {
    return nullptr;
  }
  fastread::MappedFile file(path);
  if (file.Size() == 0)
  {
    return nullptr;
  }
  if (ext == "ply")
  {
    return ReadFastPly(file);
  }
  if (ext == "stl")
  {
    return ReadFastStl(file);
  }
  return ext == "off" ? ReadFastOff(file) : ReadFastObj(file);
}

} // namespace shadinglab
