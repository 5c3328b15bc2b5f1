// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabSurfaceRepresentation.h"

#include "shadinglab/model/Materials.h"
#include "vtkShadingLabCompositePolyDataMapper.h"
#include "vtkShadingLabPolyDataMapper.h"

#include <vtkCompositeDataDisplayAttributes.h>
#include <vtkObjectFactory.h>
#include <vtkPVView.h>
#include <vtkSmartPointer.h>

namespace sl = shadinglab;

struct vtkShadingLabSurfaceRepresentation::Internals
{
  sl::Material<double> Parameters; ///< from the individual properties
  std::string Preset;              ///< "" or "Custom": use Parameters
  sl::Material<double> Applied;    ///< the last valid material, on the mappers
  std::string Problem;
  std::string AutoChoice; ///< GetAutoChoice's storage
  /// The mappers' block attributes (full and LOD), and the superclass's
  /// BlockAttributeTime they were made at.
  vtkSmartPointer<vtkCompositeDataDisplayAttributes> BlockAttributes[2];
  vtkMTimeType BlockAttributesFrom = 0;
  bool Dirty = true; ///< a material property changed since the last UpdateMaterial
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
  this->Internal->Parameters.model = sl::ReflectanceModel::BlinnPhong;
  this->UpdateMaterial();
}

vtkShadingLabSurfaceRepresentation::~vtkShadingLabSurfaceRepresentation() = default;

namespace
{
template <typename Fn>
void ForBothMappers(vtkMapper* a, vtkMapper* b, Fn&& fn)
{
  for (vtkMapper* m : { a, b })
  {
    if (auto* sm = vtkShadingLabCompositePolyDataMapper::SafeDownCast(m))
    {
      fn(sm);
    }
  }
}
} // namespace

