// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/Scene.h"

#include <iterator>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <thread>

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

/// One array's share of the hash: `slices` slices of whole 32-byte blocks
/// (the last takes the rest), each hashed on its own and folded in order.
struct HashedArray
{
  const unsigned char* data;
  size_t bytes;
  int slices;
  int firstPart; ///< its first slice's index among all the mesh's slices
};

/// A slice under 256 KB (~40 us at the ~7 GB/s HashWords reads) is not
/// worth handing to another thread; 64 keep up to 64 threads busy on the
/// largest arrays and bound the fold. The slices depend on the sizes alone,
/// so the value is the same with or without a runner and for any number of
/// threads behind it: a cache keyed on it survives a change of thread count.
constexpr size_t kMinBytesPerSlice = size_t(256) << 10;
constexpr size_t kMaxSlices = 64;
/// A mesh with less than this in all (every frame of the explorer's
/// meshes) is hashed on the calling thread: waking others costs more.
constexpr size_t kMinBytesToSpread = size_t(1) << 20;

/// Tasks from which RunOrInline, given no runner, splits them between
/// this thread and one more: 16 slices are a million points or 16 MB to
/// hash, ~1 ms of work against a thread's ~50 us start.
constexpr int kTwoThreadTasks = 16;

/// Runs task(0) .. task(n - 1) on `run` when given and worth it, else here
/// (on two threads from kTwoThreadTasks tasks). Tasks write their own
/// results: any order gives the same.
void RunOrInline(int n, bool spread, const Mesh::TaskRunner& run,
  const std::function<void(int)>& task)
{
  if (n > 1 && spread && run)
  {
    run(n, task);
    return;
  }
  if (spread && n >= kTwoThreadTasks)
  {
    std::thread other([&] {
      for (int k = n / 2; k < n; ++k)
      {
        task(k);
      }
    });
    for (int k = 0; k < n / 2; ++k)
    {
      task(k);
    }
    other.join();
    return;
  }
  for (int k = 0; k < n; ++k)
  {
    task(k);
  }
}

} // namespace

uint64_t UniqueMeshKey()
{
  static std::atomic<uint64_t> next{ 0 };
  return (uint64_t(1) << 63) | next.fetch_add(1, std::memory_order_relaxed);
}

uint64_t Mesh::ContentHash(const TaskRunner& run) const
{
  auto arrayOf = [](const auto& v)
  {
    if constexpr (std::is_same_v<std::decay_t<decltype(v)>, IdArray>)
    {
      // In place, whichever width (a narrow and a wide copy of the same
      // ids hash apart: a cache keyed on it is refilled once).
      return HashedArray{ static_cast<const unsigned char*>(v.Bytes()), v.ByteSize(), 0, 0 };
    }
    else
    {
      return HashedArray{ reinterpret_cast<const unsigned char*>(v.data()),
        v.size() * sizeof(v[0]), 0, 0 };
    }
  };
  HashedArray arrays[] = { arrayOf(this->points), arrayOf(this->normals), arrayOf(this->colors),
    arrayOf(this->offsets), arrayOf(this->connectivity), arrayOf(this->faceNormals),
    arrayOf(this->scalars), arrayOf(this->cellScalars) };
  // Every array's slices in one batch, so all the runner's threads share
  // the whole mesh (one batch per array left a 600 KB array to one thread).
  int parts = 0;
  size_t total = 0;
  std::vector<std::pair<int, int>> sliceOf; // part -> (array, slice)
  for (int a = 0; a < static_cast<int>(std::size(arrays)); ++a)
  {
    HashedArray& arr = arrays[a];
    arr.slices = static_cast<int>(
      std::max<size_t>(1, std::min<size_t>(kMaxSlices, arr.bytes / kMinBytesPerSlice)));
    arr.firstPart = parts;
    for (int s = 0; s < arr.slices; ++s)
    {
      sliceOf.emplace_back(a, s);
    }
    parts += arr.slices;
    total += arr.bytes;
  }
  std::vector<uint64_t> part(static_cast<size_t>(parts), 0);
  RunOrInline(parts, total >= kMinBytesToSpread, run,
    [&](int k)
    {
      const auto [a, s] = sliceOf[static_cast<size_t>(k)];
      const HashedArray& arr = arrays[a];
      const size_t blocks = arr.bytes / 32, per = (blocks + arr.slices - 1) / arr.slices;
      const size_t first = std::min(blocks, s * per) * 32;
      const size_t last = s + 1 == arr.slices ? arr.bytes : std::min(blocks, (s + 1) * per) * 32;
      part[static_cast<size_t>(k)] =
        HashWords(arr.data + first, last - first, static_cast<uint64_t>(s) + 1);
    });
  // Fold: each array's slices in order, seeded by the arrays before it.
  uint64_t h = 1;
  for (const HashedArray& arr : arrays)
  {
    for (int s = 0; s < arr.slices; ++s)
    {
      h = HashWords(&part[static_cast<size_t>(arr.firstPart + s)], sizeof(uint64_t), h);
    }
    h ^= arr.bytes;
  }
  return h;
}

