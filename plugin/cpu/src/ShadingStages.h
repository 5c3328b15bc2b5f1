// SPDX-License-Identifier: BSD-3-Clause
// The per-mode shading stages of the software renderer, mirroring the GLSL
// vertex/fragment split of the GL renderer: each stage says which
// attributes its vertices carry (Layout), computes them (Vertex: the vertex
// shader), may prepare a polygon once (BeginPolygon) and shades the pixels
// the rasterizer hands it (DrawPart: the fragment shader). The rasterizer
// (Rasterizer.h) is a template over the stage and never branches on the
// mode; the renderer picks the stage once per frame.
//
// What is evaluated is the model's (Shade, BrdfFromCosines); a stage only
// decides where: docs/model.md section 2. Fast Phong's stage, the longest,
// has its own file (FastPhongStage.h).
#pragma once

#include "Frame.h"
#include "Geometry.h"
#include "IncrementalScan.h"

namespace shadinglab::cpu
{

using raster::kAttrFirst;
using raster::kAttrInvW;
using raster::kAttrZ;
using raster::ScanConvert;
using raster::ScreenVertex;
using raster::ThreadState;

/// What every stage shares: no per-polygon state, no relighting, the
/// frame's triangulation choice.
struct StageBase
{
  const Frame& F;

  struct Polygon
  {
    int64_t id;
    bool back;
    /// A triangle's one pixel, where binning found it (Rasterizer::DrawInBand).
    raster::OnePixel onePixel;
  };
  Polygon BeginPolygon(int64_t p,
    bool back,
    const ScreenVertex**,
    const int64_t*,
    int,
    ScreenVertex*) const
  {
    return { p, back, {} };
  }
  bool Triangulates() const { return this->F.Opt.polygons == render::PolygonHandling::Triangulate; }
  /// Polygon p (its last vertex `lastVertex`) is drawn soon: what the stage reads
  /// of it beyond its screen vertices may be fetched.
  void PrefetchPolygon(int64_t, int64_t) const {}
  /// After the thread's last polygon.
  void Finish(ThreadState&) const {}

  /// raster::ScanConvert over this frame's width and attribute slots, or
  /// the lecture's incremental scan (IncrementalScan.h) when asked.
  template<typename SpanFn, typename PixelFn>
  void Scan(const ScreenVertex* const* verts,
    int n,
    int rowBegin,
    int rowEnd,
    raster::OnePixel onePixel,
    SpanFn&& beginSpan,
    PixelFn&& pixel) const
  {
    if (F.Trace && F.Trace->row >= rowBegin && F.Trace->row < rowEnd)
    {
      this->ScanTraced(verts, n, rowBegin, rowEnd, beginSpan, pixel);
      return;
    }
    this->ScanWith(verts, n, rowBegin, rowEnd, beginSpan, pixel, nullptr, onePixel);
  }

  template<typename SpanFn, typename PixelFn>
  void ScanWith(const ScreenVertex* const* verts,
    int n,
    int rowBegin,
    int rowEnd,
    SpanFn&& beginSpan,
    PixelFn&& pixel,
    raster::SpanTrace* spans,
    raster::OnePixel onePixel = {}) const
  {
    if (F.Opt.scan == render::ScanConversion::Incremental)
    {
      if (F.Opt.scanPrecision == render::ScanPrecision::Double)
      {
        raster::ScanIncremental<double>(
          F.Width, F.NumAttributes, verts, n, rowBegin, rowEnd, beginSpan, pixel, spans);
      }
      else
      {
        raster::ScanIncremental<float>(
          F.Width, F.NumAttributes, verts, n, rowBegin, rowEnd, beginSpan, pixel, spans);
      }
      return;
    }
    ScanConvert(
      F.Width, F.NumAttributes, verts, n, rowBegin, rowEnd, beginSpan, pixel, spans, onePixel);
  }

