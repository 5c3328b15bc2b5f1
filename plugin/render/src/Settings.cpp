// SPDX-License-Identifier: BSD-3-Clause
// Parsing, applying, validating and printing settings: the code every row
// of the table (SettingsTable.cpp) goes through.
#include "shadinglab/render/Settings.h"

#include "SettingsText.h"

#include "shadinglab/model/Materials.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace shadinglab::render
{

namespace
{

using settings_text::Lower;
using settings_text::Number;
using settings_text::RoundTripNumber;

bool ParseReal(const std::string& text, double& value)
{
  const char* begin = text.c_str();
  char* end = nullptr;
  value = std::strtod(begin, &end);
  return end != begin && *end == '\0' && std::isfinite(value);
}

} // namespace
const SettingRow* FindSetting(const std::string& key)
{
  for (const auto& row : SettingsTable())
  {
    if (row.key == key)
    {
      return &row;
    }
  }
  return nullptr;
}

std::string ParseSetting(
  const SettingRow& row, const std::string& text, SettingValue& value, const std::string& prefix)
{
  const std::string name = prefix + row.key;
  value = SettingValue{};
  if (row.kind == SettingKind::Choice || row.kind == SettingKind::Text)
  {
    const std::string lower = Lower(text);
    for (size_t i = 0; i < row.choices.size(); ++i)
    {
      if (lower == Lower(row.choices[i].key) || lower == Lower(row.choices[i].label))
      {
        value.numbers = { static_cast<double>(i) };
        value.text = row.choices[i].key;
        return {};
      }
    }
    if (row.kind == SettingKind::Text && row.choices.empty())
    {
      value.text = text;
      return {};
    }
    return "unknown " + name + " '" + text + "' (expected " + RangeText(row) + ")";
  }
  if (row.kind == SettingKind::Flag)
  {
    const std::string lower = Lower(text);
    if (lower == "on" || lower == "1" || lower == "true" || lower.empty())
    {
      value.numbers = { 1 };
      return {};
    }
    if (lower == "off" || lower == "0" || lower == "false")
    {
      value.numbers = { 0 };
      return {};
    }
    return name + " takes on or off (got '" + text + "')";
  }
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
  {
    double v = 0;
    if (!ParseReal(item, v))
    {
      return name + ": '" + item + "' is not a finite number";
    }
    value.numbers.push_back(v);
  }
  if (value.numbers.empty())
  {
    return name + " needs a value";
  }
  return {};
}

namespace
{

std::string ApplyRow(
  Settings& settings, const SettingRow& row, const SettingValue& value, const std::string& prefix)
{
  const std::string name = prefix + row.key;
  if (row.kind == SettingKind::Choice || row.kind == SettingKind::Text)
  {
    if (row.kind == SettingKind::Choice || !row.choices.empty())
    {
      // A Text value may arrive as text only (ParaView's string property).
      SettingValue v = value;
      if (v.numbers.empty())
      {
        const std::string problem = ParseSetting(row, value.text, v, prefix);
        if (!problem.empty())
        {
          return problem;
        }
      }
      const double i = v.numbers.empty() ? -1 : v.numbers[0];
      if (!(i >= 0 && i < static_cast<double>(row.choices.size())) || i != std::floor(i))
      {
        return name + " must be one of " + RangeText(row);
      }
      v.text = row.choices[static_cast<size_t>(i)].key;
      row.set(settings, v);
      return {};
    }
    row.set(settings, value);
    return {};
  }
  const int count = static_cast<int>(value.numbers.size());
  if (row.kind == SettingKind::Flag)
  {
    if (count != 1)
    {
      return name + " takes one value";
    }
    row.set(settings, value);
    return {};
  }
  const bool countOk = count >= row.minCount && count <= row.maxCount &&
    (!row.broadcast || count == 1 || count == row.maxCount);
  if (!countOk)
  {
    return name + ": expected " +
      (row.broadcast ? "1 or " + std::to_string(row.maxCount)
                     : (row.minCount == row.maxCount ? std::to_string(row.minCount)
                                                     : std::to_string(row.minCount) + " to " +
                              std::to_string(row.maxCount))) +
      " value" + (row.maxCount > 1 ? "s" : "") + ", got " + std::to_string(count);
  }
  for (double v : value.numbers)
  {
    if (!(v >= row.min && v <= row.max))
    {
      return name + " must be in " + RangeText(row) + " (got " + Number(v, 6) + ")";
    }
    if (row.kind == SettingKind::Integer && v != std::floor(v))
    {
      return name + " must be an integer (got " + Number(v, 6) + ")";
    }
  }
  row.set(settings, value);
  return {};
}

} // namespace

std::string ApplySetting(
  Settings& settings, const SettingRow& row, const SettingValue& value, const std::string& prefix)
{
  const std::string problem = ApplyRow(settings, row, value, prefix);
  ResolveSpectral(settings); // a missing data source is ValidateSettings' to report
  return problem;
}

std::string ResolveSpectral(Settings& settings)
{
  settings.material.spectralCount = 0;
  if (!settings.spectral)
  {
    return {};
  }
  const Dispersion* data = settings.nk ? settings.nk.get() : PresetDispersion(settings.preset);
  if (!data)
  {
    std::string presets;
    for (const std::string& name : PresetDispersionNames())
    {
      presets += (presets.empty() ? "" : ", ") + name;
    }
    return settings.nkFile.empty()
      ? "spectral Fresnel needs measured optical data: --material " + presets +
        ", or --nk FILE.yml"
      : "spectral Fresnel: --nk " + settings.nkFile + " has not been read";
  }
  return SetSpectral(settings.material, *data);
}

std::string ValidateSettings(const Settings& settings)
{
  std::string problem = ValidateMaterial(settings.material);
  if (problem.empty() && settings.spectral)
  {
    Settings copy = settings;
    problem = ResolveSpectral(copy);
  }
  return problem;
}

std::string ReadNkFile(Settings& settings)
{
  settings.nk.reset();
  if (settings.nkFile.empty())
  {
    return {};
  }
  std::ifstream in(settings.nkFile, std::ios::binary);
  if (!in)
  {
    return "--nk " + settings.nkFile + ": cannot open the file";
  }
  // The largest refractiveindex.info file is ~1 MB; 16 MB is no such file.
  constexpr std::streamsize kMaxNkFileBytes = 16 << 20;
  std::string text(kMaxNkFileBytes + 1, '\0');
  in.read(&text[0], kMaxNkFileBytes + 1);
  text.resize(static_cast<size_t>(in.gcount()));
  if (static_cast<std::streamsize>(text.size()) > kMaxNkFileBytes)
  {
    return "--nk " + settings.nkFile + ": larger than 16 MB, not an optical-constants file";
  }
  if (text.find('\0') != std::string::npos)
  {
    return "--nk " + settings.nkFile + ": binary data, not a YAML file";
  }
  auto data = std::make_shared<Dispersion>();
  const std::string problem = ParseDispersion(text, "--nk " + settings.nkFile, *data);
  if (!problem.empty())
  {
    return problem;
  }
  settings.nk = data;
  ResolveSpectral(settings);
  return {};
}

std::string ApplySettingText(
  Settings& settings, const std::string& key, const std::string& text, const std::string& prefix)
{
  const SettingRow* row = FindSetting(key);
  if (!row)
  {
    return "unknown setting '" + key + "'";
  }
  SettingValue value;
  std::string problem = ParseSetting(*row, text, value, prefix);
  return problem.empty() ? ApplySetting(settings, *row, value, prefix) : problem;
}

std::string FormatSetting(const SettingRow& row, const SettingValue& value)
{
  switch (row.kind)
  {
    case SettingKind::Choice:
      return row.choices.at(static_cast<size_t>(value.numbers.at(0))).key;
    case SettingKind::Text:
      return value.text;
    case SettingKind::Flag:
      return value.numbers.at(0) != 0 ? "on" : "off";
    default:
    {
      std::string out;
      for (size_t i = 0; i < value.numbers.size(); ++i)
      {
        out += (i ? "," : "") + RoundTripNumber(value.numbers[i]);
      }
      return out;
    }
  }
}

std::string DefaultText(const SettingRow& row)
{
  return FormatSetting(row, row.get(Settings{}));
}

std::string RangeText(const SettingRow& row)
{
  if (!row.choices.empty())
  {
    std::string out;
    for (size_t i = 0; i < row.choices.size(); ++i)
    {
      out += (i ? " | " : "") + row.choices[i].key;
    }
    return out;
  }
  if (row.kind == SettingKind::Flag)
  {
    return "on | off";
  }
  if (row.kind == SettingKind::Text)
  {
    return row.metavar; // a name or a spelling: what the flag's value looks like
  }
  return "[" + Number(row.min, 6) + ", " + Number(row.max, 6) + "]";
}

bool SameSettings(const Settings& a, const Settings& b)
{
  for (const auto& row : SettingsTable())
  {
    const SettingValue va = row.get(a), vb = row.get(b);
    if (va.numbers != vb.numbers || va.text != vb.text)
    {
      return false;
    }
  }
  return true;
}

std::string CliHelp(SettingGroup group)
{
  // Two columns: the flag (with its value's name) and the documentation,
  // wrapped at 92 columns.
  constexpr size_t kFlagColumn = 28;
  constexpr size_t kWidth = 92;
  std::string out;
  for (const auto& row : SettingsTable())
  {
    if (row.group != group || !(row.frontEnds & kCli))
    {
      continue;
    }
    std::string flag = "  --" + row.key + (row.kind == SettingKind::Flag ? "" : " " + row.metavar);
    std::string doc = row.doc;
    // (A text setting's value is spelt by its metavar, beside the flag.)
    if (row.kind == SettingKind::Choice || (row.kind == SettingKind::Text && !row.choices.empty()))
    {
      doc += ": " + RangeText(row);
    }
    else if (row.kind == SettingKind::Real || row.kind == SettingKind::Integer)
    {
      doc += "; " + RangeText(row);
    }
    if (row.kind != SettingKind::Flag)
    {
      const std::string byDefault = DefaultText(row);
      doc += " (default " + (byDefault.empty() ? std::string("none") : byDefault) + ")";
    }
    std::string line = flag;
    if (line.size() + 1 > kFlagColumn)
    {
      out += line + "\n";
      line.clear();
    }
    std::istringstream words(doc);
    std::string word;
    while (words >> word)
    {
      if (line.size() < kFlagColumn)
      {
        line.resize(kFlagColumn, ' ');
      }
      else if (line.size() + 1 + word.size() > kWidth)
      {
        out += line + "\n";
        line.assign(kFlagColumn, ' ');
      }
      else
      {
        line += ' ';
      }
      line += word;
    }
    out += line + "\n";
  }
  return out;
}

void NormalizeLobeWeights(Material<double>& material)
{
  double sum = 0;
  for (int k = 0; k < material.lobeCount; ++k)
  {
    sum += material.lobes[k].weight;
  }
  if (sum > 0)
  {
    for (int k = 0; k < material.lobeCount; ++k)
    {
      material.lobes[k].weight /= sum;
    }
  }
}

} // namespace shadinglab::render
