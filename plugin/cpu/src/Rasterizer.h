// SPDX-License-Identifier: BSD-3-Clause
// The software rasterizer: vertex stage, binning of polygons to row bands,
// near-plane clipping (Sutherland-Hodgman), culling, triangulation and the
// band loop, as a template over the shading stage (ShadingStages.h). It
// never branches on the shading mode.
//
// Each thread owns an interleaved set of kBandRows-row bands. A band is
// drawn whole before the next: cleared, then every polygon binned to it,
// in input order, then its covered pixels counted, so its depth and colour
// rows stay in the core's cache while it is drawn (a 1080p band is ~0.5 MB;
// clearing the whole frame first and drawing after made the first touch of
// every pixel a miss to memory). Each pixel belongs to one band and no
// arithmetic depends on the split, so the image is bit-identical for any
// thread count.
#pragma once

#include "BinFour.h"
#include "Frame.h"
#include "shadinglab/render/Display.h"
#include "WorkerPool.h"

#include <atomic>
#include <limits>
#include <memory>
#include <type_traits>

namespace shadinglab::cpu
{

using raster::CeilToInt;
using raster::kBandRows;
using raster::kDegenerateArea;
using raster::kMaxAttributes;
using raster::kMaxPolygonVertices;
using raster::kAttrFirst;
using raster::kAttrInvW;
using raster::kAttrZ;
using raster::Prefetch;
using raster::ScreenVertex;
using raster::ThreadState;
using raster::TwiceSignedArea;

/// Buffers the rasterizer keeps across frames (no reallocation at a steady size).
struct RasterBuffers
{
  /// Every vertex's projection, 16 bytes: binning reads these for every
  /// polygon, and reading whole ScreenVertex records (52 bytes, 26 MB for
  /// ParaView's 1M sphere) made it wait on memory.
  std::vector<ProjectedVertex> Projected;
  /// The vertices drawn (binning marked them Needed): projection and
  /// attributes, filled by ShadeVertices.
  std::vector<ScreenVertex> Screen;
  std::vector<uint8_t> Behind;            ///< vertex outside the near plane
  /// [piece * bands + band]: polygon ids, as BinEntry encodes them.
  std::vector<std::vector<int64_t>> Bins;
  /// Vertex used by a polygon that can reach a pixel: only these are shaded
  /// (set by several binning workers at once, hence atomic).
  std::unique_ptr<std::atomic<uint8_t>[]> Needed;
  int64_t NeededCapacity = 0;
  /// Per thread, the depth of the band it draws (ThreadState::bandDepth).
  std::vector<std::vector<float>> BandDepth;
  /// With cones (Frame::Cones): per run, whether it faces away this frame;
  /// per block of Rasterizer::kVertexBlock vertices, whether a run that
  /// does not face away uses a vertex in it (only such blocks are projected).
  std::vector<uint8_t> RunAway, VertexBlocks;
  WorkerPool Pool; ///< the frame's threads, kept across frames
};

template<typename StageT>
class Rasterizer
{
public:
  Rasterizer(const Frame& frame, const StageT& stage, RasterBuffers& buffers)
    : F(frame)
    , Stage(stage)
    , Projected(buffers.Projected)
    , Screen(buffers.Screen)
    , Behind(buffers.Behind)
    , Bins(buffers.Bins)
    , Buffers(buffers)
    , ColumnTest(frame.Opt.scan == render::ScanConversion::Plane)
  {
  }

