// SPDX-License-Identifier: BSD-3-Clause
// The CPU renderer. Three stages:
//   1. per vertex (parallel): clip coordinates, screen position, the
//      attributes the mode interpolates (Gouraud: the shaded colour).
//   2. per thread, over an interleaved set of 16-row bands: every polygon in
//      input order is rejected early when it misses the thread's bands, else
//      clipped at the near plane, culled, lit (flat) and scan-converted as in
//      the lecture: edge walk in y (docs/model.md eq. 2.3), span in x with
//      I_{p+1} = I_p + dI (eq. 2.4), depth test, shading. Each pixel belongs
//      to one band and sees polygons in input order, and no arithmetic
//      depends on the band split, so the image is bit-identical for any
//      thread count.
#include "shadinglab/cpu/SoftwareRenderer.h"

#include "VertexNormals.h"
#include "shadinglab/model/FastPhong.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

namespace shadinglab::cpu
{

using render::Camera;
using render::Image;
using render::InterpolationSpace;
using render::Mesh;
using render::PolygonHandling;
using render::RenderOptions;
using render::RenderStats;
using render::ShadingMode;

namespace
{

using Vec3f = Vec3<float>;

/// z, 1/w, then up to 9 interpolated values (normal, position, colour).
constexpr int kMaxAttributes = 11;
constexpr int kAttrZ = 0;
constexpr int kAttrInvW = 1;
constexpr int kAttrFirst = 2;

/// Rows per band. Bands are dealt to threads round-robin: 16 rows gives ~70
/// bands at 1080p, fine enough that two threads get even work on any image,
/// coarse enough that a typical small triangle touches one band only.
constexpr int kBandRows = 16;

/// Screen-space polygon area (pixels^2) below which a polygon is skipped as
/// degenerate: it cannot contain a pixel centre except on its own edges,
/// which the half-open fill rule assigns to neighbours anyway. 1e-10 is far
/// below any real sliver (a 1e-5 x 1e-5 pixel triangle).
constexpr float kDegenerateArea = 1e-10f;

/// Largest polygon after near-plane clipping: one more vertex than the input.
constexpr int kMaxPolygonVertices = 64;

/// ceil(x) as an int for the pixel-centre rules, without a libm call (this
/// build targets baseline x86-64, where std::ceil is not a single
/// instruction). x is clamped to +-1e9 pixels first: beyond any viewport, and
/// the int conversion stays defined.
inline int CeilToInt(float x)
{
  x = x < -1e9f ? -1e9f : (x > 1e9f ? 1e9f : x);
  const int i = static_cast<int>(x);
  return i + (x > static_cast<float>(i) ? 1 : 0);
}

struct ScreenVertex
{
  float x, y;
  float a[kMaxAttributes];
};

struct Matrix4
{
  double m[4][4];
  void Apply(const double p[3], double out[4]) const
  {
    for (int r = 0; r < 4; ++r)
    {
      out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3];
    }
  }
};

Matrix4 Multiply(const Matrix4& a, const Matrix4& b)
{
  Matrix4 r{};
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      for (int k = 0; k < 4; ++k)
      {
        r.m[i][j] += a.m[i][k] * b.m[k][j];
      }
    }
  }
  return r;
}

template <typename Fn>
void ParallelFor(int64_t count, int threads, Fn&& fn)
{
  if (threads <= 1 || count < 2)
  {
    fn(int64_t(0), count, 0);
    return;
  }
  std::vector<std::thread> pool;
  const int64_t per = (count + threads - 1) / threads;
  for (int t = 0; t < threads; ++t)
  {
    const int64_t b = t * per, e = std::min(count, b + per);
    if (b >= e)
    {
      break;
    }
    pool.emplace_back([&fn, b, e, t] { fn(b, e, t); });
  }
  for (auto& th : pool)
  {
    th.join();
  }
}

/// Per-thread scratch space and counters of stage 2.
struct ThreadState
{
  std::vector<ScreenVertex> clipped; ///< vertices made by near-plane clipping
  int64_t clippedPolygons = 0, degenerate = 0, rasterized = 0, shaded = 0, fastPhongExact = 0;
  int64_t covered = 0; ///< covered pixels in this thread's bands (full resolution)
};

} // namespace

/// The renderer's state; buffers persist across frames of one SoftwareRenderer.
struct FlatColor;

class SoftwareRenderer::Internals
{
public:
  Vec3f ComputeFlatColor(int64_t p, bool back) const;
  const Image& Run(const Mesh& mesh, const Camera& camera, const Lighting<float>& lighting,
    const Material<float>& material, const RenderOptions& options, RenderStats* stats);

private:
  void SetupTransforms();
  void ComputeVertexAttributes(int64_t v, float* raw) const;
  void ProjectVertex(const double clip[4], const float* raw, ScreenVertex& out) const;
  void RasterizeThread(int thread, int threadCount, ThreadState& state);
  int64_t BinPolygons(int64_t begin, int64_t end, int worker);
  void DrawSourcePolygon(int64_t p, int thread, int threadCount, ThreadState& state);
  template <typename PixelFn, typename SpanFn>
  void ScanConvert(const ScreenVertex* const* verts, int n, int rowBegin, int rowEnd,
    SpanFn&& beginSpan, PixelFn&& pixel) const;
  template <typename PixelFn, typename SpanFn>
  void ScanPolygon(const ScreenVertex* const* verts, int n, int rowBegin, int rowEnd,
    SpanFn&& beginSpan, PixelFn&& pixel) const;
  template <int NA, typename PixelFn, typename SpanFn>
  void ScanTriangle(const ScreenVertex* const* verts, int rowBegin, int rowEnd,
    SpanFn&& beginSpan, PixelFn&& pixel) const;
  void DrawPolygon(const ScreenVertex* const* verts, const int64_t* meshIds, int count, bool back,
    FlatColor& flatColor, int rowBegin, int rowEnd, ThreadState& state);
  void DrawTriangleFastPhong(const ScreenVertex* const* verts, const int64_t* meshIds, bool back,
    int rowBegin, int rowEnd, ThreadState& state);

  Vec3f NormalOf(int64_t v) const
  {
    const float* n = this->NormalData + 3 * v;
    return { n[0], n[1], n[2] };
  }
  Vec3f PointOf(int64_t v) const
  {
    const float* p = &this->MeshData->points[3 * v];
    return { p[0], p[1], p[2] };
  }
  Vec3f ColorOf(int64_t v) const
  {
    if (this->MeshData->colors.empty())
    {
      return this->Mat.diffuseColor;
    }
    const float* c = &this->MeshData->colors[3 * v];
    return { c[0], c[1], c[2] };
  }
  Vec3f ViewDirection(const Vec3f& P) const
  {
    if (this->Cam.parallel)
    {
      return this->ToEye;
    }
    return NormalizeOr(this->Eye - P, this->ToEye);
  }
  Vec3f ShadeAt(const Vec3f& P, const Vec3f& N, const Vec3f& color) const
  {
    return Shade(this->Mat, this->Lights, color, P, N, this->ViewDirection(P));
  }

