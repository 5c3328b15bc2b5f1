// SPDX-License-Identifier: BSD-3-Clause
// The command line's flags from the settings table
// (shadinglab/render/Settings.h): every row shown on the command line is a
// flag --KEY, parsed, range-checked and documented by the table. What is
// the CLI's own (model-dependent kd/ks defaults, the lobe count, the
// cook-torrance shorthand) is written here and in SceneArguments.cpp.
#include "Commands.h"

#include "shadinglab/render/Settings.h"

namespace shadinglab::cli
{

void AddSettingFlags(std::vector<std::string>& valued, std::vector<std::string>& flags,
  render::SettingGroup group)
{
  for (const auto& row : render::SettingsTable())
  {
    if (row.group == group && (row.frontEnds & render::kCli))
    {
      (row.kind == render::SettingKind::Flag ? flags : valued).push_back(row.key);
    }
  }
}

void ApplySettingArguments(const Arguments& args, render::SettingGroup group,
  render::Settings& settings, const std::map<std::string, std::string>& implied)
{
  for (const auto& row : render::SettingsTable())
  {
    if (row.group != group || !(row.frontEnds & render::kCli))
    {
      continue;
    }
    const auto given = implied.find(row.key);
    if (!args.Has(row.key) && given == implied.end())
    {
      continue;
    }
    const std::string text = given != implied.end() ? given->second
      : row.kind == render::SettingKind::Flag       ? "on"
                                                    : args.Get(row.key);
    const std::string problem = render::ApplySettingText(settings, row.key, text, "--");
    if (!problem.empty())
    {
      throw UsageError(problem);
    }
  }
}

ReadOptions ReadOptionsFromArguments(const Arguments& args)
{
  render::Settings settings;
  ApplySettingArguments(args, render::SettingGroup::Mesh, settings);
  ReadOptions options;
  options.nonlinearSubdivisionLevel = settings.input.nonlinearSubdivisionLevel;
  if (args.Has("time"))
  {
    options.time = ParseDouble(args.Get("time"), "--time");
  }
  if (args.Has("time-step"))
  {
    options.timeStep = args.GetInt("time-step", 0);
    if (options.timeStep < 0)
    {
      throw UsageError("--time-step must be 0 or more (got " + args.Get("time-step") + ")");
    }
  }
  return options;
}

std::string MaterialHelp()
{
  return "Material options:\n" + render::CliHelp(render::SettingGroup::Material) +
    "  Without --material or --kd/--ks, --model lambert means kd 1 (ks 0), phong and\n"
    "  blinn-phong kd 0.7, ks 0.3; brdf starts from cook-torrance with kd 0, ks 1.\n";
}

void ApplyMaterialArguments(
  const Arguments& args, bool forRender, const std::string& impliedModel, render::Settings& settings)
{
  Material<double>& m = settings.material;
  if (!forRender)
  {
    m.model = ReflectanceModel::CookTorrance;
    m.kd = 0.0;
    m.ks = 1.0;
  }
  if (args.Has("w") && !args.Has("m"))
  {
    throw UsageError("--w needs --m");
  }
  std::map<std::string, std::string> implied;
  if (!impliedModel.empty() && !args.Has("model"))
  {
    implied["model"] = impliedModel;
  }
  const bool modelGiven = args.Has("model") || !impliedModel.empty();
  ApplySettingArguments(args, render::SettingGroup::Material, settings, implied);
  if (modelGiven && !args.Has("kd") && !args.Has("ks") && !args.Has("material"))
  {
    // A model chosen alone gets its customary weights.
    if (m.model == ReflectanceModel::Phong || m.model == ReflectanceModel::BlinnPhong)
    {
      m.kd = 0.7;
      m.ks = 0.3;
    }
  }
  if (modelGiven && m.model == ReflectanceModel::Lambert)
  {
    // Lambert has no specular term: ks is 0 whatever was given, kd 1 unless given.
    m.kd = args.Has("kd") ? m.kd : 1.0;
    m.ks = 0.0;
  }
  if (args.Has("m"))
  {
    const int lobes = m.lobeCount;
    if (args.Has("w"))
    {
      const auto ws = ParseList(args.Get("w"), "--w");
      if (static_cast<int>(ws.size()) != lobes)
      {
        throw UsageError("--w needs one weight per --m value (" + std::to_string(lobes) +
          "), got " + std::to_string(ws.size()));
      }
    }
    else
    {
      for (int k = 0; k < lobes; ++k)
      {
        m.lobes[k].weight = 1.0 / static_cast<double>(lobes);
      }
    }
  }
  render::NormalizeLobeWeights(m);
  if (!settings.nkFile.empty())
  {
    const std::string unread = render::ReadNkFile(settings);
    if (!unread.empty())
    {
      throw UsageError(unread);
    }
  }
  const std::string problem = render::ValidateSettings(settings);
  if (!problem.empty())
  {
    throw UsageError("invalid material: " + problem);
  }
}

Material<double> MaterialFromArguments(const Arguments& args, bool forRender)
{
  render::Settings settings;
  ApplyMaterialArguments(args, forRender, "", settings);
  return settings.material;
}

} // namespace shadinglab::cli