  /// Vertices, then bins, then every thread's bands. Returns the polygons
  /// found degenerate before any row was known.
  int64_t Run(std::vector<ThreadState>& states)
  {
    // (Binning worker w keeps its culled and triangle counts in states[w].)
    this->TestRuns();
    this->ProjectPositions();
    const int T = F.Threads;
    this->Bands = (F.Height + kBandRows - 1) / kBandRows;
    // Binning: the polygons are cut into contiguous pieces, which the
    // threads take from one counter; each piece lists, for every band, its
    // polygons that reach it. A band is then drawn from lists [0][b],
    // [1][b], ... in order: input order is kept. Pieces, not one range per
    // thread: a view's kept polygons cluster in index order (culled back
    // faces cost little), and with halves the 100k torus binned in 2.1 ms
    // on one thread and 1.5 on two.
    const int64_t polygons = F.MeshData->NumberOfPolygons();
    // (A piece is whole runs of kClusterPolygons: BinPolygons tests a run's cone.)
    const int64_t chunk = T <= 1
      ? std::max<int64_t>(1, polygons) // one piece
      : RoundUp(std::max(kMinPolygonChunk,
                  (polygons + kPiecesPerThread * T - 1) / (kPiecesPerThread * T)),
          kClusterPolygons);
    this->Pieces = static_cast<int>(std::max<int64_t>(1, (polygons + chunk - 1) / chunk));
    this->Bins.resize(static_cast<size_t>(this->Pieces) * this->Bands);
    for (auto& list : this->Bins)
    {
      list.clear(); // capacity kept across frames
    }
    std::vector<int64_t> zeroRowDegenerate(static_cast<size_t>(T), 0);
    ParallelChunks(this->Buffers.Pool, polygons, T, chunk,
      [&](int64_t piece, int64_t begin, int64_t end, int worker)
      {
        zeroRowDegenerate[worker] +=
          this->BinPolygons(begin, end, static_cast<int>(piece), states[worker]);
      });
    this->ShadeVertices();
    // Bands are taken in turn from one counter, not dealt round-robin: a
    // band's pixels depend on its bins only, so any thread may draw it, and
    // the threads finish together (dealt, one thread of two drew for 15 ms
    // and the other 19 on the torus in Phong).
    this->NextBand.store(0, std::memory_order_relaxed);
    this->Buffers.BandDepth.resize(static_cast<size_t>(T));
    for (int t = 0; t < T; ++t)
    {
      auto& depth = this->Buffers.BandDepth[static_cast<size_t>(t)];
      depth.resize(static_cast<size_t>(kBandRows) * F.Width); // kept at a steady size
      states[t].bandDepth = depth.data();
    }
    ParallelFor(this->Buffers.Pool, T,
      T,
      [&](int64_t b, int64_t e, int)
      {
        for (int64_t t = b; t < e; ++t)
        {
          this->RasterizeThread(states[t]);
        }
      });
    int64_t degenerate = 0;
    for (int t = 0; t < T; ++t)
    {
      degenerate += zeroRowDegenerate[t];
    }
    return degenerate;
  }

private:
  /// With cones: which runs face away this frame (ClusterFacesAway), and
  /// the vertex blocks the others use. A closed mesh seen from outside
  /// turns about half its runs away, and the vertices only those runs use
  /// need no projection (a mesh's neighbours are near in index order, so a
  /// run's vertices span a short range: ~530 on ParaView's 1M sphere).
  void TestRuns()
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

  /// The vertex stage, first half: clip coordinates and screen positions of
  /// every vertex (in parallel). The stage's attributes (for Gouraud, the
  /// whole lighting model) wait for ShadeVertices, after binning has marked
  /// the vertices of the polygons that can reach a pixel: a mesh half
  /// outside the view lights half its vertices.
  void ProjectPositions()
  {
    const auto& mesh = *F.MeshData;
    const int64_t nv = mesh.NumberOfPoints();
    this->Projected.resize(static_cast<size_t>(nv));
    this->Screen.resize(static_cast<size_t>(nv));
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

  /// The vertex stage, second half: the screen vertices binning marked,
  /// their projection and the stage's attributes scaled by its 1/w
  /// (ToScreen, as for clipped vertices).
  void ShadeVertices()
  {
    const std::atomic<uint8_t>* needed = this->Buffers.Needed.get();
    auto store = [&](int64_t v, const float* raw)
    {
      this->ToScreen(this->Projected[v], raw, this->Screen[v]);
    };
    ParallelChunks(this->Buffers.Pool, F.MeshData->NumberOfPoints(), F.Threads, kVertexChunk,
      [&](int64_t, int64_t b, int64_t e, int)
      {
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
            for (int k = 0; k < count; ++k)
            {
              store(ids[k], raw[k]);
            }
            count = 0;
          };
          for (int64_t v = b; v < e; ++v)
          {
            if (!this->Behind[v] && needed[v].load(std::memory_order_relaxed))
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
            if (this->Behind[v] || !needed[v].load(std::memory_order_relaxed))
            {
              continue;
            }
            this->Stage.Vertex(v, raw);
            store(v, raw);
          }
        }
      });
  }

