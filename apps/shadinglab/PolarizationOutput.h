// SPDX-License-Identifier: BSD-3-Clause
// render --output: the Stokes images of the light reaching the camera,
// measured as a polarization camera measures them, through analysers at 0,
// 45, 90 and 135 degrees (docs/model.md eq. 8.5).
#pragma once

#include "shadinglab/render/Renderer.h"

#include <string>

namespace shadinglab::cli
{

/// "intensity" (the ordinary picture), "dolp", "aop" (false-colour PNGs
/// with a legend) or "stokes" (a .vti of S0, S1, S2 per RGB channel and the
/// luminance DoLP and AoP). Throws UsageError for anything else.
bool IsPolarizationOutput(const std::string& kind);

/// Renders the four analysed frames with `renderer` (the CPU renderer: the
/// frames must be linear) and writes `kind` to `path`. Returns the covered
/// pixels' mean DoLP (luminance), for the caller's --stats.
double WritePolarizationOutput(render::Renderer& renderer, const render::Scene& scene,
  const render::RenderOptions& options, const std::string& kind, const std::string& path);

} // namespace shadinglab::cli
