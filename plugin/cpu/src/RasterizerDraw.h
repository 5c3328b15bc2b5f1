// SPDX-License-Identifier: BSD-3-Clause
// Rasterizer's drawing: every thread's bands (RasterizeThread), a band's list
// (DrawList), one polygon clipped, triangulated and scan-converted in the
// band (DrawSourcePolygon, DrawInBand).
// Included by Rasterizer.h at its end, after the class: not on its own.
// (inline: as the definitions in the class were, for the inliner.)
#pragma once

namespace shadinglab::cpu
{

template<typename StageT>
inline void Rasterizer<StageT>::RasterizeThread(ThreadState& state)
{
  const Vec3f bg = F.Opt.background;
  for (int b; (b = this->NextBand.fetch_add(1, std::memory_order_relaxed)) < this->Bands;)
  {
    const size_t first = static_cast<size_t>(b) * kBandRows * F.Width;
    const size_t last = static_cast<size_t>(std::min(F.Height, (b + 1) * kBandRows)) * F.Width;
    if (!F.DisplayBytes) // (with them, an uncovered pixel's colour is not read)
    {
      for (size_t i = first; i < last; ++i)
      {
        F.Rgb[3 * i] = bg.x;
        F.Rgb[3 * i + 1] = bg.y;
        F.Rgb[3 * i + 2] = bg.z;
      }
    }
    state.bandFirst = first;
    std::fill(state.bandDepth, state.bandDepth + (last - first),
      std::numeric_limits<float>::infinity());
    std::fill(F.Covered + first, F.Covered + last, uint8_t(0));
    for (int piece = 0; piece < this->Pieces; ++piece)
    {
      this->DrawList(this->Bins[static_cast<size_t>(piece) * this->Bands + b], b, state);
    }
    this->Stage.Finish(state); // e.g. the band's pixels still queued for shading
    if (F.Depth)
    {
      std::copy(state.bandDepth, state.bandDepth + (last - first), F.Depth + first);
    }
    // The band's covered pixels, counted while it is in cache, for the
    // stats, and converted to display bytes (RenderOptions::displayBytes).
    if (F.DisplayBytes)
    {
      this->DisplayBand(first, last, state);
    }
    else
    {
      for (size_t i = first; i < last; ++i)
      {
        state.covered += F.Covered[i];
      }
    }
  }
}

template<typename StageT>
inline void Rasterizer<StageT>::DrawList(const std::vector<int64_t>& list, int band, ThreadState& state)
{
  const auto& offsets = F.MeshData->offsets;
  const auto& conn = F.MeshData->connectivity;
  const size_t m = list.size();
  auto id = [&](size_t e) { return EntryPolygon(list[e]); };
  for (size_t e = 0; e < m; ++e)
  {
    if (e + kAheadOffsets < m)
    {
      Prefetch(offsets.AddressOf(static_cast<size_t>(id(e + kAheadOffsets))));
    }
    if (e + kAheadConnectivity < m)
    {
      Prefetch(conn.AddressOf(static_cast<size_t>(offsets[id(e + kAheadConnectivity)])));
    }
    if (this->Buffers.CompactScreen && e + kAheadSlots < m &&
      !(list[e + kAheadSlots] & kEntryMayClip))
    {
      const int64_t p = id(e + kAheadSlots);
      const int64_t first = offsets[p];
      const int64_t n = std::min<int64_t>(offsets[p + 1] - first, kPrefetchedVertices);
      for (int64_t k = 0; k < n; ++k)
      {
        Prefetch(&this->Buffers.ScreenSlot[static_cast<size_t>(conn[first + k])]);
      }
    }
    if (e + kAheadVertices < m && !(list[e + kAheadVertices] & kEntryMayClip))
    {
      const int64_t p = id(e + kAheadVertices);
      const int64_t first = offsets[p];
      const int64_t n = std::min<int64_t>(offsets[p + 1] - first, kPrefetchedVertices);
      for (int64_t k = 0; k < n; ++k)
      {
        // A ScreenVertex (52 bytes) can straddle two cache lines.
        const char* v = reinterpret_cast<const char*>(this->ScreenOf(conn[first + k]));
        Prefetch(v);
        Prefetch(v + sizeof(ScreenVertex) - 1);
      }
      if (offsets[p + 1] > first)
      {
        this->Stage.PrefetchPolygon(p, conn[offsets[p + 1] - 1]);
      }
    }
    this->DrawSourcePolygon(list[e], band, state);
  }
}

template<typename StageT>
inline void Rasterizer<StageT>::DrawSourcePolygon(int64_t entry, int band, ThreadState& state)
{
  const int64_t p = EntryPolygon(entry);
  const auto& offsets = F.MeshData->offsets;
  const auto& conn = F.MeshData->connectivity;
  const int64_t first = offsets[p];
  const int n =
    static_cast<int>(std::min<int64_t>(offsets[p + 1] - first, kMaxPolygonVertices - 1));
  if (n < 3)
  {
    return;
  }
  // Counters are kept by the polygon's first band, so they do not depend
  // on the thread count.
  const ScreenVertex* verts[kMaxPolygonVertices];
  int64_t ids[kMaxPolygonVertices];
  for (int k = 0; k < n; ++k)
  {
    ids[k] = conn[first + k];
  }
  if (!(entry & kEntryMayClip))
  {
    // In front of the near plane: binning rejected, culled and counted
    // with the same floats.
    for (int k = 0; k < n; ++k)
    {
      verts[k] = this->ScreenOf(ids[k]);
    }
    this->DrawInBand(p, (entry & kEntryBack) != 0, (entry & kEntryOwner) != 0, false, verts,
      ids, n, band, state, EntryPixel(entry));
    return;
  }
  bool anyBehind = false;
  for (int k = 0; k < n; ++k)
  {
    anyBehind |= this->Behind[ids[k]] != 0;
  }
  int count = 0;
  bool wasClipped = false;
  if (!anyBehind)
  {
    for (int k = 0; k < n; ++k)
    {
      verts[count++] = this->ScreenOf(ids[k]);
    }
  }
  else
  {
    // Clipped against the near plane (ClipToNearPlane, Raster.h), the
    // attributes interpolated linearly in clip space (exact before the
    // divide).
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
      const double pt[3] = {
        F.MeshData->points[3 * v], F.MeshData->points[3 * v + 1], F.MeshData->points[3 * v + 2]
      };
      F.ViewProjection.Apply(pt, in[k].c);
      this->Stage.Vertex(v, in[k].raw);
    }
    state.clipped.clear();
    int64_t clippedIds[kMaxPolygonVertices];
    auto emit = [&](const ClipVertex& cv, int64_t id)
    {
      ScreenVertex sv;
      this->ToScreen(this->Project(cv.c), cv.raw, sv);
      clippedIds[state.clipped.size()] = id;
      state.clipped.push_back(sv);
    };
    raster::ClipToNearPlane(
      n, [&](int k) { return in[k].c; }, [&](int k) { emit(in[k], ids[k]); },
      [&](int inside, int outside, double t)
      {
        ClipVertex x;
        raster::NearPlaneCrossing(in[inside].c, in[outside].c, t, x.c);
        for (int i = 0; i < F.NumAttributes; ++i)
        {
          x.raw[i] = static_cast<float>(
            in[inside].raw[i] + t * (in[outside].raw[i] - in[inside].raw[i]));
        }
        emit(x, ids[inside]);
      });
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
    const ScreenVertex& b = *verts[k + 1 < count ? k + 1 : 0];
    area += static_cast<double>(a.x) * b.y - static_cast<double>(b.x) * a.y;
    xmin = std::min(xmin, a.x);
    xmax = std::max(xmax, a.x);
    ymin = std::min(ymin, a.y);
    ymax = std::max(ymax, a.y);
    zmin = std::min(zmin, a.a[kAttrZ]);
  }
  const int j0 = std::max(0, CeilToInt(ymin - 0.5f));
  const int j1 = std::min(F.Height, CeilToInt(ymax - 0.5f));
  if (xmax < 0 || xmin > F.Width || j1 <= j0 || zmin > 1.0f)
  {
    return;
  }
  const bool owner = j0 / kBandRows == band;
  const Facing facing = FacingOf(area);
  if (facing == Facing::Degenerate)
  {
    state.degenerate += owner;
    return;
  }
  const bool back = facing == Facing::Back;
  if (back && F.CullBack)
  {
    state.culled += owner; // clipped polygons only: binning culls the rest
    return;
  }
  this->DrawInBand(p, back, owner, wasClipped, verts, ids, count, band, state);
}

