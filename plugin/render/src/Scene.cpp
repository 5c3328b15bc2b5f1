// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/Scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadinglab::render
{

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
