// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "CliArgs.h"

#include "MeshIO.h"
#include "shadinglab/model/Shading.h"
#include "shadinglab/render/Settings.h"

#include <map>
#include <string>
#include <vector>

namespace shadinglab::cli
{

/// Appends the settings table's flags of `group` shown on the command line
/// to the valued options and the flags (value-less) an Arguments accepts.
void AddSettingFlags(std::vector<std::string>& valued, std::vector<std::string>& flags,
  render::SettingGroup group);
/// Applies every --KEY of `group` given (or `implied`, key -> text) to
/// `settings`, in table order. Throws UsageError with the table's message.
void ApplySettingArguments(const Arguments& args, render::SettingGroup group,
  render::Settings& settings, const std::map<std::string, std::string>& implied = {});

/// The reading options (--nonlinear-subdivision, the table's Mesh rows shown
/// on the command line, accepted through AddSettingFlags) of a command that
/// reads a mesh file; throws UsageError.
ReadOptions ReadOptionsFromArguments(const Arguments& args);

std::string MaterialHelp();

/// Builds and validates the material from --model/--material/--m/... options.
/// Without --model/--material, brdf starts from a pure Cook-Torrance
/// specular (kd 0, ks 1) and render from Blinn-Phong (kd 0.7, ks 0.3).
/// Throws UsageError with the validation message.
Material<double> MaterialFromArguments(const Arguments& args, bool forRender = false);
/// The same into `settings` (its preset too); `impliedModel` is a --model
/// implied by another flag (--mode cook-torrance).
void ApplyMaterialArguments(const Arguments& args, bool forRender, const std::string& impliedModel,
  render::Settings& settings);

int RunBrdf(int argc, char** argv);
int RunRender(int argc, char** argv);
int RunCompare(int argc, char** argv);
int RunNormals(int argc, char** argv);
int RunAccuracy(int argc, char** argv);
int RunSettings(int argc, char** argv);

} // namespace shadinglab::cli
