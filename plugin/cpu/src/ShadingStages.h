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
  };
  Polygon BeginPolygon(int64_t p,
    bool back,
    const ScreenVertex**,
    const int64_t*,
    int,
    ScreenVertex*) const
  {
    return { p, back };
  }
  bool Triangulates() const { return this->F.Opt.polygons == render::PolygonHandling::Triangulate; }
  /// After the thread's last polygon.
  void Finish(ThreadState&) const {}

  /// raster::ScanConvert over this frame's width and attribute slots.
  template<typename SpanFn, typename PixelFn>
  void Scan(const ScreenVertex* const* verts,
    int n,
    int rowBegin,
    int rowEnd,
    SpanFn&& beginSpan,
    PixelFn&& pixel) const
  {
    ScanConvert(F.Width, F.NumAttributes, verts, n, rowBegin, rowEnd, beginSpan, pixel);
  }
  /// The same, for stages with nothing to do at the start of a span.
  template<typename PixelFn>
  void Scan(const ScreenVertex* const* verts, int n, int rowBegin, int rowEnd, PixelFn&& pixel) const
  {
    this->Scan(verts, n, rowBegin, rowEnd, [](int, int) {}, pixel);
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
    Polygon&,
    int rowBegin,
    int rowEnd,
    ThreadState&) const
  {
    this->Scan(verts, n, rowBegin, rowEnd,
      [&](int j, int i, const float*)
      {
        const size_t pix = static_cast<size_t>(j) * F.Width + i;
        ++F.Coverage[pix];
        F.Covered[pix] = 1;
      });
  }
};

/// Flat (docs/model.md eq. 2.1): one intensity per polygon, computed when
/// its first pixel passes the depth test (hidden polygons are never lit).
struct FlatStage : StageBase
{
  struct Polygon
  {
    int64_t id;
    bool back;
    bool valid = false;
    Vec3f color;
  };

  static void Layout(Frame&) {}
  void Vertex(int64_t, float*) const {}
  Polygon BeginPolygon(int64_t p,
    bool back,
    const ScreenVertex**,
    const int64_t*,
    int,
    ScreenVertex*) const
  {
    return { p, back, false, Vec3f() };
  }

  Vec3f PolygonColor(int64_t p, bool back) const
  {
    // Face normal: given cell normal, else Newell's method (exact for planar
    // polygons, a least-squares normal otherwise). Lit at the polygon's last
    // vertex, OpenGL's provoking vertex, with its colour: the GPU mapper does
    // the same, so the two agree pixel for pixel on triangle meshes (the
    // lecture's flat shading assumes distant lights and viewer, where the
    // choice of point does not matter).
    const auto& conn = F.MeshData->connectivity;
    const int64_t first = F.MeshData->offsets[p];
    const int n = static_cast<int>(F.MeshData->offsets[p + 1] - first);
    Vec3f N = mesh::NewellAreaVector<float>(n, [&](int64_t k) { return F.PointOf(conn[first + k]); });
    if (!F.MeshData->faceNormals.empty())
    {
      const float* fn = &F.MeshData->faceNormals[3 * p];
      N = Vec3f(fn[0], fn[1], fn[2]);
    }
    N = NormalizeOr(N, F.ToEye);
    if (F.Opt.twoSidedLighting && back)
    {
      N = -N;
    }
    const int64_t provoking = conn[first + n - 1];
    return F.ShadeAt(F.PointOf(provoking), N, F.ColorOf(provoking));
  }

  void DrawPart(const ScreenVertex* const* verts,
    const int64_t*,
    int n,
    Polygon& poly,
    int rowBegin,
    int rowEnd,
    ThreadState& state) const
  {
    this->Scan(verts, n, rowBegin, rowEnd,
      [&](int j, int i, const float* a)
      {
        if (float* out = F.DepthTest(j, i, a, state))
        {
          if (!poly.valid)
          {
            poly.color = this->PolygonColor(poly.id, poly.back);
            poly.valid = true;
          }
          out[0] = poly.color.x;
          out[1] = poly.color.y;
          out[2] = poly.color.z;
        }
      });
  }
};

/// Gouraud (eq. 2.3-2.4): the model at the vertices, the colour interpolated.
struct GouraudStage : StageBase
{
  static void Layout(Frame& f) { f.NumAttributes = 3; }

  void Vertex(int64_t v, float* raw) const
  {
    const Vec3f c = F.ShadeAt(F.PointOf(v), F.NormalOf(v), F.ColorOf(v));
    raw[0] = c.x;
    raw[1] = c.y;
    raw[2] = c.z;
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
        const Vec3f c = F.ShadeAt(F.PointOf(v), -F.NormalOf(v), F.ColorOf(v));
        const float scale = relit[k].a[kAttrInvW];
        relit[k].a[kAttrFirst] = c.x * scale;
        relit[k].a[kAttrFirst + 1] = c.y * scale;
        relit[k].a[kAttrFirst + 2] = c.z * scale;
        verts[k] = &relit[k];
      }
    }
    return { p, back };
  }

  void DrawPart(const ScreenVertex* const* verts,
    const int64_t*,
    int n,
    Polygon&,
    int rowBegin,
    int rowEnd,
    ThreadState& state) const
  {
    this->Scan(verts, n, rowBegin, rowEnd,
      [&](int j, int i, const float* a)
      {
        if (float* out = F.DepthTest(j, i, a, state))
        {
          const float w = F.AttributeScale(a);
          out[0] = a[kAttrFirst] * w;
          out[1] = a[kAttrFirst + 1] * w;
          out[2] = a[kAttrFirst + 2] * w;
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
    if (!f.MeshData->colors.empty())
    {
      f.ColorSlot = slot;
      slot += 3;
    }
    f.NumAttributes = slot;
    f.Pixels = { &f.Mat, &f.Lights, f.Eye, f.ToEye, f.Cam.parallel, f.PositionSlot >= 0,
      f.ColorSlot >= 0 };
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
    int64_t shaded = 0;
    PixelQueue& q = state.queue;
    this->Scan(verts, n, rowBegin, rowEnd,
      [&](int j, int i, const float* a)
      {
        float* out = F.DepthTest(j, i, a, state);
        if (!out)
        {
          return;
        }
        const float w = F.AttributeScale(a);
        const int k = q.count;
        const float* nrm = a + kAttrFirst + F.NormalSlot;
        const float s = w * flip;
        q.nx[k] = nrm[0] * s;
        q.ny[k] = nrm[1] * s;
        q.nz[k] = nrm[2] * s;
        if (F.PositionSlot >= 0)
        {
          const float* p = a + kAttrFirst + F.PositionSlot;
          q.px[k] = p[0] * w;
          q.py[k] = p[1] * w;
          q.pz[k] = p[2] * w;
        }
        if (F.ColorSlot >= 0)
        {
          const float* c = a + kAttrFirst + F.ColorSlot;
          q.cr[k] = c[0] * w;
          q.cg[k] = c[1] * w;
          q.cb[k] = c[2] * w;
        }
        q.out[k] = out;
        if (++q.count == PixelQueue::kCapacity)
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
