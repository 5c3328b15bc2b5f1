// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/DataColor.h"

#include <algorithm>

namespace shadinglab::render
{

namespace
{
bool HasLobe(const Material<double>& m)
{
  return m.model != ReflectanceModel::Lambert && m.model != ReflectanceModel::LommelSeeliger &&
    m.ks > 0;
}

bool Drawn(Highlights highlights, bool coloredByData)
{
  return highlights == Highlights::On || (highlights == Highlights::Auto && !coloredByData);
}

/// A metal shows its surroundings; without an environment map a conductor
/// coloured by data stands in a uniform grey surround whose reflection is
/// Ra Ia = 0.25 of the data colour (eq. 9.4): a quarter, so faces that
/// mirror no light still show the data, while the light kit's highlights
/// (key 0.75) stay brighter than any of them.
constexpr double kMetalSurround = 0.25;

bool TintsAsMetal(const Material<double>& m, Highlights highlights, bool coloredByData)
{
  return coloredByData && highlights == Highlights::Auto &&
    m.model == ReflectanceModel::CookTorrance && m.IsConductor() && m.ks > 0;
}
} // namespace

Material<double> MaterialForData(
  const Material<double>& material, Highlights highlights, bool coloredByData)
{
  Material<double> m = material;
  if (TintsAsMetal(m, highlights, coloredByData))
  {
    // eq. 9.4 (glTF 2.0's metallic convention): the data colour is F0 and
    // tints the surround; the metal's highlights stay.
    m.albedoTintsFresnel = true;
    m.ambient = Vec3<double>(kMetalSurround, kMetalSurround, kMetalSurround);
    return m;
  }
  if (Drawn(highlights, coloredByData))
  {
    return m;
  }
  if (HasLobe(m))
  {
    // docs/model.md eq. 9.1: kd' = min(1, kd + ks), ks' = 0.
    m.kd = std::min(1.0, m.kd + m.ks);
    m.ks = 0;
  }
  m.albedoTintsFresnel = false; // no Fresnel term left to tint
  if (coloredByData)
  {
    // eq. 9.2: Ra' = 0; a grey Ra Ia would lift every colour toward grey.
    m.ambient = Vec3<double>(0, 0, 0);
  }
  return m;
}

std::string DataColorNotice(const Material<double>& material, Highlights highlights,
  bool coloredByData, const std::string& preset)
{
  if (!coloredByData || !HasLobe(material))
  {
    return "";
  }
  const std::string name = preset.empty() ? "the material" : preset;
  if (Drawn(highlights, coloredByData))
  {
    if (material.IsConductor() && material.kd <= 0)
    {
      return "highlights on a surface coloured by data: " + name +
        " is a conductor (no diffuse term), so only its highlights show, and they are not data";
    }
    return "highlights on a surface coloured by data: white added to the colour map is not data";
  }
  if (TintsAsMetal(material, highlights, coloredByData))
  {
    return name + " is a conductor: coloured by data, the data colour is its Fresnel F0 (glTF's "
                  "metallic convention) in a grey surround; its highlights whiten toward grazing "
                  "and are not data (highlights off: diffuse in the data colour)";
  }
  if (material.IsConductor())
  {
    return name + " is a conductor: with highlights off it is drawn diffuse in the data colour";
  }
  return "";
}

} // namespace shadinglab::render
