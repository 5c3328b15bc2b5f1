// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/Fidelity.h"

#include "shadinglab/render/DataColor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shadinglab::render
{

FidelityResult CompareWithMap(
  const Image& picture, const Image& white, const Image& ramp, const ColorMap& map)
{
  FidelityResult result;
  const size_t pixels = static_cast<size_t>(picture.width) * static_cast<size_t>(picture.height);
  if (white.rgb.size() != 3 * pixels || ramp.rgb.size() != 3 * pixels ||
    picture.rgb.size() != 3 * pixels || map.colors.empty())
  {
    throw std::invalid_argument("colour fidelity: the three frames differ in size");
  }
  const int bins = static_cast<int>(map.colors.size());
  for (size_t i = 0; i < pixels; ++i)
  {
    if (!picture.covered[i])
    {
      continue;
    }
    ++result.covered;
    const float* P = &picture.rgb[3 * i];
    const float* W = &white.rgb[3 * i];
    const float* Q = &ramp.rgb[3 * i];
    // The value from the brightest channel of W (lights may be tinted).
    const int c = W[0] >= W[1] && W[0] >= W[2] ? 0 : (W[1] >= W[2] ? 1 : 2);
    Vec3<double> expected(0, 0, 0);
    if (W[c] > kFidelityUnlit)
    {
      // eq. 9.3: t in bin units; between two bins' centres a supersampled
      // pixel mixes their colours linearly.
      const double t = std::clamp(static_cast<double>(Q[c]) / W[c] * bins - 0.5, 0.0, bins - 1.0);
      const int k = std::min(bins - 2 < 0 ? 0 : bins - 2, static_cast<int>(t));
      const double a = bins > 1 ? t - k : 0.0;
      const Vec3<float>& c0 = map.colors[static_cast<size_t>(k)];
      const Vec3<float>& c1 = map.colors[static_cast<size_t>(std::min(bins - 1, k + 1))];
      // The map's colour under the lights' colour (W's hue), then the
      // brightness s >= 0 that fits P best: P must be s times it.
      const double hue[3] = { W[0] / W[c], W[1] / W[c], W[2] / W[c] };
      const Vec3<double> colour((c0.x + a * (c1.x - c0.x)) * hue[0],
        (c0.y + a * (c1.y - c0.y)) * hue[1], (c0.z + a * (c1.z - c0.z)) * hue[2]);
      const double norm = Dot(colour, colour);
      const double s = norm > 0
        ? std::max(0.0, (P[0] * colour.x + P[1] * colour.y + P[2] * colour.z) / norm)
        : 0.0;
      expected = colour * s;
    }
    const bool faithful = std::abs(P[0] - expected.x) <= kFidelityTolerance &&
      std::abs(P[1] - expected.y) <= kFidelityTolerance &&
      std::abs(P[2] - expected.z) <= kFidelityTolerance;
    result.unfaithful += faithful ? 0 : 1;
  }
  return result;
}

FidelityResult MeasureColorFidelity(Renderer& renderer, const Scene& scene, RenderOptions options)
{
  if (!scene.colorMap || scene.colorMap->colors.empty())
  {
    throw std::invalid_argument("colour fidelity: the scene is not coloured by data");
  }
  options.displayBytes = false;
  // A supersampled edge pixel mixes in the background: black keeps P, W
  // and Q all scaled by the same coverage.
  options.background = Vec3<float>(0, 0, 0);
  const Image picture = renderer.Render(scene, options);
  if (picture.displayApplied)
  {
    throw std::invalid_argument("colour fidelity needs linear frames (the CPU renderer)");
  }
  const ColorMap& map = *scene.colorMap;
  ColorMap white = map, ramp = map;
  // A NaN value's pixel reads as bin 0: counted unless the NaN colour is bin 0's.
  white.nanColor = Vec3<float>(1, 1, 1);
  ramp.nanColor = Vec3<float>(0, 0, 0);
  const int bins = static_cast<int>(map.colors.size());
  for (int k = 0; k < bins; ++k)
  {
    white.colors[static_cast<size_t>(k)] = Vec3<float>(1, 1, 1);
    const float t = (static_cast<float>(k) + 0.5f) / static_cast<float>(bins);
    ramp.colors[static_cast<size_t>(k)] = Vec3<float>(t, t, t);
  }
  Scene honest = scene;
  honest.material = MaterialForData(scene.material, Highlights::Off, true);
  honest.colorMap = &white;
  const Image shade = renderer.Render(honest, options);
  honest.colorMap = &ramp;
  const Image& values = renderer.Render(honest, options);
  return CompareWithMap(picture, shade, values, map);
}

} // namespace shadinglab::render
