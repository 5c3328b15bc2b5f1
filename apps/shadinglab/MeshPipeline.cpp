// SPDX-License-Identifier: BSD-3-Clause
#include "MeshPipeline.h"

#include "vtkMeshRepair.h"
#include "vtkOpenSubdivRefine.h"
#include "vtkWeightedPolyDataNormals.h"

#include <vtkNew.h>
#include <vtkPolyData.h>

#include <cmath>

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

MeshPipelineOptions MeshPipelineFromArguments(const Arguments& args, bool always)
{
  MeshPipelineOptions o;
  o.repair = always || WantsMeshPipeline(args);
  o.computeNormals = o.repair;
  const std::string weights = args.Has("weights") ? args.Get("weights") : args.Get("normals", "area");
  const char* names[] = { "uniform", "area", "angle", "max" };
  o.weights = -1;
  for (int i = 0; i < 4; ++i)
  {
    if (weights == names[i])
    {
      o.weights = i;
    }
  }
  if (o.weights < 0)
  {
    throw UsageError("unknown weights '" + weights + "' (expected uniform, area, angle or max)");
  }
  o.featureAngle = args.GetDouble("feature-angle", 30.0);
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
  if (o.subdivisionLevels < 0 || o.subdivisionLevels > 6)
  {
    throw UsageError("--subdivide must be 0..6 levels");
  }
  const std::string scheme = args.Get("scheme", "auto");
  if (scheme == "auto")
  {
    o.scheme = vtkOpenSubdivRefine::AUTO;
  }
  else if (scheme == "loop")
  {
    o.scheme = vtkOpenSubdivRefine::LOOP;
  }
  else if (scheme == "catmull-clark")
  {
    o.scheme = vtkOpenSubdivRefine::CATMULL_CLARK;
  }
  else
  {
    throw UsageError("unknown --scheme '" + scheme + "' (expected loop or catmull-clark)");
  }
  if (args.Has("scheme") && o.subdivisionLevels == 0)
  {
    throw UsageError("--scheme needs --subdivide N");
  }
  return o;
}

vtkSmartPointer<vtkPolyData> RunMeshPipeline(
  vtkPolyData* input, const MeshPipelineOptions& o, MeshPipelineReport& report)
{
  vtkSmartPointer<vtkPolyData> current = input;
  if (!o.repair)
  {
    return current;
  }
  vtkNew<vtkMeshRepair> repair;
  repair->SetInputData(current);
  repair->SetWeld(o.weld);
  repair->SetWeldTolerance(o.weldTolerance);
  repair->SetFixTJunctions(o.fixTJunctions);
  repair->Update();
  current = repair->GetOutput();
  report.welded = repair->GetNumberOfWeldedPoints();
  report.tJunctionsFixed = repair->GetNumberOfTJunctionsFixed();
  report.degenerateRemoved = repair->GetNumberOfDegenerateCellsRemoved();
  report.nonManifoldEdges = repair->GetNumberOfNonManifoldEdges();
  report.duplicatedPoints = repair->GetNumberOfDuplicatedPoints();
  report.flipped = repair->GetNumberOfFlippedCells();
  if (current->GetNumberOfPolys() == 0)
  {
    throw UsageError("no polygon left after removing degenerate faces");
  }
  if (o.subdivisionLevels > 0)
  {
    vtkNew<vtkOpenSubdivRefine> refine;
    refine->SetInputData(current);
    refine->SetLevels(o.subdivisionLevels);
    refine->SetScheme(o.scheme);
    refine->UseFeatureAngleOn();
    refine->SetFeatureAngle(o.featureAngle);
    refine->GlobalWarningDisplayOff();
    refine->Update();
    if (refine->GetOutput()->GetNumberOfPolys() == 0)
    {
      throw UsageError("subdivision failed: Loop needs triangles (use --scheme catmull-clark)");
    }
    current = refine->GetOutput();
    report.creaseEdges = refine->GetNumberOfCreaseEdges();
    report.scheme = refine->GetSchemeUsed() == vtkOpenSubdivRefine::LOOP ? "loop" : "catmull-clark";
    report.weights = "limit";
    return current; // limit-surface normals
  }
  if (o.computeNormals)
  {
    vtkNew<vtkWeightedPolyDataNormals> normals;
    normals->SetInputData(current);
    normals->SetWeighting(o.weights);
    normals->SetFeatureAngle(o.featureAngle);
    normals->Update();
    current = normals->GetOutput();
    report.creaseEdges = normals->GetNumberOfCreaseEdges();
    report.splitPoints = normals->GetNumberOfSplitPoints();
    const char* names[] = { "uniform", "area", "angle", "max" };
    report.weights = names[o.weights];
  }
  return current;
}

} // namespace shadinglab::cli
