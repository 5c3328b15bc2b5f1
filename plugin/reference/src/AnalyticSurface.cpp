// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/reference/AnalyticSurface.h"

#include "MetaballField.h"

#include <algorithm>
#include <cmath>

namespace shadinglab::reference
{

namespace
{

using V3 = Vec3<double>;

/// Entry and exit t of a ray through the sphere |p| <= radius, if it meets it.
bool SphereSpan(const V3& o, const V3& d, double radius, double& t0, double& t1)
{
  const double b = Dot(o, d), c = Dot(o, o) - radius * radius;
  const double disc = b * b - c;
  if (disc < 0)
  {
    return false;
  }
  const double s = std::sqrt(disc);
  t0 = -b - s;
  t1 = -b + s;
  return t1 > 0;
}

class Ellipsoid final : public AnalyticSurface
{
public:
  Ellipsoid(double a, double b, double c, std::string name)
    : A(a), B(b), C(c), Label(std::move(name))
  {
  }
  std::string Name() const override { return this->Label; }
  void Bounds(double bounds[6]) const override
  {
    const double b[6] = { -A, A, -B, B, -C, C };
    std::copy(b, b + 6, bounds);
  }
  bool Intersect(const V3& o, const V3& d, double tmin, double tmax, double& t) const override
  {
    // In the frame where the ellipsoid is the unit sphere (t is unchanged).
    const V3 os(o.x / A, o.y / B, o.z / C), ds(d.x / A, d.y / B, d.z / C);
    const double a = Dot(ds, ds), b = Dot(os, ds), c = Dot(os, os) - 1.0;
    const double disc = b * b - a * c;
    if (disc < 0)
    {
      return false;
    }
    const double s = std::sqrt(disc);
    for (const double root : { (-b - s) / a, (-b + s) / a })
    {
      if (root > tmin && root < tmax)
      {
        t = root;
        return true;
      }
    }
    return false;
  }
  V3 Normal(const V3& p) const override
  {
    return NormalizeOr(V3(p.x / (A * A), p.y / (B * B), p.z / (C * C)), V3(0, 0, 1));
  }

private:
  double A, B, C;
  std::string Label;
};

/// Sphere tracing stops this close to the surface (relative to its size):
/// 1e-10 of a unit torus moves the normal by ~1e-10 rad, far below 1/255.
constexpr double kTraceEpsilon = 1e-10;
/// Sphere-tracing steps before giving up (a grazing ray converges slowly;
/// 2000 steps of at least kTraceEpsilon reach any hit in the bounds).
constexpr int kMaxTraceSteps = 2000;

class Torus final : public AnalyticSurface
{
public:
  Torus(double R, double r)
    : Major(R), Minor(r)
  {
  }
  std::string Name() const override { return "torus"; }
  void Bounds(double bounds[6]) const override
  {
    const double e = Major + Minor;
    const double b[6] = { -e, e, -e, e, -Minor, Minor };
    std::copy(b, b + 6, bounds);
  }
  /// The exact signed distance to the torus.
  double Distance(const V3& p) const
  {
    const double q = std::hypot(p.x, p.y) - Major;
    return std::hypot(q, p.z) - Minor;
  }
  bool Intersect(const V3& o, const V3& d, double tmin, double tmax, double& t) const override
  {
    double t0, t1;
    if (!SphereSpan(o, d, Major + Minor, t0, t1))
    {
      return false;
    }
    t = std::max(tmin, t0);
    const double end = std::min(tmax, t1);
    for (int i = 0; i < kMaxTraceSteps && t < end; ++i)
    {
      const double dist = this->Distance(o + d * t);
      if (dist < kTraceEpsilon)
      {
        return true;
      }
      t += dist;
    }
    return false;
  }
  V3 Normal(const V3& p) const override
  {
    const double rho = std::hypot(p.x, p.y);
    const V3 ring = rho > 0 ? V3(p.x / rho * Major, p.y / rho * Major, 0.0) : V3(Major, 0, 0);
    return NormalizeOr(p - ring, V3(0, 0, 1));
  }

private:
  double Major, Minor;
};

/// Marching step along a ray through the metaball field: the blobs' widths
/// are >= 0.25, so a step of 1/200 of the box never steps over a surface
/// crossing and back; bisection then refines the bracket to 1e-12.
constexpr double kMarchStep = 0.01;
constexpr int kBisections = 48;

class Metaballs final : public AnalyticSurface
{
public:
  std::string Name() const override { return "metaballs"; }
  void Bounds(double bounds[6]) const override
  {
    const double b[6] = { -1, 1, -1, 1, -1, 1 };
    std::copy(b, b + 6, bounds);
  }
  static double Value(const V3& p)
  {
    return datasets::MetaballField({ p.x, p.y, p.z }, nullptr) - datasets::kMetaballIsoValue;
  }
  bool Intersect(const V3& o, const V3& d, double tmin, double tmax, double& t) const override
  {
    double t0, t1;
    if (!SphereSpan(o, d, std::sqrt(3.0), t0, t1))
    {
      return false;
    }
    double a = std::max(tmin, t0);
    const double end = std::min(tmax, t1);
    double fa = Value(o + d * a);
    for (double b = a + kMarchStep; a < end; a = b, b += kMarchStep)
    {
      const double fb = Value(o + d * b);
      if (fa < 0 && fb >= 0)
      {
        double lo = a, hi = b;
        for (int i = 0; i < kBisections; ++i)
        {
          const double mid = 0.5 * (lo + hi);
          (Value(o + d * mid) < 0 ? lo : hi) = mid;
        }
        t = 0.5 * (lo + hi);
        return true;
      }
      fa = fb;
    }
    return false;
  }
  V3 Normal(const V3& p) const override
  {
    std::array<double, 3> g;
    datasets::MetaballField({ p.x, p.y, p.z }, &g);
    return NormalizeOr(V3(-g[0], -g[1], -g[2]), V3(0, 0, 1));
  }
};

} // namespace

std::unique_ptr<AnalyticSurface> MakeSphere()
{
  return std::make_unique<Ellipsoid>(1.0, 1.0, 1.0, "sphere");
}

std::unique_ptr<AnalyticSurface> MakeEllipsoid(double a, double b, double c)
{
  return std::make_unique<Ellipsoid>(a, b, c, "ellipsoid");
}

std::unique_ptr<AnalyticSurface> MakeTorus(double R, double r)
{
  return std::make_unique<Torus>(R, r);
}

std::unique_ptr<AnalyticSurface> MakeMetaballs()
{
  return std::make_unique<Metaballs>();
}

render::Image RayCast(const AnalyticSurface& surface, const render::Camera& camera,
  const Lighting<double>& lighting, const Material<double>& material, int width, int height,
  const Vec3<float>& background)
{
  render::Image image;
  image.width = width;
  image.height = height;
  image.rgb.assign(static_cast<size_t>(width) * height * 3, 0.0f);
  image.covered.assign(static_cast<size_t>(width) * height, 0);
  const render::CameraBasis basis = render::BasisOf(camera);
  const V3& forward = basis.forward;
  const V3& right = basis.right;
  const V3& up = basis.up;
  const double aspect = static_cast<double>(width) / height;
  const double tanHalf = std::tan(0.5 * camera.viewAngle * kPi<double> / 180.0);
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const double nx = 2.0 * (i + 0.5) / width - 1.0, ny = 1.0 - 2.0 * (j + 0.5) / height;
      V3 origin = camera.position, dir;
      if (camera.parallel)
      {
        origin = origin + right * (nx * camera.parallelScale * aspect) +
          up * (ny * camera.parallelScale);
        dir = forward;
      }
      else
      {
        dir = NormalizeOr(forward + right * (nx * tanHalf * aspect) + up * (ny * tanHalf), forward);
      }
      const size_t o = static_cast<size_t>(j) * width + i;
      double t;
      Vec3<double> color(background.x, background.y, background.z);
      if (surface.Intersect(origin, dir, 0.0, 1e30, t))
      {
        const V3 P = origin + dir * t;
        const V3 V = camera.parallel ? -forward : -dir;
        V3 N = surface.Normal(P);
        if (Dot(N, V) < 0)
        {
          N = -N; // two-sided lighting, as both renderers
        }
        color = Shade(material, lighting, material.diffuseColor, P, N, V);
        image.covered[o] = 1;
      }
      image.rgb[3 * o + 0] = static_cast<float>(color.x);
      image.rgb[3 * o + 1] = static_cast<float>(color.y);
      image.rgb[3 * o + 2] = static_cast<float>(color.z);
    }
  }
  return image;
}

} // namespace shadinglab::reference
