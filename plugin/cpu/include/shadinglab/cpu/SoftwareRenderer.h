// SPDX-License-Identifier: BSD-3-Clause
// The CPU software renderer: the lecture's scanline algorithms for the five
// shading modes. Fallback where no OpenGL exists and reference for the GPU
// path. No VTK, no GL: mesh + camera + lights + material + mode -> image.
// The shading itself is the model library's Shade(); this file only decides
// where it is evaluated (per polygon, per vertex, per pixel).
#pragma once

#include "shadinglab/model/FastPhong.h"
#include "shadinglab/model/Shading.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace shadinglab::cpu
{

enum class ShadingMode
{
  Flat,        ///< one intensity per polygon from its face normal (slides 1-2)
  Gouraud,     ///< model at the vertices, intensities interpolated (slides 4-6)
  Phong,       ///< normals interpolated and renormalized, model per pixel (slide 8)
  FastPhong,   ///< Bishop & Weimer 1986 quadratic by forward differences
  CookTorrance ///< per pixel, interpolated normals, Cook-Torrance model (slides 11-16)
};

/// How attributes are interpolated across a polygon.
enum class InterpolationSpace
{
  Perspective, ///< perspective-correct (interpolate a/w and 1/w)
  Screen       ///< linear in screen space, as the lecture (shows slide 9's distortion)
};

/// Polygons with more than three vertices.
enum class PolygonHandling
{
  Triangulate, ///< fan-triangulated
  Direct       ///< scan-converted as polygons: edge walk in y, span in x (slide 5)
};

enum class DisplayTransform
{
  Clamp, ///< linear intensity clamped to [0, 1] (what fixed-function GL shows)
  SRGB   ///< clamp, then the sRGB encoding curve (IEC 61966-2-1)
};

/// A surface mesh as flat arrays (borrowed by Render, never modified).
struct Mesh
{
  std::vector<float> points;      ///< 3 per vertex
  std::vector<float> normals;     ///< 3 per vertex, or empty (then computed, area-weighted)
  std::vector<float> colors;      ///< 3 per vertex in [0,1] linear, or empty
  std::vector<int64_t> offsets;   ///< polygon p uses connectivity[offsets[p] .. offsets[p+1])
  std::vector<int64_t> connectivity;
  std::vector<float> faceNormals; ///< 3 per polygon, or empty (then Newell normals)

  int64_t NumberOfPoints() const { return static_cast<int64_t>(points.size() / 3); }
  int64_t NumberOfPolygons() const
  {
    return offsets.empty() ? 0 : static_cast<int64_t>(offsets.size() - 1);
  }
  void Bounds(double bounds[6]) const;
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

struct RenderOptions
{
  ShadingMode mode = ShadingMode::Phong;
  InterpolationSpace interpolation = InterpolationSpace::Perspective;
  PolygonHandling polygons = PolygonHandling::Triangulate;
  ExpansionPoint expansion = ExpansionPoint::Centroid;
  int width = 1024;
  int height = 768;
  int ssaa = 1;    ///< supersampling factor per axis (box filter)
  int threads = 0; ///< 0: all hardware threads
  bool cullBackFaces = false;
  /// Back-facing polygons are lit with their normals flipped (VTK's default).
  bool twoSidedLighting = true;
  /// Instead of shading, count how many polygons cover each pixel (no depth
  /// test): the fill-rule check. Result in Image::coverage.
  bool countCoverage = false;
  Vec3<float> background{ 0.32f, 0.34f, 0.43f };
  /// fast-phong: a triangle whose vertex normals spread more than this
  /// (degrees) is evaluated exactly instead of by its Taylor quadratic. The
  /// quadratic's error grows as the cube of the spread: at 30 degrees it is
  /// ~1/255 (FastPhongTest measures 2.4e-3 at ~23 degrees); at 45 degrees it
  /// is ~5/255 and visible. 180 disables the fallback.
  double fastPhongMaxSpread = 30.0;
};

struct RenderStats
{
  double milliseconds = 0;
  int64_t polygons = 0;            ///< input polygons
  int64_t triangles = 0;           ///< input polygons counted as triangles (n - 2 each)
  int64_t rasterized = 0;          ///< polygons scan-converted (after culling and clipping)
  int64_t clipped = 0;             ///< polygons crossing the near plane
  int64_t degenerate = 0;          ///< zero-area polygons skipped
  int64_t pixelsCovered = 0;       ///< pixels with a surface in the final image
  int64_t pixelsShaded = 0;        ///< illumination-model evaluations at pixels
  int64_t fastPhongExact = 0;      ///< fast-phong triangles evaluated exactly (spread limit)
  int threads = 1;
  bool normalsComputed = false;    ///< the mesh had no normals: area-weighted ones were made
};

/// Linear RGB image, row 0 at the top.
struct Image
{
  int width = 0;
  int height = 0;
  std::vector<float> rgb;          ///< 3 per pixel, linear
  std::vector<uint8_t> covered;    ///< 1 where a surface was drawn
  std::vector<uint16_t> coverage;  ///< per-pixel polygon count (countCoverage only)

  /// 8-bit RGB after the display transform. NaN never occurs (tested) but
  /// would map to 0.
  std::vector<uint8_t> ToRGB8(DisplayTransform transform) const;
};

/**
 * The renderer as an object: its frame buffers, depth buffer and projected
 * vertices persist between frames, so rendering the same size again does not
 * reallocate (the steady state an interactive viewer sees).
 */
class SoftwareRenderer
{
public:
  SoftwareRenderer();
  ~SoftwareRenderer();
  SoftwareRenderer(const SoftwareRenderer&) = delete;
  SoftwareRenderer& operator=(const SoftwareRenderer&) = delete;

  /// As Render() below; the image stays valid until the next call.
  const Image& Render(const Mesh& mesh, const Camera& camera, const Lighting<float>& lighting,
    const Material<float>& material, const RenderOptions& options, RenderStats* stats = nullptr);

  class Internals;

private:
  std::unique_ptr<Internals> Impl;
};

/**
 * Renders the mesh. Throws std::invalid_argument with a one-line message for
 * unusable input (sizes, NaN camera, mode/material mismatch).
 * Output is bit-identical whatever the thread count.
 */
Image Render(const Mesh& mesh, const Camera& camera, const Lighting<float>& lighting,
  const Material<float>& material, const RenderOptions& options, RenderStats* stats = nullptr);

/**
 * Box-filters a full-resolution linear RGB frame (row 0 at the top) by
 * `factor` per axis into `out` (the supersampling resolve of both renderers).
 * A pixel is covered when any of its samples is.
 */
void DownsampleBox(const std::vector<float>& rgb, const std::vector<uint8_t>& covered, int width,
  int height, int factor, Image& out);

/// Area-weighted vertex normals (sum of unnormalized face cross products).
std::vector<float> AreaWeightedNormals(const Mesh& mesh);

const char* ModeName(ShadingMode mode);
bool ParseMode(const std::string& name, ShadingMode& mode);

} // namespace shadinglab::cpu