  /// Scan, recording the traced row (Frame::Trace): the span ends the scan
  /// met, and each pixel's attributes as the stage receives them (1/w
  /// divided out). Only the band holding the row comes here.
  template<typename SpanFn, typename PixelFn>
  void ScanTraced(const ScreenVertex* const* verts,
    int n,
    int rowBegin,
    int rowEnd,
    SpanFn&& beginSpan,
    PixelFn&& pixel) const
  {
    render::ScanTrace& trace = *F.Trace;
    const int na = F.NumAttributes;
    raster::SpanTrace spans{ trace.row,
      [&](float xl, const float* al, float xr, const float* ar)
      {
        render::TracedSpan span;
        span.xLeft = xl;
        span.xRight = xr;
        const float wl = F.AttributeScale(al), wr = F.AttributeScale(ar);
        for (int k = 0; k < na; ++k)
        {
          span.left.push_back(al[kAttrFirst + k] * wl);
          span.right.push_back(ar[kAttrFirst + k] * wr);
        }
        trace.spans.push_back(std::move(span));
      } };
    this->ScanWith(verts, n, rowBegin, rowEnd, beginSpan,
      [&](int j, int i, const float* a)
      {
        if (j == trace.row)
        {
          render::TracedPixel p;
          p.i = i;
          const float w = F.AttributeScale(a);
          for (int k = 0; k < na; ++k)
          {
            p.attributes.push_back(a[kAttrFirst + k] * w);
          }
          trace.pixels.push_back(std::move(p));
        }
        pixel(j, i, a);
      },
      &spans);
  }
  /// The same, for stages with nothing to do at the start of a span.
  template<typename PixelFn>
  void Scan(const ScreenVertex* const* verts, int n, int rowBegin, int rowEnd,
    raster::OnePixel onePixel, PixelFn&& pixel) const
  {
    this->Scan(verts, n, rowBegin, rowEnd, onePixel, [](int, int) {}, pixel);
  }
};

/// The fill-rule check (RenderOptions::countCoverage): counts polygons per
/// pixel, no depth test, no shading.
struct CoverageStage : StageBase
{
  static void Layout(Frame&) {}
  void Vertex(int64_t, float*) const {}
  bool Triangulates() const
  {
    return StageBase::Triangulates() || this->F.Opt.mode == render::ShadingMode::FastPhong;
  }
  void DrawPart(const ScreenVertex* const* verts,
    const int64_t*,
    int n,
    Polygon& poly,
    int rowBegin,
    int rowEnd,
    ThreadState&) const
  {
    this->Scan(verts, n, rowBegin, rowEnd, poly.onePixel,
      [&](int j, int i, const float*)
      {
        const size_t pix = static_cast<size_t>(j) * F.Width + i;
        ++F.Coverage[pix];
        F.Covered[pix] = 1;
      });
  }
};

/// Newell's area vector of polygon p (mesh::NewellAreaVector in float, from
/// the mesh's points): the flat stage's face normal before normalizing.
inline Vec3f AreaVectorOf(const render::Mesh& mesh, int64_t p)
{
  const int64_t first = mesh.offsets[p];
  const int n = static_cast<int>(mesh.offsets[p + 1] - first);
  return mesh::NewellAreaVector<float>(n,
    [&](int64_t k)
    {
      const float* q = &mesh.points[3 * mesh.connectivity[first + k]];
      return Vec3f(q[0], q[1], q[2]);
    });
}

/// Flat (docs/model.md eq. 2.1): one intensity per polygon, computed when
/// its first pixel passes the depth test (hidden polygons are never lit).
/// A polygon of at most kQueuedArea px has its pixels shaded in SIMD
/// batches instead (WideShading.h, as Phong's), every one from the
/// polygon's normal and point: the same intensity, at a few ns a pixel
/// where a polygon's own Shade calls cost tens.
struct FlatStage : StageBase
{
  struct Polygon : StageBase::Polygon
  {
    bool queued = false; ///< small: pixels go to the SIMD queue
    bool valid = false;  ///< the fields below are computed
    Vec3f color;  ///< the polygon's intensity; with point scalars I(0); queued: rho
    Vec3f perRho; ///< with point scalars: I(1) - I(0), which rho multiplies
    Vec3f N, P;   ///< queued: where the model is evaluated
  };

