// SPDX-License-Identifier: BSD-3-Clause
// What a renderer draws: a mesh (borrowed), a camera, lights and a material.
// Plain data, no VTK, no GL; both backends take exactly this.
#pragma once

#include "shadinglab/render/ColorMap.h"
#include "shadinglab/render/IdArray.h"

#include "shadinglab/model/Shading.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace shadinglab::render
{

/// The triangles of a polygon of `corners` corners as a fan: n - 2, and
/// none for fewer than three corners (the one count of every statistic).
inline int64_t TrianglesInPolygon(int64_t corners)
{
  return corners > 2 ? corners - 2 : 0;
}

/// A surface mesh as flat arrays (borrowed by a renderer, never modified).
struct Mesh
{
  std::vector<float> points;      ///< 3 per vertex
  std::vector<float> normals;     ///< 3 per vertex, or empty (then computed, area-weighted)
  std::vector<float> colors;      ///< 3 per vertex in [0,1] linear, or empty
  IdArray offsets;                ///< polygon p uses connectivity[offsets[p] .. offsets[p+1])
  IdArray connectivity;           ///< (owned, or shared with a VTK array: IdArray.h)
  std::vector<float> faceNormals; ///< 3 per polygon, or empty (then Newell normals)
  /// Colour by data (with Scene::colorMap): one value per vertex, mapped
  /// per pixel after interpolation (ParaView's Interpolate Scalars Before
  /// Mapping), or one per polygon; at most one of the two. Replaces
  /// `colors` and the material's diffuse colour.
  std::vector<float> scalars;
  std::vector<float> cellScalars;

  int64_t NumberOfPoints() const { return static_cast<int64_t>(points.size() / 3); }
  int64_t NumberOfPolygons() const
  {
    return offsets.empty() ? 0 : static_cast<int64_t>(offsets.size() - 1);
  }
  /// Every polygon's TrianglesInPolygon, summed.
  int64_t NumberOfTriangles() const
  {
    int64_t triangles = 0;
    for (int64_t p = 0; p < this->NumberOfPolygons(); ++p)
    {
      triangles += TrianglesInPolygon(this->offsets[p + 1] - this->offsets[p]);
    }
    return triangles;
  }
  /// f(offsets, connectivity), both in place as `const int64_t*` or, both
  /// narrow (IdArray.h), as `const int32_t*`; when only one of them is
  /// narrow, the two are widened into copies for the call.
  template <typename F>
  decltype(auto) VisitIds(F&& f) const
  {
    if (offsets.IsNarrow() && connectivity.IsNarrow())
    {
      return f(offsets.narrowData(), connectivity.narrowData());
    }
    if (!offsets.IsNarrow() && !connectivity.IsNarrow())
    {
      return f(offsets.data(), connectivity.data());
    }
    const std::vector<int64_t> o(offsets.begin(), offsets.end());
    const std::vector<int64_t> c(connectivity.begin(), connectivity.end());
    return f(o.data(), c.data());
  }
  /// Runs task(0) .. task(n - 1), possibly at once, returning when all have
  /// (the CPU renderer passes its kept threads: cpu::SpreadOver).
  using TaskRunner = std::function<void(int n, const std::function<void(int)>& task)>;
  /// The points' axis-aligned box (xmin, xmax, ymin, ymax, zmin, zmax); NaN
  /// coordinates are skipped. In slices of 64k points a runner may take at
  /// once (a renderer reads it every frame); exact for any runner.
  void Bounds(double bounds[6], const TaskRunner& run = {}) const;
  /// A hash of every array's contents and size, for caches keyed on the
  /// mesh (the GL backend's upload, the CPU backend's closed-mesh test).
  /// Arrays are hashed in slices of at least 256 KB (at most 64 per array),
  /// all of them one batch a runner may hash at once: a renderer reads it
  /// every frame (~57 MB for the 1.3M-triangle icosphere). The value
  /// depends on the contents only, not on the runner or its threads.
  uint64_t ContentHash(const TaskRunner& run = {}) const;
};

/// A key no other call returns, for Scene::meshHash of a mesh that is not
/// changed while it is drawn (made once, drawn, dropped: the command
/// line's): its caches keyed without hashing its contents (0.09 s on 16M
/// triangles). Keys have the top bit set; a ContentHash may too, with the
/// odds of any 64-bit collision.
uint64_t UniqueMeshKey();

/**
 * Where a mesh's local coordinates sit in the world: world = center +
 * scale * local. Front ends convert meshes into a local frame centred on
 * their bounds and scaled to a unit bounding sphere (in double, before the
 * renderers' float), so a mesh far from the origin or at a scale near
 * float's limits renders like the same mesh at unit scale; the camera and
 * the lights, given in world coordinates, are mapped by ToLocal().
 */
struct WorldFrame
{
  Vec3<double> center{ 0, 0, 0 };
  double scale = 1.0;

  Vec3<double> ToLocal(const Vec3<double>& world) const { return (world - center) / scale; }
  double LengthToLocal(double length) const { return length / scale; }
};

/// A vtkCamera-compatible description.
struct Camera
{
  Vec3<double> position{ 0, 0, 5 };
  Vec3<double> focalPoint{ 0, 0, 0 };
  Vec3<double> viewUp{ 0, 1, 0 };
  double viewAngle = 30.0; ///< vertical, degrees (perspective)
  bool parallel = false;
  double parallelScale = 1.0; ///< half the view height in world units (parallel)
  double nearClip = 0.01;
  double farClip = 100.0;
};

/**
 * A camera looking at the bounds like vtkRenderer::ResetCamera (view along
 * -z, up +y, 30 degree view angle, the bounding sphere filling the view),
 * then rotated by azimuth (about view up) and elevation (about the right
 * axis) around the focal point, and zoomed (view angle / zoom).
 */
Camera FitCamera(const double bounds[6], double azimuthDeg, double elevationDeg, double zoom,
  double aspect, bool parallel);

/// The camera's orthonormal frame in world coordinates: `forward` from the
/// position toward the focal point, `right` = forward x viewUp, `up` =
/// right x forward (what the image's x and y follow). Degenerate cameras
/// fall back to looking down -z with +x right.
struct CameraBasis
{
  Vec3<double> forward, right, up;
};
CameraBasis BasisOf(const Camera& camera);

/// One key light above-left of the camera, in world coordinates: the default
/// light of every front end (CLI, explorer, VTK classes).
Light<double> KeyLight(const Camera& camera, double intensity = 1.0);

/// vtkLightKit's key light direction in the camera's frame (degrees).
inline constexpr double kLightKitKeyAzimuth = 10.0, kLightKitKeyElevation = 50.0;

/**
 * The default lights of every front end that draws a mesh (the CLI, the
 * explorer's mesh scenes, the VTK classes without vtkLights): vtkLightKit's
 * geometry and intensities, as ParaView's render view lights by default.
 * Directional camera lights: key (elevation 50, azimuth 10 degrees,
 * intensity 0.75), fill (-75, -10; key / 3), two back lights (0, +-110;
 * key / 3.5 each) and a headlight (key / 3), all scaled by `intensity`.
 * White: vtkLightKit's warm key and cool fill would tint a colour map's
 * colours by a few percent (docs/model.md section 9). With it no face
 * turned toward the camera is unlit (the headlight reaches it). The key
 * light may be turned (the explorer's light control, as ParaView's Light
 * Kit panel); the others stay where vtkLightKit puts them.
 */
Lighting<double> LightKit(const Camera& camera, double intensity = 1.0,
  double keyAzimuthDeg = kLightKitKeyAzimuth, double keyElevationDeg = kLightKitKeyElevation);

/// The lights a renderer shades with: `lighting`, or with no light a
/// headlight (a directional light from the camera, as VTK's automatic light).
Lighting<double> LightsOrHeadlight(const Lighting<double>& lighting, const Camera& camera);

/**
 * A directional light given in the camera's frame, in world coordinates:
 * azimuth turns it from the view direction toward the camera's right,
 * elevation toward its up (0, 0: a headlight, light from the viewer). The
 * explorer's light control; the light follows the camera as VTK's light kit.
 */
Light<double> CameraLight(
  const Camera& camera, double azimuthDeg, double elevationDeg, double intensity = 1.0);

/// A camera of `frame`'s world in its local coordinates (position, focal
/// point, clipping range, parallel scale; directions unchanged).
void ToLocal(const WorldFrame& frame, Camera& camera);
/// Lights of `frame`'s world in its local coordinates (point lights'
/// positions and distance attenuation; directions unchanged).
void ToLocal(const WorldFrame& frame, Lighting<double>& lighting);

/// Everything a renderer draws. The mesh is borrowed: it must outlive the
/// Render call. With lighting.lightCount == 0 a headlight (a directional
/// light from the camera) is used.
struct Scene
{
  const Mesh* mesh = nullptr;
  Camera camera;
  Lighting<double> lighting;
  Material<double> material;
  /// Maps the mesh's scalars or cellScalars to the diffuse colour rho;
  /// nullptr: no colouring by data.
  const ColorMap* colorMap = nullptr;
  /// The mesh's ContentHash() when the caller knows it (one that converts
  /// the mesh once and redraws it as the camera moves: the mapper's CPU
  /// backend), so a redraw does not hash the whole mesh again (~1.5 ms a
  /// frame for a million triangles on two threads), or a UniqueMeshKey()
  /// for a mesh that does not change while it is drawn; empty: the renderer
  /// hashes it when a cache asks.
  std::optional<uint64_t> meshHash = std::nullopt;
};

} // namespace shadinglab::render