  /// Whether the stage lights vertices in batches (VertexBatch).
  template<typename S, typename = void>
  struct HasVertexBatch : std::false_type
  {
  };
  template<typename S>
  struct HasVertexBatch<S, std::void_t<decltype(&S::VertexBatch)>> : std::true_type
  {
  };

  /// Screen position, depth and attribute scale of clip coordinates.
  ProjectedVertex Project(const double clip[4]) const
  {
    const double invW = 1.0 / clip[3];
    // Screen-space interpolation: attributes are interpolated as they are and
    // 1/w is pinned to 1, so the per-pixel divide is a no-op.
    return { static_cast<float>((clip[0] * invW * 0.5 + 0.5) * F.Width),
      static_cast<float>((0.5 - clip[1] * invW * 0.5) * F.Height),
      static_cast<float>(clip[2] * invW), F.Perspective ? static_cast<float>(invW) : 1.0f };
  }

  /// The screen vertex of a projection and the stage's raw attributes,
  /// scaled by its 1/w: a marked vertex (ShadeVertices) or a clipped one.
  void ToScreen(const ProjectedVertex& pv, const float* raw, ScreenVertex& out) const
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

  void RasterizeThread(ThreadState& state)
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

  /// RenderOptions::displayBytes for pixels [first, last), counting the
  /// covered ones.
  void DisplayBand(size_t first, size_t last, ThreadState& state) const
  {
    state.covered += render::ToDisplayBytes(F.Opt.display, F.Rgb, F.Covered, first, last, F.DisplayBytes);
  }

  /// A bin's entry: polygon p shifted left by kEntryShift, and what
  /// binning found about it in the low bits, so that drawing neither reads
  /// the near-plane flags nor sums the area and bounds again in every band.
  static constexpr int kEntryFlagBits = 3;
  /// A vertex lies behind the near plane: drawing clips, then rejects,
  /// culls and counts the clipped polygon itself.
  static constexpr int64_t kEntryMayClip = 1;
  /// (Without kEntryMayClip) a back face, drawn: back faces are not culled.
  static constexpr int64_t kEntryBack = 2;
  /// (Without kEntryMayClip) the polygon's first band, which counts it: the
  /// counters do not depend on the thread count.
  static constexpr int64_t kEntryOwner = 4;
  /// Above the flags, 1 + the column of a triangle's one pixel when
  /// binning found it (PolygonTests::pixel), else 0: 17 bits hold every
  /// column of the widest frame (kMaxImageSize x kMaxSupersampling =
  /// 65,536 px); above them its row from the triangle's first (2 bits:
  /// kBinSpanRows rows); the polygon id above those.
  static constexpr int kEntryColumnBits = 17;
  static constexpr int kEntryRowBits = 2;
  static_assert(kBinSpanRows <= 1 << kEntryRowBits);
  static constexpr int kEntryShift = kEntryFlagBits + kEntryColumnBits + kEntryRowBits;
  static constexpr int64_t kEntryColumnMask = (int64_t(1) << kEntryColumnBits) - 1;
  static constexpr int64_t kEntryRowMask = (int64_t(1) << kEntryRowBits) - 1;
  static int64_t BinEntry(int64_t p, int64_t flags, raster::OnePixel pixel = {})
  {
    const bool known = pixel.column >= 0 && pixel.column < kEntryColumnMask;
    const int64_t column = known ? pixel.column + 1 : 0, row = known ? pixel.row : 0;
    return p << kEntryShift | row << (kEntryFlagBits + kEntryColumnBits) |
      column << kEntryFlagBits | flags;
  }
  static int64_t EntryPolygon(int64_t entry) { return entry >> kEntryShift; }
  static raster::OnePixel EntryPixel(int64_t entry)
  {
    return { static_cast<int>(entry >> (kEntryFlagBits + kEntryColumnBits) & kEntryRowMask),
      static_cast<int>(entry >> kEntryFlagBits & kEntryColumnMask) - 1 };
  }

