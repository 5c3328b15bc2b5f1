// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "CliArgs.h"

#include "shadinglab/model/Shading.h"

#include <string>
#include <vector>

namespace shadinglab::cli
{

/// Options every material-taking command accepts (see MaterialHelp()).
const std::vector<std::string>& MaterialOptions();
std::string MaterialHelp();

/// Builds and validates the material from --model/--material/--m/... options.
/// Without --model/--material, brdf starts from a pure Cook-Torrance
/// specular (kd 0, ks 1) and render from Blinn-Phong (kd 0.7, ks 0.3).
/// Throws UsageError with the validation message.
Material<double> MaterialFromArguments(const Arguments& args, bool forRender = false);

int RunBrdf(int argc, char** argv);
int RunRender(int argc, char** argv);
int RunCompare(int argc, char** argv);
int RunNormals(int argc, char** argv);
int RunAccuracy(int argc, char** argv);

} // namespace shadinglab::cli
