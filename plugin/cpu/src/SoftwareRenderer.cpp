// SPDX-License-Identifier: BSD-3-Clause
// The CPU renderer, in three parts: Raster.h (scan conversion), Rasterizer.h
// (vertex stage, binning, clipping, culling, the band loop) and the stages,
// ShadingStages.h and FastPhongStage.h (where each shading mode evaluates
// the model). This file sets up a frame, picks the stage once, and
// resolves the image.
#include "shadinglab/cpu/SoftwareRenderer.h"

#include "HiddenBackFaces.h"
#include "MeshCache.h"
#include "FastPhongStage.h"
#include "Rasterizer.h"
#include "ShadingStages.h"
#include "VertexNormals.h"
#include "shadinglab/render/AutoMode.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <thread>
#include <type_traits>

namespace shadinglab::cpu
{

using render::Image;
using render::Mesh;
using render::RenderStats;
using render::ShadingMode;

namespace
{

/// The analyser in front of the camera and the lights' polarizer, their
/// axes the image's (eq. 8.3, 8.6) in the camera's space; a polarizer in
/// front of the lights passes kPolarizerTransmittance of their intensity.
void SetupPolarizers(Frame& frame)
{
  frame.Lights.analyser = {};
  frame.Lights.lightPolarizer = {};
  if (frame.Opt.polarizer >= 0.0 || frame.Opt.lightPolarizer >= 0.0)
  {
    // The polarizers' axes are the image's (eq. 8.3, 8.6), in the camera's space.
    const render::CameraBasis basis = render::BasisOf(frame.Cam);
    if (frame.Opt.polarizer >= 0.0)
    {
      frame.Lights.analyser = Analyser<float>::At(frame.Opt.polarizer, frame.Opt.circularAnalyser);
      frame.Lights.analyser.right = Vec3<float>(basis.right);
      frame.Lights.analyser.up = Vec3<float>(basis.up);
    }
    if (frame.Opt.lightPolarizer >= 0.0)
    {
      const double psi = frame.Opt.lightPolarizer * kPi<double> / 180.0;
      frame.Lights.lightPolarizer.on = true;
      frame.Lights.lightPolarizer.axis = Vec3<float>(basis.right * std::cos(psi) + basis.up * std::sin(psi));
      frame.Lights.lightPolarizer.fallback = Vec3<float>(Cross(basis.right, basis.up));
      for (auto& light : frame.Lights.lights)
      {
        light.intensity *= kPolarizerTransmittance<float>;
      }
    }
  }
}

void SetupTransforms(Frame& frame)
{
  const Vec3<double> eye = frame.Cam.position;
  const render::CameraBasis basis = render::BasisOf(frame.Cam);
  const Vec3<double>& forward = basis.forward;
  const Vec3<double>& right = basis.right;
  const Vec3<double>& up = basis.up;
  raster::Matrix4 view{};
  const Vec3<double> rows[3] = { right, up, -forward };
  for (int r = 0; r < 3; ++r)
  {
    view.m[r][0] = rows[r].x;
    view.m[r][1] = rows[r].y;
    view.m[r][2] = rows[r].z;
    view.m[r][3] = -Dot(rows[r], eye);
  }
  view.m[3][3] = 1.0;
  const double aspect = static_cast<double>(frame.Width) / frame.Height;
  const double n = frame.Cam.nearClip, f = frame.Cam.farClip;
  raster::Matrix4 proj{};
  if (frame.Cam.parallel)
  {
    const double top = frame.Cam.parallelScale, rightExtent = top * aspect;
    proj.m[0][0] = 1.0 / rightExtent;
    proj.m[1][1] = 1.0 / top;
    proj.m[2][2] = -2.0 / (f - n);
    proj.m[2][3] = -(f + n) / (f - n);
    proj.m[3][3] = 1.0;
  }
  else
  {
    const double t = 1.0 / std::tan(0.5 * frame.Cam.viewAngle * kPi<double> / 180.0);
    proj.m[0][0] = t / aspect;
    proj.m[1][1] = t;
    proj.m[2][2] = -(f + n) / (f - n);
    proj.m[2][3] = -2.0 * f * n / (f - n);
    proj.m[3][2] = -1.0;
  }
  frame.ViewProjection = raster::Multiply(proj, view);
  frame.Eye = Vec3f(eye);
  frame.ToEye = Vec3f(-forward);
}

/// Fast Phong pays per triangle (its quadratics' set-up) what it saves per
/// pixel, and on this renderer the SIMD Phong pixel (WideShading.h) costs
/// about what a quadratic pixel does: fast Phong is slower below ~100
/// pixels per triangle and level above (bench BM_CpuModeBySize,
/// icospheres at 1080p, one thread: 1.5x slower at 5.5 px, 1.19x at 22,
/// 1.01x at 88, 0.92x at 351). Below 96 pixels per triangle exact Phong
/// is drawn instead.
constexpr double kFastPhongMinPixels = 96.0;

/// The worker threads of a frame: as asked, or every hardware thread.
int ThreadsFor(const render::RenderOptions& options)
{
  return options.threads > 0 ? options.threads
                             : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// The mesh's bounding box on screen, once per frame: whether all of it is
/// in front of the near plane (clip z + w > 0 at its eight corners: the
/// camera is outside the mesh and the near plane cuts nothing away), and
/// the area in pixels of its projection clipped to the image.
struct ScreenBounds
{
  bool inFrontOfNearPlane = false;
  double area = 0;
};

ScreenBounds ProjectBounds(const Frame& frame, const double b[6])
{
  double x0 = frame.Width, x1 = 0, y0 = frame.Height, y1 = 0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double p[3] = { b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)] };
    double clip[4];
    frame.ViewProjection.Apply(p, clip);
    if (!(clip[2] + clip[3] > 0.0) || !(clip[3] > 0.0))
    {
      return {};
    }
    const double x = (clip[0] / clip[3] * 0.5 + 0.5) * frame.Width;
    const double y = (0.5 - clip[1] / clip[3] * 0.5) * frame.Height;
    x0 = std::min(x0, x);
    x1 = std::max(x1, x);
    y0 = std::min(y0, y);
    y1 = std::max(y1, y);
  }
  const double W = frame.Width, H = frame.Height;
  const double w = std::clamp(x1, 0.0, W) - std::clamp(x0, 0.0, W);
  const double h = std::clamp(y1, 0.0, H) - std::clamp(y0, 0.0, H);
  return { true, std::max(0.0, w) * std::max(0.0, h) };
}

