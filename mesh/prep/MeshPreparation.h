// SPDX-License-Identifier: BSD-3-Clause
// The one mesh-preparation step (repair, then subdivision with limit normals
// or weighted vertex normals), with typed options: used by the CLI's
// 'normals' and 'render', and meant for the explorer and the ParaView
// filters. The input is never modified.
#pragma once

#include "VertexNormals.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace shadinglab::mesh
{

enum class SubdivisionScheme
{
  Auto,        ///< Loop for all-triangle meshes, Catmull-Clark otherwise
  Loop,        ///< triangles only
  CatmullClark ///< quads and polygons
};

/// Largest subdivision level: each level multiplies the face count by 4,
/// so 6 levels are 4096 faces per input face.
constexpr int kMaxSubdivisionLevels = 6;

/// Largest face count a subdivision may produce: OpenSubdiv's refiner keeps
/// every level's topology (~100 bytes per face at the last level) and the
/// output holds points, limit normals and connectivity (~60 bytes per
/// face), so 2^25 (33.5M) faces is about 5.4 GB, a quarter of the 24 GiB
/// machines this runs on. Asking for more is an error that says how many
/// faces it would make, before any work starts.
constexpr long long kMaxSubdividedFaces = 1LL << 25;

struct PreparationOptions
{
  /// weld, degenerate removal, orientation, non-manifold (vtkMeshRepair);
  /// off: the mesh goes to subdivision or normals as it is.
  bool repair = true;
  bool weld = false;           ///< weld coincident points
  double weldTolerance = 1e-6; ///< relative to the bounding-box diagonal, [0, 0.1]
  bool fixTJunctions = false;
  int subdivisionLevels = 0;   ///< 0 .. kMaxSubdivisionLevels
  SubdivisionScheme scheme = SubdivisionScheme::Auto;
  bool computeNormals = true;  ///< weighted vertex normals (when not subdividing)
  NormalWeighting weighting = NormalWeighting::Area;
  double featureAngle = 30.0;  ///< crease angle in degrees, [0, 180]
  /// The caller has found the polygons consistently oriented (the CLI
  /// checks before it decides to repair): the normals filter does not
  /// check again (0.4 s of a 16M-triangle mesh).
  bool knownConsistent = false;
};

/// What the step did (the CLI's --json).
struct PreparationReport
{
  long long welded = 0, tJunctionsFixed = 0, degenerateRemoved = 0, nonManifoldEdges = 0,
            duplicatedPoints = 0, flipped = 0, creaseEdges = 0, splitPoints = 0;
  std::string scheme = "none";
  std::string weights = "area";
  bool repairSkipped = false; ///< the cheap check found nothing to repair
};

const char* NormalWeightingName(NormalWeighting weighting);
bool ParseNormalWeighting(const std::string& name, NormalWeighting& weighting);
bool ParseSubdivisionScheme(const std::string& name, SubdivisionScheme& scheme);

/// "" or a one-line description of the first option out of range.
std::string ValidatePreparationOptions(const PreparationOptions& options);

/**
 * Runs the step. With options.repair, the repair filter runs when a weld or
 * T-junctions are asked for or when CheckRepairNeeds finds something (else
 * the report says it skipped); then subdivision or weighted normals as
 * asked (neither: the input itself is returned).
 * Throws std::invalid_argument with one line for invalid options, a mesh
 * left without polygons, or a failed subdivision.
 */
vtkSmartPointer<vtkPolyData> PrepareMesh(
  vtkPolyData* input, const PreparationOptions& options, PreparationReport& report);

} // namespace shadinglab::mesh