  /// Draws one bin list's polygons in order. A band's polygons lie all over
  /// the index range (a band is a latitude of a sphere whose polygons go
  /// by longitude), and each one's vertices are found through a chain of
  /// dependent loads (offsets, connectivity, then the vertices): perf put
  /// half of DrawSourcePolygon's time on those three loads. The entries
  /// ahead are fetched in stages, each stage reading what the one before
  /// fetched: a few polygons of work (~50-100 ns each) hide one miss.
  void DrawList(const std::vector<int64_t>& list, int band, ThreadState& state)
  {
    const auto& offsets = F.MeshData->offsets;
    const auto& conn = F.MeshData->connectivity;
    const size_t m = list.size();
    auto id = [&](size_t e) { return EntryPolygon(list[e]); };
    for (size_t e = 0; e < m; ++e)
    {
      if (e + kAheadOffsets < m)
      {
        Prefetch(&offsets[id(e + kAheadOffsets)]);
      }
      if (e + kAheadConnectivity < m)
      {
        Prefetch(&conn[offsets[id(e + kAheadConnectivity)]]);
      }
      if (e + kAheadVertices < m && !(list[e + kAheadVertices] & kEntryMayClip))
      {
        const int64_t p = id(e + kAheadVertices);
        const int64_t first = offsets[p];
        const int64_t n = std::min<int64_t>(offsets[p + 1] - first, kPrefetchedVertices);
        for (int64_t k = 0; k < n; ++k)
        {
          // A ScreenVertex (52 bytes) can straddle two cache lines.
          const char* v = reinterpret_cast<const char*>(&this->Screen[conn[first + k]]);
          Prefetch(v);
          Prefetch(v + sizeof(ScreenVertex) - 1);
        }
        this->Stage.PrefetchPolygon(p, &conn[first], offsets[p + 1] - first);
      }
      this->DrawSourcePolygon(list[e], band, state);
    }
  }

  static int64_t RoundUp(int64_t n, int64_t multiple) { return (n + multiple - 1) / multiple * multiple; }

  /// Bins a piece's polygons, run by run (begin is a multiple of
  /// kClusterPolygons): a run whose cone faces away is skipped whole.
  int64_t BinPolygons(int64_t begin, int64_t end, int piece, ThreadState& state)
  {
    std::vector<int64_t>* lists = &this->Bins[static_cast<size_t>(piece) * this->Bands];
    int64_t degenerate = 0;
    for (int64_t run = begin; run < end; run += kClusterPolygons)
    {
      const int64_t runEnd = std::min(end, run + kClusterPolygons);
      if (F.Cones && this->Buffers.RunAway[static_cast<size_t>(run / kClusterPolygons)])
      {
        // Every polygon of the run a triangle facing away (ClusterCone).
        state.triangles += runEnd - run;
        state.culledInClusters += runEnd - run;
        continue;
      }
      degenerate += this->BinRun(run, runEnd, lists, state);
    }
    return degenerate;
  }

