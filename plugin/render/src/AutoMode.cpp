// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/AutoMode.h"

#include "shadinglab/render/Image.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace shadinglab::render
{

namespace
{

/// Fitted coefficients of eq. 4.1 (a, b, c, d) per mode and a margin, the
/// 70th percentile of the fit's log residuals (chosen by the script on the
/// training rows: replaying the choice there, it meets E at <= 1.2x the
/// cheapest mode most often while meeting E in >= 97% of cases); written by
/// `scripts/fit-auto-mode.py accuracy.csv` from `shadinglab accuracy` (CPU
/// rows, area normals, Blinn-Phong and Cook-Torrance). See docs/model.md
/// section 4.
struct Fit
{
  double a, b, c, d, margin;
};
// Fit of 2026-11-25 (320x240, 2 threads, three views; 213-234 rows per
// mode with mean error >= 0.02/255; R^2 0.978, 0.948, 0.814): flat converges to first
// order in the spread (b ~ 1), Gouraud and Phong faster (b ~ 1.6-1.7; the
// silhouette and the light's terminator keep them below 2); a sharper lobe
// lights fewer pixels, so the mean error falls with it (c < 0).
constexpr Fit kFlat = { 4.9417, 0.9703, -0.3529, 0.1347, 0.0862 };
constexpr Fit kGouraud = { 4.7514, 1.6294, -0.2572, 0.2723, 0.1559 };
constexpr Fit kPhong = { 3.9660, 1.6892, -0.2412, 0.1011, 0.4186 };

/// eq. 4.2's coefficients (ms, ms per 1000 triangles, ms per 1000 front
/// pixels) per mode and model class: [0] not Cook-Torrance, [1] Cook-Torrance
/// dielectric, [2] Cook-Torrance conductor. Weighted least squares on the
/// relative error (156 rows each: two runs of the study, side by side),
/// refitted 2026-11-25 after the conductor Fresnel went to real arithmetic:
/// a conductor now costs what a dielectric does in every mode (it cost 1.1x
/// in Phong and 1.7x in Gouraud with the complex form).
struct CostFit
{
  double a, b, c;
};
constexpr CostFit kCostFlat[3] = { { 0.2903, 0.05254, 0.00423 }, { 0.2697, 0.05378, 0.00477 },
  { 0.2300, 0.05503, 0.00745 } };
constexpr CostFit kCostGouraud[3] = { { 0.1913, 0.06018, 0.00725 },
  { 0.1917, 0.06709, 0.00718 }, { 0.1958, 0.06740, 0.00656 } };
constexpr CostFit kCostPhong[3] = { { 0.2064, 0.04906, 0.01800 }, { 0.2064, 0.04830, 0.01776 },
  { 0.2069, 0.04730, 0.01854 } };

const Fit& FitOf(ShadingMode mode)
{
  switch (mode)
  {
    case ShadingMode::Flat:
      return kFlat;
    case ShadingMode::Gouraud:
      return kGouraud;
    default:
      return kPhong;
  }
}

/// Normal spreads below this (radians) are a flat region: the power law is
/// evaluated at the floor, which predicts far below 1/255 for every mode.
constexpr double kMinSpread = 1e-4;
/// A black material's peak: the power law's floor (it predicts ~0 error).
constexpr double kMinPeak = 1e-6;

double AngleBetween(const float* a, const float* b)
{
  const double la = std::sqrt(double(a[0]) * a[0] + double(a[1]) * a[1] + double(a[2]) * a[2]);
  const double lb = std::sqrt(double(b[0]) * b[0] + double(b[1]) * b[1] + double(b[2]) * b[2]);
  if (!(la > 0) || !(lb > 0))
  {
    return 0;
  }
  const double c = (double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2]) / (la * lb);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

} // namespace

ViewPredictors PredictorsOf(const Mesh& mesh, const std::vector<float>& normals,
  const Camera& camera, int width, int height)
{
  ViewPredictors out;
  const CameraBasis basis = BasisOf(camera);
  const Vec3<double>& forward = basis.forward;
  const Vec3<double>& right = basis.right;
  const Vec3<double>& up = basis.up;
  const double aspect = static_cast<double>(width) / height;
  const double tanHalf = std::tan(0.5 * camera.viewAngle * kPi<double> / 180.0);
  // Pixel coordinates of a point, false behind the camera.
  auto project = [&](int64_t v, double& x, double& y) {
    const Vec3<double> p(mesh.points[3 * v], mesh.points[3 * v + 1], mesh.points[3 * v + 2]);
    const Vec3<double> d = p - camera.position;
    const double z = Dot(d, forward);
    double sx = Dot(d, right), sy = Dot(d, up);
    if (camera.parallel)
    {
      sx /= camera.parallelScale * aspect;
      sy /= camera.parallelScale;
    }
    else
    {
      if (!(z > camera.nearClip))
      {
        return false;
      }
      sx /= z * tanHalf * aspect;
      sy /= z * tanHalf;
    }
    x = (sx + 1) * 0.5 * width;
    y = (1 - sy) * 0.5 * height;
    return true;
  };
  double weighted = 0, area = 0;
  for (int64_t p = 0; p < mesh.NumberOfPolygons(); ++p)
  {
    out.triangles += mesh.offsets[p + 1] - mesh.offsets[p] - 2;
  }
  const bool haveNormals = normals.size() == mesh.points.size();
  for (int64_t p = 0; p < mesh.NumberOfPolygons(); ++p)
  {
    const int64_t b = mesh.offsets[p], e = mesh.offsets[p + 1];
    for (int64_t k = b + 1; k + 1 < e; ++k) // the polygon's fan
    {
      const int64_t v[3] = { mesh.connectivity[b], mesh.connectivity[k], mesh.connectivity[k + 1] };
      double x[3], y[3];
      if (!project(v[0], x[0], y[0]) || !project(v[1], x[1], y[1]) || !project(v[2], x[2], y[2]))
      {
        continue;
      }
      // Signed area, y down: front faces (counter-clockwise in the world)
      // are clockwise here. Both sides are lit (two-sided lighting): count
      // either, as the renderers draw either.
      const double a2 = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
      const double a = 0.5 * std::abs(a2);
      const double cx = (x[0] + x[1] + x[2]) / 3, cy = (y[0] + y[1] + y[2]) / 3;
      if (!(a > 0) || cx < 0 || cy < 0 || cx > width || cy > height)
      {
        continue;
      }
      double spread = 0;
      if (haveNormals)
      {
        const float* n0 = &normals[3 * v[0]];
        const float* n1 = &normals[3 * v[1]];
        const float* n2 = &normals[3 * v[2]];
        spread = std::max({ AngleBetween(n0, n1), AngleBetween(n1, n2), AngleBetween(n0, n2) });
      }
      weighted += a * spread;
      area += a;
      ++out.visibleTriangles;
      if (haveNormals)
      {
        // Facing the viewer: the mean vertex normal toward the eye.
        Vec3<double> n(0, 0, 0), c(0, 0, 0);
        for (int j = 0; j < 3; ++j)
        {
          n += Vec3<double>(normals[3 * v[j]], normals[3 * v[j] + 1], normals[3 * v[j] + 2]);
          c += Vec3<double>(mesh.points[3 * v[j]], mesh.points[3 * v[j] + 1], mesh.points[3 * v[j] + 2]);
        }
        const Vec3<double> toEye = camera.parallel ? -forward : camera.position - c / 3.0;
        if (Dot(n, toEye) > 0)
        {
          out.frontPixels += a;
        }
      }
    }
  }
  if (area > 0)
  {
    out.normalSpread = weighted / area;
    out.trianglePixels = area / static_cast<double>(out.visibleTriangles);
  }
  return out;
}

double LobeSharpness(const Material<double>& material)
{
  if (!(material.ks > 0) || material.model == ReflectanceModel::Lambert ||
    material.model == ReflectanceModel::LommelSeeliger)
  {
    return 0;
  }
  if (material.model != ReflectanceModel::CookTorrance)
  {
    return material.shininess;
  }
  double m = 1.0;
  for (int i = 0; i < material.lobeCount; ++i)
  {
    if (material.lobes[i].weight > 0)
    {
      m = std::min(m, material.lobes[i].m);
    }
  }
  return std::max(0.0, 2.0 / (m * m) - 2.0);
}

double LobePeak(const Material<double>& material)
{
  const Vec3<double> N(0, 0, 1);
  return std::max(Luminance(EvaluateBrdf(material, material.diffuseColor, N, N, N)), kMinPeak);
}

double PredictError(ShadingMode mode, const ViewPredictors& view, double sharpness, double peak,
  bool conservative)
{
  const Fit& f = FitOf(mode);
  const double spread = std::max(view.normalSpread, kMinSpread);
  const double log = f.a + f.b * std::log(spread) + f.c * std::log1p(sharpness) +
    f.d * std::log(std::max(peak, kMinPeak)) + (conservative ? f.margin : 0.0);
  return std::exp(log);
}

double LightScale(const Lighting<double>& lighting)
{
  if (lighting.lightCount == 0)
  {
    return 1.0; // the renderers' headlight
  }
  double scale = 0;
  for (int j = 0; j < lighting.lightCount; ++j)
  {
    const Light<double>& l = lighting.lights[j];
    scale += std::max({ l.intensity.x, l.intensity.y, l.intensity.z }) * l.solidAngle /
      kPi<double>;
  }
  return scale;
}

double PredictCost(ShadingMode mode, const ViewPredictors& view, const Material<double>& material)
{
  const int k = material.model != ReflectanceModel::CookTorrance ? 0
    : material.IsConductor()                                   ? 2
                                                               : 1;
  const CostFit& f = mode == ShadingMode::Flat ? kCostFlat[k]
    : mode == ShadingMode::Gouraud             ? kCostGouraud[k]
                                               : kCostPhong[k];
  return f.a + f.b * view.triangles / 1000.0 + f.c * view.frontPixels / 1000.0;
}

ModeChoice ChooseMode(const Mesh& mesh, const std::vector<float>& normals, const Camera& camera,
  const Lighting<double>& lighting, const Material<double>& material, int width, int height,
  double maxError)
{
  const double light = LightScale(lighting);
  ModeChoice choice;
  choice.view = PredictorsOf(mesh, normals, camera, width, height);
  choice.sharpness = LobeSharpness(material);
  choice.peak = LobePeak(material);
  std::ostringstream why;
  why.precision(3);
  why << "normal spread " << choice.view.normalSpread * 180.0 / kPi<double> << " deg over "
      << choice.view.visibleTriangles << " visible triangles of " << choice.view.trianglePixels
      << " px, lobe n = " << choice.sharpness << ", peak " << choice.peak << "/sr:";
  bool found = false;
  for (ShadingMode mode : { ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong })
  {
    const double e =
      light * PredictError(mode, choice.view, choice.sharpness, choice.peak, true);
    const double ms = PredictCost(mode, choice.view, material);
    why << " " << ShadingModeName(mode) << " " << e << "/255 " << ms << " ms;";
    const bool meets = e <= maxError;
    if ((meets && (!found || ms < choice.predictedMs)) ||
      (!found && mode == ShadingMode::Phong))
    {
      choice.mode = mode;
      choice.predicted = e;
      choice.predictedMs = ms;
      found = found || meets;
    }
  }
  why << " -> " << ShadingModeName(choice.mode);
  if (choice.predicted > maxError)
  {
    why << ", the most accurate; no mode is predicted under " << maxError;
  }
  choice.why = why.str();
  return choice;
}

} // namespace shadinglab::render
