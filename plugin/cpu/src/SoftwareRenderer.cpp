// SPDX-License-Identifier: BSD-3-Clause
// The CPU renderer. Three stages:
//   1. per vertex (parallel): clip coordinates, screen position, the
//      attributes the mode interpolates (Gouraud: the shaded colour).
//   2. per polygon (parallel, in chunks): trivial frustum reject, near-plane
//      clipping, facing and culling, flat colour, binning into row bands.
//   3. per band of rows (parallel): scan conversion as in the lecture, edge
//      walk in y (slide 5), span in x with I_{p+1} = I_p + dI (slide 6), depth
//      test, shading. Each pixel belongs to exactly one band and polygons are
//      visited in input order, so the image is bit-identical for any thread
//      count.
#include "shadinglab/cpu/SoftwareRenderer.h"

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

namespace
{

using Vec3f = Vec3<float>;

/// z, 1/w, then up to 9 interpolated values (normal, position, colour).
constexpr int kMaxAttributes = 11;
constexpr int kAttrZ = 0;
constexpr int kAttrInvW = 1;
constexpr int kAttrFirst = 2;

/// Rows per band in stage 3. 16 rows keeps ~70 bands at 1080p so two threads
/// balance dynamically, while a typical small triangle touches one band.
constexpr int kBandRows = 16;

/// Polygons per stage-2 chunk: large enough that chunk bookkeeping is
/// negligible, small enough that two threads balance.
constexpr int64_t kChunkPolygons = 16384;

/// Screen-space polygon area (pixels^2) below which a polygon is skipped as
/// degenerate: it cannot contain a pixel centre except on its own edges,
/// which the half-open fill rule assigns to neighbours anyway. 1e-10 is far
/// below any real sliver (a 1e-5 x 1e-5 pixel triangle).
constexpr float kDegenerateArea = 1e-10f;

/// Largest polygon after near-plane clipping: one more vertex than the input.
constexpr int kMaxPolygonVertices = 64;

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

/// A polygon to scan-convert: vertex references into the global screen
/// vertices (>= 0) or the chunk's own clipped vertices (~index).
struct RasterPolygon
{
  int64_t firstRef;
  int32_t count;
  bool backFacing;
  float ymin, ymax;
  Vec3f flatColor;
};

struct Chunk
{
  std::vector<RasterPolygon> polygons;
  std::vector<int64_t> refs;
  std::vector<ScreenVertex> extra;
  std::vector<std::vector<int32_t>> bins; ///< per band: polygon indices
  int64_t clipped = 0, degenerate = 0, rasterized = 0;
};

class Renderer
{
public:
  Renderer(const Mesh& mesh, const Camera& camera, const Lighting<float>& lighting,
    const Material<float>& material, const RenderOptions& options)
    : MeshData(mesh)
    , Cam(camera)
    , Lights(lighting)
    , Mat(material)
    , Opt(options)
  {
  }

  Image Run(RenderStats* stats);

private:
  void SetupTransforms();
  void ComputeVertexAttributes(int64_t v, float* raw) const;
  void ProjectVertex(const double clip[4], const float* raw, ScreenVertex& out) const;
  void ProcessChunk(int64_t begin, int64_t end, Chunk& chunk) const;
  void RasterizeBand(int band, std::vector<float>& depth) ;
  template <typename PixelFn, typename SpanFn>
  void ScanConvert(const ScreenVertex* const* verts, int n, int rowBegin, int rowEnd,
    SpanFn&& beginSpan, PixelFn&& pixel) const;
  void DrawPolygon(const Chunk& chunk, const RasterPolygon& poly, int rowBegin, int rowEnd,
    std::vector<float>& depth);
  void DrawTriangleFastPhong(const ScreenVertex* const* verts, const int64_t* meshIds,
    bool back, int rowBegin, int rowEnd, std::vector<float>& depth);