void Mesh::Bounds(double bounds[6], const TaskRunner& run) const
{
  // Slices of kPointsPerSlice points (their min and max are exact, so the
  // result does not depend on the slicing): a renderer reads the bounds
  // every frame, ~2 ms for the 1.3M-triangle icosphere's 655k points.
  constexpr int64_t kPointsPerSlice = 65536;
  const int64_t n = this->NumberOfPoints();
  const int slices = static_cast<int>(std::max<int64_t>(1, (n + kPointsPerSlice - 1) / kPointsPerSlice));
  std::vector<std::array<float, 6>> part(static_cast<size_t>(slices));
  RunOrInline(slices, true, run,
    [&](int s)
    {
      // float min/max (exact; NaN coordinates are skipped, as by std::min);
      // written as selects so the loop vectorizes.
      constexpr float kInf = std::numeric_limits<float>::infinity();
      float lo[3] = { kInf, kInf, kInf }, hi[3] = { -kInf, -kInf, -kInf };
      const float* p = this->points.data();
      const int64_t end = std::min(n, (s + 1) * kPointsPerSlice);
      for (int64_t v = s * kPointsPerSlice; v < end; ++v)
      {
        for (int c = 0; c < 3; ++c)
        {
          const float x = p[3 * v + c];
          lo[c] = x < lo[c] ? x : lo[c];
          hi[c] = x > hi[c] ? x : hi[c];
        }
      }
      part[static_cast<size_t>(s)] = { lo[0], hi[0], lo[1], hi[1], lo[2], hi[2] };
    });
  bounds[0] = bounds[2] = bounds[4] = std::numeric_limits<double>::infinity();
  bounds[1] = bounds[3] = bounds[5] = -std::numeric_limits<double>::infinity();
  for (const auto& b : part)
  {
    for (int c = 0; c < 3; ++c)
    {
      bounds[2 * c] = std::min(bounds[2 * c], static_cast<double>(b[2 * c]));
      bounds[2 * c + 1] = std::max(bounds[2 * c + 1], static_cast<double>(b[2 * c + 1]));
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

Lighting<double> LightKit(
  const Camera& camera, double intensity, double keyAzimuthDeg, double keyElevationDeg)
{
  // vtkLightKit's defaults (VTK 9.2 to 9.6, Rendering/Core/vtkLightKit.cxx):
  // KeyLightIntensity and the key-to-fill, key-to-back and key-to-head ratios.
  constexpr double kKey = 0.75, kKeyToFill = 3.0, kKeyToBack = 3.5, kKeyToHead = 3.0;
  // Its angles (elevation, azimuth) in the camera's frame: vtkLight's
  // SetDirectionAngle, which is CameraLight's convention.
  struct KitLight
  {
    double elevation, azimuth, intensity;
  };
  const KitLight kit[] = { { keyElevationDeg, keyAzimuthDeg, kKey }, { -75.0, -10.0, kKey / kKeyToFill },
    { 0.0, 110.0, kKey / kKeyToBack }, { 0.0, -110.0, kKey / kKeyToBack },
    { 0.0, 0.0, kKey / kKeyToHead } };
  Lighting<double> lighting;
  lighting.lightCount = 0;
  for (const KitLight& light : kit)
  {
    lighting.lights[lighting.lightCount++] =
      CameraLight(camera, light.azimuth, light.elevation, intensity * light.intensity);
  }
  return lighting;
}

Lighting<double> LightsOrHeadlight(const Lighting<double>& lighting, const Camera& camera)
{
  if (lighting.lightCount > 0)
  {
    return lighting;
  }
  Lighting<double> out = lighting;
  Light<double> headlight;
  headlight.vector =
    NormalizeOr(camera.position - camera.focalPoint, Vec3<double>(0, 0, 1));
  out.lights[0] = headlight;
  out.lightCount = 1;
  return out;
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