  /// Bins polygons [begin, end): four triangles at a time where they are
  /// (BinFour.h), the others one by one.
  int64_t BinRun(int64_t begin, int64_t end, std::vector<int64_t>* lists, ThreadState& state)
  {
    int64_t degenerate = 0;
    int64_t p = begin;
#if defined(__SSE2__)
    const auto& offsets = F.MeshData->offsets;
    const auto& conn = F.MeshData->connectivity;
    for (; p + 4 <= end; p += 4)
    {
      const int64_t first = offsets[p];
      bool triangles = true;
      for (int t = 1; t <= 4; ++t)
      {
        triangles &= offsets[p + t] == first + 3 * t;
      }
      int64_t ids[4][3];
      const ProjectedVertex* v[3][4];
      bool anyBehind = false;
      for (int t = 0; t < 4 && triangles; ++t)
      {
        for (int k = 0; k < 3; ++k)
        {
          const int64_t id = conn[first + 3 * t + k];
          ids[t][k] = id;
          v[k][t] = &this->Projected[id];
          anyBehind |= this->Behind[id] != 0;
        }
      }
      if (!triangles || anyBehind)
      {
        // A polygon of another size, or a vertex behind the near plane
        // (whose projection is not computed): one by one.
        for (int t = 0; t < 4; ++t)
        {
          degenerate += this->BinOne(p + t, lists, state);
        }
        continue;
      }
      const FourTriangleTests tests = TestFourTriangles(v, F.Width, F.Height, this->ColumnTest);
      state.triangles += 4;
      for (int t = 0; t < 4; ++t)
      {
        const Facing facing = (tests.degenerate >> t & 1) ? Facing::Degenerate
          : (tests.back >> t & 1)                           ? Facing::Back
                                                            : Facing::Front;
        const PolygonTests lane{ tests.j0[t], tests.j1[t], (tests.hasRow >> t & 1) != 0,
          (tests.rejected >> t & 1) != 0, (tests.noPixel >> t & 1) != 0, 0.0, tests.pixel[t] };
        degenerate += this->BinTested(p + t, ids[t], 3, lane, facing, lists, state);
      }
    }
#endif
    for (; p < end; ++p)
    {
      degenerate += this->BinOne(p, lists, state);
    }
    return degenerate;
  }

  /// Bins polygon p alone.
  int64_t BinOne(int64_t p, std::vector<int64_t>* lists, ThreadState& state)
  {
    const auto& offsets = F.MeshData->offsets;
    const int64_t first = offsets[p];
    const int64_t size = offsets[p + 1] - first;
    state.triangles += render::TrianglesInPolygon(size); // for the stats
    const int n = static_cast<int>(std::min<int64_t>(size, kMaxPolygonVertices - 1));
    if (n < 3)
    {
      return 0;
    }
    // Triangles, most meshes' polygons, with their loops unrolled.
    return n == 3 ? this->BinPolygon<3>(p, first, n, lists, state)
                  : this->BinPolygon<0>(p, first, n, lists, state);
  }

  /// Bins polygon p (its n vertices from connectivity[first]; N = n known
  /// at compile time, or 0); returns 1 when it has no pixel row and is
  /// degenerate.
  template<int N>
  int64_t BinPolygon(int64_t p, int64_t first, int n, std::vector<int64_t>* lists,
    ThreadState& state)
  {
    const auto& conn = F.MeshData->connectivity;
    const int count = N > 0 ? N : n;
    const ProjectedVertex* sv[kMaxPolygonVertices];
    int64_t ids[kMaxPolygonVertices];
    bool anyBehind = false, allBehind = true;
    for (int k = 0; k < count; ++k)
    {
      const int64_t v = conn[first + k];
      ids[k] = v;
      sv[k] = &this->Projected[v];
      anyBehind |= this->Behind[v] != 0;
      allBehind &= this->Behind[v] != 0;
    }
    if (allBehind)
    {
      return 0; // clipping keeps nothing (Behind is its inside test negated)
    }
    if (anyBehind)
    {
      // Rows are known only after clipping, which DrawSourcePolygon does
      // per band: binned to the bands its clipped part can reach, nothing
      // when it lies wholly behind the near plane (a mesh behind the
      // camera, half of a floor the camera stands on). Before, every band
      // looked: the 100k torus behind the camera took 150 ms at 1080p,
      // clipped 68 times, against 17 ms in view.
      int rowBegin = 0, rowEnd = 0;
      this->ClippedRows(first, count, rowBegin, rowEnd);
      for (int b = rowBegin / kBandRows; rowEnd > rowBegin && b <= (rowEnd - 1) / kBandRows; ++b)
      {
        lists[b].push_back(BinEntry(p, kEntryMayClip));
        ++state.binned;
      }
      return 0;
    }
    // Whether the polygon can reach a pixel (most triangles of a mesh
    // finer than the pixels, ParaView's 1M sphere at 1080p, fall between
    // pixel rows or columns), and its facing.
    const PolygonTests t = TestPolygon<N>(sv, count, F.Width, F.Height, this->ColumnTest);
    return this->BinTested(p, ids, count, t, FacingOf(t.twiceArea), lists, state);
  }

