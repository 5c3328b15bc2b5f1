// SPDX-License-Identifier: BSD-3-Clause
// Which triangles the auto mode's predictors read (AutoMode.cpp,
// ModeDifference.cpp): all of a small mesh, and of a large one runs of
// consecutive triangles spread evenly over it.
#pragma once

#include "shadinglab/render/Scene.h"

#include <algorithm>
#include <cstdint>

namespace shadinglab::render
{

/// The triangles of the mesh's polygon fans, in the order Take() walks them.
inline long long TriangleCount(const Mesh& mesh)
{
  return mesh.NumberOfTriangles();
}

/// Triangles are sampled in runs of this many consecutive ones: neighbours
/// in index order share vertices and cache lines, and one triangle in 80
/// read alone cost a cache miss per vertex (10 ms for 16,384 triangles of
/// the 1.3M-triangle icosphere, against ~1 ms in runs of 16).
constexpr long long kSampleRun = 16;

/// Keeps at most about `budget` of `triangles`: one run of kSampleRun
/// consecutive triangles in every period of stride * kSampleRun, at a
/// pseudo-random place in its period. A run at the same place in every
/// period aliased with the rings of a UV sphere (a ring of 2,048 triangles,
/// a period dividing it): all samples fell on a few longitudes, and the
/// 1M-triangle sphere's flat-from-Phong distance came out 0.002/255, not
/// 0.2. Call Take() once per triangle, in index order; Scale() is what a
/// kept triangle stands for.
class TriangleSample
{
public:
  TriangleSample(long long triangles, long long budget)
  {
    const long long runs = std::max(1LL, budget / kSampleRun);
    this->Stride = std::max(1LL, (triangles + runs * kSampleRun - 1) / (runs * kSampleRun));
    this->Period = this->Stride * kSampleRun;
  }
  bool Take()
  {
    if (this->Cycle == this->Period)
    {
      this->Cycle = 0;
      ++this->Index;
    }
    if (this->Cycle == 0)
    {
      // splitmix64 (Steele, Lea & Flood 2014) of the period's index.
      uint64_t z = static_cast<uint64_t>(this->Index) * 0x9E3779B97F4A7C15ull;
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
      z ^= z >> 31;
      this->First = static_cast<long long>(z % static_cast<uint64_t>(this->Period - kSampleRun + 1));
    }
    const long long c = this->Cycle++;
    return c >= this->First && c < this->First + kSampleRun;
  }
  long long Scale() const { return this->Stride; }

private:
  long long Stride = 1, Period = 1, Cycle = 0, Index = 0, First = 0;
};

} // namespace shadinglab::render