/// The closed-mesh test (HiddenBackFaces.h) runs, once per mesh, on the
/// mesh's first frame only when the image has at least this many pixels per
/// polygon, else on its second. It costs ~120 ns per triangle; culling
/// saves the set-up of the back faces that reach a row of pixel centres,
/// ~2,000 instructions each (measured on the 100k torus at 1080p), and with
/// fewer pixels than polygons most of them reach none: on a 5M-triangle
/// sphere at 16x16 the test cost 0.6 s to cull 23,302 faces, which one
/// frame does not earn back. Redrawn, it does: the 1.3M icosphere at
/// 640x480 (BM_CpuMaterialChange) takes 53 ms a frame unculled and 33 ms
/// culled, for a test of ~0.16 s.
constexpr double kCullTestMinPixelsPerPolygon = 1.0;

} // namespace

class SoftwareRenderer::Internals
{
public:
  /// `knownHash`: the mesh's content hash when the caller knows it
  /// (Scene::meshHash, or RunAuto computed it this frame), so it is not
  /// computed again.
  const Image& Run(const Mesh& mesh,
    const render::Camera& camera,
    const Lighting<float>& lighting,
    const Material<float>& material,
    const render::RenderOptions& options,
    RenderStats* stats,
    std::optional<uint64_t> knownHash = std::nullopt);

  void SetColorMap(const render::ColorMap* map) { this->FrameState.Map = map; }

