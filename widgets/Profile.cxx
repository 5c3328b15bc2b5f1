// SPDX-License-Identifier: BSD-3-Clause
#include "Profile.h"

#include <algorithm>
#include <cmath>

namespace shadinglab::widgets
{

double Luminance(const float* rgb)
{
  return render::Luminance(Vec3<double>(rgb[0], rgb[1], rgb[2]));
}

Profile SampleProfile(const render::Image& image, const ProfileLine& line)
{
  Profile out;
  if (image.width <= 0 || image.height <= 0)
  {
    return out;
  }
  const double x0 = line.x0 * image.width, y0 = line.y0 * image.height;
  const double x1 = line.x1 * image.width, y1 = line.y1 * image.height;
  const double length = std::hypot(x1 - x0, y1 - y0);
  const int samples = std::max(2, static_cast<int>(std::ceil(length)) + 1);
  for (int i = 0; i < samples; ++i)
  {
    const double t = static_cast<double>(i) / (samples - 1);
    const int px = std::clamp(static_cast<int>(std::floor(x0 + t * (x1 - x0))), 0, image.width - 1);
    const int py =
      std::clamp(static_cast<int>(std::floor(y0 + t * (y1 - y0))), 0, image.height - 1);
    const size_t o = static_cast<size_t>(py) * image.width + px;
    out.distance.push_back(t * length);
    out.intensity.push_back(Luminance(&image.rgb[3 * o]));
    out.covered.push_back(image.covered.empty() ? 1 : image.covered[o]);
    out.pixelX.push_back(px + 0.5);
    out.pixelY.push_back(py + 0.5);
  }
  return out;
}

std::vector<double> Derivative(const Profile& profile)
{
  const size_t n = profile.intensity.size();
  std::vector<double> d(n, 0.0);
  for (size_t i = 0; i < n; ++i)
  {
    const size_t a = i > 0 ? i - 1 : i;
    const size_t b = i + 1 < n ? i + 1 : i;
    if (b == a || !profile.covered[a] || !profile.covered[b])
    {
      continue;
    }
    d[i] = (profile.intensity[b] - profile.intensity[a]) /
      (profile.distance[b] - profile.distance[a]);
  }
  return d;
}

std::vector<double> PerceivedProfile(const Profile& profile, double sigma, double gain)
{
  const size_t n = profile.intensity.size();
  std::vector<double> out(profile.intensity);
  const int radius = static_cast<int>(std::ceil(3.0 * sigma));
  for (size_t i = 0; i < n; ++i)
  {
    if (!profile.covered[i])
    {
      continue;
    }
    double sum = 0.0, weight = 0.0;
    for (int k = -radius; k <= radius; ++k)
    {
      const long j = static_cast<long>(i) + k;
      if (j < 0 || j >= static_cast<long>(n) || !profile.covered[j])
      {
        continue;
      }
      const double w = std::exp(-0.5 * k * k / (sigma * sigma));
      sum += w * profile.intensity[j];
      weight += w;
    }
    out[i] = profile.intensity[i] + gain * (profile.intensity[i] - sum / weight);
  }
  return out;
}

} // namespace shadinglab::widgets