template<typename StageT>
inline void Rasterizer<StageT>::DrawInBand(int64_t p,
  bool back,
  bool owner,
  bool wasClipped,
  const ScreenVertex** verts,
  int64_t* ids,
  int count,
  int band,
  ThreadState& state,
  raster::OnePixel onePixel)
{
  state.clippedPolygons += owner && wasClipped;
  state.rasterized += owner;

  // The stage's per-polygon state (flat: the lazy colour; Gouraud back
  // faces: vertices relit with flipped normals into `relit`).
  ScreenVertex relit[kMaxPolygonVertices];
  auto polygon = this->Stage.BeginPolygon(p, back, verts, ids, count, relit);
  polygon.onePixel = onePixel; // binning's (a triangle's, or none)
  // Scan-convert each part into this band's rows.
  const int bandBegin = band * kBandRows, bandEnd = std::min(F.Height, bandBegin + kBandRows);
  auto drawPart = [&](const ScreenVertex* const* partVerts, const int64_t* partIds, int m)
  {
    float pymin = partVerts[0]->y, pymax = pymin;
    for (int k = 1; k < m; ++k)
    {
      pymin = std::min(pymin, partVerts[k]->y);
      pymax = std::max(pymax, partVerts[k]->y);
    }
    const int r0 = std::max(bandBegin, CeilToInt(pymin - 0.5f));
    const int r1 = std::min(bandEnd, CeilToInt(pymax - 0.5f));
    if (r1 > r0)
    {
      this->Stage.DrawPart(partVerts, partIds, m, polygon, r0, r1, state);
    }
  };
  if (this->Stage.Triangulates() && count > 3)
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

} // namespace shadinglab::cpu
