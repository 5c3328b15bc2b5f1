// SPDX-License-Identifier: BSD-3-Clause
// One frame of the software renderer: its inputs, the derived transforms and
// attribute layout, and the frame buffers, shared read-only by the
// rasterizer (Rasterizer.h) and the shading stages (ShadingStages.h).
#pragma once

#include "HiddenBackFaces.h"
#include "Raster.h"

#include "shadinglab/model/FastPhong.h"
#include "shadinglab/model/Shading.h"
#include "shadinglab/render/Options.h"
#include "shadinglab/render/Scene.h"

namespace shadinglab::cpu
{

using Vec3f = Vec3<float>;

struct Frame
{
  // Inputs.
  const render::Mesh* MeshData = nullptr;
  render::Camera Cam;
  Lighting<float> Lights;
  Material<float> Mat;
  render::RenderOptions Opt;
  /// Colour by data: maps the mesh's scalars (per vertex) or cellScalars
  /// (per polygon) to rho; nullptr when the scene colours by none.
  const render::ColorMap* Map = nullptr;

  // Derived once per frame.
  int Width = 0, Height = 0, Threads = 1; ///< full (supersampled) resolution
  raster::Matrix4 ViewProjection{};
  Vec3f Eye, ToEye;
  const float* NormalData = nullptr; ///< the mesh's normals or computed ones
  /// Flat shading: per polygon, Newell's area vector (FlatStage::Geometry),
  /// kept across frames of one mesh; or nullptr (computed per polygon).
  const float* AreaVectors = nullptr;
  int NumAttributes = 0;             ///< interpolated values beyond z and 1/w
  int NormalSlot = -1, PositionSlot = -1, ColorSlot = -1;
  int ScalarSlot = -1; ///< the interpolated scalar (colour by point data)
  bool Perspective = true;       ///< perspective-correct interpolation
  SpecularPowerTable PowerTable; ///< fast-phong's x^n, as Bishop & Weimer
  float FastPhongMinCos = 0.0f;  ///< cos of RenderOptions::fastPhongMaxSpread
  bool CullBack = false;         ///< back faces are culled (asked, or hidden)
  /// With CullBack, the mesh's runs of kClusterPolygons polygons, binning
  /// skipping those ClusterFacesAway from ConeEye (HiddenBackFaces.h); or nullptr.
  const ClusterCone* Cones = nullptr;
  ClusterEye ConeEye;
  PixelUniforms Pixels{};        ///< what the Phong stage's queued pixels are shaded with
  /// Where the scan records RenderOptions::traceRow (written by the one
  /// thread whose band holds the row), or nullptr.
  render::ScanTrace* Trace = nullptr;

  // Frame buffers (full resolution), owned by the renderer.
  float* Rgb = nullptr;
  uint8_t* Covered = nullptr;
  uint16_t* Coverage = nullptr;
  float* Depth = nullptr; ///< the frame's depth (RenderOptions::keepDepth), or nullptr
  uint8_t* DisplayBytes = nullptr; ///< RGBA8 (RenderOptions::displayBytes), or nullptr

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
  bool PointScalars() const { return this->Map && !this->MeshData->scalars.empty(); }
  bool CellScalars() const { return this->Map && !this->MeshData->cellScalars.empty(); }
  /// rho varies per pixel or per polygon (scalars), or per vertex (colors).
  bool HasColor() const { return this->ColorSlot >= 0 || this->ScalarSlot >= 0 || this->CellScalars(); }
  /// Polygon p's rho under colour by cell data.
  Vec3f CellColorOf(int64_t p) const { return this->Map->Map(this->MeshData->cellScalars[p]); }
  /// rho of an interpolated scalar (Interpolate Scalars Before Mapping).
  Vec3f ScalarColor(float s) const { return this->Map->Map(s); }
  Vec3f ColorOf(int64_t v) const
  {
    if (this->PointScalars())
    {
      return this->Map->Map(this->MeshData->scalars[v]);
    }
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
  /// The illumination model (docs/model.md eq. 1.1) at one point.
  Vec3f ShadeAt(const Vec3f& P, const Vec3f& N, const Vec3f& color) const
  {
    return Shade(this->Mat, this->Lights, color, P, N, this->ViewDirection(P));
  }
  /// 1 / (interpolated 1/w) for perspective-correct attributes, else 1.
  float AttributeScale(const float* a) const
  {
    return this->Perspective ? 1.0f / a[raster::kAttrInvW] : 1.0f;
  }
  /// Depth test at pixel (i, j): on a pass, writes the depth, marks the
  /// pixel covered and returns its RGB slot; else nullptr.
  float* DepthTest(int j, int i, const float* a, const raster::ThreadState& state) const
  {
    const float z = a[raster::kAttrZ];
    if (!(z <= 1.0f))
    {
      return nullptr; // beyond the far plane
    }
    const size_t pix = static_cast<size_t>(j) * this->Width + i;
    float& d = state.bandDepth[pix - state.bandFirst];
    if (!(z < d))
    {
      return nullptr;
    }
    d = z;
    this->Covered[pix] = 1;
    return this->Rgb + 3 * pix;
  }
};

} // namespace shadinglab::cpu
