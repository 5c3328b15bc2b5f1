// SPDX-License-Identifier: BSD-3-Clause
#include "MeshPreparation.h"

#include "MeshArrays.h"
#include "RepairCheck.h"
#include "vtkMeshRepair.h"
#include "vtkOpenSubdivRefine.h"
#include "vtkWeightedPolyDataNormals.h"

#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <stdexcept>

namespace shadinglab::mesh
{

namespace
{
constexpr const char* kWeightingNames[] = { "uniform", "area", "angle", "max" };

// The filters' int enums are the typed enums' values, checked here.
static_assert(vtkWeightedPolyDataNormals::UNIFORM == static_cast<int>(NormalWeighting::Uniform) &&
  vtkWeightedPolyDataNormals::MAX == static_cast<int>(NormalWeighting::Max));
static_assert(vtkOpenSubdivRefine::AUTO == static_cast<int>(SubdivisionScheme::Auto) &&
  vtkOpenSubdivRefine::CATMULL_CLARK == static_cast<int>(SubdivisionScheme::CatmullClark));
} // namespace

const char* NormalWeightingName(NormalWeighting weighting)
{
  return kWeightingNames[static_cast<int>(weighting)];
}

bool ParseNormalWeighting(const std::string& name, NormalWeighting& weighting)
{
  for (int i = 0; i < 4; ++i)
  {
    if (name == kWeightingNames[i])
    {
      weighting = static_cast<NormalWeighting>(i);
      return true;
    }
  }
  return false;
}

bool ParseSubdivisionScheme(const std::string& name, SubdivisionScheme& scheme)
{
  if (name == "auto" || name == "loop" || name == "catmull-clark")
  {
    scheme = name == "auto" ? SubdivisionScheme::Auto
      : name == "loop"      ? SubdivisionScheme::Loop
                            : SubdivisionScheme::CatmullClark;
    return true;
  }
  return false;
}

std::string ValidatePreparationOptions(const PreparationOptions& o)
{
  if (!(o.featureAngle >= 0 && o.featureAngle <= 180))
  {
    return "feature angle must be in [0, 180] degrees";
  }
  if (!(o.weldTolerance >= 0 && o.weldTolerance <= 0.1))
  {
    return "weld tolerance must be in [0, 0.1] (relative to the bounding box)";
  }
  if (o.subdivisionLevels < 0 || o.subdivisionLevels > kMaxSubdivisionLevels)
  {
    return "subdivision must be 0.." + std::to_string(kMaxSubdivisionLevels) + " levels";
  }
  return {};
}

namespace
{

/// The repair filter with the options' settings; fills the report's counts.
vtkSmartPointer<vtkPolyData> Repair(
  vtkPolyData* input, const PreparationOptions& o, PreparationReport& report)
{
  vtkSmartPointer<vtkPolyData> current = input;
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
  return current;
}

} // namespace

vtkSmartPointer<vtkPolyData> PrepareMesh(
  vtkPolyData* input, const PreparationOptions& o, PreparationReport& report)
{
  const std::string problem = ValidatePreparationOptions(o);
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  vtkSmartPointer<vtkPolyData> current = input;
  // Repair only when asked for a weld or T-junctions, or when the cheap
  // check finds something to repair: a clean 5M-triangle mesh does not pay
  // for the OpenMesh halfedge build.
  bool needed = o.repair && (o.weld || o.fixTJunctions || input->GetNumberOfStrips() > 0);
  if (o.repair && !needed)
  {
    // A fast reader's arrays (float points, 32-bit cells) are read in
    // place; others through a double, 64-bit copy.
    auto* floats = vtkFloatArray::SafeDownCast(input->GetPoints() ? input->GetPoints()->GetData() : nullptr);
    NarrowMeshView narrow;
    if (floats && NarrowPolygonsOf(input, narrow))
    {
      needed = CheckRepairNeeds(FloatNarrowMeshView{ floats->GetPointer(0), narrow.numberOfPoints,
                                  narrow.offsets, narrow.connectivity, narrow.numberOfPolygons })
                 .Any();
    }
    else
    {
      FlatPolygons flat;
      FlatPolygonsFromPolyData(input, flat);
      needed = CheckRepairNeeds(flat).Any();
    }
    report.repairSkipped = !needed;
  }
  if (needed)
  {
    current = Repair(input, o, report);
  }
  if (current->GetNumberOfPolys() == 0)
  {
    throw std::invalid_argument("no polygon left after removing degenerate faces");
  }
  if (o.subdivisionLevels > 0)
  {
    const long long faces = current->GetNumberOfPolys() * (1LL << (2 * o.subdivisionLevels));
    if (faces > kMaxSubdividedFaces)
    {
      throw std::invalid_argument("subdividing " + std::to_string(current->GetNumberOfPolys()) +
        " faces " + std::to_string(o.subdivisionLevels) + " times would make " +
        std::to_string(faces) + " faces (about " + std::to_string(faces * 160 / 1000000000) +
        " GB); the limit is " + std::to_string(kMaxSubdividedFaces) + ": use fewer levels");
    }
    vtkNew<vtkOpenSubdivRefine> refine;
    refine->SetInputData(current);
    refine->SetLevels(o.subdivisionLevels);
    refine->SetScheme(static_cast<int>(o.scheme));
    refine->UseFeatureAngleOn();
    refine->SetFeatureAngle(o.featureAngle);
    refine->GlobalWarningDisplayOff();
    refine->Update();
    if (refine->GetOutput()->GetNumberOfPolys() == 0)
    {
      throw std::invalid_argument(
        "subdivision failed: Loop needs triangles (use --scheme catmull-clark)");
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
    normals->SetWeighting(static_cast<int>(o.weighting));
    normals->SetFeatureAngle(o.featureAngle);
    normals->SetConsistency(!(o.knownConsistent && current == input));
    normals->Update();
    current = normals->GetOutput();
    report.creaseEdges = normals->GetNumberOfCreaseEdges();
    report.splitPoints = normals->GetNumberOfSplitPoints();
    report.weights = NormalWeightingName(o.weighting);
  }
  return current;
}

} // namespace shadinglab::mesh