  /// Rows [rowBegin, rowEnd) that polygon `first`'s part in front of the
  /// near plane may reach, by DrawSourcePolygon's clipping on positions
  /// only, widened by kClipRowMargin (the bins need a superset of the rows:
  /// DrawSourcePolygon finds the exact ones). Empty when no part is in front.
  void ClippedRows(int64_t first, int n, int& rowBegin, int& rowEnd) const
  {
    const auto& conn = F.MeshData->connectivity;
    const auto& pts = F.MeshData->points;
    double c[kMaxPolygonVertices][4];
    for (int k = 0; k < n; ++k)
    {
      const int64_t v = conn[first + k];
      const double pt[3] = { pts[3 * v], pts[3 * v + 1], pts[3 * v + 2] };
      F.ViewProjection.Apply(pt, c[k]);
    }
    float ymin = std::numeric_limits<float>::infinity(), ymax = -ymin;
    auto row = [&](const double* clip)
    {
      const float y = this->Project(clip).y;
      ymin = std::min(ymin, y);
      ymax = std::max(ymax, y);
    };
    raster::ClipToNearPlane(
      n, [&](int k) { return c[k]; }, [&](int k) { row(c[k]); },
      [&](int inside, int outside, double t)
      {
        double x[4];
        raster::NearPlaneCrossing(c[inside], c[outside], t, x);
        row(x);
      });
    rowBegin = rowEnd = 0;
    if (!(ymax >= ymin))
    {
      return; // wholly behind the near plane (or not finite): no rows
    }
    rowBegin = std::max(0, CeilToInt(ymin - 0.5f) - kClipRowMargin);
    rowEnd = std::min(F.Height, CeilToInt(ymax - 0.5f) + kClipRowMargin);
  }

  enum class Facing
  {
    Degenerate, ///< no area (below kDegenerateArea) or not finite
    Front,
    Back,
  };
  /// The one rule for a polygon of twice-signed area `area`.
  static Facing FacingOf(double area)
  {
    if (!(std::abs(area) * 0.5 >= kDegenerateArea) || !std::isfinite(area))
    {
      return Facing::Degenerate;
    }
    return area > 0 ? Facing::Back : Facing::Front;
  }

  /// The rest of BinPolygon, once the tests are known. A polygon that
  /// cannot reach a pixel is not binned and its vertices need no shading.
  /// The facing is tested first: back faces come in runs (a mesh's
  /// neighbours are near in index order), so the culling branch is
  /// predicted, while whether a polygon of a pixel or less reaches a pixel
  /// centre is a coin toss (tested first, it cost every back face a
  /// misprediction). The counts are DrawSourcePolygon's: a degenerate
  /// polygon counts unless it was rejected in x or depth, a culled back
  /// face only where it reaches a pixel; the facing of the others goes in
  /// the entry. Returns 1 for a counted degenerate polygon.
  int64_t BinTested(int64_t p, const int64_t* ids, int count, const PolygonTests& t,
    Facing facing, std::vector<int64_t>* lists, ThreadState& state)
  {
    const bool reaches = t.hasRow & !t.rejected & !t.noPixel;
    if (facing == Facing::Degenerate)
    {
      return !(t.hasRow & t.rejected);
    }
    if (facing == Facing::Back && F.CullBack)
    {
      state.culled += reaches;
      return 0;
    }
    if (!reaches)
    {
      return 0;
    }
    for (int k = 0; k < count; ++k)
    {
      this->Buffers.Needed[ids[k]].store(1, std::memory_order_relaxed);
    }
    const int64_t flags = facing == Facing::Back ? kEntryBack : 0;
    const int firstBand = t.j0 / kBandRows, lastBand = (t.j1 - 1) / kBandRows;
    // A triangle's one pixel goes to a triangle within one band, whose
    // first row is then the draw's (OnePixel).
    const raster::OnePixel pixel = firstBand == lastBand ? t.pixel : raster::OnePixel{};
    for (int b = firstBand; b <= lastBand; ++b)
    {
      lists[b].push_back(BinEntry(p, flags | (b == firstBand ? kEntryOwner : 0), pixel));
      ++state.binned;
    }
    return 0;
  }

