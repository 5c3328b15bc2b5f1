// SPDX-License-Identifier: BSD-3-Clause
#include "CompositeIO.h"
#include <algorithm>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkInformation.h>

#include "MeshIO.h"
#include "MeshPrecheck.h"

#include <vtkAppendPolyData.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkExodusIIReader.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <unistd.h>
#include <fstream>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace shadinglab
{

namespace
{

struct Listed
{
  std::string file;
  double timestep = 0;
};

/// Every <DataSet file="..."> below `e` (a .vtm's blocks nest).
void Collect(vtkXMLDataElement* e, std::vector<Listed>& out, const std::string& path)
{
  for (int i = 0; i < e->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* child = e->GetNestedElement(i);
    if (std::strcmp(child->GetName(), "DataSet") == 0 && child->GetAttribute("file"))
    {
      Listed l;
      l.file = child->GetAttribute("file");
      if (const char* t = child->GetAttribute("timestep"))
      {
        char* end = nullptr;
        l.timestep = std::strtod(t, &end);
        if (end == t)
        {
          throw MeshError("malformed '" + path + "': timestep=\"" + t + "\"");
        }
      }
      out.push_back(l);
      if (out.size() > static_cast<size_t>(kMaxListedFiles))
      {
        throw MeshError("'" + path + "' lists more than " + std::to_string(kMaxListedFiles) + " files");
      }
    }
    Collect(child, out, path);
  }
}

/// Standard error pointed at /dev/null while alive: the Exodus and netCDF
/// libraries print their own multi-line reports there, which would break
/// the one-line error (ours says what failed).
struct SilencedStderr
{
  int saved = -1;
  SilencedStderr()
  {
    std::fflush(stderr);
    saved = dup(2);
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0)
    {
      dup2(null, 2);
      close(null);
    }
  }
  ~SilencedStderr()
  {
    std::fflush(stderr);
    if (saved >= 0)
    {
      dup2(saved, 2);
      close(saved);
    }
  }
  SilencedStderr(const SilencedStderr&) = delete;
  SilencedStderr& operator=(const SilencedStderr&) = delete;
};

} // namespace

vtkSmartPointer<vtkPolyData> ReadListing(
  const std::string& path, bool collection, const ReadOptions& options, int depth)
{
  if (depth >= kMaxListingDepth)
  {
    throw MeshError("'" + path + "': files nested more than " + std::to_string(kMaxListingDepth) +
      " deep (does a listing name itself?)");
  }
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(path.c_str());
  const char* type = collection ? "Collection" : "vtkMultiBlockDataSet";
  vtkXMLDataElement* root = parser->Parse() ? parser->GetRootElement() : nullptr;
  if (!root || std::strcmp(root->GetName(), "VTKFile") != 0 || !root->GetAttribute("type") ||
    std::strcmp(root->GetAttribute("type"), type) != 0)
  {
    throw MeshError("malformed '" + path + "': not a VTKFile of type " + type +
      " (truncated, corrupt or another type)");
  }
  std::vector<Listed> listed;
  Collect(root, listed, path);
  if (collection && !listed.empty())
  {
    // A .pvd's time step (the first, unless --time or --time-step asks
    // another): every part listed with that timestep.
    std::vector<double> times;
    for (const Listed& l : listed)
    {
      times.push_back(l.timestep);
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    const double chosen = times[ChooseTimeStep(times, depth == 0 ? options : ReadOptions{}, path)];
    std::vector<Listed> kept;
    for (const Listed& l : listed)
    {
      if (l.timestep == chosen)
      {
        kept.push_back(l);
      }
    }
    listed.swap(kept);
  }
  if (listed.empty())
  {
    throw MeshError("'" + path + "' lists no data set file");
  }
  const size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
  vtkNew<vtkAppendPolyData> append;
  for (const Listed& l : listed)
  {
    const std::string file = (!l.file.empty() && l.file[0] == '/') ? l.file : dir + l.file;
    vtkSmartPointer<vtkPolyData> block;
    try
    {
      block.TakeReference(ReadMeshAt(file, options, depth + 1));
    }
    catch (const MeshError& e)
    {
      if (depth > 0)
      {
        throw; // named once, by the user's file
      }
      throw MeshError("'" + path + "', block '" + l.file + "': " + e.what());
    }
    append->AddInputData(block);
  }
  append->Update();
  vtkSmartPointer<vtkPolyData> mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(append->GetOutput());
  return mesh;
}

namespace
{

/// Every cell of a block names points the block has: the Exodus library
/// leaves a block's connectivity unset when its variable is missing, and
/// VTK's surface filters index (and assert on) the points unchecked.
void CheckCellPoints(vtkDataSet* data, const std::string& path)
{
  const vtkIdType points = data->GetNumberOfPoints();
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
  {
    data->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      if (ids->GetId(k) < 0 || ids->GetId(k) >= points)
      {
        throw MeshError("malformed Exodus II file '" + path + "': element " + std::to_string(c) +
          " names node " + std::to_string(ids->GetId(k)) + " of a block with " +
          std::to_string(points) + " nodes");
      }
    }
  }
}

} // namespace

vtkSmartPointer<vtkPolyData> ReadExodus(const std::string& path, const ReadOptions& options)
{
  // The netCDF / HDF5 signature first: anything else never reaches the
  // Exodus library.
  char magic[8] = {};
  std::ifstream in(path, std::ios::binary);
  in.read(magic, sizeof magic);
  const bool netcdf = in.gcount() >= 4 && std::memcmp(magic, "CDF", 3) == 0 &&
    (magic[3] == 1 || magic[3] == 2 || magic[3] == 5);
  const bool hdf5 = in.gcount() == 8 && std::memcmp(magic, "\x89HDF\r\n\x1a\n", 8) == 0;
  if (hdf5)
  {
    throw MeshError("cannot read '" + path + "': a netCDF-4 (HDF5) Exodus II file; only the "
                                             "classic netCDF format is read (nccopy -k classic converts)");
  }
  if (!netcdf)
  {
    throw MeshError("cannot read '" + path + "': not an Exodus II file (no netCDF signature)");
  }
  PrecheckNetcdfClassic(path);
  const SilencedStderr quiet;
  vtkNew<vtkExodusIIReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    throw MeshError("cannot read '" + path + "': not an Exodus II file (malformed or truncated)");
  }
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  reader->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK, 1);
  reader->SetAllArrayStatus(vtkExodusIIReader::NODAL, 1);
  reader->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK_ELEM_CONN, 1);
  // The step asked for (--time, --time-step), or the first. A file without
  // time steps has one state, step 0.
  std::vector<double> times;
  vtkInformation* info = reader->GetOutputInformation(0);
  if (info && info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
  {
    const int n = info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    const double* values = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    times.assign(values, values + n);
  }
  if (times.empty())
  {
    times.push_back(0.0);
  }
  reader->SetTimeStep(static_cast<int>(ChooseTimeStep(times, options, path)));
  reader->Update();
  auto* blocks = vtkCompositeDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (reader->GetErrorCode() != 0 || !blocks)
  {
    throw MeshError("cannot read '" + path + "': malformed Exodus II file");
  }
  vtkNew<vtkAppendPolyData> append;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(blocks->NewIterator());
  int leaves = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    if (auto* data = vtkDataSet::SafeDownCast(it->GetCurrentDataObject()))
    {
      CheckCellPoints(data, path);
      append->AddInputData(SurfaceOf(data, options));
      ++leaves;
    }
  }
  if (leaves == 0)
  {
    throw MeshError("cannot read '" + path + "': no element block");
  }
  append->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(append->GetOutput());
  return mesh;
}

} // namespace shadinglab
