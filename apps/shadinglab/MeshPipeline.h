// SPDX-License-Identifier: BSD-3-Clause
// Command-line options of the mesh-preparation step (mesh/prep), shared by
// 'normals' and 'render'.
#pragma once

#include "CliArgs.h"
#include "MeshPreparation.h"

namespace shadinglab::cli
{

/// Parses --weights (or --normals), --feature-angle, --weld, --fix-t-junctions,
/// --subdivide, --scheme (those present in args). `always` makes the step
/// repair and compute normals even without options (the 'normals' command).
mesh::PreparationOptions MeshPipelineFromArguments(const Arguments& args, bool always);

/// True when any mesh-preparation option was given.
bool WantsMeshPipeline(const Arguments& args);

} // namespace shadinglab::cli
