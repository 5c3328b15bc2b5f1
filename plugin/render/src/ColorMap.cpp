// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/ColorMap.h"

#include "shadinglab_colormaps.h" // generated: generated::kColorMapTables

#include <algorithm>
#include <cctype>
#include <cmath>

namespace shadinglab::render
{

namespace
{
std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}
} // namespace

const std::vector<ColorMapName>& ColorMapNames()
{
  static const std::vector<ColorMapName> names = [] {
    std::vector<ColorMapName> n;
    for (const auto& table : generated::kColorMapTables)
    {
      n.push_back({ table.label, table.alias, table.key });
    }
    return n;
  }();
  return names;
}

bool FindColorMap(const std::string& name, ColorMap& map)
{
  const std::string lower = Lower(name);
  for (const auto& table : generated::kColorMapTables)
  {
    if (lower != Lower(table.label) && lower != table.key &&
      (!*table.alias || lower != Lower(table.alias)))
    {
      continue;
    }
    map = ColorMap();
    map.label = table.label;
    map.colors.resize(generated::kColorMapBins);
    for (int b = 0; b < generated::kColorMapBins; ++b)
    {
      map.colors[b] = Vec3<float>(table.rgb[3 * b] / 255.0f, table.rgb[3 * b + 1] / 255.0f,
        table.rgb[3 * b + 2] / 255.0f);
    }
    map.nanColor =
      Vec3<float>(table.nan[0] / 255.0f, table.nan[1] / 255.0f, table.nan[2] / 255.0f);
    return true;
  }
  return false;
}

Vec3<float> ColorMap::LegendColor(double t) const
{
  // Map's own bin (a constant field's one colour included).
  return this->Map(this->rangeMin + std::clamp(t, 0.0, 1.0) * (this->rangeMax - this->rangeMin));
}

double ColorMap::LegendTick(int k, int count) const
{
  const double width = this->rangeMax - this->rangeMin;
  const double value = this->rangeMin + k * width / count;
  return std::abs(value) <= kLegendZeroFraction * std::abs(width) ? 0.0 : value;
}

namespace
{
/// Pixels without light, apart from every colour of both maps.
const Vec3<float> kNoLightColor{ 0.2f, 0.2f, 0.2f };
} // namespace

ColorMap DolpColorMap()
{
  ColorMap map;
  FindColorMap("viridis", map);
  map.rangeMin = 0.0;
  map.rangeMax = 1.0;
  map.nanColor = kNoLightColor;
  return map;
}

ColorMap AopColorMap()
{
  ColorMap map;
  map.label = "hue wheel (cyclic)";
  constexpr int kBins = 256;
  for (int i = 0; i < kBins; ++i)
  {
    const double h = 6.0 * i / kBins;
    const int sector = static_cast<int>(h) % 6;
    const float f = static_cast<float>(h - std::floor(h));
    const float up = f, down = 1.0f - f;
    const Vec3<float> rgb[6] = { { 1, up, 0 }, { down, 1, 0 }, { 0, 1, up }, { 0, down, 1 },
      { up, 0, 1 }, { 1, 0, down } };
    map.colors.push_back(rgb[sector] * 0.9f + Vec3<float>(0.05f, 0.05f, 0.05f));
  }
  map.rangeMin = -90.0;
  map.rangeMax = 90.0;
  map.nanColor = kNoLightColor;
  return map;
}

} // namespace shadinglab::render
