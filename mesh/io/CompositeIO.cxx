// SPDX-License-Identifier: BSD-3-Clause
#include "CompositeIO.h"

#include "MeshIO.h"

#include <vtkAppendPolyData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <cstdlib>
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

} // namespace

vtkSmartPointer<vtkPolyData> ReadListing(const std::string& path, bool collection, int depth)
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
    // A .pvd's first time step: every part listed with the smallest timestep.
    double first = std::numeric_limits<double>::infinity();
    for (const Listed& l : listed)
    {
      first = std::min(first, l.timestep);
    }
    std::vector<Listed> kept;
    for (const Listed& l : listed)
    {
      if (l.timestep == first)
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
      block.TakeReference(ReadMeshAt(file, depth + 1));
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

} // namespace shadinglab