  /// Run with ShadingMode::Auto resolved (ChooseMode) from this mesh's
  /// normals, made once per mesh version and shared with the drawing.
  const Image& RunAuto(const render::Scene& scene, const Lighting<double>& lights,
    const render::RenderOptions& options, RenderStats* stats);

private:
  /// What a frame decided before drawing, for its RenderStats.
  struct FrameFacts
  {
    int64_t polygons = 0;
    bool hiddenBackFaces = false;
    bool fastPhongAsPhong = false;
    double pixelsPerTriangle = 0;
    bool normalsComputed = false;
    bool normalsCached = false;
    bool areaVectorsKept = false;
  };
  /// Scan-converts the frame with the stage of its mode; returns the
  /// polygons found degenerate before rows were drawn.
  int64_t RasterizeFrame(std::vector<ThreadState>& states, bool fastPhongAsPhong);
  /// The frame's buffers, sized for it: for ssaa 1 the last image's own
  /// (one set, allocated by the first frame only).
  void PrepareBuffers();
  /// The frame's buffers as the Output image (box-filtered for ssaa > 1).
  void ResolveImage();
  void FillStats(
    const std::vector<ThreadState>& states, const FrameFacts& facts, RenderStats& stats) const;
  template<typename StageT>
  int64_t Rasterize(std::vector<ThreadState>& states)
  {
    StageT::Layout(this->FrameState);
    const StageT stage{ { this->FrameState } };
    return Rasterizer<StageT>(this->FrameState, stage, this->Buffers).Run(states);
  }

  Frame FrameState;
  RasterBuffers Buffers;
  ClosedMeshCache Closed;
  ClusterConeCache Cones;
  double MeshBounds[6] = { 0, 0, 0, 0, 0, 0 };
  std::optional<uint64_t> BoundsFor; ///< the content hash MeshBounds are for

  /// The mesh's bounds: an earlier frame's when the caller knows the
  /// mesh's content hash and it is the same (a pass over every point a
  /// frame, ~0.6% of a CPU-backend frame of ParaView's 1M sphere);
  /// without a known hash, computed (hashing costs more than the bounds).
  const double* BoundsOf(const Mesh& mesh, std::optional<uint64_t> knownHash)
  {
    if (!knownHash || this->BoundsFor != knownHash)
    {
      mesh.Bounds(this->MeshBounds, SpreadOver(this->Buffers.Pool, this->FrameState.Threads));
      this->BoundsFor = knownHash;
    }
    return this->MeshBounds;
  }

  SecondFrameCache<std::vector<float>> AreaVectors; ///< flat shading's (AreaVectorsOf)

  /// Flat shading's per-polygon area vectors (AreaVectorOf), kept for the
  /// mesh of content hash `hash` from its second flat frame on
  /// (SecondFrameCache); nullptr before. Each lit polygon otherwise reads
  /// its points again every frame, missing the cache (flat frames of
  /// ParaView's 1M sphere x0.984 with them).
  const float* AreaVectorsOf(const Mesh& mesh, uint64_t hash)
  {
    const std::vector<float>* kept = this->AreaVectors.Get(hash,
      [&](std::vector<float>& vectors)
      {
        const int64_t polygons = mesh.NumberOfPolygons();
        vectors.resize(static_cast<size_t>(3 * polygons));
        ParallelFor(this->Buffers.Pool, polygons, this->FrameState.Threads,
          [&](int64_t b, int64_t e, int)
          {
            for (int64_t p = b; p < e; ++p)
            {
              const Vec3f a = AreaVectorOf(mesh, p);
              float* out = &vectors[static_cast<size_t>(3 * p)];
              out[0] = a.x;
              out[1] = a.y;
              out[2] = a.z;
            }
          });
      });
    return kept ? kept->data() : nullptr;
  }

  std::vector<float> ComputedNormals; ///< area-weighted, for a mesh without normals
  std::optional<uint64_t> NormalsFor;  ///< the content hash they were made for