  /// Screen area (px) up to which a polygon's pixels are queued. Measured
  /// on ParaView's 1M sphere (Blinn-Phong, one light, AVX2): a queued
  /// pixel costs ~9 ns, one scalar Shade call ~30 ns, and a polygon makes
  /// one call (two with colour by point data). A polygon of area A covers
  /// about A pixels, so queuing wins up to ~3-6 px; 4 lies between.
  static constexpr double kQueuedArea = 4.0;

  /// Colour by point data: the scalar is interpolated and mapped per pixel
  /// (as the GPU's texture lookup), the lighting stays the polygon's.
  static void Layout(Frame& f)
  {
    if (f.PointScalars())
    {
      f.ScalarSlot = 0;
      f.NumAttributes = 1;
    }
    f.Pixels = { &f.Mat, &f.Lights, f.Eye, f.ToEye, f.Cam.parallel, true, true };
  }
  void Vertex(int64_t v, float* raw) const
  {
    if (F.ScalarSlot >= 0)
    {
      raw[0] = F.MeshData->scalars[v];
    }
  }
  Polygon BeginPolygon(int64_t p,
    bool back,
    const ScreenVertex** verts,
    const int64_t*,
    int count,
    ScreenVertex*) const
  {
    Polygon poly;
    poly.id = p;
    poly.back = back;
    poly.queued = std::abs(raster::TwiceSignedArea(verts, count)) * 0.5 <= kQueuedArea;
    return poly;
  }

  /// PolygonColor's reads: the area vector and the provoking vertex's
  /// point (a cache miss each on a large mesh: ~1% of a flat frame of
  /// ParaView's 1M sphere).
  void PrefetchPolygon(int64_t p, int64_t lastVertex) const
  {
    if (F.AreaVectors)
    {
      raster::Prefetch(F.AreaVectors + 3 * p);
    }
    raster::Prefetch(&F.MeshData->points[3 * lastVertex]);
  }

  /// The polygon's unit normal (facing the viewer when two-sided lighting
  /// lights its back) and the point it is lit at. Face normal: given cell
  /// normal, else Newell's method (exact for planar polygons, a
  /// least-squares normal otherwise). Lit at the polygon's last vertex,
  /// OpenGL's provoking vertex, with its colour: the GPU mapper does the
  /// same, so the two agree pixel for pixel on triangle meshes (the
  /// lecture's flat shading assumes distant lights and viewer, where the
  /// choice of point does not matter).
  void Geometry(const Polygon& poly, Vec3f& N, int64_t& provoking) const
  {
    const int64_t p = poly.id;
    const auto& conn = F.MeshData->connectivity;
    const int64_t first = F.MeshData->offsets[p];
    const int n = static_cast<int>(F.MeshData->offsets[p + 1] - first);
    if (!F.MeshData->faceNormals.empty())
    {
      const float* fn = &F.MeshData->faceNormals[3 * p];
      N = Vec3f(fn[0], fn[1], fn[2]);
    }
    else if (F.AreaVectors)
    {
      const float* a = F.AreaVectors + 3 * p; // AreaVectorsOf: the same sums, made once
      N = Vec3f(a[0], a[1], a[2]);
    }
    else
    {
      N = AreaVectorOf(*F.MeshData, p);
    }
    N = NormalizeOr(N, F.ToEye);
    if (F.Opt.twoSidedLighting && poly.back)
    {
      N = -N;
    }
    provoking = conn[first + n - 1];
  }