  Vec3f NormalOf(int64_t v) const
  {
    const float* n = &this->Normals[3 * v];
    return { n[0], n[1], n[2] };
  }
  Vec3f PointOf(int64_t v) const
  {
    const float* p = &this->MeshData.points[3 * v];
    return { p[0], p[1], p[2] };
  }
  Vec3f ColorOf(int64_t v) const
  {
    if (this->MeshData.colors.empty())
    {
      return this->Mat.diffuseColor;
    }
    const float* c = &this->MeshData.colors[3 * v];
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

  const Mesh& MeshData;
  const Camera& Cam;
  const Lighting<float>& Lights;
  const Material<float>& Mat;
  const RenderOptions& Opt;

  int Width = 0, Height = 0, Threads = 1;
  Matrix4 ViewProjection{};
  Vec3f Eye, ToEye;
  std::vector<float> Normals;
  int NumAttributes = 0;   // beyond z and 1/w
  bool HasPosition = false; // phong: world position interpolated
  int NormalSlot = -1, PositionSlot = -1, ColorSlot = -1;
  bool Perspective = true;
  std::vector<ScreenVertex> Screen;
  std::vector<uint8_t> Behind; // vertex outside the near plane
  std::vector<Chunk> Chunks;
  std::vector<float> Rgb;
  std::vector<uint8_t> Covered;
  std::vector<uint16_t> Coverage;
  std::atomic<int64_t> Shaded{ 0 };
};

void Renderer::SetupTransforms()
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

void Renderer::ComputeVertexAttributes(int64_t v, float* raw) const
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

void Renderer::ProjectVertex(const double clip[4], const float* raw, ScreenVertex& out) const
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

Image Renderer::Run(RenderStats* stats)
{
  const auto start = std::chrono::steady_clock::now();
  const int ssaa = this->Opt.ssaa;
  this->Width = this->Opt.width * ssaa;
  this->Height = this->Opt.height * ssaa;
  this->Threads = this->Opt.threads > 0
    ? this->Opt.threads
    : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  this->Perspective =
    this->Opt.interpolation == InterpolationSpace::Perspective && !this->Cam.parallel;
  this->SetupTransforms();

  const int64_t nv = this->MeshData.NumberOfPoints();
  const int64_t np = this->MeshData.NumberOfPolygons();
  bool computedNormals = false;
  const bool needNormals = this->Opt.mode != ShadingMode::Flat;
  if (needNormals)
  {
    if (static_cast<int64_t>(this->MeshData.normals.size()) == 3 * nv)
    {
      this->Normals = this->MeshData.normals;
    }
    else
    {
      this->Normals = AreaWeightedNormals(this->MeshData);
      computedNormals = true;
    }
  }

  // Attribute layout by mode: only what the mode reads is interpolated.
  int slot = 0;
  const bool perPixel =
    this->Opt.mode == ShadingMode::Phong || this->Opt.mode == ShadingMode::CookTorrance;
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
    if (!this->Cam.parallel || pointLight)
    {
      this->PositionSlot = slot;
      slot += 3;
    }
  }
  if ((perPixel || this->Opt.mode == ShadingMode::FastPhong) && !this->MeshData.colors.empty())
  {
    this->ColorSlot = slot;
    slot += 3;
  }
  this->NumAttributes = slot;

