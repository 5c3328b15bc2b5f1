// SPDX-License-Identifier: BSD-3-Clause
// Rasterizer's the vertex stage: which runs of faces face away (TestRuns), the clip
// coordinates and screen positions of every vertex (ProjectPositions), then
// the stage's attributes of the vertices binning marked (ShadeVertices).
// Included by Rasterizer.h at its end, after the class: not on its own.
// (inline: as the definitions in the class were, for the inliner.)
#pragma once

namespace shadinglab::cpu
{

template<typename StageT>
inline void Rasterizer<StageT>::TestRuns()
{
  if (!F.Cones)
  {
    return;
  }
  const int64_t polygons = F.MeshData->NumberOfPolygons();
  const int64_t runs = (polygons + kClusterPolygons - 1) / kClusterPolygons;
  auto& away = this->Buffers.RunAway;
  away.resize(static_cast<size_t>(runs));
  ParallelFor(this->Buffers.Pool, runs, F.Threads,
    [&](int64_t b, int64_t e, int)
    {
      for (int64_t r = b; r < e; ++r)
      {
        away[static_cast<size_t>(r)] = ClusterFacesAway(F.Cones[r], F.ConeEye);
      }
    });
  auto& blocks = this->Buffers.VertexBlocks;
  blocks.assign(static_cast<size_t>(F.MeshData->NumberOfPoints() / kVertexBlock + 1), 0);
  for (int64_t r = 0; r < runs; ++r)
  {
    const ClusterCone& cone = F.Cones[r];
    if (!away[static_cast<size_t>(r)] && cone.endVertex > cone.firstVertex)
    {
      std::fill(blocks.begin() + cone.firstVertex / kVertexBlock,
        blocks.begin() + (cone.endVertex - 1) / kVertexBlock + 1, uint8_t(1));
    }
  }
}

template<typename StageT>
inline void Rasterizer<StageT>::ProjectPositions()
{
  const auto& mesh = *F.MeshData;
  const int64_t nv = mesh.NumberOfPoints();
  this->Projected.resize(static_cast<size_t>(nv));
  this->Behind.resize(static_cast<size_t>(nv));
  if (this->Buffers.NeededCapacity < nv)
  {
    this->Buffers.Needed.reset(new std::atomic<uint8_t>[static_cast<size_t>(nv)]);
    this->Buffers.NeededCapacity = nv;
  }
  std::atomic<uint8_t>* needed = this->Buffers.Needed.get();
  ParallelFor(this->Buffers.Pool, nv,
    F.Threads,
    [&](int64_t b, int64_t e, int)
    {
      const uint8_t* blocks = F.Cones ? this->Buffers.VertexBlocks.data() : nullptr;
      for (int64_t v = b; v < e; ++v)
      {
        needed[v].store(0, std::memory_order_relaxed);
        if (blocks && !blocks[v / kVertexBlock])
        {
          continue; // used by runs facing away only (TestRuns): never read
        }
        const double p[3] = {
          mesh.points[3 * v], mesh.points[3 * v + 1], mesh.points[3 * v + 2]
        };
        double clip[4];
        F.ViewProjection.Apply(p, clip);
        this->Behind[v] = clip[2] < -clip[3];
        if (this->Behind[v])
        {
          continue; // such vertices are only used through clipping
        }
        this->Projected[v] = this->Project(clip);
      }
    });
}

template<typename StageT>
inline void Rasterizer<StageT>::ShadeVertices()
{
  const std::atomic<uint8_t>* needed = this->Buffers.Needed.get();
  const int64_t nv = F.MeshData->NumberOfPoints();
  const int64_t pieces = (nv + kVertexChunk - 1) / kVertexChunk;
  auto drawn = [&](int64_t v)
  { return !this->Behind[v] && needed[v].load(std::memory_order_relaxed) != 0; };
  // Count the drawn vertices of each piece, then give each piece its first
  // record: records in vertex order, whatever thread shades a piece.
  auto& first = this->Buffers.PieceRecords;
  first.assign(static_cast<size_t>(pieces) + 1, 0);
  ParallelChunks(this->Buffers.Pool, nv, F.Threads, kVertexChunk,
    [&](int64_t k, int64_t b, int64_t e, int)
    {
      int64_t count = 0;
      for (int64_t v = b; v < e; ++v)
      {
        count += drawn(v);
      }
      first[static_cast<size_t>(k) + 1] = count;
    });
  for (size_t k = 1; k < first.size(); ++k)
  {
    first[k] += first[k - 1];
  }
  const int64_t records = first.back();
  const ScreenRecords forced = ForcedScreenRecords();
  const bool compact = records <= static_cast<int64_t>(std::numeric_limits<uint32_t>::max()) &&
    (forced == ScreenRecords::Compact ||
      (forced == ScreenRecords::Auto && CompactRecordsPay(records, nv)));
  this->Buffers.ScreenRecordsMade = records;
  this->Buffers.CompactScreen = compact;
  this->Screen.resize(static_cast<size_t>(compact ? records : nv));
  if (compact)
  {
    this->Buffers.ScreenSlot.resize(static_cast<size_t>(nv));
  }
  uint32_t* slots = this->Buffers.ScreenSlot.data();
  ParallelChunks(this->Buffers.Pool, nv, F.Threads, kVertexChunk,
    [&](int64_t k, int64_t b, int64_t e, int)
    {
      int64_t next = first[static_cast<size_t>(k)];
      auto store = [&](int64_t v, const float* raw)
      {
        int64_t at = v;
        if (compact)
        {
          at = next++;
          slots[v] = static_cast<uint32_t>(at);
        }
        this->ToScreen(this->Projected[v], raw, this->Screen[static_cast<size_t>(at)]);
      };
      if constexpr (HasVertexBatch<StageT>::value)
      {
        // The stage lights its vertices in batches (Gouraud).
        constexpr int kBatch = StageT::kVertexBatch;
        int64_t ids[kBatch];
        float raw[kBatch][kMaxAttributes] = {};
        int count = 0;
        auto flush = [&]
        {
          this->Stage.VertexBatch(ids, count, raw);
          for (int i = 0; i < count; ++i)
          {
            store(ids[i], raw[i]);
          }
          count = 0;
        };
        for (int64_t v = b; v < e; ++v)
        {
          if (drawn(v))
          {
            ids[count++] = v;
            if (count == kBatch)
            {
              flush();
            }
          }
        }
        flush();
      }
      else
      {
        float raw[kMaxAttributes] = {};
        for (int64_t v = b; v < e; ++v)
        {
          if (drawn(v))
          {
            this->Stage.Vertex(v, raw);
            store(v, raw);
          }
        }
      }
    });
}

template<typename StageT>
inline ProjectedVertex Rasterizer<StageT>::Project(const double clip[4]) const
{
  const double invW = 1.0 / clip[3];
  // Screen-space interpolation: attributes are interpolated as they are and
  // 1/w is pinned to 1, so the per-pixel divide is a no-op.
  return { static_cast<float>((clip[0] * invW * 0.5 + 0.5) * F.Width),
    static_cast<float>((0.5 - clip[1] * invW * 0.5) * F.Height),
    static_cast<float>(clip[2] * invW), F.Perspective ? static_cast<float>(invW) : 1.0f };
}

template<typename StageT>
inline void Rasterizer<StageT>::ToScreen(const ProjectedVertex& pv, const float* raw, ScreenVertex& out) const
{
  out.x = pv.x;
  out.y = pv.y;
  out.a[kAttrZ] = pv.z;
  out.a[kAttrInvW] = pv.invW;
  for (int k = 0; k < F.NumAttributes; ++k)
  {
    out.a[kAttrFirst + k] = raw[k] * pv.invW;
  }
}

} // namespace shadinglab::cpu