  // Frame inputs.
  const Mesh* MeshData = nullptr;
  Camera Cam;
  Lighting<float> Lights;
  Material<float> Mat;
  RenderOptions Opt;

  int Width = 0, Height = 0, Threads = 1;
  Matrix4 ViewProjection{};
  Vec3f Eye, ToEye;
  const float* NormalData = nullptr;
  std::vector<float> ComputedNormals;
  int NumAttributes = 0;   // beyond z and 1/w
  int NormalSlot = -1, PositionSlot = -1, ColorSlot = -1;
  bool Perspective = true;
  SpecularPowerTable PowerTable; // fast-phong's (N.H)^n, as Bishop & Weimer
  float FastPhongMinCos = 0.0f;  // cos of RenderOptions::fastPhongMaxSpread

  // Buffers reused across frames.
  std::vector<ScreenVertex> Screen;
  std::vector<uint8_t> Behind; // vertex outside the near plane
  std::vector<float> Rgb;
  std::vector<float> Depth;
  std::vector<uint8_t> Covered;
  std::vector<uint16_t> Coverage;
  std::vector<std::vector<int64_t>> Bins; // [worker * Threads + thread]: polygon ids
  Image Output;
};

/// A polygon's flat-shaded colour, computed when its first pixel passes the
/// depth test: hidden polygons are never lit.
struct FlatColor
{
  const SoftwareRenderer::Internals* owner;
  int64_t polygon;
  bool back;
  bool valid = false;
  Vec3f value;
  const Vec3f& Get()
  {
    if (!this->valid)
    {
      this->value = this->owner->ComputeFlatColor(this->polygon, this->back);
      this->valid = true;
    }
    return this->value;
  }
};

void SoftwareRenderer::Internals::SetupTransforms()
{
  const Vec3<double> eye = this->Cam.position, focal = this->Cam.focalPoint;
  const Vec3<double> forward = NormalizeOr(focal - eye, Vec3<double>(0, 0, -1));
  const Vec3<double> right = NormalizeOr(Cross(forward, this->Cam.viewUp), Vec3<double>(1, 0, 0));
  const Vec3<double> up = Cross(right, forward);
  Matrix4 view{};
  const Vec3<double> rows[3] = { right, up, -forward };
  for (int r = 0; r < 3; ++r)
  {
    view.m[r][0] = rows[r].x;
    view.m[r][1] = rows[r].y;
    view.m[r][2] = rows[r].z;
    view.m[r][3] = -Dot(rows[r], eye);
  }
  view.m[3][3] = 1.0;
  const double aspect = static_cast<double>(this->Width) / this->Height;
  const double n = this->Cam.nearClip, f = this->Cam.farClip;
  Matrix4 proj{};
  if (this->Cam.parallel)
  {
    const double top = this->Cam.parallelScale, rightExtent = top * aspect;
    proj.m[0][0] = 1.0 / rightExtent;
    proj.m[1][1] = 1.0 / top;
    proj.m[2][2] = -2.0 / (f - n);
    proj.m[2][3] = -(f + n) / (f - n);
    proj.m[3][3] = 1.0;
  }
  else
  {
    const double t = 1.0 / std::tan(0.5 * this->Cam.viewAngle * kPi<double> / 180.0);
    proj.m[0][0] = t / aspect;
    proj.m[1][1] = t;
    proj.m[2][2] = -(f + n) / (f - n);
    proj.m[2][3] = -2.0 * f * n / (f - n);
    proj.m[3][2] = -1.0;
  }
  this->ViewProjection = Multiply(proj, view);
  this->Eye = Vec3f(eye);
  this->ToEye = Vec3f(-forward);
}

void SoftwareRenderer::Internals::ComputeVertexAttributes(int64_t v, float* raw) const
{
  switch (this->Opt.mode)
  {
    case ShadingMode::Flat:
      return;
    case ShadingMode::Gouraud:
    {
      const Vec3f c = this->ShadeAt(this->PointOf(v), this->NormalOf(v), this->ColorOf(v));
      raw[0] = c.x;
      raw[1] = c.y;
      raw[2] = c.z;
      return;
    }
    default:
      break;
  }
  if (this->NormalSlot >= 0)
  {
    const Vec3f n = this->NormalOf(v);
    raw[this->NormalSlot] = n.x;
    raw[this->NormalSlot + 1] = n.y;
    raw[this->NormalSlot + 2] = n.z;
  }
  if (this->PositionSlot >= 0)
  {
    const Vec3f p = this->PointOf(v);
    raw[this->PositionSlot] = p.x;
    raw[this->PositionSlot + 1] = p.y;
    raw[this->PositionSlot + 2] = p.z;
  }
  if (this->ColorSlot >= 0)
  {
    const Vec3f c = this->ColorOf(v);
    raw[this->ColorSlot] = c.x;
    raw[this->ColorSlot + 1] = c.y;
    raw[this->ColorSlot + 2] = c.z;
  }
}

void SoftwareRenderer::Internals::ProjectVertex(const double clip[4], const float* raw, ScreenVertex& out) const
{
  const double invW = 1.0 / clip[3];
  out.x = static_cast<float>((clip[0] * invW * 0.5 + 0.5) * this->Width);
  out.y = static_cast<float>((0.5 - clip[1] * invW * 0.5) * this->Height);
  out.a[kAttrZ] = static_cast<float>(clip[2] * invW);
  // Screen-space interpolation: attributes are interpolated as they are and
  // 1/w is pinned to 1, so the per-pixel divide is a no-op.
  const float scale = this->Perspective ? static_cast<float>(invW) : 1.0f;
  out.a[kAttrInvW] = scale;
  for (int k = 0; k < this->NumAttributes; ++k)
  {
    out.a[kAttrFirst + k] = raw[k] * scale;
  }
}

