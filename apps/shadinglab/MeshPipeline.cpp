// SPDX-License-Identifier: BSD-3-Clause
#include "MeshPipeline.h"

#include "shadinglab/render/Settings.h"

#include <string>

namespace shadinglab::cli
{

bool WantsMeshPipeline(const Arguments& args)
{
  for (const char* o : { "weights", "normals", "feature-angle", "weld", "fix-t-junctions", "subdivide", "scheme" })
  {
    if (args.Has(o))
    {
      return true;
    }
  }
  return false;
}

mesh::PreparationOptions MeshPipelineFromArguments(const Arguments& args, bool always)
{
  mesh::PreparationOptions o;
  o.repair = always || WantsMeshPipeline(args);
  o.computeNormals = o.repair;
  // The defaults are the settings table's (render::Settings::normals).
  const render::NormalSettings defaults;
  o.weighting = static_cast<mesh::NormalWeighting>(defaults.weighting);
  const std::string weights = args.Has("weights") ? args.Get("weights")
                                                  : args.Get("normals", mesh::NormalWeightingName(o.weighting));
  if (!mesh::ParseNormalWeighting(weights, o.weighting))
  {
    throw UsageError("unknown weights '" + weights + "' (expected uniform, area, angle or max)");
  }
  o.featureAngle = args.GetDouble("feature-angle", defaults.featureAngle);
  if (!(o.featureAngle >= 0 && o.featureAngle <= 180))
  {
    throw UsageError("--feature-angle must be in [0, 180] degrees");
  }
  if (args.Has("weld"))
  {
    o.weld = true;
    const std::string tol = args.Get("weld");
    if (!tol.empty())
    {
      o.weldTolerance = ParseDouble(tol, "--weld");
      if (!(o.weldTolerance >= 0 && o.weldTolerance <= 0.1))
      {
        throw UsageError("--weld tolerance must be in [0, 0.1] (relative to the bounding box)");
      }
    }
  }
  o.fixTJunctions = args.Has("fix-t-junctions");
  o.subdivisionLevels = args.GetInt("subdivide", 0);
  if (o.subdivisionLevels < 0 || o.subdivisionLevels > mesh::kMaxSubdivisionLevels)
  {
    throw UsageError("--subdivide must be 0.." + std::to_string(mesh::kMaxSubdivisionLevels) +
      " levels");
  }
  const std::string scheme = args.Get("scheme", "auto");
  if (!mesh::ParseSubdivisionScheme(scheme, o.scheme))
  {
    throw UsageError("unknown --scheme '" + scheme + "' (expected loop or catmull-clark)");
  }
  if (args.Has("scheme") && o.subdivisionLevels == 0)
  {
    throw UsageError("--scheme needs --subdivide N");
  }
  if ((args.Has("weights") || args.Has("normals")) && o.subdivisionLevels > 0)
  {
    // Not silently ignored: the refined mesh's normals are the limit
    // surface's own, whatever weighting was asked for.
    throw UsageError("--" + std::string(args.Has("weights") ? "weights" : "normals") + " " +
      weights + " has no effect with --subdivide: the normals then come from the limit surface");
  }
  return o;
}

} // namespace shadinglab::cli
