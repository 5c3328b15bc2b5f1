// SPDX-License-Identifier: BSD-3-Clause
// Run-time choice of the pixel kernel (WideShading.h) and the one-lane path.
#include "WideShading.h"

#include <atomic>

namespace shadinglab::cpu
{

namespace
{

bool CpuHasAvx2()
{
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return avx2;
}

int BestLanes()
{
  return CpuHasAvx2() ? 8 : 4;
}

std::atomic<int> gForcedLanes{ 0 };

/// One pixel at a time: the scalar model, as the renderer did before the
/// wide kernels (and bit-identical to it).
void ShadeQueueScalar(const PixelUniforms& u, PixelQueue& q)
{
  for (int k = 0; k < q.count; ++k)
  {
    const Vec3<float> P = u.hasPosition ? Vec3<float>(q.px[k], q.py[k], q.pz[k]) : Vec3<float>();
    const Vec3<float> color =
      u.hasColor ? Vec3<float>(q.cr[k], q.cg[k], q.cb[k]) : u.material->diffuseColor;
    const Vec3<float> I = ShadeQueuedPixel(*u.material, *u.lighting, u.eye, u.toEye, u.parallel,
      Vec3<float>(q.nx[k], q.ny[k], q.nz[k]), P, color);
    q.out[k][0] = I.x;
    q.out[k][1] = I.y;
    q.out[k][2] = I.z;
  }
  q.count = 0;
}

} // namespace

int PixelLanes()
{
  const int forced = gForcedLanes.load(std::memory_order_relaxed);
  return forced > 0 ? forced : BestLanes();
}

void SetPixelLanes(int lanes)
{
  const bool available = lanes == 1 || lanes == 4 || (lanes == 8 && CpuHasAvx2());
  gForcedLanes.store(available ? lanes : 0, std::memory_order_relaxed);
}

namespace
{
std::atomic<ScreenRecords> gScreenRecords{ ScreenRecords::Auto };
}

void SetScreenRecords(ScreenRecords layout)
{
  gScreenRecords.store(layout, std::memory_order_relaxed);
}

ScreenRecords ForcedScreenRecords()
{
  return gScreenRecords.load(std::memory_order_relaxed);
}

void ShadeQueue(const PixelUniforms& uniforms, PixelQueue& queue)
{
  switch (PixelLanes())
  {
    case 8:
      ShadeQueueAvx2(uniforms, queue);
      return;
    case 4:
      ShadeQueueSse2(uniforms, queue);
      return;
    default:
      ShadeQueueScalar(uniforms, queue);
  }
}

} // namespace shadinglab::cpu
