// SPDX-License-Identifier: BSD-3-Clause
// Synthetic meshes for tests, benchmarks and the shipped datasets. Surfaces
// with a known exact normal carry it in the point array "ExactNormal" (not
// set as the active normals: renderers and filters must compute their own).
#pragma once

class vtkPolyData;

namespace shadinglab::datasets
{

/// Name of the point array holding the analytic unit normal.
constexpr const char* kExactNormalArray = "ExactNormal";

/// Unit sphere, `slices` around the z axis and `stacks` from pole to pole;
/// triangles only (quads split), one vertex per pole.
vtkPolyData* MakeUVSphere(int slices, int stacks);
/// Unit sphere from an icosahedron subdivided `level` times (20 * 4^level triangles).
vtkPolyData* MakeIcosphere(int level);
/// Torus with major radius R about z and minor radius r; triangles.
vtkPolyData* MakeTorus(double R, double r, int major, int minor);
/// Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1; triangles.
vtkPolyData* MakeEllipsoid(double a, double b, double c, int slices, int stacks);
/// Prism approximation of a cylinder: `sides` quads around, polygon caps.
vtkPolyData* MakeLowPolyCylinder(int sides);
/// Plane whose rows of vertices alternate between +amplitude and
/// -amplitude: every interior vertex normal averages to straight up, so
/// smooth shading renders the corrugation flat (docs/model.md eq. 2.2).
vtkPolyData* MakeCorrugatedPlane(int ridges, int depth, double amplitude);
/// A strip of quads bent along a half cylinder.
vtkPolyData* MakeQuadStrip(int quads);
/// A curved height field meshed coarse on the left and fine on the right:
/// the fine vertices on the shared column lie on coarse edges (T-junctions).
vtkPolyData* MakeTJunctionPatch(int coarse);
/// Isosurface of a sum of Gaussian blobs sampled on an n^3 grid (marching
/// cubes family: vtkFlyingEdges3D), with the analytic gradient normal.
vtkPolyData* MakeMetaballIsosurface(int n);
/// A unit-wide floor (y = 0, facing +y) receding from z = 0 to z = -depth,
/// one quad, with point colours black at the near edge and white at the far
/// edge: rendered in screen-space interpolation it shows the lecture's
/// perspective distortion (docs/model.md eq. 3.1) at a glance.
vtkPolyData* MakeRecedingPlane(double depth);
/// Analytic terrain height field on an n x n grid with an "Elevation" array
/// and the exact normal.
vtkPolyData* MakeTerrain(int n);

/// An irregular surface like a scanned part: an icosphere of `level`
/// (20 * 4^level triangles) with deterministic radial noise of relative
/// amplitude `noise`, then quadric-decimated to `keep` of its triangles, so
/// triangle sizes and vertex valences vary widely. No exact normal.
vtkPolyData* MakeNoisyDecimatedSphere(int level, double noise, double keep);

} // namespace shadinglab::datasets
