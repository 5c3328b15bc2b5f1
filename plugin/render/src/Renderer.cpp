// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/Renderer.h"

namespace shadinglab::render
{

bool SupportsModel(ShadingMode mode, ReflectanceModel model)
{
  // Fast Phong expands cosines of the interpolated normal (N.L, N.H, N.V)
  // as quadratics (docs/model.md eq. 2.6-2.8); Cook-Torrance's D, G and F
  // are not functions of those cosines alone in a form the paper expands;
  // Lommel-Seeliger divides by N.L + N.V, which the quadratics do not carry.
  return !(mode == ShadingMode::FastPhong &&
    (model == ReflectanceModel::CookTorrance || model == ReflectanceModel::LommelSeeliger));
}

std::string ValidateRequest(const Scene& scene, const RenderOptions& options)
{
  if (!scene.mesh)
  {
    return "no mesh to render";
  }
  std::string error = ValidateOptions(options);
  if (!error.empty())
  {
    return error;
  }
  error = ValidateMaterial(scene.material);
  if (!error.empty())
  {
    return error;
  }
  if (scene.lighting.lightCount < 0 || scene.lighting.lightCount > kMaxLights)
  {
    return "between 0 and " + std::to_string(kMaxLights) + " lights";
  }
  const Mesh& mesh = *scene.mesh;
  if ((!mesh.scalars.empty() && static_cast<int64_t>(mesh.scalars.size()) != mesh.NumberOfPoints()) ||
    (!mesh.cellScalars.empty() &&
      static_cast<int64_t>(mesh.cellScalars.size()) != mesh.NumberOfPolygons()) ||
    (!mesh.scalars.empty() && !mesh.cellScalars.empty()))
  {
    return "scalars: one per vertex or one per polygon, not both";
  }
  if (scene.colorMap && scene.colorMap->colors.empty())
  {
    return "an empty colour map";
  }
  const Camera& camera = scene.camera;
  if (!IsFinite(camera.position) || !IsFinite(camera.focalPoint) || !IsFinite(camera.viewUp) ||
    !(camera.viewAngle > 0 && camera.viewAngle < 180) || !(camera.nearClip > 0) ||
    !(camera.farClip > camera.nearClip) || !(camera.parallelScale > 0))
  {
    return "invalid camera (non-finite, view angle outside (0,180), or bad clipping range)";
  }
  if (!SupportsModel(options.mode, scene.material.model))
  {
    return "fast-phong evaluates (N.L), (N.H)^n and (R.V)^n quadratics: use a lambert, phong or "
           "blinn-phong material (or another --mode for cook-torrance)";
  }
  return {};
}

} // namespace shadinglab::render
