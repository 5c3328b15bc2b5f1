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
/// Throws UsageError with the validation message.
Material<double> MaterialFromArguments(const Arguments& args);

int RunBrdf(int argc, char** argv);

} // namespace shadinglab::cli