  // Stage 1: vertices.
  this->Screen.resize(static_cast<size_t>(nv));
  this->Behind.resize(static_cast<size_t>(nv));
  ParallelFor(nv, this->Threads, [&](int64_t b, int64_t e, int) {
    float raw[kMaxAttributes];
    for (int64_t v = b; v < e; ++v)
    {
      const double p[3] = { this->MeshData.points[3 * v], this->MeshData.points[3 * v + 1],
        this->MeshData.points[3 * v + 2] };
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

  // Stage 2: polygons.
  const int64_t chunkCount = (np + kChunkPolygons - 1) / kChunkPolygons;
  this->Chunks.assign(static_cast<size_t>(chunkCount), Chunk());
  const int bands = (this->Height + kBandRows - 1) / kBandRows;
  std::atomic<int64_t> nextChunk{ 0 };
  ParallelFor(this->Threads, this->Threads, [&](int64_t, int64_t, int) {
    for (;;)
    {
      const int64_t c = nextChunk.fetch_add(1);
      if (c >= chunkCount)
      {
        break;
      }
      Chunk& chunk = this->Chunks[c];
      chunk.bins.assign(static_cast<size_t>(bands), {});
      this->ProcessChunk(c * kChunkPolygons, std::min(np, (c + 1) * kChunkPolygons), chunk);
    }
  });

  // Stage 3: bands of rows.
  const size_t pixels = static_cast<size_t>(this->Width) * this->Height;
  this->Rgb.assign(pixels * 3, 0.0f);
  for (size_t i = 0; i < pixels; ++i)
  {
    this->Rgb[3 * i] = this->Opt.background.x;
    this->Rgb[3 * i + 1] = this->Opt.background.y;
    this->Rgb[3 * i + 2] = this->Opt.background.z;
  }
  this->Covered.assign(pixels, 0);
  if (this->Opt.countCoverage)
  {
    this->Coverage.assign(pixels, 0);
  }
  std::atomic<int> nextBand{ 0 };
  ParallelFor(this->Threads, this->Threads, [&](int64_t, int64_t, int) {
    std::vector<float> depth(static_cast<size_t>(kBandRows) * this->Width);
    for (;;)
    {
      const int band = nextBand.fetch_add(1);
      if (band >= bands)
      {
        break;
      }
      this->RasterizeBand(band, depth);
    }
  });

  // Resolve supersampling with a box filter.
  Image image;
  image.width = this->Opt.width;
  image.height = this->Opt.height;
  if (ssaa == 1)
  {
    image.rgb = std::move(this->Rgb);
    image.covered = std::move(this->Covered);
    image.coverage = std::move(this->Coverage);
  }
  else
  {
    image.rgb.assign(static_cast<size_t>(image.width) * image.height * 3, 0.0f);
    image.covered.assign(static_cast<size_t>(image.width) * image.height, 0);
    const float norm = 1.0f / static_cast<float>(ssaa * ssaa);
    for (int y = 0; y < image.height; ++y)
    {
      for (int x = 0; x < image.width; ++x)
      {
        float sum[3] = { 0, 0, 0 };
        uint8_t any = 0;
        for (int sy = 0; sy < ssaa; ++sy)
        {
          for (int sx = 0; sx < ssaa; ++sx)
          {
            const size_t i = static_cast<size_t>(y * ssaa + sy) * this->Width + (x * ssaa + sx);
            for (int c = 0; c < 3; ++c)
            {
              sum[c] += this->Rgb[3 * i + c];
            }
            any |= this->Covered[i];
          }
        }
        const size_t o = static_cast<size_t>(y) * image.width + x;
        for (int c = 0; c < 3; ++c)
        {
          image.rgb[3 * o + c] = sum[c] * norm;
        }
        image.covered[o] = any;
      }
    }
  }

  if (stats)
  {
    stats->polygons = np;
    stats->triangles = 0;
    for (int64_t p = 0; p < np; ++p)
    {
      stats->triangles += std::max<int64_t>(0,
        this->MeshData.offsets[p + 1] - this->MeshData.offsets[p] - 2);
    }
    stats->rasterized = stats->clipped = stats->degenerate = 0;
    for (const auto& chunk : this->Chunks)
    {
      stats->rasterized += chunk.rasterized;
      stats->clipped += chunk.clipped;
      stats->degenerate += chunk.degenerate;
    }
    stats->pixelsCovered = 0;
    for (uint8_t c : image.covered)
    {
      stats->pixelsCovered += c;
    }
    stats->pixelsShaded = this->Shaded.load();
    stats->threads = this->Threads;
    stats->normalsComputed = computedNormals;
    stats->milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  return image;
}

void Renderer::ProcessChunk(int64_t begin, int64_t end, Chunk& chunk) const
{
  const auto& offsets = this->MeshData.offsets;
  const auto& conn = this->MeshData.connectivity;
  const bool triangulate = this->Opt.polygons == PolygonHandling::Triangulate ||
    this->Opt.mode == ShadingMode::FastPhong;
  int64_t local[kMaxPolygonVertices];

  for (int64_t p = begin; p < end; ++p)
  {
    const int64_t first = offsets[p];
    const int n = static_cast<int>(std::min<int64_t>(offsets[p + 1] - first, kMaxPolygonVertices - 1));
    if (n < 3)
    {
      continue;
    }
    bool anyBehind = false;
    for (int k = 0; k < n; ++k)
    {
      anyBehind |= this->Behind[conn[first + k]] != 0;
    }
    int count = 0;
    if (!anyBehind)
    {
      for (int k = 0; k < n; ++k)
      {
        local[count++] = conn[first + k];
      }
    }
    else
    {
      // Sutherland-Hodgman against the near plane z + w >= 0 in clip space,
      // attributes interpolated linearly there (exact before the divide).
      // Each crossing is computed from its inside end towards its outside
      // end, so two polygons sharing an edge get bit-identical vertices.
      ++chunk.clipped;
      struct ClipVertex
      {
        double c[4];
        float raw[kMaxAttributes];
      };
      ClipVertex in[kMaxPolygonVertices];
      for (int k = 0; k < n; ++k)
      {
        const int64_t v = conn[first + k];
        const double pt[3] = { this->MeshData.points[3 * v], this->MeshData.points[3 * v + 1],
          this->MeshData.points[3 * v + 2] };
        this->ViewProjection.Apply(pt, in[k].c);
        this->ComputeVertexAttributes(v, in[k].raw);
      }
      for (int k = 0; k < n; ++k)
      {
        const ClipVertex& a = in[k];
        const ClipVertex& b = in[(k + 1) % n];
        const double da = a.c[2] + a.c[3], db = b.c[2] + b.c[3];
        const bool aIn = da >= 0, bIn = db >= 0;
        auto emit = [&](const ClipVertex& cv) {
          ScreenVertex sv;
          this->ProjectVertex(cv.c, cv.raw, sv);
          chunk.extra.push_back(sv);
          local[count++] = ~static_cast<int64_t>(chunk.extra.size() - 1);
        };
        if (aIn)
        {
          emit(a);
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
          emit(x);
        }
      }
      if (count < 3)
      {
        continue;
      }
    }
    auto vertex = [&](int64_t ref) -> const ScreenVertex& {
      return ref >= 0 ? this->Screen[ref] : chunk.extra[~ref];
    };
    // Trivial reject outside the viewport or beyond the far plane, signed
    // area (y down: front faces have negative area) and bounds.
    float xmin = std::numeric_limits<float>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
    float zmin = xmin;
    double area = 0;
    for (int k = 0; k < count; ++k)
    {
      const ScreenVertex& a = vertex(local[k]);
      const ScreenVertex& b = vertex(local[(k + 1) % count]);
      area += static_cast<double>(a.x) * b.y - static_cast<double>(b.x) * a.y;
      xmin = std::min(xmin, a.x);
      xmax = std::max(xmax, a.x);
      ymin = std::min(ymin, a.y);
      ymax = std::max(ymax, a.y);
      zmin = std::min(zmin, a.a[kAttrZ]);
    }
    if (xmax < 0 || ymax < 0 || xmin > this->Width || ymin > this->Height || zmin > 1.0f)
    {
      continue;
    }
    if (std::abs(area) * 0.5 < kDegenerateArea || !std::isfinite(area))
    {
      ++chunk.degenerate;
      continue;
    }
    const bool back = area > 0;
    if (back && this->Opt.cullBackFaces)
    {
      continue;
    }
    Vec3f flat;
    if (this->Opt.mode == ShadingMode::Flat && !this->Opt.countCoverage)
    {
      // Face normal: given cell normal, else Newell's method (exact for
      // planar polygons, a least-squares normal otherwise).
      Vec3f N;
      Vec3f centroid;
      Vec3f color;
      for (int k = 0; k < n; ++k)
      {
        const int64_t v = conn[first + k];
        centroid += this->PointOf(v);
        color += this->ColorOf(v);
        const Vec3f a = this->PointOf(v), b = this->PointOf(conn[first + (k + 1) % n]);
        N += Vec3f((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
      }
      if (!this->MeshData.faceNormals.empty())
      {
        N = Vec3f(this->MeshData.faceNormals[3 * p], this->MeshData.faceNormals[3 * p + 1],
          this->MeshData.faceNormals[3 * p + 2]);
      }
      centroid *= 1.0f / n;
      color *= 1.0f / n;
      N = NormalizeOr(N, this->ToEye);
      if (this->Opt.twoSidedLighting && back)
      {
        N = -N;
      }
      flat = this->ShadeAt(centroid, N, color);
    }
    // Gouraud back faces: relight their vertices with flipped normals.
    if (this->Opt.mode == ShadingMode::Gouraud && back && this->Opt.twoSidedLighting &&
      !this->Opt.countCoverage)
    {
      for (int k = 0; k < count; ++k)
      {
        if (local[k] < 0)
        {
          continue; // clipped vertices: keep front lighting (rare, at the near plane)
        }
        const int64_t v = local[k];
        ScreenVertex sv = this->Screen[v];
        const Vec3f c = this->ShadeAt(this->PointOf(v), -this->NormalOf(v), this->ColorOf(v));
        const float scale = sv.a[kAttrInvW];
        sv.a[kAttrFirst] = c.x * scale;
        sv.a[kAttrFirst + 1] = c.y * scale;
        sv.a[kAttrFirst + 2] = c.z * scale;
        chunk.extra.push_back(sv);
        local[k] = ~static_cast<int64_t>(chunk.extra.size() - 1);
      }
    }
    auto addPolygon = [&](const int64_t* refs, int m) {
      RasterPolygon rp;
      rp.firstRef = static_cast<int64_t>(chunk.refs.size());
      rp.count = m;
      rp.backFacing = back;
      rp.flatColor = flat;
      rp.ymin = std::numeric_limits<float>::infinity();
      rp.ymax = -rp.ymin;
      for (int k = 0; k < m; ++k)
      {
        chunk.refs.push_back(refs[k]);
        const float y = vertex(refs[k]).y;
        rp.ymin = std::min(rp.ymin, y);
        rp.ymax = std::max(rp.ymax, y);
      }
      const int firstRow = std::max(0, static_cast<int>(std::ceil(rp.ymin - 0.5f)));
      const int lastRow =
        std::min(this->Height, static_cast<int>(std::ceil(rp.ymax - 0.5f))) - 1;
      if (lastRow < firstRow)
      {
        return;
      }
      const int32_t index = static_cast<int32_t>(chunk.polygons.size());
      chunk.polygons.push_back(rp);
      ++chunk.rasterized;
      for (int b = firstRow / kBandRows; b <= lastRow / kBandRows; ++b)
      {
        chunk.bins[b].push_back(index);
      }
    };
    if (triangulate && count > 3)
    {
      for (int k = 1; k + 1 < count; ++k)
      {
        const int64_t tri[3] = { local[0], local[k], local[k + 1] };
        addPolygon(tri, 3);
      }
    }
    else
    {
      addPolygon(local, count);
    }
  }
}

template <typename PixelFn, typename SpanFn>
void Renderer::ScanConvert(const ScreenVertex* const* verts, int n, int rowBegin, int rowEnd,
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
  const int j0 = std::max(rowBegin, static_cast<int>(std::ceil(ymin - 0.5f)));
  const int j1 = std::min(rowEnd, static_cast<int>(std::ceil(ymax - 0.5f)));
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
      // Slide 5: I_4 = (y_1 - y_4)/(y_1 - y_2) I_2 + (y_4 - y_2)/(y_1 - y_2) I_1.
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
      const int i0 = std::max(0, static_cast<int>(std::ceil(L.x - 0.5f)));
      const int i1 = std::min(this->Width, static_cast<int>(std::ceil(R.x - 0.5f)));
      if (i1 <= i0)
      {
        continue;
      }
      // Slide 6: I_p = (x_5 - x_p)/(x_5 - x_4) I_4 + (x_p - x_4)/(x_5 - x_4) I_5,
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

void Renderer::RasterizeBand(int band, std::vector<float>& depth)
{
  const int rowBegin = band * kBandRows;
  const int rowEnd = std::min(this->Height, rowBegin + kBandRows);
  std::fill(depth.begin(), depth.end(), std::numeric_limits<float>::infinity());
  for (const Chunk& chunk : this->Chunks)
  {
    for (int32_t index : chunk.bins[band])
    {
      this->DrawPolygon(chunk, chunk.polygons[index], rowBegin, rowEnd, depth);
    }
  }
}

void Renderer::DrawPolygon(const Chunk& chunk, const RasterPolygon& poly, int rowBegin,
  int rowEnd, std::vector<float>& depth)
{
  const ScreenVertex* verts[kMaxPolygonVertices];
  int64_t meshIds[kMaxPolygonVertices];
  for (int k = 0; k < poly.count; ++k)
  {
    const int64_t ref = chunk.refs[poly.firstRef + k];
    verts[k] = ref >= 0 ? &this->Screen[ref] : &chunk.extra[~ref];
    meshIds[k] = ref;
  }
  const int W = this->Width;
  float* rgb = this->Rgb.data();
  uint8_t* covered = this->Covered.data();
  auto noSpan = [](int, int) {};

  if (this->Opt.countCoverage)
  {
    uint16_t* coverage = this->Coverage.data();
    this->ScanConvert(verts, poly.count, rowBegin, rowEnd, noSpan, [&](int j, int i, const float*) {
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
    float& d = depth[static_cast<size_t>(j - rowBegin) * W + i];
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
      const Vec3f c = poly.flatColor;
      this->ScanConvert(verts, poly.count, rowBegin, rowEnd, noSpan, [&](int j, int i, const float* a) {
        if (float* out = depthTest(j, i, a))
        {
          out[0] = c.x;
          out[1] = c.y;
          out[2] = c.z;
        }
      });
      return;
    }
    case ShadingMode::Gouraud:
    {
      this->ScanConvert(verts, poly.count, rowBegin, rowEnd, noSpan, [&](int j, int i, const float* a) {
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
      this->DrawTriangleFastPhong(verts, meshIds, poly.backFacing, rowBegin, rowEnd, depth);
      return;
    case ShadingMode::Phong:
    case ShadingMode::CookTorrance:
      break;
  }
  const float flip = (poly.backFacing && this->Opt.twoSidedLighting) ? -1.0f : 1.0f;
  int64_t shaded = 0;
  this->ScanConvert(verts, poly.count, rowBegin, rowEnd, noSpan, [&](int j, int i, const float* a) {
    float* out = depthTest(j, i, a);
    if (!out)
    {
      return;
    }
    const float w = this->Perspective ? 1.0f / a[kAttrInvW] : 1.0f;
    const float* n = a + kAttrFirst + this->NormalSlot;
    // Slide 8: the interpolated normal is renormalized before lighting.
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
  this->Shaded += shaded;
}

void Renderer::DrawTriangleFastPhong(const ScreenVertex* const* verts, const int64_t* meshIds,
  bool back, int rowBegin, int rowEnd, std::vector<float>& depth)
{
  // Bishop & Weimer 1986: L and H constant over the triangle (their
  // assumption of a distant light and viewer), evaluated at its centroid;
  // the normal field is affine in screen space, so this mode always
  // interpolates in screen space.
  float sx[3], sy[3];
  Vec3f normals[3];
  Vec3f centroid;
  for (int k = 0; k < 3; ++k)
  {
    sx[k] = verts[k]->x;
    sy[k] = verts[k]->y;
    // Clipped vertices (negative ids) are rare (near plane); take the
    // normal of the nearest unclipped vertex of this triangle.
    int64_t id = meshIds[k];
    for (int m = 0; m < 3 && id < 0; ++m)
    {
      id = meshIds[m];
    }
    if (id < 0)
    {
      return;
    }
    normals[k] = this->NormalOf(id) * ((back && this->Opt.twoSidedLighting) ? -1.0f : 1.0f);
    centroid += this->PointOf(id) * (1.0f / 3.0f);
  }
  FastPhongTriangle<float> tri;
  tri.Setup(sx, sy, normals);
  const Vec3f V = this->ViewDirection(centroid);
  const int nl = this->Lights.lightCount;
  FastPhongQuadratic<float> diffuseQ[kMaxLights], specularQ[kMaxLights];
  Vec3f irradiance[kMaxLights];
  bool active[kMaxLights];
  const bool specular = this->Mat.model != ReflectanceModel::Lambert && this->Mat.ks > 0.0f;
  for (int l = 0; l < nl; ++l)
  {
    Vec3f L;
    active[l] = LightIncidence(this->Lights.lights[l], centroid, L, irradiance[l]);
    if (!active[l])
    {
      continue;
    }
    diffuseQ[l] = tri.Expand(L, this->Opt.expansion);
    if (specular)
    {
      specularQ[l] = tri.Expand(HalfVector(L, V, tri.Normal(tri.centroidX, tri.centroidY)),
        this->Opt.expansion);
    }
  }
  FastPhongScanline<float> diffuseLine[kMaxLights], specularLine[kMaxLights];
  const Vec3f ambient = this->Mat.ambient * this->Lights.ambientIntensity;
  const float kdOverPi = this->Mat.kd * Fd_Lambert<float>();
  const Vec3f specColor = this->Mat.specularColor * this->Mat.ks;
  int64_t shaded = 0;
  const int W = this->Width;
  float* rgb = this->Rgb.data();
  uint8_t* covered = this->Covered.data();
  this->ScanConvert(
    verts, 3, rowBegin, rowEnd,
    [&](int j, int i0) {
      const float yc = static_cast<float>(j) + 0.5f, xc = static_cast<float>(i0) + 0.5f;
      for (int l = 0; l < nl; ++l)
      {
        diffuseLine[l].Begin(diffuseQ[l], xc, yc);
        if (specular)
        {
          specularLine[l].Begin(specularQ[l], xc, yc);
        }
      }
    },
    [&](int j, int i, const float* a) {
      // Forward differences advance for every pixel of the span, drawn or not.
      float NoL[kMaxLights], NoH[kMaxLights];
      for (int l = 0; l < nl; ++l)
      {
        NoL[l] = diffuseLine[l].Next();
        NoH[l] = specular ? specularLine[l].Next() : 0.0f;
      }
      const float z = a[kAttrZ];
      float& d = depth[static_cast<size_t>(j - rowBegin) * W + i];
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
        Vec3f f = color * kdOverPi;
        if (specular)
        {
          f += specColor * Fs_BlinnPhong(std::min(NoH[l], 1.0f), this->Mat.shininess);
        }
        I += irradiance[l] * f * cl;
      }
      const size_t pix = static_cast<size_t>(j) * W + i;
      covered[pix] = 1;
      rgb[3 * pix] = I.x;
      rgb[3 * pix + 1] = I.y;
      rgb[3 * pix + 2] = I.z;
      ++shaded;
    });
  this->Shaded += shaded;
}

float EncodeSRGB(float v)
{
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

} // namespace

void Mesh::Bounds(double bounds[6]) const
{
  bounds[0] = bounds[2] = bounds[4] = std::numeric_limits<double>::infinity();
  bounds[1] = bounds[3] = bounds[5] = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 2 < this->points.size(); i += 3)
  {
    for (int c = 0; c < 3; ++c)
    {
      bounds[2 * c] = std::min(bounds[2 * c], static_cast<double>(this->points[i + c]));
      bounds[2 * c + 1] = std::max(bounds[2 * c + 1], static_cast<double>(this->points[i + c]));
    }
  }
}

std::vector<float> AreaWeightedNormals(const Mesh& mesh)
{
  const int64_t nv = mesh.NumberOfPoints();
  std::vector<double> sum(static_cast<size_t>(3 * nv), 0.0);
  for (int64_t p = 0; p < mesh.NumberOfPolygons(); ++p)
  {
    const int64_t b = mesh.offsets[p], e = mesh.offsets[p + 1];
    if (e - b < 3)
    {
      continue;
    }
    // Fan cross products: |sum| = 2 x polygon area, direction = normal.
    Vec3<double> n;
    const float* p0 = &mesh.points[3 * mesh.connectivity[b]];
    for (int64_t k = b + 1; k + 1 < e; ++k)
    {
      const float* p1 = &mesh.points[3 * mesh.connectivity[k]];
      const float* p2 = &mesh.points[3 * mesh.connectivity[k + 1]];
      const Vec3<double> u(p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]);
      const Vec3<double> v(p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]);
      n += Cross(u, v);
    }
    for (int64_t k = b; k < e; ++k)
    {
      const int64_t v = mesh.connectivity[k];
      sum[3 * v] += n.x;
      sum[3 * v + 1] += n.y;
      sum[3 * v + 2] += n.z;
    }
  }
  std::vector<float> out(static_cast<size_t>(3 * nv));
  for (int64_t v = 0; v < nv; ++v)
  {
    const Vec3<double> n =
      NormalizeOr(Vec3<double>(sum[3 * v], sum[3 * v + 1], sum[3 * v + 2]), Vec3<double>(0, 0, 1));
    out[3 * v] = static_cast<float>(n.x);
    out[3 * v + 1] = static_cast<float>(n.y);
    out[3 * v + 2] = static_cast<float>(n.z);
  }
  return out;
}

Camera FitCamera(const double bounds[6], double azimuthDeg, double elevationDeg, double zoom,
  double aspect, bool parallel)
{
  Camera cam;
  const Vec3<double> center(
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]));
  const Vec3<double> extent(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);
  double radius = 0.5 * Length(extent);
  if (!(radius > 0))
  {
    radius = 0.5;
  }
  // vtkRenderer::ResetCamera: distance so the bounding sphere fits the view
  // angle (the narrower of the vertical and horizontal angles).
  cam.viewAngle = 30.0;
  double half = 0.5 * cam.viewAngle * kPi<double> / 180.0;
  if (aspect < 1.0)
  {
    half = std::atan(std::tan(half) * aspect);
  }
  const double distance = radius / std::sin(half);
  const double az = azimuthDeg * kPi<double> / 180.0, el = elevationDeg * kPi<double> / 180.0;
  // Start on +z looking down -z with +y up; azimuth about y, then elevation.
  const Vec3<double> dir(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
  cam.focalPoint = center;
  cam.position = center + dir * distance;
  const Vec3<double> right = NormalizeOr(Cross(Vec3<double>(0, 1, 0), dir), Vec3<double>(1, 0, 0));
  cam.viewUp = NormalizeOr(Cross(dir, right), Vec3<double>(0, 1, 0));
  cam.viewAngle /= std::max(zoom, 1e-6);
  cam.parallel = parallel;
  cam.parallelScale = radius / std::max(zoom, 1e-6);
  cam.nearClip = std::max(distance - 1.01 * radius, 1e-3 * distance);
  cam.farClip = distance + 1.01 * radius;
  return cam;
}

std::vector<uint8_t> Image::ToRGB8(DisplayTransform transform) const
{
  std::vector<uint8_t> out(this->rgb.size());
  for (size_t i = 0; i < this->rgb.size(); ++i)
  {
    float v = this->rgb[i];
    v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
    if (transform == DisplayTransform::SRGB)
    {
      v = EncodeSRGB(v);
    }
    out[i] = static_cast<uint8_t>(std::lround(v * 255.0f));
  }
  return out;
}

const char* ModeName(ShadingMode mode)
{
  switch (mode)
  {
    case ShadingMode::Flat:
      return "flat";
    case ShadingMode::Gouraud:
      return "gouraud";
    case ShadingMode::Phong:
      return "phong";
    case ShadingMode::FastPhong:
      return "fast-phong";
    case ShadingMode::CookTorrance:
      return "cook-torrance";
  }
  return "?";
}

bool ParseMode(const std::string& name, ShadingMode& mode)
{
  for (ShadingMode m : { ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong,
         ShadingMode::FastPhong, ShadingMode::CookTorrance })
  {
    if (name == ModeName(m))
    {
      mode = m;
      return true;
    }
  }
  return false;
}

Image Render(const Mesh& mesh, const Camera& camera, const Lighting<float>& lighting,
  const Material<float>& material, const RenderOptions& options, RenderStats* stats)
{
  if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
  {
    throw std::invalid_argument("image size must be between 1x1 and 16384x16384");
  }
  if (options.ssaa < 1 || options.ssaa > 8)
  {
    throw std::invalid_argument("supersampling factor must be 1 to 8");
  }
  if (static_cast<double>(options.width) * options.height * options.ssaa * options.ssaa > 4e8)
  {
    throw std::invalid_argument("image size times supersampling exceeds 4e8 samples");
  }
  if (!IsFinite(camera.position) || !IsFinite(camera.focalPoint) || !IsFinite(camera.viewUp) ||
    !(camera.viewAngle > 0 && camera.viewAngle < 180) || !(camera.nearClip > 0) ||
    !(camera.farClip > camera.nearClip) || !(camera.parallelScale > 0))
  {
    throw std::invalid_argument("invalid camera (non-finite, view angle outside (0,180), or "
                                "bad clipping range)");
  }
  if (options.mode == ShadingMode::FastPhong && material.model == ReflectanceModel::CookTorrance)
  {
    throw std::invalid_argument(
      "fast-phong evaluates (N.L) and (N.H)^n quadratics: use a lambert, phong or blinn-phong "
      "material");
  }
  if (lighting.lightCount < 0 || lighting.lightCount > kMaxLights)
  {
    throw std::invalid_argument("between 0 and 8 lights");
  }
  Material<float> effective = material;
  if (options.mode == ShadingMode::CookTorrance)
  {
    effective.model = ReflectanceModel::CookTorrance;
  }
  Renderer renderer(mesh, camera, lighting, effective, options);
  return renderer.Run(stats);
}

} // namespace shadinglab::cpu
