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
// decides where: docs/model.md section 2.
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

/// Fast Phong (Bishop & Weimer 1986; eq. 2.6-2.9): triangles only, the
/// cosines by Taylor quadratics stepped with forward differences, shaded
/// through BrdfFromCosines.
struct FastPhongStage : StageBase
{
  static void Layout(Frame& f)
  {
    if (!f.MeshData->colors.empty())
    {
      f.ColorSlot = 0;
      f.NumAttributes = 3;
    }
    f.PowerTable.Build(f.Mat.shininess);
    f.FastPhongMinCos = static_cast<float>(
      std::cos(std::clamp(f.Opt.fastPhongMaxSpread, 0.0, 180.0) * kPi<double> / 180.0));
  }

  void Vertex(int64_t v, float* raw) const { WriteVertexSlots(F, v, raw); }
  bool Triangulates() const { return true; }

  void DrawPart(const ScreenVertex* const* verts,
    const int64_t* meshIds,
    int n,
    Polygon& poly,
    int rowBegin,
    int rowEnd,
    ThreadState& state) const
  {
    // The model is fixed per frame: one pixel loop per model, so the
    // compiler folds BrdfFromCosines' choice and the unused quadratics.
    // Without a specular term every model is Lambert's here.
    switch (F.Mat.ks > 0.0f ? F.Mat.model : ReflectanceModel::Lambert)
    {
      case ReflectanceModel::Phong:
        return this->Draw<ReflectanceModel::Phong>(
          verts, meshIds, n, poly, rowBegin, rowEnd, state);
      case ReflectanceModel::BlinnPhong:
        return this->Draw<ReflectanceModel::BlinnPhong>(
          verts, meshIds, n, poly, rowBegin, rowEnd, state);
      default:
        return this->Draw<ReflectanceModel::Lambert>(
          verts, meshIds, n, poly, rowBegin, rowEnd, state);
    }
  }

  template<ReflectanceModel Model>
  void Draw(const ScreenVertex* const* verts,
    const int64_t* meshIds,
    int,
    Polygon& poly,
    int rowBegin,
    int rowEnd,
    ThreadState& state) const
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
      normals[k] = F.NormalOf(meshIds[k]) * ((poly.back && F.Opt.twoSidedLighting) ? -1.0f : 1.0f);
      centroid += F.PointOf(meshIds[k]) * (1.0f / 3.0f);
    }
    // The triangle's setup is done lazily, on its first span with pixels:
    // most triangles of a million-triangle mesh cover no pixel centre at all.
    FastPhongTriangle<float> tri;
    Vec3f Ls[kMaxLights], Hs[kMaxLights], V, N0;
    float LoV[kMaxLights];
    const int nl = F.Lights.lightCount;
    // The quadratics each model needs: N.L always; N.H for Blinn-Phong; N.V
    // for Phong, whose R.V = 2 (N.L)(N.V) - L.V (docs/model.md eq. 2.8).
    constexpr bool halfVector = Model == ReflectanceModel::BlinnPhong;
    constexpr bool viewCosine = Model == ReflectanceModel::Phong;
    FastPhongQuadratic<float> diffuseQ[kMaxLights], specularQ[kMaxLights], viewQ;
    Vec3f irradiance[kMaxLights];
    bool active[kMaxLights];
    bool ready = false;
    bool perPixelRule = true;
    auto setup = [&]()
    {
      ready = true;
      tri.Setup(sx, sy, normals);
      // L, V and H are taken at the expansion point's surface position.
      const Vec3f expansionPoint =
        F.Opt.expansion == ExpansionPoint::Vertex ? F.PointOf(meshIds[2]) : centroid;
      V = F.ViewDirection(expansionPoint);
      // Bishop & Weimer's expansion holds for small normal variation: where
      // the interpolated normal turns more than the spread limit away from the
      // expansion point's, the pixel is evaluated exactly (the same affine
      // normal, renormalized), so no Taylor blow-up reaches a pixel. The same
      // per-pixel rule as the GPU (FastPhongTriangle::WithinSpread).
      N0 = F.Opt.expansion == ExpansionPoint::Vertex ? tri.Normal(tri.vertexX, tri.vertexY)
                                                     : tri.Normal(tri.centroidX, tri.centroidY);
      // Inside a cone of half-angle under 90 degrees about N0, every convex
      // combination of the vertex normals (every interpolated normal) stays
      // in the cone: when all three vertices are within the limit, so is
      // every pixel, and the per-pixel test is skipped (same result).
      perPixelRule = !(F.FastPhongMinCos > 0.0f);
      for (int k = 0; k < 3 && !perPixelRule; ++k)
      {
        perPixelRule = !tri.WithinSpread(N0, sx[k], sy[k], F.FastPhongMinCos);
      }
      const Vec3f unit2 = NormalizeOr(normals[2], F.ToEye);
      if (viewCosine)
      {
        viewQ = tri.Expand(V, F.Opt.expansion);
      }
      for (int l = 0; l < nl; ++l)
      {
        Vec3f L;
        active[l] = LightIncidence(F.Lights.lights[l], expansionPoint, L, irradiance[l]);
        if (!active[l])
        {
          continue;
        }
        Ls[l] = L;
        LoV[l] = Dot(L, V);
        diffuseQ[l] = tri.Expand(L, F.Opt.expansion);
        if (halfVector)
        {
          // HalfVector's fallback normal (for L = -V only): the provoking vertex's.
          Hs[l] = HalfVector(L, V, unit2);
          specularQ[l] = tri.Expand(Hs[l], F.Opt.expansion);
        }
      }
    };
    FastPhongScanline<float> diffuseLine[kMaxLights], specularLine[kMaxLights], viewLine;
    const Vec3f ambient = F.Mat.ambient * F.Lights.ambientIntensity;
    // The cosine power by table, as Bishop & Weimer (their section 4).
    const auto tablePower = [this](float x, float) { return F.PowerTable.Lookup(x); };
    // The model is the template parameter: BrdfFromCosines<Model> has no switch.
    int64_t shaded = 0, exactPixels = 0;
    const int W = F.Width;
    float* rgb = F.Rgb;
    uint8_t* covered = F.Covered;
    this->Scan(verts, 3, rowBegin, rowEnd,
      [&](int j, int i0)
      {
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
      [&](int j, int i, const float* a)
      {
        // Forward differences advance for every pixel of the span, drawn or not.
        float NoL[kMaxLights], NoH[kMaxLights], NoV = 0.0f;
        if (perPixelRule &&
          !tri.WithinSpread(N0, static_cast<float>(i) + 0.5f, static_cast<float>(j) + 0.5f,
            F.FastPhongMinCos))
        {
          const float xc = static_cast<float>(i) + 0.5f, yc = static_cast<float>(j) + 0.5f;
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
        float& d = state.bandDepth[static_cast<size_t>(j) * W + i - state.bandFirst];
        if (!(z <= 1.0f) || !(z < d))
        {
          return;
        }
        d = z;
        Vec3f color = F.Mat.diffuseColor;
        if (F.ColorSlot >= 0)
        {
          const float* c = a + kAttrFirst + F.ColorSlot;
          const float w = F.Perspective ? 1.0f / a[kAttrInvW] : 1.0f;
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
          I += irradiance[l] * BrdfFromCosines<Model>(F.Mat, color, NoH[l], RoV, tablePower) * cl;
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
};

} // namespace shadinglab::cpu