  /// Fills poly.color (and poly.perRho with point scalars: eq. 1.1 is
  /// affine in rho, I(rho) = I(0) + rho (I(1) - I(0))); queued, poly.N,
  /// poly.P and poly.color = rho.
  void PolygonColor(Polygon& poly) const
  {
    Vec3f N;
    int64_t provoking;
    this->Geometry(poly, N, provoking);
    const Vec3f P = F.PointOf(provoking);
    const Vec3f rho = F.CellScalars() ? F.CellColorOf(poly.id) : F.ColorOf(provoking);
    if (poly.queued)
    {
      poly.N = N;
      poly.P = P;
      poly.color = rho;
      return;
    }
    if (F.PointScalars())
    {
      poly.color = F.ShadeAt(P, N, Vec3f(0, 0, 0));
      poly.perRho = F.ShadeAt(P, N, Vec3f(1, 1, 1)) - poly.color;
      return;
    }
    poly.color = F.ShadeAt(P, N, rho);
  }

  void DrawPart(const ScreenVertex* const* verts,
    const int64_t*,
    int n,
    Polygon& poly,
    int rowBegin,
    int rowEnd,
    ThreadState& state) const
  {
    PixelQueue& q = state.queue;
    this->Scan(verts, n, rowBegin, rowEnd, poly.onePixel,
      [&](int j, int i, const float* a)
      {
        float* out = F.DepthTest(j, i, a, state);
        if (!out)
        {
          return;
        }
        if (!poly.valid)
        {
          this->PolygonColor(poly);
          poly.valid = true;
        }
        if (poly.queued)
        {
          const Vec3f rho =
            F.ScalarSlot >= 0 ? F.ScalarColor(a[kAttrFirst] * F.AttributeScale(a)) : poly.color;
          if (q.Push(poly.N, poly.P, rho, out))
          {
            ShadeQueue(F.Pixels, q);
          }
          return;
        }
        if (q.count > 0)
        {
          // Queued pixels are written when shaded: before this write, so
          // that a pixel drawn twice keeps its last fragment's colour.
          ShadeQueue(F.Pixels, q);
        }
        Vec3f c = poly.color;
        if (F.ScalarSlot >= 0)
        {
          c += F.ScalarColor(a[kAttrFirst] * F.AttributeScale(a)) * poly.perRho;
        }
        out[0] = c.x;
        out[1] = c.y;
        out[2] = c.z;
      });
  }

  void Finish(ThreadState& state) const { ShadeQueue(F.Pixels, state.queue); }
};

/// Gouraud (eq. 2.3-2.4): the model at the vertices, the colour interpolated.
struct GouraudStage : StageBase
{
  /// Colour by data (point or cell scalars): the vertex carries I(0) and
  /// I(1) - I(0) (eq. 1.1 is affine in rho) and rho is applied per pixel,
  /// mapped from the interpolated scalar or the polygon's, as the GPU does.
  static void Layout(Frame& f)
  {
    f.NumAttributes = f.Map ? 6 : 3;
    if (f.PointScalars())
    {
      f.ScalarSlot = 6;
      f.NumAttributes = 7;
    }
    // VertexBatch's lighting goes through the pixel kernel: a vertex is a
    // "pixel" with its normal, position and colour.
    f.Pixels = { &f.Mat, &f.Lights, f.Eye, f.ToEye, f.Cam.parallel, true, true };
  }

  /// The vertex's lit colour, or with colour by data I(0) and I(1) - I(0).
  void Light(int64_t v, const Vec3f& N, float* raw) const
  {
    const Vec3f P = F.PointOf(v);
    if (!F.Map)
    {
      const Vec3f c = F.ShadeAt(P, N, F.ColorOf(v));
      raw[0] = c.x;
      raw[1] = c.y;
      raw[2] = c.z;
      return;
    }
    const Vec3f i0 = F.ShadeAt(P, N, Vec3f(0, 0, 0));
    const Vec3f i1 = F.ShadeAt(P, N, Vec3f(1, 1, 1)) - i0;
    const float v6[6] = { i0.x, i0.y, i0.z, i1.x, i1.y, i1.z };
    std::copy(v6, v6 + 6, raw);
  }

  void Vertex(int64_t v, float* raw) const
  {
    this->Light(v, F.NormalOf(v), raw);
    if (F.ScalarSlot >= 0)
    {
      raw[F.ScalarSlot] = F.MeshData->scalars[v];
    }
  }

