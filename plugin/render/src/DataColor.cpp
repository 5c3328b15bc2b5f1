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
} // namespace

Material<double> MaterialForData(
  const Material<double>& material, Highlights highlights, bool coloredByData)
{
  Material<double> m = material;
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
  if (material.IsConductor())
  {
    return name + " is a conductor: coloured by data it is drawn diffuse in the data colour "
                  "(highlights on keeps its Fresnel highlights, which are not data)";
  }
  return "";
}

} // namespace shadinglab::render
