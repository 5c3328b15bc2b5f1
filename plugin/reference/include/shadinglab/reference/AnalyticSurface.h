// SPDX-License-Identifier: BSD-3-Clause
// The ground truth of the accuracy study: analytic surfaces (sphere,
// ellipsoid, torus, metaball isosurface) ray-cast per pixel with their
// exact normals and shaded by the model's Shade(), with the camera, lights,
// material and pixel centres the renderers use. What a tessellated mesh
// drawn by a renderer should converge to. No VTK, no GL.
#pragma once

#include "shadinglab/render/Image.h"
#include "shadinglab/render/Scene.h"

#include <memory>
#include <string>

namespace shadinglab::reference
{

class AnalyticSurface
{
public:
  virtual ~AnalyticSurface() = default;
  virtual std::string Name() const = 0;
  /// Axis-aligned bounds (xmin, xmax, ymin, ymax, zmin, zmax).
  virtual void Bounds(double bounds[6]) const = 0;
  /// The first hit t in (tmin, tmax) of the ray o + t d (d unit), if any.
  virtual bool Intersect(const Vec3<double>& o, const Vec3<double>& d, double tmin, double tmax,
    double& t) const = 0;
  /// The exact outward unit normal at a surface point.
  virtual Vec3<double> Normal(const Vec3<double>& p) const = 0;
};

/// Unit sphere at the origin (datasets' MakeUVSphere, MakeIcosphere).
std::unique_ptr<AnalyticSurface> MakeSphere();
/// x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 (MakeEllipsoid).
std::unique_ptr<AnalyticSurface> MakeEllipsoid(double a, double b, double c);
/// Torus about z, major radius R, minor r (MakeTorus).
std::unique_ptr<AnalyticSurface> MakeTorus(double R, double r);
/// The metaball field's isosurface (MetaballField.h; MakeMetaballIsosurface).
std::unique_ptr<AnalyticSurface> MakeMetaballs();

/**
 * Ray-casts `surface` through the centre of every pixel (i + 0.5, j + 0.5,
 * row 0 at the top) of `camera` (perspective or parallel) and shades each
 * hit with Shade(material, lighting, albedo, P, N, V) in double, N the exact
 * normal (turned toward the viewer, as two-sided lighting does). Misses get
 * `background` and covered = 0.
 */
render::Image RayCast(const AnalyticSurface& surface, const render::Camera& camera,
  const Lighting<double>& lighting, const Material<double>& material, int width, int height,
  const Vec3<float>& background);

} // namespace shadinglab::reference
