// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/Scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace shadinglab::render
{

namespace
{

/// Four independent multiply-xor lanes over 64-bit words (one chain would
/// be bound by the multiply's latency), folded at the end.
uint64_t HashWords(const void* data, size_t bytes, uint64_t seed)
{
  constexpr uint64_t kMul = 0x9E3779B97F4A7C15ull;
  uint64_t h[4] = { seed, seed ^ 0x1234567ull, seed ^ 0x89abcdefull, seed ^ 0x5555aaaaull };
  const auto* p = static_cast<const unsigned char*>(data);
  size_t i = 0;
  for (; i + 32 <= bytes; i += 32)
  {
    for (int k = 0; k < 4; ++k)
    {
      uint64_t w;
      std::memcpy(&w, p + i + 8 * k, 8);
      h[k] = (h[k] ^ w) * kMul;
      h[k] ^= h[k] >> 29;
    }
  }
  // The last 0-31 bytes: whole words, then the 0-7 left over.
  for (; i + 8 <= bytes; i += 8)
  {
    uint64_t w;
    std::memcpy(&w, p + i, 8);
    h[0] = (h[0] ^ w) * kMul;
    h[0] ^= h[0] >> 29;
  }
  uint64_t tail = 0;
  if (bytes > i)
  {
    std::memcpy(&tail, p + i, bytes - i);
  }
  uint64_t out = (h[0] ^ tail) * kMul;
  for (int k = 1; k < 4; ++k)
  {
    out = (out ^ h[k]) * kMul;
    out ^= out >> 31;
  }
  return out ^ bytes;
}

/// One array in slices of whole 32-byte blocks, hashed by `run` when there
/// is more than one and folded in order. The slices depend on the size
/// alone, so the value is the same with or without a runner and for any
/// number of threads behind it: a cache keyed on it survives a change of
/// thread count.
uint64_t HashArray(const void* data, size_t bytes, const Mesh::TaskRunner& run, uint64_t seed)
{
  // A slice under 1 MB (~0.3 ms at ~3 GB/s) is not worth handing to another
  // thread: a small mesh (every frame of the explorer) is hashed in one.
  // 16 slices keep up to 16 threads busy on the largest arrays.
  constexpr size_t kMinBytesPerSlice = size_t(1) << 20;
  constexpr size_t kMaxSlices = 16;
  const int n = static_cast<int>(
    std::max<size_t>(1, std::min<size_t>(kMaxSlices, bytes / kMinBytesPerSlice)));
  std::vector<uint64_t> part(static_cast<size_t>(n), 0);
  const size_t blocks = bytes / 32, per = (blocks + n - 1) / n;
  auto hashSlice = [&](int s)
  {
    const size_t first = std::min(blocks, s * per) * 32;
    const size_t last = s + 1 == n ? bytes : std::min(blocks, (s + 1) * per) * 32;
    part[s] = HashWords(static_cast<const unsigned char*>(data) + first, last - first,
      static_cast<uint64_t>(s) + 1);
  };
  if (n > 1 && run)
  {
    run(n, hashSlice);
  }
  else
  {
    for (int k = 0; k < n; ++k)
    {
      hashSlice(k);
    }
  }
  uint64_t h = seed;
  for (const uint64_t p : part)
  {
    h = HashWords(&p, sizeof(p), h);
  }
  return h ^ bytes;
}

} // namespace

uint64_t Mesh::ContentHash(const TaskRunner& run) const
{
  uint64_t h = 1;
  h = HashArray(this->points.data(), this->points.size() * sizeof(float), run, h);
  h = HashArray(this->normals.data(), this->normals.size() * sizeof(float), run, h);
  h = HashArray(this->colors.data(), this->colors.size() * sizeof(float), run, h);
  h = HashArray(this->offsets.data(), this->offsets.size() * sizeof(int64_t), run, h);
  h = HashArray(this->connectivity.data(), this->connectivity.size() * sizeof(int64_t), run, h);
  return HashArray(this->faceNormals.data(), this->faceNormals.size() * sizeof(float), run, h);
}

void Mesh::Bounds(double bounds[6]) const
{
  bounds[0] = bounds[2] = bounds[4] = std::numeric_limits<double>::infinity();
  bounds[1] = bounds[3] = bounds[5] = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 2 < this->points.size(); i += 3)
  {
    for (int c = 0; c < 3; ++c)
    {
      bounds[2 * c] = std::min(bounds[2 * c], static_cast<double>(this->points[i + c]));
      bounds[2 * c + 1] = std::max(bounds[2 * c + 1], static_cast<double>(this->points[i + c]));
    }
  }
}

