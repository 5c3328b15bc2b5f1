// SPDX-License-Identifier: BSD-3-Clause
// shadinglab settings: the settings table (shadinglab/render/Settings.h) as
// Markdown, the reference docs/settings.md is (checked by the docs test).
#include "Commands.h"

#include "shadinglab/render/Settings.h"

#include <iostream>

namespace shadinglab::cli
{

namespace
{

const char* GroupName(render::SettingGroup group)
{
  switch (group)
  {
    case render::SettingGroup::Render:
      return "Render";
    case render::SettingGroup::Lights:
      return "Lights";
    case render::SettingGroup::Material:
      return "Material";
    case render::SettingGroup::Mesh:
      return "Normals of a mesh without them";
  }
  return "?";
}

std::string FrontEnds(unsigned mask)
{
  std::string out;
  const std::pair<unsigned, const char*> names[] = { { render::kCli, "CLI" },
    { render::kExplorer, "explorer" }, { render::kMapper, "mapper" },
    { render::kParaView, "ParaView" } };
  for (const auto& [bit, name] : names)
  {
    if (mask & bit)
    {
      out += (out.empty() ? "" : ", ") + std::string(name);
    }
  }
  return out;
}

std::string Choices(const render::SettingRow& row)
{
  if (row.kind == render::SettingKind::Flag)
  {
    return "on, off";
  }
  if (row.choices.empty())
  {
    return render::RangeText(row);
  }
  std::string out;
  for (size_t i = 0; i < row.choices.size(); ++i)
  {
    out += (i ? ", " : "") + ("`" + row.choices[i].key + "`") +
      (row.choices[i].label != row.choices[i].key ? " (" + row.choices[i].label + ")" : "");
  }
  return out;
}

} // namespace

int RunSettings(int argc, char** argv)
{
  const Arguments args(argc, argv, {}, { "help", "markdown" });
  if (args.Has("help"))
  {
    std::cout << "usage: shadinglab settings --markdown\n"
                 "Prints every setting of the settings table (shadinglab/render/Settings.h) as "
                 "Markdown: key (the CLI flag),\nParaView property, values, default, front "
                 "ends and documentation.\n";
    return 0;
  }
  if (!args.Has("markdown"))
  {
    throw UsageError("settings needs --markdown (the one output it has)");
  }
  if (!args.Positionals().empty())
  {
    throw UsageError("unexpected argument '" + args.Positionals().front() + "'");
  }
  std::cout << "# Settings\n\n"
               "Every setting a user sets, from the one table every front end reads "
               "(`plugin/render/src/SettingsTable.cpp`). Written by `shadinglab settings --markdown`; "
               "do not edit. The key is the command-line flag (`--key`), the property the "
               "ParaView property of the ShadingLab Surface (and the key of "
               "`vtkShadingLabPolyDataMapper::SetSetting`). Choices are accepted in either "
               "spelling, any case.\n";
  for (auto group : { render::SettingGroup::Render, render::SettingGroup::Lights,
         render::SettingGroup::Material, render::SettingGroup::Mesh })
  {
    std::cout << "\n## " << GroupName(group) << "\n\n"
              << "| key | property | values | default | front ends | what |\n"
              << "|---|---|---|---|---|---|\n";
    for (const auto& row : render::SettingsTable())
    {
      if (row.group != group)
      {
        continue;
      }
      std::cout << "| `" << row.key << "` | " << row.property << " | " << Choices(row) << " | `"
                << render::DefaultText(row) << "` | " << FrontEnds(row.frontEnds) << " | "
                << row.doc << " |\n";
    }
  }
  return 0;
}

} // namespace shadinglab::cli
