// SPDX-License-Identifier: BSD-3-Clause
// The software renderer's fast Phong stage (ShadingStages.h says what a
// stage is): per triangle, the cosines' Taylor quadratics (the model's
// FastPhong.h) set up once and stepped across each span by forward
// differences; per pixel, the model's BrdfFromCosines.
#pragma once

#include "ShadingStages.h"

namespace shadinglab::cpu
{

/// Fast Phong (Bishop & Weimer 1986; eq. 2.6-2.9): triangles only, the
/// cosines by Taylor quadratics stepped with forward differences, shaded
/// through BrdfFromCosines.
struct FastPhongStage : StageBase
{
  static void Layout(Frame& f)
  {
    if (f.PointScalars())
    {
      f.ScalarSlot = 0; // mapped per pixel, as the Phong stage
      f.NumAttributes = 1;
    }
    else if (!f.MeshData->colors.empty() && !f.Map)
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
    // rho without per-pixel colours: the polygon's (cell data) or the material's.
    const Vec3f cellRho = F.CellScalars() ? F.CellColorOf(poly.id) : F.Mat.diffuseColor;
    // The cosine power by table, as Bishop & Weimer (their section 4).
    const auto tablePower = [this](float x, float) { return F.PowerTable.Lookup(x); };
    // The model is the template parameter: BrdfFromCosines<Model> has no switch.
    int64_t shaded = 0, exactPixels = 0;
    const int W = F.Width;
    float* rgb = F.Rgb;
    uint8_t* covered = F.Covered;
    this->Scan(verts, 3, rowBegin, rowEnd, poly.onePixel,
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
        Vec3f color = cellRho;
        const float w = F.Perspective ? 1.0f / a[kAttrInvW] : 1.0f;
        if (F.ColorSlot >= 0)
        {
          const float* c = a + kAttrFirst + F.ColorSlot;
          color = Vec3f(c[0] * w, c[1] * w, c[2] * w);
        }
        else if (F.ScalarSlot >= 0)
        {
          color = F.ScalarColor(a[kAttrFirst + F.ScalarSlot] * w);
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
        if (F.Lights.analyser.on)
        {
          I *= kPolarizerTransmittance<float>; // no Fresnel term: depolarized, half passes (eq. 8.4)
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
