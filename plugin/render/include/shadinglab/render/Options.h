// SPDX-License-Identifier: BSD-3-Clause
// The choices a render is made of, as one enum each: where the illumination
// model is evaluated (ShadingMode), how attributes are interpolated
// (InterpolationSpace), how polygons are scan-converted, and how linear
// intensity becomes a display value. What is evaluated (the reflectance
// model) is the Material's, in plugin/model: the two are independent.
//
// Each enum's names live in one table below; the CLI, the VTK classes and
// the GLSL #defines (generated at build time by plugin/gl/GenerateGlslDefines)
// all read these tables, so the lists cannot drift.
#pragma once

#include "shadinglab/model/FastPhong.h"
#include "shadinglab/model/Vec3.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadinglab::render
{

/// Where the illumination model is evaluated: the lecture's four
/// interpolation schemes (docs/model.md, section 2).
enum class ShadingMode
{
  Flat,     ///< once per polygon from its face normal (eq. 2.1)
  Gouraud,  ///< at the vertices, intensities interpolated (eq. 2.2-2.4)
  Phong,    ///< normals interpolated and renormalized, model per pixel (eq. 2.5)
  FastPhong, ///< Bishop & Weimer 1986 quadratic by forward differences (eq. 2.6-2.8)
  /// Resolved by each backend inside Render, per mesh, view and material:
  /// the cheapest of Flat, Gouraud and Phong predicted to keep the mean
  /// error under RenderOptions::maxError (ChooseMode, eq. 4.1-4.5).
  /// RenderStats::drawnMode says what was drawn, autoChoice why.
  Auto
};

/// One row of an enum's name table.
template <typename E>
struct EnumName
{
  E value;
  const char* name;  ///< command-line / settings name
  const char* label; ///< for people (menus, panel titles)
  const char* glsl;  ///< GLSL #define suffix (SL_MODE_<glsl>), or nullptr
};

/// The drawn modes (Auto resolves to one of them).
inline constexpr EnumName<ShadingMode> kShadingModes[] = {
  { ShadingMode::Flat, "flat", "Flat", "FLAT" },
  { ShadingMode::Gouraud, "gouraud", "Gouraud", "GOURAUD" },
  { ShadingMode::Phong, "phong", "Phong", "PHONG" },
  { ShadingMode::FastPhong, "fast-phong", "Fast Phong", "FAST_PHONG" },
};
inline constexpr int kShadingModeCount = 4;

/// How attributes are interpolated across a polygon.
enum class InterpolationSpace
{
  Perspective, ///< perspective-correct (interpolate a/w and 1/w)
  Screen       ///< linear in screen space, as the lecture (shows its perspective distortion)
};

inline constexpr EnumName<InterpolationSpace> kInterpolationSpaces[] = {
  { InterpolationSpace::Perspective, "perspective", "Perspective-correct", nullptr },
  { InterpolationSpace::Screen, "screen", "Screen-space", nullptr },
};

/// Polygons with more than three vertices.
enum class PolygonHandling
{
  Triangulate, ///< fan-triangulated
  Direct       ///< scan-converted as polygons: edge walk in y, span in x (eq. 2.3)
};

/// How a polygon's attributes reach its pixels (CPU renderer).
enum class ScanConversion
{
  /// Each row's span starts from the polygon's own interpolation (the
  /// triangle's plane equation, or the polygon's edge crossings computed
  /// afresh), then steps across the span: no error carries from row to row.
  Plane,
  /// The lecture's DDA as written (docs/model.md eq. 2.10-2.11): every edge
  /// steps its crossing x and its attributes from row to row, every span
  /// steps its attributes from pixel to pixel, in ScanPrecision, always in
  /// screen space as on the slides (the interpolation space is ignored).
  /// Forward differences accumulate rounding error along edges and spans.
  Incremental
};

inline constexpr EnumName<ScanConversion> kScanConversions[] = {
  { ScanConversion::Plane, "plane", "Per row", nullptr },
  { ScanConversion::Incremental, "incremental", "Incremental (lecture DDA)", nullptr },
};

/// The arithmetic of the incremental scan.
enum class ScanPrecision
{
  Float, ///< IEEE single: unit roundoff 2^-24
  Double ///< IEEE double: unit roundoff 2^-53
};

inline constexpr EnumName<ScanPrecision> kScanPrecisions[] = {
  { ScanPrecision::Float, "float", "Float", nullptr },
  { ScanPrecision::Double, "double", "Double", nullptr },
};

/// How linear intensity becomes a display value in [0, 1] (docs/model.md,
/// section 6). Both backends apply it per pixel, after interpolation: the
/// CPU renderer in Image::ToRGB8, the GL mapper in its fragment shader.
enum class DisplayTransform
{
  Clamp,   ///< linear intensity clamped to [0, 1] (what fixed-function GL shows)
  SRGB,    ///< clamp, then the sRGB encoding curve (IEC 61966-2-1, eq. 6.2)
  Neutral  ///< Khronos PBR Neutral (eq. 6.1): highlights above 0.76 compressed towards 1, never clipped
};

inline constexpr EnumName<DisplayTransform> kDisplayTransforms[] = {
  { DisplayTransform::Clamp, "clamp", "Clamp", "CLAMP" },
  { DisplayTransform::SRGB, "srgb", "sRGB", "SRGB" },
  { DisplayTransform::Neutral, "neutral", "PBR Neutral", "NEUTRAL" },
};

/// Largest image side in pixels (both backends, the CLI and the VTK
/// classes). 16384 is OpenGL's usual GL_MAX_VIEWPORT_DIMS and keeps one
/// float RGB frame under 3.2 GB.
inline constexpr int kMaxImageSize = 16384;
/// Largest supersampling factor per axis: 8 x 8 = 64 samples per pixel is
/// beyond any visible gain for a box filter.
inline constexpr int kMaxSupersampling = 8;
/// Largest supersampled frame (samples): 4e8 samples are 6.4 GB of float
/// RGB + depth, the memory budget of a render on the 24 GiB machines we
/// target.
inline constexpr double kMaxFrameSamples = 4e8;

/// Auto's budget: below 0.01/255 no mode is predicted to comply (the fit's
/// floor, docs/model.md section 4); above 255 every mode does.
inline constexpr double kMinMaxError = 0.01;
inline constexpr double kMaxMaxError = 255.0;

struct RenderOptions
{
  ShadingMode mode = ShadingMode::Phong;
  /// Auto's error budget: the mean error allowed against exact shading, in
  /// 1/255 of the display range.
  double maxError = 1.0;
  InterpolationSpace interpolation = InterpolationSpace::Perspective;
  PolygonHandling polygons = PolygonHandling::Triangulate;
  /// The lecture's incremental scan in float or double, or the per-row
  /// default (CPU).
  ScanConversion scan = ScanConversion::Plane;
  ScanPrecision scanPrecision = ScanPrecision::Float;
  /// fast-phong's Taylor point: the provoking (last) vertex on both
  /// backends by default; Centroid (lower error, docs/model.md eq. 2.7) is
  /// CPU only: a fragment shader cannot see its triangle's centroid.
  ExpansionPoint expansion = ExpansionPoint::Vertex;
  /// Linear intensity to display value. PBR Neutral by default: the default
  /// material's highlight peaks at 2.2 (kd + ks (n + 8) / 8) and would clip
  /// whole faces to white under Clamp.
  DisplayTransform display = DisplayTransform::Neutral;
  int width = 1024;
  int height = 768;
  int ssaa = 1;    ///< supersampling factor per axis (box filter)
  int threads = 0; ///< 0: all hardware threads (CPU backend)
  bool cullBackFaces = false;
  /// Cull back faces where no pixel can show one (CPU): a closed, outward
  /// triangle mesh with its bounding box in front of the near plane
  /// (plugin/cpu/src/HiddenBackFaces.h). Off only to compare.
  bool cullHiddenBackFaces = true;
  /// Back-facing polygons are lit with their normals flipped (VTK's default).
  bool twoSidedLighting = true;
  /// Instead of shading, count how many polygons cover each pixel (no depth
  /// test): the fill-rule check (CPU backend). Result in Image::coverage.
  bool countCoverage = false;
  Vec3<float> background{ 0.32f, 0.34f, 0.43f };
  /// fast-phong: a pixel whose interpolated normal is more than this many
  /// degrees from the expansion point's normal is evaluated exactly instead
  /// of by the Taylor quadratic (the same per-pixel rule on both backends).
  /// The quadratic's error grows as the cube of the spread: at 30 degrees it
  /// is ~1/255 (FastPhongTest measures 2.4e-3 at ~23 degrees); at 45 degrees
  /// it is ~5/255 and visible. 180 disables the fallback.
  double fastPhongMaxSpread = 30.0;
  /// An analyser (linear polarizer) in front of the camera, its transmission
  /// axis this many degrees from the image's x axis, counter-clockwise
  /// (docs/model.md eq. 8.3-8.4); < 0: none, the eye sees all the light.
  double polarizer = -1.0;
  /// A linear polarizer in front of every light, its transmission axis at
  /// this many degrees from the image's x axis as the camera sees it
  /// (docs/model.md eq. 8.6); < 0: unpolarized lights.
  double lightPolarizer = -1.0;
  /// The analyser is circular (a quarter-wave plate before it: it passes
  /// right-handed light, eq. 8.5), for measuring S3; `polarizer` must be >= 0.
  bool circularAnalyser = false;
  /// fast-phong on the CPU: when the mesh's triangles are too small on
  /// screen for the quadratics to pay (their set-up costs more than the
  /// SIMD Phong pixels it saves), draw exact Phong instead and say so
  /// (RenderStats::fastPhongAsPhong). Off to study fast Phong itself.
  bool fastPhongFallback = true;
  /// >= 0: record what the scan computes on this pixel row (full
  /// resolution) in RenderStats::trace: the span ends and every pixel's
  /// interpolated attributes (CPU; the explorer's scanline inspector).
  int traceRow = -1;
  /// Keep the frame's depth (Image::depth): what a caller needs to merge
  /// the image into a depth-tested framebuffer (the VTK mapper's CPU
  /// backend). CPU only, without supersampling.
  bool keepDepth = false;
  /// Also write Image::displayBytes (RGBA8: `display` applied and rounded
  /// as Image::ToRGB8 does, alpha 255 where covered and 0 elsewhere), each
  /// band converted as it is finished, while it is in the core's cache; and
  /// leave the linear colour of uncovered pixels unwritten (no background
  /// fill, ~25 MB a 1080p frame). What the VTK mapper's CPU backend hands
  /// to OpenGL. CPU only, without supersampling.
  bool displayBytes = false;
};

/// True when the CPU renderer scans polygons of more than three corners
/// whole (--polygons direct, even-odd: docs/model.md section 3), so a mesh
/// for it keeps concave polygons whole too. Fast Phong's Taylor form is per
/// triangle (it fans every polygon), so its concave polygons are split.
inline bool ScansPolygonsWhole(const RenderOptions& options)
{
  return options.polygons == PolygonHandling::Direct && options.mode != ShadingMode::FastPhong;
}

/// One span of a traced row: its ends (the edge crossings x_4, x_5 of
/// docs/model.md eq. 2.3) and the attributes there.
struct TracedSpan
{
  float xLeft = 0, xRight = 0;
  std::vector<float> left, right;
};

/// One pixel of a traced row: the attributes the scan handed the shading.
struct TracedPixel
{
  int i = 0;
  std::vector<float> attributes;
};

/// What the CPU renderer's scan computed on RenderOptions::traceRow, in the
/// numbers it used (screen-space values: 1/w divided out). Attributes are
/// the stage's slots: Gouraud's lit colour at `intensitySlot` (3 values),
/// Phong's interpolated, not yet renormalized normal at `normalSlot`.
struct ScanTrace
{
  int row = -1;
  int intensitySlot = -1, normalSlot = -1;
  std::vector<TracedSpan> spans;
  std::vector<TracedPixel> pixels;
};

/// What a render did; fields a backend cannot know stay 0.
struct RenderStats
{
  double milliseconds = 0;
  int64_t polygons = 0;       ///< input polygons
  int64_t triangles = 0;      ///< input polygons counted as triangles (n - 2 each)
  int64_t rasterized = 0;     ///< polygons scan-converted (after culling and clipping; CPU)
  int64_t clipped = 0;        ///< polygons crossing the near plane (CPU)
  /// Polygon set-ups: one per polygon and 16-row band it is binned to, for
  /// the bands its rows (after near-plane clipping) reach (CPU).
  int64_t binned = 0;
  int64_t degenerate = 0;     ///< zero-area polygons skipped (CPU)
  /// Vertices of the polygons that reach a pixel: the vertex stage's
  /// screen records (CPU).
  int64_t verticesDrawn = 0;
  /// ... kept one per drawn vertex, not by vertex id: few of the mesh's
  /// vertices were drawn (CPU; cpu::ScreenRecords).
  bool compactScreenRecords = false;
  /// Polygons skipped before scan conversion: outside the view, beyond the
  /// far plane, culled back faces, or between pixel centres (CPU).
  int64_t skipped = 0;
  int64_t culled = 0;         ///< back faces culled before set-up (of `skipped`; CPU)
  /// Back faces culled in whole runs before binning read them, found facing
  /// away by their cone of normals (of `skipped`, not in `culled`; from a
  /// mesh's second frame with back faces culled; CPU).
  int64_t culledInClusters = 0;
  /// Back faces were culled because none can be seen (closed outward mesh,
  /// camera outside; CPU), without --cull.
  bool hiddenBackFacesCulled = false;
  /// fast-phong was asked for and exact Phong drawn: the triangles average
  /// fewer than kFastPhongMinPixels on screen (CPU).
  bool fastPhongAsPhong = false;
  double pixelsPerTriangle = 0; ///< the estimate that choice was made on (CPU)
  int64_t pixelsCovered = 0;  ///< pixels with a surface in the final image
  int64_t pixelsShaded = 0;   ///< illumination-model evaluations at pixels (CPU)
  int64_t fastPhongExact = 0; ///< fast-phong pixels evaluated exactly (spread limit; CPU)
  int threads = 1;
  int shaderBuilds = 0;       ///< shader sources generated by this render (GPU)
  bool normalsComputed = false; ///< the mesh had no normals: area-weighted ones were made
  /// ... and were those of an earlier frame, the mesh's arrays unchanged (CPU).
  bool normalsCached = false;
  /// Flat: the polygons' area vectors were kept from an earlier frame of
  /// the same mesh (CPU; SoftwareRenderer, with the scene's meshHash).
  bool areaVectorsKept = false;
  /// The mode drawn: RenderOptions::mode, or Auto's choice.
  ShadingMode drawnMode = ShadingMode::Phong;
  /// Auto: the choice's reasons (predictors, each mode's predicted error
  /// and cost; ModeChoice::why); "" in the other modes.
  std::string autoChoice;
  /// RenderOptions::traceRow's spans and pixels (CPU).
  ScanTrace trace;
};

const char* ShadingModeName(ShadingMode mode);
const char* ShadingModeLabel(ShadingMode mode);
/// Parses a ShadingMode name ("flat", "gouraud", "phong", "fast-phong", "auto").
bool ParseShadingMode(const std::string& name, ShadingMode& mode);
/// "flat, gouraud, phong or fast-phong" (the drawn modes), for error messages.
std::string ShadingModeChoices();

const char* InterpolationSpaceName(InterpolationSpace space);
bool ParseInterpolationSpace(const std::string& name, InterpolationSpace& space);

/**
 * Checks what every backend needs of the options: image size in
 * [1, kMaxImageSize], supersampling in [1, kMaxSupersampling], the frame
 * under kMaxFrameSamples, threads in [0, 256], a spread limit in [0, 180],
 * Auto's budget in [kMinMaxError, kMaxMaxError].
 * Returns "" or a one-line error.
 */
std::string ValidateOptions(const RenderOptions& options);

} // namespace shadinglab::render
