// SPDX-License-Identifier: BSD-3-Clause
// The metaball field (a sum of three Gaussian blobs) whose isosurface
// MakeMetaballIsosurface meshes and the accuracy study's reference ray-casts:
// one definition for both. No VTK.
#pragma once

#include <array>
#include <cmath>

namespace shadinglab::datasets
{

/// The isosurface is field = kMetaballIsoValue (inside: larger).
constexpr double kMetaballIsoValue = 0.5;

/// The field at p; with `gradient`, also its gradient.
inline double MetaballField(const std::array<double, 3>& p, std::array<double, 3>* gradient)
{
  struct Blob
  {
    double c[3];
    double s;
  };
  static constexpr Blob kBlobs[] = { { { -0.35, 0.0, 0.0 }, 0.35 }, { { 0.35, 0.1, 0.05 }, 0.3 },
    { { 0.0, -0.3, 0.25 }, 0.25 } };
  double f = 0;
  std::array<double, 3> g = { 0, 0, 0 };
  for (const auto& b : kBlobs)
  {
    const double d[3] = { p[0] - b.c[0], p[1] - b.c[1], p[2] - b.c[2] };
    const double e = std::exp(-(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / (b.s * b.s));
    f += e;
    for (int k = 0; k < 3; ++k)
    {
      g[k] += -2.0 * d[k] / (b.s * b.s) * e;
    }
  }
  if (gradient)
  {
    *gradient = g;
  }
  return f;
}

} // namespace shadinglab::datasets
