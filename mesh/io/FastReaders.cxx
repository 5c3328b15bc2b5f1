// SPDX-License-Identifier: BSD-3-Clause
#include "FastReaders.h"

#include "FastReadCommon.h"
#include "MeshIO.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt64Array.h>

#include <algorithm>
#include <cstdlib>

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

Polygons::Polygons(int64_t numberOfPoints, int64_t numberOfPolygons, int64_t idsEstimate)
{
  this->points = vtkSmartPointer<vtkFloatArray>::New();
  this->points->SetNumberOfComponents(3);
  this->points->SetNumberOfTuples(numberOfPoints);
  this->xyz = this->points->GetPointer(0);
  this->offsets = vtkSmartPointer<vtkTypeInt64Array>::New();
  this->offsets->SetNumberOfValues(numberOfPolygons + 1);
  this->polygonCapacity = numberOfPolygons;
  this->offset = this->offsets->GetPointer(0);
  this->offset[0] = 0;
  this->connectivity = vtkSmartPointer<vtkTypeInt64Array>::New();
  this->capacity = std::max<int64_t>(idsEstimate, 1);
  this->connectivity->SetNumberOfValues(this->capacity);
  this->ids = this->connectivity->GetPointer(0);
}

void Polygons::Reserve(int64_t more)
{
  if (this->used + more <= this->capacity)
  {
    return;
  }
  this->capacity = std::max(this->used + more, this->capacity + this->capacity / 2);
  this->connectivity->Resize(this->capacity);
  this->connectivity->SetNumberOfValues(this->capacity);
  this->ids = this->connectivity->GetPointer(0);
}

void Polygons::ReservePolygons(int64_t count)
{
  if (count <= this->polygonCapacity)
  {
    return;
  }
  this->polygonCapacity = std::max(count, this->polygonCapacity + this->polygonCapacity / 2);
  this->offsets->Resize(this->polygonCapacity + 1);
  this->offsets->SetNumberOfValues(this->polygonCapacity + 1);
  this->offset = this->offsets->GetPointer(0);
}

vtkSmartPointer<vtkPolyData> Polygons::Finish(int64_t numberOfPolygons)
{
  if (numberOfPolygons >= 0 && numberOfPolygons != this->polygonCapacity)
  {
    this->offsets->Resize(numberOfPolygons + 1);
    this->offsets->SetNumberOfValues(numberOfPolygons + 1);
  }
  if (this->used != this->capacity)
  {
    this->connectivity->Resize(this->used);
    this->connectivity->SetNumberOfValues(this->used);
  }
  auto pts = vtkSmartPointer<vtkPoints>::New();
  pts->SetData(this->points);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->SetData(this->offsets, this->connectivity);
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
