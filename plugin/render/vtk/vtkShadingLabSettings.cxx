// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabSettings.h"

#include "shadinglab/render/Settings.h"

#include <vtkObjectFactory.h>

#include <cstdio>
#include <sstream>

namespace sl = shadinglab;

vtkStandardNewMacro(vtkShadingLabSettings);

vtkShadingLabSettings::vtkShadingLabSettings()
  : Values(new sl::render::Settings)
{
}

vtkShadingLabSettings::~vtkShadingLabSettings() = default;

std::string vtkShadingLabSettings::Set(const char* key, const char* value)
{
  if (!key || !value)
  {
    return "a setting needs a key and a value";
  }
  sl::render::Settings changed = *this->Values;
  const std::string problem = sl::render::ApplySettingText(changed, key, value, "");
  if (problem.empty())
  {
    *this->Values = std::move(changed);
    this->Modified();
  }
  return problem;
}

std::string vtkShadingLabSettings::Get(const char* key) const
{
  const sl::render::SettingRow* row = key ? sl::render::FindSetting(key) : nullptr;
  return row ? sl::render::FormatSetting(*row, row->get(*this->Values)) : std::string();
}

void vtkShadingLabSettings::Reset()
{
  *this->Values = sl::render::Settings();
  this->Modified();
}

std::string vtkShadingLabSettings::Validate() const
{
  return sl::render::ValidateSettings(*this->Values);
}

const sl::render::Settings& vtkShadingLabSettings::GetSettings() const
{
  return *this->Values;
}

void vtkShadingLabSettings::SetSettings(const sl::render::Settings& settings)
{
  *this->Values = settings;
  this->Modified();
}

namespace
{

std::string Quoted(const std::string& text)
{
  std::string out = "\"";
  for (const char c : text)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}

const char* KindName(sl::render::SettingKind kind)
{
  switch (kind)
  {
    case sl::render::SettingKind::Choice:
      return "choice";
    case sl::render::SettingKind::Real:
      return "real";
    case sl::render::SettingKind::Integer:
      return "integer";
    case sl::render::SettingKind::Flag:
      return "flag";
    case sl::render::SettingKind::Text:
      break;
  }
  return "text";
}

const char* GroupName(sl::render::SettingGroup group)
{
  switch (group)
  {
    case sl::render::SettingGroup::Render:
      return "render";
    case sl::render::SettingGroup::Material:
      return "material";
    case sl::render::SettingGroup::Lights:
      return "lights";
    case sl::render::SettingGroup::Mesh:
      break;
  }
  return "mesh";
}

} // namespace

std::string vtkShadingLabSettings::GetTableJson()
{
  std::ostringstream json;
  json.precision(17);
  json << "[";
  bool firstRow = true;
  for (const sl::render::SettingRow& row : sl::render::SettingsTable())
  {
    json << (firstRow ? "" : ",") << "{\"key\":" << Quoted(row.key)
         << ",\"label\":" << Quoted(row.label) << ",\"group\":\"" << GroupName(row.group)
         << "\",\"kind\":\"" << KindName(row.kind) << "\",\"count\":[" << row.minCount << ","
         << row.maxCount << "],\"min\":" << row.min << ",\"max\":" << row.max << ",\"choices\":[";
    for (size_t c = 0; c < row.choices.size(); ++c)
    {
      json << (c ? "," : "") << Quoted(row.choices[c].key);
    }
    json << "],\"default\":" << Quoted(sl::render::DefaultText(row))
         << ",\"range\":" << Quoted(sl::render::RangeText(row))
         << ",\"metavar\":" << Quoted(row.metavar) << ",\"doc\":" << Quoted(row.doc)
         << ",\"front_ends\":[";
    const char* names[] = { "cli", "paraview", "mapper", "explorer" };
    bool firstEnd = true;
    for (int bit = 0; bit < 4; ++bit)
    {
      if (row.frontEnds & (1u << bit))
      {
        json << (firstEnd ? "" : ",") << "\"" << names[bit] << "\"";
        firstEnd = false;
      }
    }
    json << "]}";
    firstRow = false;
  }
  json << "]";
  return json.str();
}

void vtkShadingLabSettings::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (const sl::render::SettingRow& row : sl::render::SettingsTable())
  {
    os << indent << row.key << ": " << sl::render::FormatSetting(row, row.get(*this->Values)) << "\n";
  }
}
