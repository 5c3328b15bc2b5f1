// SPDX-License-Identifier: BSD-3-Clause
// How far flat and Gouraud shading would land from Phong in a view, and
// how far Phong moves under other vertex normals, estimated by quadrature
// over the triangles before anything is rendered (docs/model.md eq. 4.4):
// the auto mode's direct measure, in this scene and under its lights, of
// what interpolating colours instead of normals costs and of how well the
// mesh pins its normals down.
#include "shadinglab/render/AutoMode.h"

#include "Geometry.h"
#include "VertexNormals.h"
#include "ScreenProjection.h"
#include "TriangleSample.h"

#include <algorithm>
#include <cmath>

namespace shadinglab::render
{

namespace
{

/// At most this many triangles are sampled (in runs spread over the mesh,
/// TriangleSample.h): with 4,096 the fits of eq. 4.1 and 4.5 lost R^2
/// (Gouraud 0.994 -> 0.990), with 8,192 they are as with 16,384 single
/// triangles; the whole estimate then takes 5-14 ms at 1080p on 0.1-1.3M
/// triangles (BM_AutoChoice).
constexpr long long kMaxSampledTriangles = 8192;
/// At most this many quadrature points in all (~0.3 us a point: Phong, and
/// Phong under two other sets of normals, plus Gouraud's interpolation);
/// past it, fewer triangles are kept.
constexpr double kMaxPoints = 16384;
/// Sub-triangles are made no smaller than this (pixels): a narrow highlight
/// of n = 150 on a coarse mesh spans ~10 pixels, so 4-pixel cells see it.
constexpr double kMinCellPixels = 4.0;
/// A triangle is split into at most kMaxOrder^2 sub-triangles.
constexpr int kMaxOrder = 16;

Vec3<double> PointOf(const Mesh& mesh, int64_t v)
{
  return { mesh.points[3 * v], mesh.points[3 * v + 1], mesh.points[3 * v + 2] };
}

/// Largest channel difference of two linear colours after the display's
/// clamp to [0, 1], in 1/255 (as the accuracy study measures).
double Difference255(const Vec3<double>& a, const Vec3<double>& b)
{
  auto clamp = [](double v) { return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0; };
  return 255.0 *
    std::max({ std::abs(clamp(a.x) - clamp(b.x)), std::abs(clamp(a.y) - clamp(b.y)),
      std::abs(clamp(a.z) - clamp(b.z)) });
}

struct Sampled
{
  int64_t polygon;
  int64_t v[3];
  double area; ///< pixels
  bool back;
};

/// Each triangle is split into cells of about kMinCellPixels whatever the
/// image's size, so that the estimate means the same at 320x240 (where it
/// was fitted) and at 1080p: the split's order for a triangle of `pixels`.
int QuadratureOrder(double pixels)
{
  return std::clamp(static_cast<int>(std::ceil(std::sqrt(pixels / kMinCellPixels))), 1, kMaxOrder);
}

/// The sampled triangles in view that the estimate weighs (TriangleSample's
/// runs), with their screen areas; none when no triangle is in view.
std::vector<Sampled> TrianglesToWeigh(const Mesh& mesh, const ScreenProjection& screen)
{
  TriangleSample picked(TriangleCount(mesh), kMaxSampledTriangles);
  // The sampled triangles in view, front and back (by their winding on the
  // screen, as the renderers decide it) kept apart: on a closed mesh the
  // back faces are hidden, so only front faces are weighed unless the view
  // has none.
  std::vector<Sampled> samples;
  double area[2] = { 0, 0 };
  for (int64_t p = 0; p < mesh.NumberOfPolygons(); ++p)
  {
    const int64_t b = mesh.offsets[p], e = mesh.offsets[p + 1];
    for (int64_t k = b + 1; k + 1 < e; ++k)
    {
      if (!picked.Take())
      {
        continue;
      }
      Sampled s{ p, { mesh.connectivity[b], mesh.connectivity[k], mesh.connectivity[k + 1] }, 0,
        false };
      double x[3], y[3];
      bool inFront = true;
      for (int j = 0; j < 3; ++j)
      {
        inFront = inFront && screen(PointOf(mesh, s.v[j]), x[j], y[j]);
      }
      if (!inFront || !screen.OnImage((x[0] + x[1] + x[2]) / 3, (y[0] + y[1] + y[2]) / 3))
      {
        continue;
      }
      // Signed area, y down: front faces (counter-clockwise in the world)
      // are clockwise here.
      const double a2 = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
      s.area = 0.5 * std::abs(a2);
      s.back = a2 > 0;
      if (!(s.area > 0))
      {
        continue;
      }
      area[s.back] += s.area;
      samples.push_back(s);
    }
  }
  const bool weighBack = !(area[0] > 0);
  if (!(area[weighBack ? 1 : 0] > 0))
  {
    return {};
  }
  // Past kMaxPoints quadrature points in all, fewer triangles are kept
  // (every m-th), not coarser cells.
  double points = 0;
  samples.erase(std::remove_if(samples.begin(), samples.end(),
                  [&](const Sampled& s) { return s.back != weighBack; }),
    samples.end());
  for (const Sampled& s : samples)
  {
    points += static_cast<double>(QuadratureOrder(s.area)) * QuadratureOrder(s.area);
  }
  if (points > kMaxPoints)
  {
    const size_t every = static_cast<size_t>(std::ceil(points / kMaxPoints));
    size_t kept = 0;
    for (size_t i = 0; i < samples.size(); i += every)
    {
      samples[kept++] = samples[i];
    }
    samples.resize(kept);
  }
  return samples;
}

} // namespace

ModeDifferences EstimateModeDifferences(const Mesh& mesh, const std::vector<float>& normals,
  const Camera& camera, const Lighting<double>& sceneLighting, const Material<double>& material,
  int width, int height)
{
  ModeDifferences out;
  if (normals.size() != mesh.points.size() || mesh.NumberOfPolygons() == 0)
  {
    return out;
  }
  const ScreenProjection screen(camera, width, height);
  const Lighting<double> lighting = LightsOrHeadlight(sceneLighting, camera);
  std::vector<Sampled> samples = TrianglesToWeigh(mesh, screen);
  if (samples.empty())
  {
    return out;
  }
  double weighed = 0;
  for (const Sampled& s : samples)
  {
    weighed += s.area;
  }
  // The vertex normals' own uncertainty: Phong with area-weighted and with
  // Max-weighted normals (Max 1999, exact on spheres). Where they agree the
  // mesh pins its normals down; where they do not (irregular triangles, as
  // marching cubes makes) neither is the surface's, and no interpolation
  // mode removes that error.
  // Recomputed at the weighed triangles' vertices only (one pass over the
  // polygons for both weightings, not two whole normal passes).
  std::vector<int64_t> slotOf(static_cast<size_t>(mesh.NumberOfPoints()), -1);
  int64_t slots = 0;
  for (const Sampled& s : samples)
  {
    for (int64_t v : s.v)
    {
      if (slotOf[v] < 0)
      {
        slotOf[v] = slots++;
      }
    }
  }
  std::vector<std::vector<double>> alternatives;
  mesh.VisitIds([&](const auto* offsets, const auto* connectivity) {
    mesh::ComputeVertexNormalsAt(mesh.points.data(), offsets, connectivity, mesh.NumberOfPolygons(),
      { mesh::NormalWeighting::Area, mesh::NormalWeighting::Max }, slotOf, slots, alternatives);
  });
  auto normalOf = [&](int64_t v, double sign) {
    return NormalizeOr(Vec3<double>(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]) * sign,
      Vec3<double>(0, 0, 0));
  };
  auto colorOf = [&](int64_t v) {
    if (mesh.colors.empty())
    {
      return material.diffuseColor;
    }
    return Vec3<double>(mesh.colors[3 * v], mesh.colors[3 * v + 1], mesh.colors[3 * v + 2]);
  };
  auto shade = [&](const Vec3<double>& P, const Vec3<double>& N, const Vec3<double>& color) {
    return Shade(material, lighting, color, P, N, screen.ToViewer(P));
  };
  double sumFlat = 0, sumGouraud = 0, sumNormals = 0;
  for (const Sampled& s : samples)
  {
    // Two-sided lighting: a back face is lit with its normals flipped.
    const double sign = s.back ? -1.0 : 1.0;
    Vec3<double> P[3], N[3], C[3], gouraud[3], A[2][3];
    for (int j = 0; j < 3; ++j)
    {
      P[j] = PointOf(mesh, s.v[j]);
      N[j] = normalOf(s.v[j], sign);
      for (int w = 0; w < 2; ++w)
      {
        const double* a = &alternatives[w][3 * slotOf[s.v[j]]];
        A[w][j] = Vec3<double>(a[0], a[1], a[2]) * sign;
      }
      C[j] = colorOf(s.v[j]);
      gouraud[j] = shade(P[j], N[j], C[j]);
    }
    // Flat: the polygon's face normal (given, else Newell's), lit at its
    // last vertex with that vertex's colour, as the renderers do.
    const int64_t first = mesh.offsets[s.polygon];
    const int n = static_cast<int>(mesh.offsets[s.polygon + 1] - first);
    Vec3<double> faceN = mesh::NewellAreaVector<double>(
      n, [&](int64_t k) { return PointOf(mesh, mesh.connectivity[first + k]); });
    if (!mesh.faceNormals.empty())
    {
      const float* fn = &mesh.faceNormals[3 * s.polygon];
      faceN = Vec3<double>(fn[0], fn[1], fn[2]);
    }
    faceN = NormalizeOr(faceN * sign, screen.ToViewer(P[0]));
    const int64_t provoking = mesh.connectivity[first + n - 1];
    const Vec3<double> flat = shade(PointOf(mesh, provoking), faceN, colorOf(provoking));
    // The midpoint rule on the k^2 congruent sub-triangles of an order-k
    // split: their centroids at barycentrics (i + 1/3, j + 1/3, l + 1/3)/k,
    // i + j + l = k - 1 (upright), and (i + 2/3, j + 2/3, l + 2/3)/k,
    // i + j + l = k - 2 (inverted).
    const int order = QuadratureOrder(s.area);
    double dFlat = 0, dGouraud = 0, dNormals = 0;
    auto sample = [&](double u, double v, double w) {
      const Vec3<double> p = P[0] * u + P[1] * v + P[2] * w;
      const Vec3<double> nrm = NormalizeOr(N[0] * u + N[1] * v + N[2] * w, faceN);
      const Vec3<double> color = C[0] * u + C[1] * v + C[2] * w;
      const Vec3<double> phong = shade(p, nrm, color);
      dFlat += Difference255(flat, phong);
      double far = 0;
      for (const Vec3<double>* a : A)
      {
        const Vec3<double> other = NormalizeOr(a[0] * u + a[1] * v + a[2] * w, faceN);
        far = std::max(far, Difference255(shade(p, other, color), phong));
      }
      dNormals += far;
      dGouraud += Difference255(gouraud[0] * u + gouraud[1] * v + gouraud[2] * w, phong);
    };
    const double k = order;
    for (int i = 0; i < order; ++i)
    {
      for (int j = 0; i + j < order; ++j)
      {
        const int l = order - 1 - i - j;
        sample((i + 1.0 / 3) / k, (j + 1.0 / 3) / k, (l + 1.0 / 3) / k);
        if (l >= 1)
        {
          sample((i + 2.0 / 3) / k, (j + 2.0 / 3) / k, (l - 1 + 2.0 / 3) / k);
        }
      }
    }
    sumFlat += s.area * dFlat / (k * k);
    sumGouraud += s.area * dGouraud / (k * k);
    sumNormals += s.area * dNormals / (k * k);
    ++out.sampledTriangles;
  }
  out.flat = sumFlat / weighed;
  out.gouraud = sumGouraud / weighed;
  out.normals = sumNormals / weighed;
  return out;
}

} // namespace shadinglab::render