Camera FitCamera(const double bounds[6], double azimuthDeg, double elevationDeg, double zoom,
  double aspect, bool parallel)
{
  Camera cam;
  const Vec3<double> center(
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]));
  const Vec3<double> extent(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);
  double radius = 0.5 * Length(extent);
  if (!(radius > 0))
  {
    radius = 0.5;
  }
  // As vtkRenderer::ResetCamera: the distance at which the bounding sphere
  // fits the view angle (the narrower of the vertical and horizontal angles).
  cam.viewAngle = 30.0;
  double half = 0.5 * cam.viewAngle * kPi<double> / 180.0;
  if (aspect < 1.0)
  {
    half = std::atan(std::tan(half) * aspect);
  }
  const double distance = radius / std::sin(half);
  const double az = azimuthDeg * kPi<double> / 180.0, el = elevationDeg * kPi<double> / 180.0;
  // Start on +z looking down -z with +y up; azimuth about y, then elevation.
  const Vec3<double> dir(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
  cam.focalPoint = center;
  cam.position = center + dir * distance;
  const Vec3<double> right = NormalizeOr(Cross(Vec3<double>(0, 1, 0), dir), Vec3<double>(1, 0, 0));
  cam.viewUp = NormalizeOr(Cross(dir, right), Vec3<double>(0, 1, 0));
  // Zoom is validated by the front ends; the floor keeps a zero from dividing.
  cam.viewAngle /= std::max(zoom, 1e-6);
  cam.parallel = parallel;
  cam.parallelScale = radius / std::max(zoom, 1e-6);
  cam.nearClip = std::max(distance - 1.01 * radius, 1e-3 * distance);
  cam.farClip = distance + 1.01 * radius;
  return cam;
}

void ToLocal(const WorldFrame& frame, Camera& camera)
{
  camera.position = frame.ToLocal(camera.position);
  camera.focalPoint = frame.ToLocal(camera.focalPoint);
  camera.nearClip = frame.LengthToLocal(camera.nearClip);
  camera.farClip = frame.LengthToLocal(camera.farClip);
  camera.parallelScale = frame.LengthToLocal(camera.parallelScale);
}

void ToLocal(const WorldFrame& frame, Lighting<double>& lighting)
{
  for (int j = 0; j < lighting.lightCount; ++j)
  {
    Light<double>& light = lighting.lights[j];
    if (light.type == LightType::Point)
    {
      light.vector = frame.ToLocal(light.vector);
      // c0 + c1 d + c2 d^2 with d = scale * d_local.
      light.attenuation.y *= frame.scale;
      light.attenuation.z *= frame.scale * frame.scale;
    }
  }
}

CameraBasis BasisOf(const Camera& camera)
{
  CameraBasis b;
  b.forward = NormalizeOr(camera.focalPoint - camera.position, Vec3<double>(0, 0, -1));
  b.right = NormalizeOr(Cross(b.forward, camera.viewUp), Vec3<double>(1, 0, 0));
  b.up = Cross(b.right, b.forward);
  return b;
}

Light<double> KeyLight(const Camera& camera, double intensity)
{
  const CameraBasis b = BasisOf(camera);
  const Vec3<double> toEye = -b.forward, right = b.right, up = b.up;
  Light<double> key;
  key.type = LightType::Directional;
  key.vector = NormalizeOr(toEye + up * 0.5 - right * 0.4, toEye);
  key.intensity = Vec3<double>(intensity, intensity, intensity);
  return key;
}

Light<double> CameraLight(
  const Camera& camera, double azimuthDeg, double elevationDeg, double intensity)
{
  const CameraBasis b = BasisOf(camera);
  const Vec3<double> toEye = -b.forward, right = b.right, up = b.up;
  const double az = azimuthDeg * kPi<double> / 180.0, el = elevationDeg * kPi<double> / 180.0;
  Light<double> light;
  light.type = LightType::Directional;
  light.vector = NormalizeOr(
    toEye * (std::cos(el) * std::cos(az)) + right * (std::cos(el) * std::sin(az)) +
      up * std::sin(el),
    toEye);
  light.intensity = Vec3<double>(intensity, intensity, intensity);
  return light;
}

} // namespace shadinglab::render
