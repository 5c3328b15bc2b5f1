// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/AutoMode.h"

#include "shadinglab/render/Image.h"

#include "ScreenProjection.h"
#include "TriangleSample.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace shadinglab::render
{

namespace
{

/// Fitted coefficients (a, b, c, d) per mode and a margin, a percentile of
/// the fit's log residuals (chosen by the script on the training rows:
/// replaying the choice there, it meets E at <= 1.2x the cheapest mode most
/// often while meeting E in >= 97% of cases); written by
/// `scripts/fit-auto-mode.py accuracy.csv` from `shadinglab accuracy` (CPU
/// rows, area normals, Blinn-Phong and Cook-Torrance). See docs/model.md
/// section 4.
struct Fit
{
  double a, b, c, d, e, margin;
};
// Fit of 2026-12-02 (320x240, 2 threads, three views; 213-234 rows per mode
// with mean error >= 0.02/255; margin at the 40th percentile).
// Phong, eq. 4.1 (R^2 0.983): its error grows with the spread of the
// normals (interpolation) and with how far it moves under other vertex
// normals (their own error, e ~ 0.75: on irregular meshes the larger term).
constexpr Fit kPhong = { 1.2965, 0.5183, 0.0089, 0.0511, 0.7437, -0.0730 };
// Flat and Gouraud, eq. 4.5 (R^2 0.992, 0.994): their distance from Phong
// (eq. 4.4) plus Phong's own predicted error, to a power near 1 (e unused).
constexpr Fit kFlat = { 2.3377, 0.5715, -0.2783, 0.2934, 0.0000, -0.0239 };
constexpr Fit kGouraud = { -0.1592, 0.9410, 0.0224, 0.0537, 0.0000, -0.0270 };
/// Added to the normals' term of eq. 4.1 (1/255) before its log: a mesh
/// whose area and Max normals agree (D_N = 0) must not send it to -inf.
/// 0.01/255 is half the study's error floor (0.02/255), so it matters only
/// where Phong is predicted far under any budget.
constexpr double kNormalsFloor = 0.01;

/// eq. 4.2's coefficients (ms, ms per 1000 triangles, ms per 1000 front
/// pixels) per mode and model class: [0] not Cook-Torrance, [1] Cook-Torrance
/// dielectric, [2] Cook-Torrance conductor. Weighted least squares on the
/// relative error (78 rows each; each row's time the median of four runs of
/// the study), refitted 2026-12-02: since the fit of 2026-11-25 the
/// renderer lost most of its fixed cost per frame (0.19-0.29 -> ~0.07 ms:
/// kept, spinning workers, depth per band) and flat and Gouraud most of
/// their cost per pixel relative to Phong (Phong's is now ~5x theirs, was
/// ~2.5x). A conductor costs what a dielectric does in every mode.
struct CostFit
{
  double a, b, c;
};
constexpr CostFit kCostFlat[3] = { { 0.0722, 0.04343, 0.00251 }, { 0.0809, 0.04540, 0.00184 },
  { 0.0725, 0.04542, 0.00221 } };
constexpr CostFit kCostGouraud[3] = { { 0.0694, 0.04725, 0.00190 },
  { 0.0758, 0.05008, 0.00131 }, { 0.0644, 0.05265, 0.00238 } };
constexpr CostFit kCostPhong[3] = { { 0.0743, 0.04036, 0.00952 }, { 0.0764, 0.03916, 0.00944 },
  { 0.0769, 0.03985, 0.00981 } };

/// Normal spreads below this (radians) are a flat region: the power law is
/// evaluated at the floor, which predicts far below 1/255 for every mode.
constexpr double kMinSpread = 1e-4;
/// The view's predictors are read off at most this many triangles (in runs
/// spread over the mesh, TriangleSample.h): a mean over 16,384 triangles is within a percent of the whole
/// mesh's (the study's spreads, compared), and a 1.3M-triangle mesh no
/// longer takes longer to read (139 ms over all of them, 1920x1080) than
/// to draw.
constexpr long long kMaxPredictorTriangles = 16384;
/// Predicted costs within this ratio are a tie, which the more accurate mode
/// takes: the cost model's median relative error is 10-20% (eq. 4.2), so a
/// cheaper mode by less than that is not reliably cheaper, while the more
/// accurate one meets E more surely; at 1.1 it stays within the 1.2x the
/// choice is held to even when the prediction is right.
constexpr double kTieCost = 1.1;
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
  const ScreenProjection screen(camera, width, height);
  const Vec3<double> forward = screen.Axes().forward;
  auto project = [&](int64_t v, double& x, double& y) {
    return screen(Vec3<double>(mesh.points[3 * v], mesh.points[3 * v + 1], mesh.points[3 * v + 2]), x, y);
  };
  double weighted = 0, area = 0;
  out.triangles = TriangleCount(mesh);
  const bool haveNormals = normals.size() == mesh.points.size();
  // Runs of triangles spread over the mesh, counts scaled back.
  TriangleSample sample(out.triangles, kMaxPredictorTriangles);
  const long long stride = sample.Scale();
  for (int64_t p = 0; p < mesh.NumberOfPolygons(); ++p)
  {
    const int64_t b = mesh.offsets[p], e = mesh.offsets[p + 1];
    for (int64_t k = b + 1; k + 1 < e; ++k) // the polygon's fan
    {
      if (!sample.Take())
      {
        continue;
      }
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
      if (!(a > 0) || !screen.OnImage(cx, cy))
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
  out.visibleTriangles *= stride;
  out.frontPixels *= static_cast<double>(stride);
  if (area > 0)
  {
    out.normalSpread = weighted / area;
    out.trianglePixels = area * static_cast<double>(stride) / static_cast<double>(out.visibleTriangles);
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

double PredictError(ShadingMode mode, const ViewPredictors& view,
  const ModeDifferences& difference, double sharpness, double peak, bool conservative)
{
  const double logSpread = std::log(std::max(view.normalSpread, kMinSpread));
  // eq. 4.1: Phong's own error, from the spread of the normals and their
  // uncertainty.
  const double phong = std::exp(kPhong.a + kPhong.b * logSpread +
    kPhong.c * std::log1p(sharpness) + kPhong.d * std::log(std::max(peak, kMinPeak)) +
    kPhong.e * std::log(difference.normals + kNormalsFloor));
  if (mode != ShadingMode::Flat && mode != ShadingMode::Gouraud)
  {
    return phong * (conservative ? std::exp(kPhong.margin) : 1.0);
  }
  // eq. 4.5: flat's and Gouraud's distance from Phong (eq. 4.4) on top of it.
  const Fit& f = mode == ShadingMode::Flat ? kFlat : kGouraud;
  const double distance = mode == ShadingMode::Flat ? difference.flat : difference.gouraud;
  const double log = f.a + f.b * std::log(distance + phong) + f.c * std::log1p(sharpness) +
    f.d * logSpread + (conservative ? f.margin : 0.0);
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
  // The distance is estimated under the scene's lights; the fit's errors are
  // for one light of strength 1, so it is divided back by their strength.
  choice.difference =
    EstimateModeDifferences(mesh, normals, camera, lighting, material, width, height);
  ModeDifferences unitLight = choice.difference;
  if (light > 0)
  {
    unitLight.flat /= light;
    unitLight.gouraud /= light;
    unitLight.normals /= light;
  }
  std::ostringstream why;
  why.precision(3);
  why << "normal spread " << choice.view.normalSpread * 180.0 / kPi<double> << " deg over "
      << choice.view.visibleTriangles << " visible triangles of " << choice.view.trianglePixels
      << " px, lobe n = " << choice.sharpness << ", peak " << choice.peak
      << "/sr, flat / Gouraud from Phong " << choice.difference.flat << " / "
      << choice.difference.gouraud << "/255, Phong under other normals "
      << choice.difference.normals << "/255:";
  const ShadingMode candidates[3] = { ShadingMode::Flat, ShadingMode::Gouraud,
    ShadingMode::Phong }; // from the least to the most accurate
  int cheapest = -1;
  for (int k = 0; k < 3; ++k)
  {
    const ShadingMode mode = candidates[k];
    choice.modeError[k] =
      light * PredictError(mode, choice.view, unitLight, choice.sharpness, choice.peak, true);
    choice.modeMs[k] = PredictCost(mode, choice.view, material);
    why << " " << ShadingModeName(mode) << " " << choice.modeError[k] << "/255 "
        << choice.modeMs[k] << " ms;";
    if (choice.modeError[k] <= maxError && (cheapest < 0 || choice.modeMs[k] < choice.modeMs[cheapest]))
    {
      cheapest = k;
    }
  }
  // eq. 4.3: the cheapest predicted to meet E, or the most accurate of those
  // predicted to cost at most kTieCost times as much; Phong when none meets E.
  int chosen = 2;
  if (cheapest >= 0)
  {
    chosen = cheapest;
    for (int k = cheapest + 1; k < 3; ++k)
    {
      if (choice.modeError[k] <= maxError && choice.modeMs[k] <= kTieCost * choice.modeMs[cheapest])
      {
        chosen = k;
      }
    }
  }
  choice.mode = candidates[chosen];
  choice.predicted = choice.modeError[chosen];
  choice.predictedMs = choice.modeMs[chosen];
  why << " -> " << ShadingModeName(choice.mode);
  if (choice.predicted > maxError)
  {
    why << ", the most accurate; no mode is predicted under " << maxError;
  }
  choice.why = why.str();
  return choice;
}

} // namespace shadinglab::render