const Image& SoftwareRenderer::Internals::Run(const Mesh& mesh, const Camera& camera,
  const Lighting<float>& lighting, const Material<float>& material, const RenderOptions& options,
  RenderStats* stats)
{
  const auto start = std::chrono::steady_clock::now();
  this->MeshData = &mesh;
  this->Cam = camera;
  this->Lights = lighting;
  this->Mat = material;
  this->Opt = options;
  const int ssaa = this->Opt.ssaa;
  this->Width = this->Opt.width * ssaa;
  this->Height = this->Opt.height * ssaa;
  this->Threads = this->Opt.threads > 0
    ? this->Opt.threads
    : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  this->Perspective =
    this->Opt.interpolation == InterpolationSpace::Perspective && !this->Cam.parallel;
  this->NormalSlot = this->PositionSlot = this->ColorSlot = -1;
  this->SetupTransforms();

  const int64_t nv = mesh.NumberOfPoints();
  const int64_t np = mesh.NumberOfPolygons();
  bool computedNormals = false;
  this->NormalData = nullptr;
  if (this->Opt.mode != ShadingMode::Flat)
  {
    if (static_cast<int64_t>(mesh.normals.size()) == 3 * nv)
    {
      this->NormalData = mesh.normals.data();
    }
    else
    {
      this->ComputedNormals = AreaWeightedNormals(mesh);
      this->NormalData = this->ComputedNormals.data();
      computedNormals = true;
    }
  }

  // Attribute layout by mode: only what the mode reads is interpolated.
  int slot = 0;
  const bool perPixel =
    this->Opt.mode == ShadingMode::Phong;
  if (this->Opt.mode == ShadingMode::Gouraud)
  {
    slot = 3;
  }
  else if (perPixel)
  {
    this->NormalSlot = slot;
    slot += 3;
    bool pointLight = false;
    for (int j = 0; j < this->Lights.lightCount; ++j)
    {
      pointLight |= this->Lights.lights[j].type == LightType::Point;
    }
    // The world position is only needed for a local viewer or point lights.
    if (!this->Cam.parallel || pointLight)
    {
      this->PositionSlot = slot;
      slot += 3;
    }
  }
  if ((perPixel || this->Opt.mode == ShadingMode::FastPhong) && !mesh.colors.empty())
  {
    this->ColorSlot = slot;
    slot += 3;
  }
  this->NumAttributes = slot;
  if (this->Opt.mode == ShadingMode::FastPhong)
  {
    this->PowerTable.Build(this->Mat.shininess);
    this->FastPhongMinCos = static_cast<float>(
      std::cos(std::clamp(this->Opt.fastPhongMaxSpread, 0.0, 180.0) * kPi<double> / 180.0));
  }

  // Stage 1: vertices.
  this->Screen.resize(static_cast<size_t>(nv));
  this->Behind.resize(static_cast<size_t>(nv));
  ParallelFor(nv, this->Threads, [&](int64_t b, int64_t e, int) {
    float raw[kMaxAttributes];
    for (int64_t v = b; v < e; ++v)
    {
      const double p[3] = { mesh.points[3 * v], mesh.points[3 * v + 1], mesh.points[3 * v + 2] };
      double clip[4];
      this->ViewProjection.Apply(p, clip);
      this->Behind[v] = clip[2] < -clip[3];
      if (this->Behind[v])
      {
        continue; // such vertices are only used through clipping
      }
      this->ComputeVertexAttributes(v, raw);
      this->ProjectVertex(clip, raw, this->Screen[v]);
    }
  });

  // Stage 2: each thread owns an interleaved set of row bands, clears them
  // and draws every polygon, in input order, into its own rows.
  const size_t pixels = static_cast<size_t>(this->Width) * this->Height;
  this->Rgb.resize(pixels * 3);
  this->Depth.resize(pixels);
  this->Covered.resize(pixels);
  if (this->Opt.countCoverage)
  {
    this->Coverage.assign(pixels, 0);
  }
  std::vector<ThreadState> states(static_cast<size_t>(this->Threads));
  // Binning: each worker takes a contiguous range of polygons and lists, for
  // every rasterizing thread, the polygons that reach its bands. Thread t
  // then reads lists [0][t], [1][t], ... in order: input order is kept and
  // the per-polygon reject work is split across threads instead of repeated.
  const int T = this->Threads;
  this->Bins.resize(static_cast<size_t>(T) * T);
  for (auto& list : this->Bins)
  {
    list.clear(); // capacity kept across frames
  }
  std::vector<int64_t> zeroRowDegenerate(static_cast<size_t>(T), 0);
  ParallelFor(np, T, [&](int64_t begin, int64_t end, int worker) {
    zeroRowDegenerate[worker] = this->BinPolygons(begin, end, worker);
  });
  ParallelFor(T, T, [&](int64_t b, int64_t e, int) {
    for (int64_t t = b; t < e; ++t)
    {
      this->RasterizeThread(static_cast<int>(t), T, states[t]);
    }
  });
  for (int t = 0; t < T; ++t)
  {
    states[0].degenerate += zeroRowDegenerate[t];
  }

  // Resolve supersampling with a box filter.
  Image& image = this->Output;
  image.width = this->Opt.width;
  image.height = this->Opt.height;
  if (ssaa == 1)
  {
    image.rgb.swap(this->Rgb);
    image.covered.swap(this->Covered);
    image.coverage.swap(this->Coverage);
  }
  else
  {
    render::DownsampleBox(this->Rgb, this->Covered, this->Width, this->Height, ssaa, image);
    image.coverage.clear();
  }

  if (stats)
  {
    *stats = RenderStats();
    stats->polygons = np;
    for (int64_t p = 0; p < np; ++p)
    {
      stats->triangles += std::max<int64_t>(0, mesh.offsets[p + 1] - mesh.offsets[p] - 2);
    }
    for (const auto& st : states)
    {
      stats->rasterized += st.rasterized;
      stats->clipped += st.clippedPolygons;
      stats->degenerate += st.degenerate;
      stats->pixelsShaded += st.shaded;
      stats->fastPhongExact += st.fastPhongExact;
    }
    if (ssaa == 1)
    {
      for (const auto& st : states)
      {
        stats->pixelsCovered += st.covered; // counted by the threads
      }
    }
    else
    {
      for (uint8_t c : image.covered)
      {
        stats->pixelsCovered += c;
      }
    }
    stats->threads = this->Threads;
    stats->normalsComputed = computedNormals;
    stats->milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  return image;
}

Vec3f SoftwareRenderer::Internals::ComputeFlatColor(int64_t p, bool back) const
{
  // Face normal: given cell normal, else Newell's method (exact for planar
  // polygons, a least-squares normal otherwise). Lit at the polygon's last
  // vertex, OpenGL's provoking vertex, with its colour: the GPU mapper does
  // the same, so the two agree pixel for pixel on triangle meshes (the
  // lecture's flat shading assumes distant lights and viewer, where the
  // choice of point does not matter).
  const auto& conn = this->MeshData->connectivity;
  const int64_t first = this->MeshData->offsets[p];
  const int n = static_cast<int>(this->MeshData->offsets[p + 1] - first);
  Vec3f N;
  for (int k = 0; k < n; ++k)
  {
    const Vec3f a = this->PointOf(conn[first + k]), b = this->PointOf(conn[first + (k + 1) % n]);
    N += Vec3f((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  if (!this->MeshData->faceNormals.empty())
  {
    const float* fn = &this->MeshData->faceNormals[3 * p];
    N = Vec3f(fn[0], fn[1], fn[2]);
  }
  N = NormalizeOr(N, this->ToEye);
  if (this->Opt.twoSidedLighting && back)
  {
    N = -N;
  }
  const int64_t provoking = conn[first + n - 1];
  return this->ShadeAt(this->PointOf(provoking), N, this->ColorOf(provoking));
}

void SoftwareRenderer::Internals::RasterizeThread(int thread, int threadCount, ThreadState& state)
{
  const Vec3f bg = this->Opt.background;
  const int bands = (this->Height + kBandRows - 1) / kBandRows;
  for (int b = thread; b < bands; b += threadCount)
  {
    const size_t first = static_cast<size_t>(b) * kBandRows * this->Width;
    const size_t last =
      static_cast<size_t>(std::min(this->Height, (b + 1) * kBandRows)) * this->Width;
    for (size_t i = first; i < last; ++i)
    {
      this->Rgb[3 * i] = bg.x;
      this->Rgb[3 * i + 1] = bg.y;
      this->Rgb[3 * i + 2] = bg.z;
    }
    std::fill(this->Depth.begin() + first, this->Depth.begin() + last,
      std::numeric_limits<float>::infinity());
    std::fill(this->Covered.begin() + first, this->Covered.begin() + last, uint8_t(0));
  }
  for (int w = 0; w < threadCount; ++w)
  {
    for (const int64_t p : this->Bins[static_cast<size_t>(w) * threadCount + thread])
    {
      this->DrawSourcePolygon(p, thread, threadCount, state);
    }
  }
  // Count this thread's covered pixels here, in parallel, for the stats.
  for (int b = thread; b < bands; b += threadCount)
  {
    const size_t first = static_cast<size_t>(b) * kBandRows * this->Width;
    const size_t last =
      static_cast<size_t>(std::min(this->Height, (b + 1) * kBandRows)) * this->Width;
    for (size_t i = first; i < last; ++i)
    {
      state.covered += this->Covered[i];
    }
  }
}

int64_t SoftwareRenderer::Internals::BinPolygons(int64_t begin, int64_t end, int worker)
{
  const int T = this->Threads;
  const auto& offsets = this->MeshData->offsets;
  const auto& conn = this->MeshData->connectivity;
  std::vector<int64_t>* lists = &this->Bins[static_cast<size_t>(worker) * T];
  int64_t degenerate = 0;
  for (int64_t p = begin; p < end; ++p)
  {
    const int64_t first = offsets[p];
    const int n = static_cast<int>(std::min<int64_t>(offsets[p + 1] - first, kMaxPolygonVertices - 1));
    if (n < 3)
    {
      continue;
    }
    bool anyBehind = false;
    float ymin = std::numeric_limits<float>::infinity(), ymax = -ymin;
    for (int k = 0; k < n; ++k)
    {
      const int64_t v = conn[first + k];
      anyBehind |= this->Behind[v] != 0;
      ymin = std::min(ymin, this->Screen[v].y);
      ymax = std::max(ymax, this->Screen[v].y);
    }
    if (anyBehind)
    {
      // Rows are known only after clipping (rare): every thread looks.
      for (int t = 0; t < T; ++t)
      {
        lists[t].push_back(p);
      }
      continue;
    }
    const int j0 = std::max(0, CeilToInt(ymin - 0.5f));
    const int j1 = std::min(this->Height, CeilToInt(ymax - 0.5f));
    if (j1 <= j0)
    {
      // No pixel row: count it if it is degenerate (zero screen area).
      double area = 0;
      for (int k = 0; k < n; ++k)
      {
        const ScreenVertex& a = this->Screen[conn[first + k]];
        const ScreenVertex& b = this->Screen[conn[first + (k + 1) % n]];
        area += static_cast<double>(a.x) * b.y - static_cast<double>(b.x) * a.y;
      }
      degenerate += !(std::abs(area) * 0.5 >= kDegenerateArea);
      continue;
    }
    const int b0 = j0 / kBandRows, b1 = (j1 - 1) / kBandRows;
    if (b1 - b0 + 1 >= T)
    {
      for (int t = 0; t < T; ++t)
      {
        lists[t].push_back(p);
      }
    }
    else
    {
      for (int b = b0; b <= b1; ++b)
      {
        lists[b % T].push_back(p);
      }
    }
  }
  return degenerate;
}

void SoftwareRenderer::Internals::DrawSourcePolygon(
  int64_t p, int thread, int threadCount, ThreadState& state)
{
  const auto& offsets = this->MeshData->offsets;
  const auto& conn = this->MeshData->connectivity;
  const int64_t first = offsets[p];
  const int n =
    static_cast<int>(std::min<int64_t>(offsets[p + 1] - first, kMaxPolygonVertices - 1));
  if (n < 3)
  {
    return;
  }
  // Counters are kept by the thread that owns the polygon's first band (or
  // thread 0 for polygons rejected before rows are known), so they do not
  // depend on the thread count.
  const ScreenVertex* verts[kMaxPolygonVertices];
  int64_t ids[kMaxPolygonVertices];
  bool anyBehind = false;
  for (int k = 0; k < n; ++k)
  {
    ids[k] = conn[first + k];
    anyBehind |= this->Behind[ids[k]] != 0;
  }
  int count = 0;
  bool wasClipped = false;
  if (!anyBehind)
  {
    for (int k = 0; k < n; ++k)
    {
      verts[count++] = &this->Screen[ids[k]];
    }
  }
  else
  {
    // Sutherland-Hodgman against the near plane z + w >= 0 in clip space,
    // attributes interpolated linearly there (exact before the divide).
    // Each crossing is computed from its inside end towards its outside
    // end, so two polygons sharing an edge get bit-identical vertices.
    wasClipped = true;
    struct ClipVertex
    {
      double c[4];
      float raw[kMaxAttributes];
    };
    ClipVertex in[kMaxPolygonVertices];
    for (int k = 0; k < n; ++k)
    {
      const int64_t v = ids[k];
      const double pt[3] = { this->MeshData->points[3 * v], this->MeshData->points[3 * v + 1],
        this->MeshData->points[3 * v + 2] };
      this->ViewProjection.Apply(pt, in[k].c);
      this->ComputeVertexAttributes(v, in[k].raw);
    }
    state.clipped.clear();
    int64_t clippedIds[kMaxPolygonVertices];
    for (int k = 0; k < n; ++k)
    {
      const ClipVertex& a = in[k];
      const ClipVertex& b = in[(k + 1) % n];
      const double da = a.c[2] + a.c[3], db = b.c[2] + b.c[3];
      const bool aIn = da >= 0, bIn = db >= 0;
      auto emit = [&](const ClipVertex& cv, int64_t id) {
        ScreenVertex sv;
        this->ProjectVertex(cv.c, cv.raw, sv);
        clippedIds[state.clipped.size()] = id;
        state.clipped.push_back(sv);
      };
      if (aIn)
      {
        emit(a, ids[k]);
      }
      if (aIn != bIn)
      {
        const ClipVertex& inside = aIn ? a : b;
        const ClipVertex& outside = aIn ? b : a;
        const double di = aIn ? da : db, dout = aIn ? db : da;
        const double t = di / (di - dout);
        ClipVertex x;
        for (int i = 0; i < 4; ++i)
        {
          x.c[i] = inside.c[i] + t * (outside.c[i] - inside.c[i]);
        }
        // Land exactly on the plane so 1/w stays finite.
        x.c[2] = -x.c[3];
        for (int i = 0; i < this->NumAttributes; ++i)
        {
          x.raw[i] = static_cast<float>(inside.raw[i] + t * (outside.raw[i] - inside.raw[i]));
        }
        emit(x, aIn ? ids[k] : ids[(k + 1) % n]);
      }
    }
    count = static_cast<int>(state.clipped.size());
    if (count < 3)
    {
      return;
    }
    for (int k = 0; k < count; ++k)
    {
      verts[k] = &state.clipped[k];
      ids[k] = clippedIds[k];
    }
  }
  // Trivial reject outside the viewport or beyond the far plane, signed
  // area (y down: front faces have negative area) and row range.
  float xmin = std::numeric_limits<float>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  float zmin = xmin;
  double area = 0;
  for (int k = 0; k < count; ++k)
  {
    const ScreenVertex& a = *verts[k];
    const ScreenVertex& b = *verts[(k + 1) % count];
    area += static_cast<double>(a.x) * b.y - static_cast<double>(b.x) * a.y;
    xmin = std::min(xmin, a.x);
    xmax = std::max(xmax, a.x);
    ymin = std::min(ymin, a.y);
    ymax = std::max(ymax, a.y);
    zmin = std::min(zmin, a.a[kAttrZ]);
  }
  const int j0 = std::max(0, CeilToInt(ymin - 0.5f));
  const int j1 = std::min(this->Height, CeilToInt(ymax - 0.5f));
  if (xmax < 0 || xmin > this->Width || j1 <= j0 || zmin > 1.0f)
  {
    return;
  }
  const bool owner = (j0 / kBandRows) % threadCount == thread;
  if (!(std::abs(area) * 0.5 >= kDegenerateArea) || !std::isfinite(area))
  {
    state.degenerate += owner;
    return;
  }
  const bool back = area > 0;
  if (back && this->Opt.cullBackFaces)
  {
    return;
  }
  state.clippedPolygons += owner && wasClipped;
  state.rasterized += owner;

  // Flat colour, computed when the first pixel of the polygon passes the
  // depth test: hidden polygons are never lit.
  FlatColor flat{ this, p, back, false, Vec3f() };
  // Gouraud back faces: relight their vertices with flipped normals.
  ScreenVertex relit[kMaxPolygonVertices];
  if (this->Opt.mode == ShadingMode::Gouraud && back && this->Opt.twoSidedLighting &&
    !this->Opt.countCoverage)
  {
    for (int k = 0; k < count; ++k)
    {
      relit[k] = *verts[k];
      const int64_t v = ids[k];
      const Vec3f c = this->ShadeAt(this->PointOf(v), -this->NormalOf(v), this->ColorOf(v));
      const float scale = relit[k].a[kAttrInvW];
      relit[k].a[kAttrFirst] = c.x * scale;
      relit[k].a[kAttrFirst + 1] = c.y * scale;
      relit[k].a[kAttrFirst + 2] = c.z * scale;
      verts[k] = &relit[k];
    }
  }
  // Scan-convert each part into the bands of this thread.
  auto drawPart = [&](const ScreenVertex* const* partVerts, const int64_t* partIds, int m) {
    float pymin = partVerts[0]->y, pymax = pymin;
    for (int k = 1; k < m; ++k)
    {
      pymin = std::min(pymin, partVerts[k]->y);
      pymax = std::max(pymax, partVerts[k]->y);
    }
    const int r0 = std::max(0, CeilToInt(pymin - 0.5f));
    const int r1 = std::min(this->Height, CeilToInt(pymax - 0.5f));
    if (r1 <= r0)
    {
      return;
    }
    const int bFirst = r0 / kBandRows, bLast = (r1 - 1) / kBandRows;
    // First band of this thread at or after bFirst.
    int b = bFirst + ((thread - bFirst % threadCount) + threadCount) % threadCount;
    for (; b <= bLast; b += threadCount)
    {
      this->DrawPolygon(partVerts, partIds, m, back, flat, std::max(r0, b * kBandRows),
        std::min(r1, (b + 1) * kBandRows), state);
    }
  };
  const bool triangulate = this->Opt.polygons == PolygonHandling::Triangulate ||
    this->Opt.mode == ShadingMode::FastPhong;
  if (triangulate && count > 3)
  {
    for (int k = 1; k + 1 < count; ++k)
    {
      const ScreenVertex* tri[3] = { verts[0], verts[k], verts[k + 1] };
      const int64_t triIds[3] = { ids[0], ids[k], ids[k + 1] };
      drawPart(tri, triIds, 3);
    }
  }
  else
  {
    drawPart(verts, ids, count);
  }
}

template <typename PixelFn, typename SpanFn>
void SoftwareRenderer::Internals::ScanConvert(const ScreenVertex* const* verts, int n, int rowBegin, int rowEnd,
  SpanFn&& beginSpan, PixelFn&& pixel) const
{
  if (n != 3)
  {
    this->ScanPolygon(verts, n, rowBegin, rowEnd, beginSpan, pixel);
    return;
  }
  // The attribute count is fixed per frame; a compile-time count lets the
  // span loop unroll.
  switch (kAttrFirst + this->NumAttributes)
  {
    case 2:
      this->ScanTriangle<2>(verts, rowBegin, rowEnd, beginSpan, pixel);
      return;
    case 5:
      this->ScanTriangle<5>(verts, rowBegin, rowEnd, beginSpan, pixel);
      return;
    case 8:
      this->ScanTriangle<8>(verts, rowBegin, rowEnd, beginSpan, pixel);
      return;
    case 11:
      this->ScanTriangle<11>(verts, rowBegin, rowEnd, beginSpan, pixel);
      return;
    default:
      this->ScanPolygon(verts, n, rowBegin, rowEnd, beginSpan, pixel);
  }
}

/*
 * Triangles. The interpolation along the edges (docs/model.md eq. 2.3) and across
 * the span give, on a triangle, the one linear function of (x, y) through
 * the three vertex values: its gradients dI/dx and dI/dy are constant. They
 * are computed once per triangle; each span starts from the plane value at
 * its first pixel centre and steps I_{p+1} = I_p + dI/dx (eq. 2.4). Edge
 * crossings are computed from each edge's canonical endpoint order, as in
 * ScanPolygon, so shared edges stay watertight.
 */
template <int NA, typename PixelFn, typename SpanFn>
void SoftwareRenderer::Internals::ScanTriangle(const ScreenVertex* const* verts, int rowBegin, int rowEnd,
  SpanFn&& beginSpan, PixelFn&& pixel) const
{
  const ScreenVertex& v0 = *verts[0];
  const ScreenVertex& v1 = *verts[1];
  const ScreenVertex& v2 = *verts[2];
  const double e1x = v1.x - v0.x, e1y = v1.y - v0.y;
  const double e2x = v2.x - v0.x, e2y = v2.y - v0.y;
  const double det = e1x * e2y - e2x * e1y;
  if (!(std::abs(det) > 0.0))
  {
    return;
  }
  // Attribute gradients, computed on the first span with pixels: most
  // triangles of a very fine mesh cover no pixel centre.
  double dadx[NA] = {}, dady[NA] = {};
  float stepX[NA] = {};
  bool gradients = false;
  auto computeGradients = [&]() {
    const double invDet = 1.0 / det;
    for (int k = 0; k < NA; ++k)
    {
      const double d1 = static_cast<double>(v1.a[k]) - v0.a[k];
      const double d2 = static_cast<double>(v2.a[k]) - v0.a[k];
      dadx[k] = (d1 * e2y - d2 * e1y) * invDet;
      dady[k] = (d2 * e1x - d1 * e2x) * invDet;
      stepX[k] = static_cast<float>(dadx[k]);
    }
    gradients = true;
  };
  struct Edge
  {
    float px, py, qy, invSlope;
  };
  Edge edges[3];
  float ymin = v0.y, ymax = v0.y;
  for (int k = 0; k < 3; ++k)
  {
    const ScreenVertex* p = verts[k];
    const ScreenVertex* q = verts[(k + 1) % 3];
    if (q->y < p->y || (q->y == p->y && q->x < p->x))
    {
      std::swap(p, q);
    }
    edges[k] = { p->x, p->y, q->y, q->y > p->y ? (q->x - p->x) / (q->y - p->y) : 0.0f };
    ymin = std::min(ymin, p->y);
    ymax = std::max(ymax, q->y);
  }
  const int j0 = std::max(rowBegin, CeilToInt(ymin - 0.5f));
  const int j1 = std::min(rowEnd, CeilToInt(ymax - 0.5f));
  float value[kMaxAttributes] = {}; // full size: pixel functors index by slot
  for (int j = j0; j < j1; ++j)
  {
    const float yc = static_cast<float>(j) + 0.5f;
    float xs[2];
    int nc = 0;
    for (int k = 0; k < 3 && nc < 2; ++k)
    {
      const Edge& e = edges[k];
      if (e.py <= yc && yc < e.qy)
      {
        xs[nc++] = e.px + (yc - e.py) * e.invSlope;
      }
    }
    if (nc < 2)
    {
      continue;
    }
    const float xl = std::min(xs[0], xs[1]), xr = std::max(xs[0], xs[1]);
    const int i0 = std::max(0, CeilToInt(xl - 0.5f));
    const int i1 = std::min(this->Width, CeilToInt(xr - 0.5f));
    if (i1 <= i0)
    {
      continue;
    }
    if (!gradients)
    {
      computeGradients();
    }
    const double dx = static_cast<double>(i0) + 0.5 - v0.x, dy = static_cast<double>(yc) - v0.y;
    for (int k = 0; k < NA; ++k)
    {
      value[k] = static_cast<float>(v0.a[k] + dadx[k] * dx + dady[k] * dy);
    }
    beginSpan(j, i0);
    for (int i = i0; i < i1; ++i)
    {
      pixel(j, i, value);
      for (int k = 0; k < NA; ++k)
      {
        value[k] += stepX[k];
      }
    }
  }
}

/*
 * General polygons (--polygons direct): the lecture's algorithm literally.
 * For each scanline, every edge crossing is interpolated along its edge in y
 * (eq. 2.3), crossings are paired left to right, and each span is
 * interpolated in x (eq. 2.4). For a polygon of more than three vertices the
 * result depends on the polygon's orientation on screen (docs/model.md eq. 3.2).
 */
template <typename PixelFn, typename SpanFn>
void SoftwareRenderer::Internals::ScanPolygon(const ScreenVertex* const* verts, int n, int rowBegin, int rowEnd,
  SpanFn&& beginSpan, PixelFn&& pixel) const
{
  const int na = kAttrFirst + this->NumAttributes;
  float ymin = verts[0]->y, ymax = verts[0]->y;
  for (int k = 1; k < n; ++k)
  {
    ymin = std::min(ymin, verts[k]->y);
    ymax = std::max(ymax, verts[k]->y);
  }
  // Pixel centres at (i + 0.5, j + 0.5). Rows j with ymin <= j + 0.5 < ymax
  // and, within a row, pixels with xl <= i + 0.5 < xr: half-open on both
  // axes, so a pixel centre on an edge shared by two polygons belongs to
  // exactly one of them.
  const int j0 = std::max(rowBegin, CeilToInt(ymin - 0.5f));
  const int j1 = std::min(rowEnd, CeilToInt(ymax - 0.5f));
  struct Crossing
  {
    float x;
    float a[kMaxAttributes];
  };
  Crossing cross[kMaxPolygonVertices];
  float value[kMaxAttributes], delta[kMaxAttributes];
  for (int j = j0; j < j1; ++j)
  {
    const float yc = static_cast<float>(j) + 0.5f;
    int nc = 0;
    for (int k = 0; k < n; ++k)
    {
      const ScreenVertex* p = verts[k];
      const ScreenVertex* q = verts[(k + 1) % n];
      // Canonical direction (lower y first, then lower x): the two polygons
      // sharing this edge compute bit-identical crossings.
      if (q->y < p->y || (q->y == p->y && q->x < p->x))
      {
        std::swap(p, q);
      }
      if (!(p->y <= yc && yc < q->y))
      {
        continue;
      }
      // docs/model.md eq. 2.3: I_4 = (y_1 - y_4)/(y_1 - y_2) I_2 + (y_4 - y_2)/(y_1 - y_2) I_1.
      const float t = (yc - p->y) / (q->y - p->y);
      Crossing& c = cross[nc++];
      c.x = p->x + t * (q->x - p->x);
      for (int i = 0; i < na; ++i)
      {
        c.a[i] = p->a[i] + t * (q->a[i] - p->a[i]);
      }
    }
    // Sort crossings by x (n is small); pair them even-odd into spans.
    for (int a = 1; a < nc; ++a)
    {
      for (int b = a; b > 0 && cross[b].x < cross[b - 1].x; --b)
      {
        std::swap(cross[b], cross[b - 1]);
      }
    }
    for (int s = 0; s + 1 < nc; s += 2)
    {
      const Crossing& L = cross[s];
      const Crossing& R = cross[s + 1];
      const int i0 = std::max(0, CeilToInt(L.x - 0.5f));
      const int i1 = std::min(this->Width, CeilToInt(R.x - 0.5f));
      if (i1 <= i0)
      {
        continue;
      }
      // docs/model.md eq. 2.4: I_p = (x_5 - x_p)/(x_5 - x_4) I_4 + (x_p - x_4)/(x_5 - x_4) I_5,
      // then incrementally I_{p+1} = I_p + (I_5 - I_4)/(x_5 - x_4).
      const float invSpan = 1.0f / (R.x - L.x);
      const float start = (static_cast<float>(i0) + 0.5f - L.x);
      for (int i = 0; i < na; ++i)
      {
        delta[i] = (R.a[i] - L.a[i]) * invSpan;
        value[i] = L.a[i] + start * delta[i];
      }
      beginSpan(j, i0);
      for (int i = i0; i < i1; ++i)
      {
        pixel(j, i, value);
        for (int k = 0; k < na; ++k)
        {
          value[k] += delta[k];
        }
      }
    }
  }
}

void SoftwareRenderer::Internals::DrawPolygon(const ScreenVertex* const* verts,
  const int64_t* meshIds, int count, bool back, FlatColor& flatColor, int rowBegin, int rowEnd,
  ThreadState& state)
{
  const int W = this->Width;
  float* rgb = this->Rgb.data();
  uint8_t* covered = this->Covered.data();
  auto noSpan = [](int, int) {};

  if (this->Opt.countCoverage)
  {
    uint16_t* coverage = this->Coverage.data();
    this->ScanConvert(verts, count, rowBegin, rowEnd, noSpan, [&](int j, int i, const float*) {
      const size_t pix = static_cast<size_t>(j) * W + i;
      ++coverage[pix];
      covered[pix] = 1;
    });
    return;
  }
  auto depthTest = [&](int j, int i, const float* a) -> float* {
    const float z = a[kAttrZ];
    if (!(z <= 1.0f))
    {
      return nullptr; // beyond the far plane
    }
    float& d = this->Depth[static_cast<size_t>(j) * W + i];
    if (!(z < d))
    {
      return nullptr;
    }
    d = z;
    const size_t pix = static_cast<size_t>(j) * W + i;
    covered[pix] = 1;
    return rgb + 3 * pix;
  };

  switch (this->Opt.mode)
  {
    case ShadingMode::Flat:
    {
      this->ScanConvert(verts, count, rowBegin, rowEnd, noSpan, [&](int j, int i, const float* a) {
        if (float* out = depthTest(j, i, a))
        {
          const Vec3f& c = flatColor.Get();
          out[0] = c.x;
          out[1] = c.y;
          out[2] = c.z;
        }
      });
      return;
    }
    case ShadingMode::Gouraud:
    {
      this->ScanConvert(verts, count, rowBegin, rowEnd, noSpan, [&](int j, int i, const float* a) {
        if (float* out = depthTest(j, i, a))
        {
          const float w = this->Perspective ? 1.0f / a[kAttrInvW] : 1.0f;
          out[0] = a[kAttrFirst] * w;
          out[1] = a[kAttrFirst + 1] * w;
          out[2] = a[kAttrFirst + 2] * w;
        }
      });
      return;
    }
    case ShadingMode::FastPhong:
      this->DrawTriangleFastPhong(verts, meshIds, back, rowBegin, rowEnd, state);
      return;
    case ShadingMode::Phong:
      break;
  }
  const float flip = (back && this->Opt.twoSidedLighting) ? -1.0f : 1.0f;
  int64_t shaded = 0;
  this->ScanConvert(verts, count, rowBegin, rowEnd, noSpan, [&](int j, int i, const float* a) {
    float* out = depthTest(j, i, a);
    if (!out)
    {
      return;
    }
    const float w = this->Perspective ? 1.0f / a[kAttrInvW] : 1.0f;
    const float* n = a + kAttrFirst + this->NormalSlot;
    // docs/model.md eq. 2.5: the interpolated normal is renormalized before lighting.
    const Vec3f N = NormalizeOr(Vec3f(n[0], n[1], n[2]) * (w * flip), this->ToEye);
    Vec3f P;
    if (this->PositionSlot >= 0)
    {
      const float* p = a + kAttrFirst + this->PositionSlot;
      P = Vec3f(p[0] * w, p[1] * w, p[2] * w);
    }
    Vec3f color = this->Mat.diffuseColor;
    if (this->ColorSlot >= 0)
    {
      const float* c = a + kAttrFirst + this->ColorSlot;
      color = Vec3f(c[0] * w, c[1] * w, c[2] * w);
    }
    const Vec3f I = this->ShadeAt(P, N, color);
    out[0] = I.x;
    out[1] = I.y;
    out[2] = I.z;
    ++shaded;
  });
  state.shaded += shaded;
}

void SoftwareRenderer::Internals::DrawTriangleFastPhong(const ScreenVertex* const* verts, const int64_t* meshIds,
  bool back, int rowBegin, int rowEnd, ThreadState& state)
{
  // Bishop & Weimer 1986: L and H constant over the triangle (their
  // assumption of a distant light and viewer), evaluated at the expansion
  // point; the normal field is affine in screen space, so this mode always
  // interpolates in screen space. meshIds are mesh vertices (a vertex made
  // by near-plane clipping carries its inside end's id).
  float sx[3], sy[3];
  Vec3f normals[3];
  Vec3f centroid;
  for (int k = 0; k < 3; ++k)
  {
    sx[k] = verts[k]->x;
    sy[k] = verts[k]->y;
    normals[k] = this->NormalOf(meshIds[k]) * ((back && this->Opt.twoSidedLighting) ? -1.0f : 1.0f);
    centroid += this->PointOf(meshIds[k]) * (1.0f / 3.0f);
  }
  // The triangle's setup is done lazily, on its first span with pixels:
  // most triangles of a million-triangle mesh cover no pixel centre at all.
  FastPhongTriangle<float> tri;
  Vec3f Ls[kMaxLights], Hs[kMaxLights], V, N0;
  float LoV[kMaxLights];
  const int nl = this->Lights.lightCount;
  // The quadratics each model needs: N.L always; N.H for Blinn-Phong; N.V
  // for Phong, whose R.V = 2 (N.L)(N.V) - L.V (docs/model.md eq. 2.8).
  const bool specular = this->Mat.ks > 0.0f &&
    (this->Mat.model == ReflectanceModel::BlinnPhong || this->Mat.model == ReflectanceModel::Phong);
  const bool halfVector = specular && this->Mat.model == ReflectanceModel::BlinnPhong;
  const bool viewCosine = specular && this->Mat.model == ReflectanceModel::Phong;
  FastPhongQuadratic<float> diffuseQ[kMaxLights], specularQ[kMaxLights], viewQ;
  Vec3f irradiance[kMaxLights];
  bool active[kMaxLights];
  bool ready = false;
  auto setup = [&]() {
    ready = true;
    tri.Setup(sx, sy, normals);
    // L, V and H are taken at the expansion point's surface position.
    const Vec3f expansionPoint =
      this->Opt.expansion == ExpansionPoint::Vertex ? this->PointOf(meshIds[2]) : centroid;
    V = this->ViewDirection(expansionPoint);
    // Bishop & Weimer's expansion holds for small normal variation: where
    // the interpolated normal turns more than the spread limit away from the
    // expansion point's, the pixel is evaluated exactly (the same affine
    // normal, renormalized), so no Taylor blow-up reaches a pixel. The same
    // per-pixel rule as the GPU (FastPhongTriangle::WithinSpread).
    N0 = this->Opt.expansion == ExpansionPoint::Vertex ? tri.Normal(tri.vertexX, tri.vertexY)
                                                      : tri.Normal(tri.centroidX, tri.centroidY);
    const Vec3f unit2 = NormalizeOr(normals[2], this->ToEye);
    if (viewCosine)
    {
      viewQ = tri.Expand(V, this->Opt.expansion);
    }
    for (int l = 0; l < nl; ++l)
    {
      Vec3f L;
      active[l] = LightIncidence(this->Lights.lights[l], expansionPoint, L, irradiance[l]);
      if (!active[l])
      {
        continue;
      }
      Ls[l] = L;
      LoV[l] = Dot(L, V);
      diffuseQ[l] = tri.Expand(L, this->Opt.expansion);
      if (halfVector)
      {
        // HalfVector's fallback normal (for L = -V only): the provoking vertex's.
        Hs[l] = HalfVector(L, V, unit2);
        specularQ[l] = tri.Expand(Hs[l], this->Opt.expansion);
      }
    }
  };
  FastPhongScanline<float> diffuseLine[kMaxLights], specularLine[kMaxLights], viewLine;
  const Vec3f ambient = this->Mat.ambient * this->Lights.ambientIntensity;
  // The cosine power by table, as Bishop & Weimer (their section 4).
  const auto tablePower = [this](float x, float) { return this->PowerTable.Lookup(x); };
  int64_t shaded = 0, exactPixels = 0;
  const int W = this->Width;
  float* rgb = this->Rgb.data();
  uint8_t* covered = this->Covered.data();
  this->ScanConvert(
    verts, 3, rowBegin, rowEnd,
    [&](int j, int i0) {
      if (!ready)
      {
        setup();
      }
      const float yc = static_cast<float>(j) + 0.5f, xc = static_cast<float>(i0) + 0.5f;
      if (viewCosine)
      {
        viewLine.Begin(viewQ, xc, yc);
      }
      for (int l = 0; l < nl; ++l)
      {
        diffuseLine[l].Begin(diffuseQ[l], xc, yc);
        if (halfVector)
        {
          specularLine[l].Begin(specularQ[l], xc, yc);
        }
      }
    },
    [&](int j, int i, const float* a) {
      // Forward differences advance for every pixel of the span, drawn or not.
      float NoL[kMaxLights], NoH[kMaxLights], NoV = 0.0f;
      const float xc = static_cast<float>(i) + 0.5f, yc = static_cast<float>(j) + 0.5f;
      if (!tri.WithinSpread(N0, xc, yc, this->FastPhongMinCos))
      {
        ++exactPixels;
        // The forward differences still advance by one pixel.
        if (viewCosine)
        {
          viewLine.Next();
        }
        for (int l = 0; l < nl; ++l)
        {
          diffuseLine[l].Next();
          if (halfVector)
          {
            specularLine[l].Next();
          }
        }
        NoV = viewCosine ? tri.Exact(V, xc, yc) : 0.0f;
        for (int l = 0; l < nl; ++l)
        {
          NoL[l] = tri.Exact(Ls[l], xc, yc);
          NoH[l] = halfVector ? tri.Exact(Hs[l], xc, yc) : 0.0f;
        }
      }
      else
      {
        NoV = viewCosine ? viewLine.Next() : 0.0f;
        for (int l = 0; l < nl; ++l)
        {
          NoL[l] = diffuseLine[l].Next();
          NoH[l] = halfVector ? specularLine[l].Next() : 0.0f;
        }
      }
      const float z = a[kAttrZ];
      float& d = this->Depth[static_cast<size_t>(j) * W + i];
      if (!(z <= 1.0f) || !(z < d))
      {
        return;
      }
      d = z;
      Vec3f color = this->Mat.diffuseColor;
      if (this->ColorSlot >= 0)
      {
        const float* c = a + kAttrFirst + this->ColorSlot;
        const float w = this->Perspective ? 1.0f / a[kAttrInvW] : 1.0f;
        color = Vec3f(c[0] * w, c[1] * w, c[2] * w);
      }
      Vec3f I = ambient;
      for (int l = 0; l < nl; ++l)
      {
        // The quadratic may overshoot [-1, 1] slightly; clamp like a cosine.
        const float cl = std::min(NoL[l], 1.0f);
        if (!active[l] || !(cl > 0.0f))
        {
          continue;
        }
        const float RoV = 2.0f * cl * NoV - LoV[l];
        I += irradiance[l] * BrdfFromCosines(this->Mat, color, NoH[l], RoV, tablePower) * cl;
      }
      const size_t pix = static_cast<size_t>(j) * W + i;
      covered[pix] = 1;
      rgb[3 * pix] = I.x;
      rgb[3 * pix + 1] = I.y;
      rgb[3 * pix + 2] = I.z;
      ++shaded;
    });
  state.shaded += shaded;
  state.fastPhongExact += exactPixels;
}

std::vector<float> AreaWeightedNormals(const Mesh& mesh)
{
  // The project's one implementation (mesh/core), on double coordinates.
  const std::vector<double> points(mesh.points.begin(), mesh.points.end());
  const shadinglab::mesh::PolygonMesh polygons{ points.data(), mesh.NumberOfPoints(), mesh.offsets.data(),
    mesh.connectivity.data(), mesh.NumberOfPolygons() };
  std::vector<double> normals;
  shadinglab::mesh::ComputeVertexNormalsNoSplit(
    polygons, shadinglab::mesh::NormalWeighting::Area, normals);
  return std::vector<float>(normals.begin(), normals.end());
}

SoftwareRenderer::SoftwareRenderer()
  : Impl(new Internals)
{
}

SoftwareRenderer::~SoftwareRenderer() = default;

const render::Image& SoftwareRenderer::Render(
  const render::Scene& scene, const render::RenderOptions& options, render::RenderStats* stats)
{
  const std::string error = render::ValidateRequest(scene, options);
  if (!error.empty())
  {
    throw std::invalid_argument(error);
  }
  Lighting<float> lighting = scene.lighting.Cast<float>();
  if (lighting.lightCount == 0)
  {
    // No lights: a headlight, as VTK's automatic light (and the GL backend).
    Light<float> headlight;
    headlight.vector = Vec3f(NormalizeOr(
      scene.camera.position - scene.camera.focalPoint, Vec3<double>(0, 0, 1)));
    lighting.lights[0] = headlight;
    lighting.lightCount = 1;
  }
  return this->Impl->Run(
    *scene.mesh, scene.camera, lighting, scene.material.Cast<float>(), options, stats);
}

} // namespace shadinglab::cpu
