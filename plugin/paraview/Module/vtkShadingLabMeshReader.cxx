// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabMeshReader.h"

#include "MeshIO.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <cctype>

vtkStandardNewMacro(vtkShadingLabMeshReader);

vtkShadingLabMeshReader::vtkShadingLabMeshReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkShadingLabMeshReader::~vtkShadingLabMeshReader()
{
  this->SetFileName(nullptr);
}

int vtkShadingLabMeshReader::CanReadFile(const char* name)
{
  std::string path = name ? name : "";
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == "ply" || ext == "stl" || ext == "off" || ext == "obj" ? 1 : 0;
}

int vtkShadingLabMeshReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkShadingLabMeshReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->LastError.clear();
  if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) &&
    info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
  {
    return 1; // the whole mesh is piece 0's
  }
  if (!this->FileName || !*this->FileName)
  {
    this->LastError = "no FileName given";
    vtkErrorMacro(<< this->LastError);
    return 0;
  }
  try
  {
    vtkSmartPointer<vtkPolyData> mesh;
    mesh.TakeReference(shadinglab::ReadMesh(this->FileName));
    output->ShallowCopy(mesh);
  }
  catch (const shadinglab::MeshError& e)
  {
    this->LastError = e.what();
    vtkErrorMacro(<< this->LastError);
    return 0;
  }
  return 1;
}

void vtkShadingLabMeshReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
