// SPDX-License-Identifier: BSD-3-Clause
// What colouring by data does to a material (docs/model.md section 9):
// the one rule every front end (CLI, explorer, the VTK mapper, ParaView)
// applies before drawing, so a pixel of a surface coloured by data is the
// colour map's colour scaled by shading, and nothing the map does not hold.
#pragma once

#include "shadinglab/model/Shading.h"
#include "shadinglab/render/Options.h"

#include <string>

namespace shadinglab::render
{

/// Whether the specular lobe is drawn.
enum class Highlights
{
  Auto, ///< drawn, except on a surface coloured by data
  On,   ///< always drawn (white added to a colour map reads as data)
  Off   ///< never drawn
};

inline constexpr EnumName<Highlights> kHighlightModes[] = {
  { Highlights::Auto, "auto", "Auto", "AUTO" },
  { Highlights::On, "on", "On", "ON" },
  { Highlights::Off, "off", "Off", "OFF" },
};

/**
 * The material a surface is drawn with. Unchanged when it is not coloured
 * by data and highlights are not Off. Without highlights (Off, or Auto on
 * a surface coloured by data) the specular weight goes to the diffuse one
 * (kd + ks, at most 1: the reflected energy is kept), and on a surface
 * coloured by data the grey ambient Ra goes too (ParaView's Surface:
 * Specular 0, Ambient 0, Diffuse 1), so every pixel is s * map(value) with
 * s in [0, 1]. A Lambert or Lommel-Seeliger material has no lobe to drop.
 * A Cook-Torrance conductor coloured by data with highlights Auto keeps its
 * highlights instead, the data colour as its Fresnel F0 and tinting a grey
 * surround (eq. 9.4, Material::albedoTintsFresnel), as glTF draws metals.
 */
Material<double> MaterialForData(const Material<double>& material, Highlights highlights,
  bool coloredByData);

/**
 * The one-line notice a front end prints (once) for what MaterialForData
 * did or kept, or "": highlights kept on data ("highlights are not data"),
 * or a conductor drawn by its data colour. `preset` names the material.
 */
std::string DataColorNotice(const Material<double>& material, Highlights highlights,
  bool coloredByData, const std::string& preset = "");

} // namespace shadinglab::render
