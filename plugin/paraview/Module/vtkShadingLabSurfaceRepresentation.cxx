// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabSurfaceRepresentation.h"

#include "shadinglab/model/Materials.h"
#include "shadinglab/render/Settings.h"
#include "vtkShadingLabCompositePolyDataMapper.h"
#include "vtkShadingLabPolyDataMapper.h"

#include "vtkShadingLabNormals.h"

#include <vtkCommunicator.h>
#include <vtkCompositeDataDisplayAttributes.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPVView.h>
#include <vtkSmartPointer.h>

namespace sl = shadinglab;

struct vtkShadingLabSurfaceRepresentation::Internals
{
  /// The properties as set. A preset (Settings.preset) replaces the
  /// material parameters when the material is applied (UpdateSettings).
  sl::render::Settings Parameters;
  sl::render::Settings Applied; ///< the last valid settings, on the mappers
  std::string Problem;
  std::string AutoChoice; ///< GetAutoChoice's storage
  std::string BackendChoice; ///< GetBackendChoice's storage
  /// The mappers' block attributes (full and LOD), and the superclass's
  /// BlockAttributeTime they were made at.
  vtkSmartPointer<vtkCompositeDataDisplayAttributes> BlockAttributes[2];
  vtkMTimeType BlockAttributesFrom = 0;
  bool Dirty = true; ///< a property changed since the last UpdateSettings
};

vtkStandardNewMacro(vtkShadingLabSurfaceRepresentation);

vtkShadingLabSurfaceRepresentation::vtkShadingLabSurfaceRepresentation()
  : Internal(new Internals)
{
  // Replace the mappers made by the superclass (as ParaView's
  // Examples/Plugins/Representation): VTK 9.2's vtkCompositePolyDataMapper2
  // does not hand shader replacements to its per-block helpers.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->Mapper = vtkShadingLabCompositePolyDataMapper::New();
  this->LODMapper = vtkShadingLabCompositePolyDataMapper::New();
  this->SetupDefaults();
  this->UpdateSettings();
}

vtkShadingLabSurfaceRepresentation::~vtkShadingLabSurfaceRepresentation() = default;

const char* vtkShadingLabSurfaceRepresentation::GetAutoChoice()
{
  auto* mapper = vtkShadingLabCompositePolyDataMapper::SafeDownCast(this->Mapper);
  this->Internal->AutoChoice = mapper ? mapper->GetAutoChoices() : std::string();
  return this->Internal->AutoChoice.c_str();
}

const char* vtkShadingLabSurfaceRepresentation::GetBackendChoice()
{
  auto* mapper = vtkShadingLabCompositePolyDataMapper::SafeDownCast(this->Mapper);
  this->Internal->BackendChoice = mapper ? mapper->GetBackendChoices() : std::string();
  return this->Internal->BackendChoice.c_str();
}

void vtkShadingLabSurfaceRepresentation::SetSetting(
  const char* key, const std::vector<double>& numbers, const char* text)
{
  const sl::render::SettingValue value{ numbers, text ? text : "" };
  const sl::render::SettingRow* row = sl::render::FindSetting(key ? key : "");
  if (!row)
  {
    vtkErrorMacro("unknown ShadingLab setting '" << (key ? key : "") << "'");
    return;
  }
  Internals& in = *this->Internal;
  if (row->key == "material")
  {
    // The preset is kept apart: it replaces the parameters when applied, so
    // the order in which ParaView sends the properties does not matter.
    sl::render::Settings probe;
    const std::string problem = sl::render::ApplySetting(probe, *row, value, "");
    if (!problem.empty())
    {
      vtkErrorMacro("ShadingLab: " << problem);
      return;
    }
    in.Parameters.preset = probe.preset;
  }
  else
  {
    const std::string problem = sl::render::ApplySetting(in.Parameters, *row, value, "");
    if (!problem.empty())
    {
      vtkErrorMacro("ShadingLab: " << problem);
      return;
    }
    if (row->key == "nk")
    {
      // Read once here (on the server that draws), not per frame.
      const std::string unread = sl::render::ReadNkFile(in.Parameters);
      if (!unread.empty())
      {
        vtkErrorMacro("ShadingLab: " << unread << " (OpticalDataFile cleared)");
        in.Parameters.nkFile.clear();
      }
    }
  }
  in.Dirty = true;
  if (row->group == sl::render::SettingGroup::Mesh)
  {
    // Normals may be made in RequestData (several ranks): run it again.
    this->MarkModified();
  }
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetIntSetting(const char* key, int value)
{
  this->SetSetting(key, { static_cast<double>(value) }, nullptr);
}

void vtkShadingLabSurfaceRepresentation::SetRealSetting1(const char* key, double v0)
{
  this->SetSetting(key, { v0 }, nullptr);
}

void vtkShadingLabSurfaceRepresentation::SetRealSetting3(
  const char* key, double v0, double v1, double v2)
{
  this->SetSetting(key, { v0, v1, v2 }, nullptr);
}

void vtkShadingLabSurfaceRepresentation::SetRealSetting4(
  const char* key, double v0, double v1, double v2, double v3)
{
  this->SetSetting(key, { v0, v1, v2, v3 }, nullptr);
}

void vtkShadingLabSurfaceRepresentation::SetTextSetting(const char* key, const char* value)
{
  this->SetSetting(key, {}, value);
}

const char* vtkShadingLabSurfaceRepresentation::GetMaterialProblem()
{
  return this->Internal->Problem.c_str();
}

int vtkShadingLabSurfaceRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (this->Internal->Dirty)
  {
    this->UpdateSettings();
  }
  const int result = this->Superclass::ProcessViewRequest(request, inInfo, outInfo);
  if (result && request == vtkPVView::REQUEST_RENDER())
  {
    this->UpdateBlockAttributes();
  }
  return result;
}

int vtkShadingLabSurfaceRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  this->MakeDistributedNormals();
  return 1;
}

void vtkShadingLabSurfaceRepresentation::MakeDistributedNormals()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  auto* blocks = vtkCompositeDataSet::SafeDownCast(this->MultiBlockMaker->GetOutputDataObject(0));
  if (!controller || controller->GetNumberOfProcesses() < 2 || !blocks)
  {
    return;
  }
  // Every rank holds the same tree of blocks (some empty): each block is
  // handled by all ranks together, even those with nothing of it.
  const sl::render::NormalSettings& made = this->Internal->Parameters.normals;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(blocks->NewIterator());
  it->SkipEmptyNodesOff();
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto* block = vtkPolyData::SafeDownCast(it->GetCurrentDataObject());
    int needs = block && block->GetNumberOfPolys() > 0 &&
        (made.recompute || !block->GetPointData()->GetNormals())
      ? 1
      : 0;
    int anyone = 0;
    controller->AllReduce(&needs, &anyone, 1, vtkCommunicator::MAX_OP);
    if (!anyone)
    {
      continue;
    }
    vtkNew<vtkPolyData> piece;
    if (block)
    {
      piece->ShallowCopy(block);
    }
    if (made.recompute)
    {
      piece->GetPointData()->SetNormals(nullptr);
    }
    vtkNew<vtkShadingLabNormals> normals;
    normals->SetWeighting(made.weighting);
    normals->SetFeatureAngle(made.featureAngle);
    normals->SetSplitting(made.featureAngle < 180.0);
    normals->SetInputData(piece);
    normals->Update();
    if (block)
    {
      auto result = vtkSmartPointer<vtkPolyData>::New();
      result->ShallowCopy(normals->GetOutput());
      blocks->SetDataSet(it, result);
    }
  }
}

void vtkShadingLabSurfaceRepresentation::UpdateBlockAttributes()
{
  // The superclass hands block colours, opacities and visibility only to a
  // vtkCompositePolyDataMapper2; it stamps BlockAttributeTime when they or
  // the data changed: then ours are made from the same settings
  // (PopulateBlockAttributes) for the data the mappers were just given.
  Internals& in = *this->Internal;
  if (in.BlockAttributesFrom == this->BlockAttributeTime.GetMTime())
  {
    return;
  }
  in.BlockAttributesFrom = this->BlockAttributeTime.GetMTime();
  vtkMapper* mappers[2] = { this->Mapper, this->LODMapper };
  for (int k = 0; k < 2; ++k)
  {
    auto* mapper = vtkShadingLabCompositePolyDataMapper::SafeDownCast(mappers[k]);
    vtkDataObject* data = mapper ? mapper->GetInputDataObject(0, 0) : nullptr;
    if (!data)
    {
      continue;
    }
    if (!in.BlockAttributes[k])
    {
      in.BlockAttributes[k] = vtkSmartPointer<vtkCompositeDataDisplayAttributes>::New();
    }
    this->PopulateBlockAttributes(in.BlockAttributes[k], data);
    mapper->SetBlockAttributes(in.BlockAttributes[k]);
  }
}

void vtkShadingLabSurfaceRepresentation::UpdateSettings()
{
  Internals& in = *this->Internal;
  in.Dirty = false;
  sl::render::Settings settings = in.Parameters;
  if (!settings.preset.empty())
  {
    settings.material = sl::FindMaterialPreset(settings.preset)->material;
  }
  sl::render::NormalizeLobeWeights(settings.material);
  sl::render::ResolveSpectral(settings); // the preset's data, after the preset's material
  in.Problem = sl::render::ValidateSettings(settings);
  if (!in.Problem.empty())
  {
    vtkErrorMacro("ShadingLab material: " << in.Problem << " (keeping the last valid material)");
    settings.material = in.Applied.material;
  }
  in.Applied = settings;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    // On several ranks RequestData has made the normals already
    // (MakeDistributedNormals); the mappers must not remake them locally.
    settings.normals.recompute = false;
  }
  for (vtkMapper* m : { this->Mapper, this->LODMapper })
  {
    if (auto* sm = vtkShadingLabCompositePolyDataMapper::SafeDownCast(m))
    {
      sm->SetSettings(settings);
    }
  }
}

void vtkShadingLabSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (const auto& row : sl::render::SettingsTable())
  {
    if (row.frontEnds & sl::render::kParaView)
    {
      os << indent << row.property << ": "
         << sl::render::FormatSetting(row, row.get(this->Internal->Applied)) << "\n";
    }
  }
}