void vtkShadingLabSurfaceRepresentation::SetShadingMode(int mode)
{
  ForBothMappers(this->Mapper, this->LODMapper,
    [&](vtkShadingLabCompositePolyDataMapper* m) { m->SetShadingMode(mode); });
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetMaxError(double maxError)
{
  ForBothMappers(this->Mapper, this->LODMapper,
    [&](vtkShadingLabCompositePolyDataMapper* m) { m->SetMaxError(maxError); });
  this->Modified();
}

const char* vtkShadingLabSurfaceRepresentation::GetAutoChoice()
{
  auto* mapper = vtkShadingLabCompositePolyDataMapper::SafeDownCast(this->Mapper);
  this->Internal->AutoChoice = mapper ? mapper->GetAutoChoices() : std::string();
  return this->Internal->AutoChoice.c_str();
}

void vtkShadingLabSurfaceRepresentation::SetReflectanceModel(int model)
{
  if (model < 0 || model > static_cast<int>(sl::ReflectanceModel::LommelSeeliger))
  {
    vtkErrorMacro("ReflectanceModel must be 0..4 (got " << model << ")");
    return;
  }
  this->Internal->Parameters.model = static_cast<sl::ReflectanceModel>(model);
  this->Internal->Dirty = true;
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetInterpolationSpace(int space)
{
  ForBothMappers(this->Mapper, this->LODMapper,
    [&](vtkShadingLabCompositePolyDataMapper* m) { m->SetPerspectiveCorrect(space == 0); });
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetFastPhongMaxSpread(double degrees)
{
  ForBothMappers(this->Mapper, this->LODMapper,
    [&](vtkShadingLabCompositePolyDataMapper* m) { m->SetFastPhongMaxSpread(degrees); });
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetNormalWeighting(int weighting)
{
  ForBothMappers(this->Mapper, this->LODMapper,
    [&](vtkShadingLabCompositePolyDataMapper* m) { m->SetNormalWeighting(weighting); });
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetFeatureAngle(double degrees)
{
  ForBothMappers(this->Mapper, this->LODMapper,
    [&](vtkShadingLabCompositePolyDataMapper* m) { m->SetFeatureAngle(degrees); });
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetRecomputeNormals(int recompute)
{
  ForBothMappers(this->Mapper, this->LODMapper,
    [&](vtkShadingLabCompositePolyDataMapper* m) { m->SetRecomputeNormals(recompute != 0); });
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetKd(double kd)
{
  this->Internal->Parameters.kd = kd;
  this->Internal->Dirty = true;
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetKs(double ks)
{
  this->Internal->Parameters.ks = ks;
  this->Internal->Dirty = true;
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetShininess(double n)
{
  this->Internal->Parameters.shininess = n;
  this->Internal->Dirty = true;
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetAmbientReflectance(double ra)
{
  this->Internal->Parameters.ambient = sl::Vec3d(ra, ra, ra);
  this->Internal->Dirty = true;
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetSpecularTint(double r, double g, double b)
{
  this->Internal->Parameters.specularColor = sl::Vec3d(r, g, b);
  this->Internal->Dirty = true;
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetBeckmannRoughness(double m0, double m1, double m2, double m3)
{
  // A lobe is used when its m is > 0: the lobe count is the number of
  // leading positive roughnesses.
  const double m[4] = { m0, m1, m2, m3 };
  sl::Material<double>& p = this->Internal->Parameters;
  p.lobeCount = 0;
  for (int k = 0; k < sl::kMaxLobes && m[k] > 0; ++k)
  {
    p.lobes[k].m = m[k];
    p.lobeCount = k + 1;
  }
  if (p.lobeCount == 0)
  {
    p.lobeCount = 1;
    p.lobes[0].m = m0; // rejected by validation with its own message
  }
  this->Internal->Dirty = true;
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetBeckmannWeights(double w0, double w1, double w2, double w3)
{
  const double w[4] = { w0, w1, w2, w3 };
  for (int k = 0; k < sl::kMaxLobes; ++k)
  {
    this->Internal->Parameters.lobes[k].weight = w[k];
  }
  this->Internal->Dirty = true;
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetEta(double r, double g, double b)
{
  this->Internal->Parameters.eta = sl::Vec3d(r, g, b);
  this->Internal->Dirty = true;
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetExtinction(double r, double g, double b)
{
  this->Internal->Parameters.k = sl::Vec3d(r, g, b);
  this->Internal->Dirty = true;
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetSpecularVariant(int variant)
{
  this->Internal->Parameters.variant =
    variant == 1 ? sl::SpecularVariant::Walter2007 : sl::SpecularVariant::CookTorrance1982;
  this->Internal->Dirty = true;
  this->Modified();
}

void vtkShadingLabSurfaceRepresentation::SetMaterialPreset(const char* name)
{
  this->Internal->Preset = name ? name : "";
  this->Internal->Dirty = true;
  this->Modified();
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
    this->UpdateMaterial();
  }
  const int result = this->Superclass::ProcessViewRequest(request, inInfo, outInfo);
  if (result && request == vtkPVView::REQUEST_RENDER())
  {
    this->UpdateBlockAttributes();
  }
  return result;
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

void vtkShadingLabSurfaceRepresentation::UpdateMaterial()
{
  Internals& in = *this->Internal;
  in.Dirty = false;
  sl::Material<double> material = in.Parameters;
  if (!in.Preset.empty() && in.Preset != "Custom")
  {
    const sl::MaterialPreset* preset = sl::FindMaterialPreset(in.Preset);
    if (!preset)
    {
      in.Problem = "unknown material preset '" + in.Preset + "'";
      vtkErrorMacro(<< in.Problem);
      return;
    }
    material = preset->material;
  }
  // The lobe weights are normalized to sum to 1 over the used lobes, so a
  // user may give relative weights (and one lobe always has weight 1).
  double sum = 0;
  for (int k = 0; k < material.lobeCount; ++k)
  {
    sum += material.lobes[k].weight;
  }
  if (sum > 0)
  {
    for (int k = 0; k < material.lobeCount; ++k)
    {
      material.lobes[k].weight /= sum;
    }
  }
  in.Problem = sl::ValidateMaterial(material);
  if (!in.Problem.empty())
  {
    vtkErrorMacro("ShadingLab material: " << in.Problem << " (keeping the last valid material)");
    return;
  }
  in.Applied = material;
  ForBothMappers(this->Mapper, this->LODMapper,
    [&](vtkShadingLabCompositePolyDataMapper* m) { m->SetMaterial(material); });
}

void vtkShadingLabSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Material: " << sl::SerializeMaterial(this->Internal->Applied) << "\n";
}
