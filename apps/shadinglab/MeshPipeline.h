// SPDX-License-Identifier: BSD-3-Clause
// The mesh-preparation pipeline shared by 'normals' and 'render'.
#pragma once

#include "CliArgs.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace shadinglab::cli
{

struct MeshPipelineOptions
{
  bool repair = true;
  bool weld = false;
  double weldTolerance = 1e-6;
  bool fixTJunctions = false;
  int subdivisionLevels = 0;
  int scheme = 0; // vtkOpenSubdivRefine::Schemes
  bool computeNormals = true;
  int weights = 1; // vtkWeightedPolyDataNormals::Weightings
  double featureAngle = 30.0;
};

struct MeshPipelineReport
{
  long long welded = 0, tJunctionsFixed = 0, degenerateRemoved = 0, nonManifoldEdges = 0,
            duplicatedPoints = 0, flipped = 0, creaseEdges = 0, splitPoints = 0;
  std::string scheme = "none";
  std::string weights = "area";
};

/// Parses --weights, --feature-angle, --weld, --fix-t-junctions, --subdivide,
/// --scheme (those present in args). `always` makes the pipeline repair and
/// compute normals even without options (the 'normals' command).
MeshPipelineOptions MeshPipelineFromArguments(const Arguments& args, bool always);

/// True when any mesh-preparation option was given.
bool WantsMeshPipeline(const Arguments& args);

vtkSmartPointer<vtkPolyData> RunMeshPipeline(
  vtkPolyData* input, const MeshPipelineOptions& options, MeshPipelineReport& report);

} // namespace shadinglab::cli