  /// Vertex() for count <= kVertexBatch vertices, raw[k] for ids[k]: the
  /// model in SIMD batches (WideShading.h), as Phong's pixels, where
  /// Vertex() lights one vertex at a time (two Shade calls each with
  /// colour by data: Gouraud took longer than Phong on ParaView's 1M
  /// sphere, 43.5 ms against 39.3).
  static constexpr int kVertexBatch = PixelQueue::kCapacity / 2;
  void VertexBatch(const int64_t* ids, int count, float (*raw)[raster::kMaxAttributes]) const
  {
    PixelQueue q;
    float lit1[kVertexBatch][3]; // I(1), with colour by data
    // At most kCapacity entries (two a vertex): the queue never fills early.
    auto queue = [&](int64_t v, const Vec3f& c, float* out)
    { q.Push(F.NormalOf(v), F.PointOf(v), c, out); };
    for (int k = 0; k < count; ++k)
    {
      if (!F.Map)
      {
        queue(ids[k], F.ColorOf(ids[k]), raw[k]);
        continue;
      }
      // eq. 1.1 is affine in rho: I(0), and I(1) to subtract from it below.
      queue(ids[k], Vec3f(0, 0, 0), raw[k]);
      queue(ids[k], Vec3f(1, 1, 1), lit1[k]);
    }
    ShadeQueue(F.Pixels, q);
    for (int k = 0; k < count; ++k)
    {
      if (F.Map)
      {
        for (int c = 0; c < 3; ++c)
        {
          raw[k][3 + c] = lit1[k][c] - raw[k][c];
        }
      }
      if (F.ScalarSlot >= 0)
      {
        raw[k][F.ScalarSlot] = F.MeshData->scalars[ids[k]];
      }
    }
  }

  /// Back faces (two-sided lighting): their vertices relit with flipped
  /// normals, into `relit`.
  Polygon BeginPolygon(int64_t p,
    bool back,
    const ScreenVertex** verts,
    const int64_t* ids,
    int count,
    ScreenVertex* relit) const
  {
    if (back && F.Opt.twoSidedLighting)
    {
      for (int k = 0; k < count; ++k)
      {
        relit[k] = *verts[k];
        const int64_t v = ids[k];
        float lit[6];
        this->Light(v, -F.NormalOf(v), lit);
        const float scale = relit[k].a[kAttrInvW];
        for (int c = 0; c < (F.Map ? 6 : 3); ++c)
        {
          relit[k].a[kAttrFirst + c] = lit[c] * scale;
        }
        verts[k] = &relit[k];
      }
    }
    return { p, back, {} };
  }