  /// Draws the pixels of a bin entry's polygon in one band.
  void DrawSourcePolygon(int64_t entry, int band, ThreadState& state)
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
        verts[k] = &this->Screen[ids[k]];
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
        verts[count++] = &this->Screen[ids[k]];
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

  /// The rest of DrawSourcePolygon for a polygon that is drawn: its
  /// counters (in its owner band), the stage's set-up and the scan of each
  /// part (triangle, or the polygon) in the band's rows.
  void DrawInBand(int64_t p,
    bool back,
    bool owner,
    bool wasClipped,
    const ScreenVertex** verts,
    int64_t* ids,
    int count,
    int band,
    ThreadState& state,
    raster::OnePixel onePixel = {})
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

  /// Vertices per piece of ShadeVertices: the marked vertices of a view
  /// cluster in index order, so fixed halves were uneven (the 100k torus's
  /// Gouraud lighting: 1.03 ms on one thread, 0.87 on two). 2,048 vertices
  /// are ~25-100 us of lighting, far above a piece's fetch from the counter.
  static constexpr int64_t kVertexChunk = 2048;
  /// Vertices per block of TestRuns' marks: a run of ParaView's 1M sphere
  /// spans ~530 vertices, so blocks of 256 waste at most two partial
  /// blocks a run, and the marks of 500k vertices are 2k bytes.
  static constexpr int64_t kVertexBlock = 256;
  /// DrawList's prefetch distances, in bin entries: the offsets of the
  /// entry kAheadOffsets ahead, its connectivity when it is
  /// kAheadConnectivity ahead, its vertices at kAheadVertices (a miss to
  /// memory is ~100 ns, a polygon's set-up and pixels ~50-100 ns; four
  /// entries between stages hide it without evicting what they fetched).
  static constexpr size_t kAheadOffsets = 12;
  static constexpr size_t kAheadConnectivity = 8;
  static constexpr size_t kAheadVertices = 4;
  /// Vertices prefetched per entry: a triangle's (a larger polygon's
  /// others are read on demand).
  static constexpr int64_t kPrefetchedVertices = 3;
  /// Rows added on each side of a clipped polygon's rows when it is binned:
  /// ClippedRows projects with Project, from the same clip coordinates (the
  /// same ClipToNearPlane crossings), but in another inlined copy that a
  /// build allowed to contract into FMA may round differently, and a y on
  /// a pixel centre could then land a row apart; one row covers that, and
  /// a band too many only costs a set-up that finds no row.
  static constexpr int kClipRowMargin = 1;
  /// Binning's pieces: about this many per thread, so a thread that drew
  /// the cheap ones takes more, and of at least kMinPolygonChunk polygons
  /// (~50-100 us of binning), so that a band's lists stay few: a band
  /// visits every piece's list, and each list is kept across frames.
  static constexpr int64_t kPiecesPerThread = 16;
  static constexpr int64_t kMinPolygonChunk = 4096;

  const Frame& F;
  const StageT& Stage;
  std::vector<ProjectedVertex>& Projected;
  std::vector<ScreenVertex>& Screen;
  std::vector<uint8_t>& Behind;
  std::vector<std::vector<int64_t>>& Bins;
  RasterBuffers& Buffers;
  /// Binning skips polygons between pixel columns (the plane scan only).
  const bool ColumnTest;
  int Bands = 0;  ///< kBandRows-row bands of the frame
  int Pieces = 0; ///< binning's pieces of the polygon range
  std::atomic<int> NextBand{ 0 }; ///< the next band a thread takes
};

} // namespace shadinglab::cpu
