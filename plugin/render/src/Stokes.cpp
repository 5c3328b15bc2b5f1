// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/Stokes.h"

#include "shadinglab/render/ColorMap.h"
#include "shadinglab/render/Image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shadinglab::render
{

StokesImage MeasureStokes(
  Renderer& renderer, const Scene& scene, const RenderOptions& options, RenderStats* stats)
{
  // eq. 8.5: I(theta) = (S0 + S1 cos 2 theta + S2 sin 2 theta) / 2, so
  // S0 = I0 + I90, S1 = I0 - I90, S2 = I45 - I135; and through the circular
  // analyser I_R = (S0 + S3) / 2, so S3 = 2 I_R - S0.
  Image frames[5];
  for (int a = 0; a < 5; ++a)
  {
    RenderOptions analysed = options;
    analysed.polarizer = a < 4 ? 45.0 * a : 0.0;
    analysed.circularAnalyser = a == 4;
    frames[a] = renderer.Render(scene, analysed, a == 0 ? stats : nullptr);
    if (frames[a].displayApplied)
    {
      throw std::invalid_argument(
        "the Stokes image is measured on linear frames: the CPU renderer");
    }
  }
  StokesImage out;
  out.width = frames[0].width;
  out.height = frames[0].height;
  const size_t n = static_cast<size_t>(out.width) * out.height;
  for (auto& component : out.s)
  {
    component.assign(3 * n, 0.0f);
  }
  out.dolp.assign(n, std::nanf(""));
  out.aop.assign(n, std::nanf(""));
  out.covered = frames[0].covered;
  out.depth = frames[0].depth;
  double dolpSum = 0.0;
  long long counted = 0;
  for (size_t p = 0; p < n; ++p)
  {
    Vec3<double> y[4];
    for (int c = 0; c < 3; ++c)
    {
      const size_t i = 3 * p + c;
      out.s[0][i] = frames[0].rgb[i] + frames[2].rgb[i];
      out.s[1][i] = frames[0].rgb[i] - frames[2].rgb[i];
      out.s[2][i] = frames[1].rgb[i] - frames[3].rgb[i];
      out.s[3][i] = 2.0f * frames[4].rgb[i] - out.s[0][i];
    }
    for (int k = 0; k < 3; ++k)
    {
      y[k] = Vec3<double>(out.s[k][3 * p], out.s[k][3 * p + 1], out.s[k][3 * p + 2]);
    }
    const double y0 = Luminance(y[0]), y1 = Luminance(y[1]), y2 = Luminance(y[2]);
    if (out.covered[p] && y0 > kMinStokesS0)
    {
      out.dolp[p] = static_cast<float>(std::min(1.0, std::sqrt(y1 * y1 + y2 * y2) / y0));
      out.aop[p] = static_cast<float>(0.5 * std::atan2(y2, y1) * 180.0 / kPi<double>);
      dolpSum += out.dolp[p];
      ++counted;
    }
  }
  out.meanDolp = counted ? dolpSum / counted : 0.0;
  return out;
}

std::vector<float> FalseColour(
  const StokesImage& stokes, StokesQuantity quantity, const Vec3<float>& background)
{
  const bool dolp = quantity == StokesQuantity::Dolp;
  const ColorMap map = dolp ? DolpColorMap() : AopColorMap();
  const std::vector<float>& values = dolp ? stokes.dolp : stokes.aop;
  std::vector<float> rgb(3 * stokes.covered.size());
  for (size_t p = 0; p < stokes.covered.size(); ++p)
  {
    const Vec3<float> c = stokes.covered[p] ? map.Map(values[p]) : background;
    rgb[3 * p] = c.x;
    rgb[3 * p + 1] = c.y;
    rgb[3 * p + 2] = c.z;
  }
  return rgb;
}

} // namespace shadinglab::render