  void DrawPart(const ScreenVertex* const* verts,
    const int64_t*,
    int n,
    Polygon& poly,
    int rowBegin,
    int rowEnd,
    ThreadState& state) const
  {
    const Vec3f cellRho = F.CellScalars() ? F.CellColorOf(poly.id) : Vec3f();
    this->Scan(verts, n, rowBegin, rowEnd, poly.onePixel,
      [&](int j, int i, const float* a)
      {
        if (float* out = F.DepthTest(j, i, a, state))
        {
          const float w = F.AttributeScale(a);
          const float* c = a + kAttrFirst;
          Vec3f I(c[0] * w, c[1] * w, c[2] * w);
          if (F.Map)
          {
            const Vec3f rho = F.ScalarSlot >= 0 ? F.ScalarColor(c[F.ScalarSlot] * w) : cellRho;
            I += rho * Vec3f(c[3] * w, c[4] * w, c[5] * w);
          }
          out[0] = I.x;
          out[1] = I.y;
          out[2] = I.z;
        }
      });
  }
};

/// Writes a vertex's normal, position and colour into the slots the layout
/// assigned (Phong and fast Phong).
inline void WriteVertexSlots(const Frame& F, int64_t v, float* raw)
{
  if (F.NormalSlot >= 0)
  {
    const Vec3f n = F.NormalOf(v);
    raw[F.NormalSlot] = n.x;
    raw[F.NormalSlot + 1] = n.y;
    raw[F.NormalSlot + 2] = n.z;
  }
  if (F.PositionSlot >= 0)
  {
    const Vec3f p = F.PointOf(v);
    raw[F.PositionSlot] = p.x;
    raw[F.PositionSlot + 1] = p.y;
    raw[F.PositionSlot + 2] = p.z;
  }
  if (F.ColorSlot >= 0)
  {
    const Vec3f c = F.ColorOf(v);
    raw[F.ColorSlot] = c.x;
    raw[F.ColorSlot + 1] = c.y;
    raw[F.ColorSlot + 2] = c.z;
  }
  if (F.ScalarSlot >= 0)
  {
    raw[F.ScalarSlot] = F.MeshData->scalars[v];
  }
}

/// Phong (eq. 2.5): normals (and positions, colours) interpolated, the
/// normal renormalized, the model per pixel.
struct PhongStage : StageBase
{
  static void Layout(Frame& f)
  {
    int slot = 0;
    f.NormalSlot = slot;
    slot += 3;
    bool pointLight = false;
    for (int j = 0; j < f.Lights.lightCount; ++j)
    {
      pointLight |= f.Lights.lights[j].type == LightType::Point;
    }
    // The world position is only needed for a local viewer or point lights.
    if (!f.Cam.parallel || pointLight)
    {
      f.PositionSlot = slot;
      slot += 3;
    }
    if (f.PointScalars())
    {
      // Interpolate Scalars Before Mapping: the scalar, mapped per pixel.
      f.ScalarSlot = slot;
      slot += 1;
    }
    else if (!f.MeshData->colors.empty() && !f.Map)
    {
      f.ColorSlot = slot;
      slot += 3;
    }
    f.NumAttributes = slot;
    f.Pixels = { &f.Mat, &f.Lights, f.Eye, f.ToEye, f.Cam.parallel, f.PositionSlot >= 0,
      f.HasColor() };
  }

  void Vertex(int64_t v, float* raw) const { WriteVertexSlots(F, v, raw); }

  /// Depth test per pixel; the survivors' attributes are queued and shaded
  /// in SIMD batches (WideShading.h) when the queue is full and in Finish.
  void DrawPart(const ScreenVertex* const* verts,
    const int64_t*,
    int n,
    Polygon& poly,
    int rowBegin,
    int rowEnd,
    ThreadState& state) const
  {
    const float flip = (poly.back && F.Opt.twoSidedLighting) ? -1.0f : 1.0f;
    const Vec3f cellRho = F.CellScalars() ? F.CellColorOf(poly.id) : Vec3f();
    int64_t shaded = 0;
    PixelQueue& q = state.queue;
    this->Scan(verts, n, rowBegin, rowEnd, poly.onePixel,
      [&](int j, int i, const float* a)
      {
        float* out = F.DepthTest(j, i, a, state);
        if (!out)
        {
          return;
        }
        const float w = F.AttributeScale(a);
        const float* nrm = a + kAttrFirst + F.NormalSlot;
        const float s = w * flip;
        const Vec3f normal(nrm[0] * s, nrm[1] * s, nrm[2] * s);
        Vec3f P, color;
        if (F.PositionSlot >= 0)
        {
          const float* p = a + kAttrFirst + F.PositionSlot;
          P = Vec3f(p[0] * w, p[1] * w, p[2] * w);
        }
        if (F.ColorSlot >= 0)
        {
          const float* c = a + kAttrFirst + F.ColorSlot;
          color = Vec3f(c[0] * w, c[1] * w, c[2] * w);
        }
        else if (F.Map)
        {
          color = F.ScalarSlot >= 0 ? F.ScalarColor(a[kAttrFirst + F.ScalarSlot] * w) : cellRho;
        }
        if (q.Push(normal, P, color, out))
        {
          ShadeQueue(F.Pixels, q);
        }
        ++shaded;
      });
    state.shaded += shaded;
  }

  void Finish(ThreadState& state) const { ShadeQueue(F.Pixels, state.queue); }
};

} // namespace shadinglab::cpu