  /// The area-weighted normals of a mesh without normals, made once per
  /// mesh version (kept while its arrays hash the same); `cached` says
  /// whether they were an earlier frame's.
  const std::vector<float>& ComputedNormalsOf(const Mesh& mesh, uint64_t hash, bool& cached)
  {
    cached = this->NormalsFor == hash;
    if (!cached)
    {
      this->ComputedNormals = AreaWeightedNormals(mesh);
      this->NormalsFor = hash;
    }
    return this->ComputedNormals;
  }
  std::vector<float> Rgb;
  std::vector<uint8_t> Covered;
  std::vector<uint16_t> Coverage;
  std::vector<float> Depth;
  std::vector<uint8_t> DisplayBytes;
  Image Output;
};

const Image& SoftwareRenderer::Internals::Run(const Mesh& mesh,
  const render::Camera& camera,
  const Lighting<float>& lighting,
  const Material<float>& material,
  const render::RenderOptions& options,
  RenderStats* stats,
  std::optional<uint64_t> knownHash)
{
  const auto start = std::chrono::steady_clock::now();
  Frame& F = this->FrameState; // kept across frames: the power table's storage is reused
  F.NormalData = nullptr;
  F.NumAttributes = 0;
  F.NormalSlot = F.PositionSlot = F.ColorSlot = F.ScalarSlot = -1;
  F.MeshData = &mesh;
  F.Cam = camera;
  F.Lights = lighting;
  F.Mat = material;
  F.Opt = options;
  SetupPolarizers(F);
  const int ssaa = F.Opt.ssaa;
  F.Width = F.Opt.width * ssaa;
  F.Height = F.Opt.height * ssaa;
  F.Threads = ThreadsFor(F.Opt);
  // The incremental scan is the lecture's, in screen space (IncrementalScan.h).
  F.Perspective = F.Opt.interpolation == render::InterpolationSpace::Perspective &&
    !F.Cam.parallel && F.Opt.scan == render::ScanConversion::Plane;
  SetupTransforms(F);
  // Back faces: culled when asked, or when none can be seen (HiddenBackFaces.h;
  // not in the fill-rule check, which counts every polygon).
  const int64_t polygons = mesh.NumberOfPolygons();
  const bool mayCullHidden = !F.Opt.cullBackFaces && F.Opt.cullHiddenBackFaces && polygons > 0;
  const bool fastPhongMayFallBack = F.Opt.mode == ShadingMode::FastPhong && F.Opt.fastPhongFallback;
  const ScreenBounds onScreen = !F.Opt.countCoverage && (mayCullHidden || fastPhongMayFallBack)
    ? ProjectBounds(F, this->BoundsOf(mesh, knownHash))
    : ScreenBounds();
  // The mesh's content hash, the key of the caches below: computed at most
  // once a frame, on the frame's threads, and only when a cache is asked.
  bool hashed = false;
  uint64_t fingerprint = 0;
  auto contentHash = [&]
  {
    if (!hashed)
    {
      fingerprint =
        knownHash ? *knownHash : mesh.ContentHash(SpreadOver(this->Buffers.Pool, F.Threads));
      hashed = true;
    }
    return fingerprint;
  };
  const double imagePixels = static_cast<double>(F.Width) * F.Height;
  const bool hiddenBackFaces = mayCullHidden && onScreen.inFrontOfNearPlane &&
    this->Closed.IsClosedOutward(mesh, contentHash(),
      imagePixels >= kCullTestMinPixelsPerPolygon * static_cast<double>(polygons));
  F.CullBack = F.Opt.cullBackFaces || hiddenBackFaces;
  F.Cones = nullptr;
  if (F.CullBack && !F.Opt.countCoverage && polygons >= kClusterPolygons)
  {
    const auto* cones =
      this->Cones.ConesOf(mesh, contentHash(), SpreadOver(this->Buffers.Pool, F.Threads));
    if (cones && !cones->empty())
    {
      F.Cones = cones->data();
      const render::CameraBasis basis = render::BasisOf(F.Cam);
      for (int c = 0; c < 3; ++c)
      {
        F.ConeEye.position[c] = F.Cam.position[c];
        F.ConeEye.forward[c] = basis.forward[c];
      }
      F.ConeEye.parallel = F.Cam.parallel;
    }
  }
  // Pixels per triangle: the projected box over the triangles (about half
  // of a closed mesh's triangles face the viewer and cover about half the
  // box: the halves cancel); 0 (exact Phong) when the box crosses the near plane.
  const double pixelsPerTriangle = onScreen.area / static_cast<double>(std::max<int64_t>(1, polygons));
  const bool fastPhongAsPhong =
    fastPhongMayFallBack && !F.Opt.countCoverage && pixelsPerTriangle < kFastPhongMinPixels;

  const int64_t nv = mesh.NumberOfPoints();
  bool computedNormals = false, normalsCached = false;
  F.AreaVectors = nullptr;
  if (F.Opt.mode == ShadingMode::Flat && mesh.faceNormals.empty() && !F.Opt.countCoverage &&
    (knownHash || hashed))
  {
    // Only where the content hash costs nothing more (given by the caller,
    // or computed this frame for another cache).
    F.AreaVectors = this->AreaVectorsOf(mesh, contentHash());
  }
  if (F.Opt.mode != ShadingMode::Flat)
  {
    if (static_cast<int64_t>(mesh.normals.size()) == 3 * nv)
    {
      F.NormalData = mesh.normals.data();
    }
    else
    {
      // Made once per mesh, not per frame: kept while its arrays hash the
      // same (a redraw of a large mesh without normals otherwise paid
      // the whole normal pass every frame). The hash covers the arrays'
      // sizes too.
      F.NormalData = this->ComputedNormalsOf(mesh, contentHash(), normalsCached).data();
      computedNormals = true;
    }
  }

  Image& image = this->Output;
  this->PrepareBuffers();

  render::ScanTrace trace;
  trace.row = F.Opt.traceRow;
  F.Trace = stats && F.Opt.traceRow >= 0 ? &trace : nullptr;
  std::vector<ThreadState> states(static_cast<size_t>(F.Threads));
  const int64_t degenerateBeforeRows = this->RasterizeFrame(states, fastPhongAsPhong);
  F.Trace = nullptr;
  trace.normalSlot = F.NormalSlot;
  trace.intensitySlot = F.Opt.mode == ShadingMode::Gouraud ? 0 : -1;
  states[0].degenerate += degenerateBeforeRows;

  this->ResolveImage();

  if (stats)
  {
    FrameFacts facts;
    facts.polygons = polygons;
    facts.hiddenBackFaces = hiddenBackFaces;
    facts.fastPhongAsPhong = fastPhongAsPhong;
    facts.pixelsPerTriangle = fastPhongMayFallBack ? pixelsPerTriangle : 0.0;
    facts.normalsComputed = computedNormals;
    facts.normalsCached = normalsCached;
    facts.areaVectorsKept = F.AreaVectors != nullptr;
    this->FillStats(states, facts, *stats);
    stats->trace = std::move(trace);
    stats->milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  return image;
}

void SoftwareRenderer::Internals::PrepareBuffers()
{
  Frame& F = this->FrameState;
  const int ssaa = F.Opt.ssaa;
  const size_t pixels = static_cast<size_t>(F.Width) * F.Height;
  Image& image = this->Output;
  if (ssaa == 1)
  {
    // Draw straight into the previous image's buffers (handed back below):
    // one set of frame buffers, allocated by the first frame only. (Swapping
    // only at the end made two sets that alternated, so the second frame
    // allocated and faulted in ~27 MB at 1080p on the calling thread.)
    this->Rgb.swap(image.rgb);
    this->Covered.swap(image.covered);
    this->Coverage.swap(image.coverage);
  }
  this->Rgb.resize(pixels * 3);
  this->Covered.resize(pixels);
  if (F.Opt.countCoverage)
  {
    this->Coverage.assign(pixels, 0);
  }
  else
  {
    this->Coverage.clear(); // no stale counts from an earlier frame in the image
  }
  if (F.Opt.keepDepth)
  {
    this->Depth.swap(image.depth); // the last frame's buffer, as Rgb's
    this->Depth.resize(pixels);
  }
  const bool displayBytes = F.Opt.displayBytes && ssaa == 1;
  if (displayBytes)
  {
    this->DisplayBytes.swap(image.displayBytes); // the last frame's buffer, as Rgb's
    this->DisplayBytes.resize(4 * pixels);
  }
  F.Rgb = this->Rgb.data();
  F.Covered = this->Covered.data();
  F.Coverage = this->Coverage.data();
  F.Depth = F.Opt.keepDepth ? this->Depth.data() : nullptr;
  F.DisplayBytes = displayBytes ? this->DisplayBytes.data() : nullptr;

}

int64_t SoftwareRenderer::Internals::RasterizeFrame(
  std::vector<ThreadState>& states, bool fastPhongAsPhong)
{
  // The one choice of stage per frame: the rasterizer is compiled once per
  // stage and never branches on the mode.
  if (this->FrameState.Opt.countCoverage)
  {
    return this->Rasterize<CoverageStage>(states);
  }
  switch (this->FrameState.Opt.mode)
  {
    case ShadingMode::Auto: // resolved by RunAuto before Run
    case ShadingMode::Flat:
      return this->Rasterize<FlatStage>(states);
    case ShadingMode::Gouraud:
      return this->Rasterize<GouraudStage>(states);
    case ShadingMode::Phong:
      return this->Rasterize<PhongStage>(states);
    case ShadingMode::FastPhong:
      return fastPhongAsPhong ? this->Rasterize<PhongStage>(states)
                              : this->Rasterize<FastPhongStage>(states);
  }
  return 0;
}

void SoftwareRenderer::Internals::ResolveImage()
{
  // Supersampling resolved with a box filter; without it the frame's
  // buffers become the image's (and the last image's come back next frame).
  const Frame& F = this->FrameState;
  Image& image = this->Output;
  image.width = F.Opt.width;
  image.height = F.Opt.height;
  if (F.Opt.ssaa == 1)
  {
    image.rgb.swap(this->Rgb);
    image.covered.swap(this->Covered);
    image.coverage.swap(this->Coverage);
    if (F.Opt.keepDepth)
    {
      image.depth.swap(this->Depth);
    }
    else
    {
      image.depth.clear();
    }
    if (F.DisplayBytes)
    {
      image.displayBytes.swap(this->DisplayBytes);
    }
    else
    {
      image.displayBytes.clear();
    }
  }
  else
  {
    render::DownsampleBox(this->Rgb, this->Covered, F.Width, F.Height, F.Opt.ssaa, image);
    image.coverage.clear();
    image.depth.clear();
    image.displayBytes.clear();
  }
}

void SoftwareRenderer::Internals::FillStats(
  const std::vector<ThreadState>& states, const FrameFacts& facts, RenderStats& stats) const
{
  stats = RenderStats();
  stats.polygons = facts.polygons;
  for (const auto& st : states)
  {
    stats.triangles += st.triangles; // counted by binning, which reads every polygon's size
    stats.rasterized += st.rasterized;
    stats.clipped += st.clippedPolygons;
    stats.binned += st.binned;
    stats.degenerate += st.degenerate;
    stats.pixelsShaded += st.shaded;
    stats.fastPhongExact += st.fastPhongExact;
    stats.culled += st.culled;
    stats.culledInClusters += st.culledInClusters;
  }
  stats.verticesDrawn = this->Buffers.ScreenRecordsMade;
  stats.compactScreenRecords = this->Buffers.CompactScreen;
  stats.hiddenBackFacesCulled = facts.hiddenBackFaces;
  stats.fastPhongAsPhong = facts.fastPhongAsPhong;
  stats.pixelsPerTriangle = facts.pixelsPerTriangle;
  if (this->FrameState.Opt.ssaa == 1)
  {
    for (const auto& st : states)
    {
      stats.pixelsCovered += st.covered; // counted by the threads
    }
  }
  else
  {
    for (uint8_t c : this->Output.covered)
    {
      stats.pixelsCovered += c;
    }
  }
  stats.skipped = std::max<int64_t>(0, stats.polygons - stats.rasterized - stats.degenerate);
  stats.threads = this->FrameState.Threads;
  stats.normalsComputed = facts.normalsComputed;
  stats.normalsCached = facts.normalsCached;
  stats.areaVectorsKept = facts.areaVectorsKept;
  stats.drawnMode = this->FrameState.Opt.mode;
}

std::vector<float> AreaWeightedNormals(const Mesh& mesh)
{
  // The project's one implementation (mesh/core), on double coordinates.
  const std::vector<double> points(mesh.points.begin(), mesh.points.end());
  std::vector<double> normals;
  mesh.VisitIds([&](const auto* offsets, const auto* connectivity) {
    using Id = std::remove_const_t<std::remove_pointer_t<decltype(offsets)>>;
    const shadinglab::mesh::MeshViewOf<double, Id> polygons{ points.data(),
      mesh.NumberOfPoints(), offsets, connectivity, mesh.NumberOfPolygons() };
    shadinglab::mesh::ComputeVertexNormalsNoSplit(
      polygons, shadinglab::mesh::NormalWeighting::Area, normals);
  });
  return std::vector<float>(normals.begin(), normals.end());
}

const Image& SoftwareRenderer::Internals::RunAuto(const render::Scene& scene,
  const Lighting<double>& lights, const render::RenderOptions& options, RenderStats* stats)
{
  // Chosen from the normals the smooth modes draw with (the mesh's, or the
  // area-weighted ones made once per mesh version and drawn by Run), with
  // the lights as drawn.
  const Mesh& mesh = *scene.mesh;
  const std::vector<float>* normals = &mesh.normals;
  bool cached = false;
  std::optional<uint64_t> hash = scene.meshHash;
  const bool computed = static_cast<int64_t>(mesh.normals.size()) != 3 * mesh.NumberOfPoints();
  if (computed)
  {
    if (!hash)
    {
      hash = mesh.ContentHash(SpreadOver(this->Buffers.Pool, ThreadsFor(options)));
    }
    normals = &this->ComputedNormalsOf(mesh, *hash, cached);
  }
  const render::ModeChoice choice = render::ChooseMode(mesh, *normals, scene.camera, lights,
    scene.material, options.width, options.height, options.maxError);
  render::RenderOptions drawn = options;
  drawn.mode = choice.mode;
  const Image& image = this->Run(
    mesh, scene.camera, lights.Cast<float>(), scene.material.Cast<float>(), drawn, stats, hash);
  if (stats)
  {
    stats->autoChoice = choice.why;
    stats->normalsCached = computed && cached && stats->normalsComputed;
  }
  return image;
}

SoftwareRenderer::SoftwareRenderer()
  : Impl(new Internals)
{
}

SoftwareRenderer::~SoftwareRenderer() = default;

const render::Image& SoftwareRenderer::Render(const render::Scene& scene,
  const render::RenderOptions& options,
  render::RenderStats* stats)
{
  const std::string error = render::ValidateRequest(scene, options);
  if (!error.empty())
  {
    throw std::invalid_argument(error);
  }
  // No lights: a headlight, as VTK's automatic light (and the GL backend).
  const Lighting<double> lights = render::LightsOrHeadlight(scene.lighting, scene.camera);
  const Lighting<float> lighting = lights.Cast<float>();
  const render::Mesh& mesh = *scene.mesh;
  this->Impl->SetColorMap(
    (mesh.scalars.empty() && mesh.cellScalars.empty()) ? nullptr : scene.colorMap);
  if (options.mode != render::ShadingMode::Auto)
  {
    return this->Impl->Run(*scene.mesh, scene.camera, lighting, scene.material.Cast<float>(),
      options, stats, scene.meshHash);
  }
  return this->Impl->RunAuto(scene, lights, options, stats);
}

} // namespace shadinglab::cpu
