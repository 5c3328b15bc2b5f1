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
#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/render/Display.h"
#include "WorkerPool.h"

#include <atomic>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

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

/// An allocator whose resize leaves new elements uninitialised (for
/// trivial records): the pages of a vertex array the frame never writes
/// (vertices of faces turned away or never drawn) are never touched, so
/// never resident (16M triangles: ~0.2 GB). Unwritten records are never
/// read (at a steady size a resize keeps the last frame's records anyway).
template<typename T>
struct UninitializedAllocator : std::allocator<T>
{
  static_assert(std::is_trivially_default_constructible_v<T>);
  template<typename U>
  struct rebind
  {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template<typename U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept
  {
  }
  template<typename U>
  void construct(U* p) noexcept
  {
    ::new (static_cast<void*>(p)) U; // default-initialised: left as it is
  }
  template<typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
template<typename T>
using UninitializedVector = std::vector<T, UninitializedAllocator<T>>;

/// Screen records are kept for the drawn vertices only (with a 4-byte slot
/// per vertex) when at most this share of the vertices is drawn. A big
/// mesh at screen size draws few: of the 16M-triangle torus at 1080p, 4 %
/// of the triangles reach a pixel centre and 1.9M of its 8M vertices are
/// drawn, so compact records are 130 MB with the slots instead of 416 (a
/// frame has ~2M pixels, whatever the mesh). Records cost 52 bytes and a
/// slot 4, so compact saves memory below ~90 %; the slot is one more
/// dependent load per vertex in the draw, so a mostly drawn mesh (a model
/// filling the view) keeps records by vertex.
constexpr double kCompactNeededShare = 0.5;
/// ... and when records by vertex would take at least this many bytes.
/// Below it the saving is small and the slot's load is not: ParaView's 1M
/// sphere at 1080p (500k vertices, 26 MB of records) draws 41 % of its
/// vertices, and compact records made its frames 2.5-3.4 % slower for 13
/// MB saved (BM_CpuScreenRecords); at 16M triangles they are smaller and
/// faster (render 0.46 -> 0.38 s: less memory touched).
constexpr size_t kCompactMinimumBytes = size_t(64) << 20;

/// Whether a frame drawing `drawn` of `vertices` vertices keeps compact
/// screen records (without cpu::SetScreenRecords forcing a layout).
inline bool CompactRecordsPay(int64_t drawn, int64_t vertices)
{
  return static_cast<double>(drawn) <= kCompactNeededShare * static_cast<double>(vertices) &&
    static_cast<size_t>(vertices) * sizeof(ScreenVertex) >= kCompactMinimumBytes;
}

/// Buffers the rasterizer keeps across frames (no reallocation at a steady size).
struct RasterBuffers
{
  /// Every vertex's projection, 16 bytes: binning reads these for every
  /// polygon, and reading whole ScreenVertex records (52 bytes, 26 MB for
  /// ParaView's 1M sphere) made it wait on memory.
  UninitializedVector<ProjectedVertex> Projected;
  /// The vertices drawn (binning marked them Needed): projection and
  /// attributes, filled by ShadeVertices. Indexed by vertex id, or, when
  /// few vertices are drawn (CompactRecordsPay), one record per drawn
  /// vertex in id order, found through ScreenSlot.
  UninitializedVector<ScreenVertex> Screen;
  /// With compact records: vertex id -> its record in Screen (drawn
  /// vertices only; the others' entries are never written or read).
  UninitializedVector<uint32_t> ScreenSlot;
  bool CompactScreen = false;
  int64_t ScreenRecordsMade = 0; ///< this frame's drawn vertices (RenderStats)
  /// ShadeVertices' drawn vertices per piece, then each piece's first record.
  std::vector<int64_t> PieceRecords;
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
  void TestRuns();

  /// The vertex stage, first half: clip coordinates and screen positions of
  /// every vertex (in parallel). The stage's attributes (for Gouraud, the
  /// whole lighting model) wait for ShadeVertices, after binning has marked
  /// the vertices of the polygons that can reach a pixel: a mesh half
  /// outside the view lights half its vertices.
  void ProjectPositions();

  /// The vertex stage, second half: the screen vertices binning marked,
  /// their projection and the stage's attributes scaled by its 1/w
  /// (ToScreen, as for clipped vertices). Counts them first, and keeps
  /// compact records when few are (CompactRecordsPay).
  void ShadeVertices();

  /// Vertex v's screen record (v marked Needed and not Behind).
  const ScreenVertex* ScreenOf(int64_t v) const
  {
    return this->Buffers.CompactScreen
      ? &this->Screen[this->Buffers.ScreenSlot[static_cast<size_t>(v)]]
      : &this->Screen[static_cast<size_t>(v)];
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
  ProjectedVertex Project(const double clip[4]) const;

  /// The screen vertex of a projection and the stage's raw attributes,
  /// scaled by its 1/w: a marked vertex (ShadeVertices) or a clipped one.
  void ToScreen(const ProjectedVertex& pv, const float* raw, ScreenVertex& out) const;

  void RasterizeThread(ThreadState& state);

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
  void DrawList(const std::vector<int64_t>& list, int band, ThreadState& state);

  static int64_t RoundUp(int64_t n, int64_t multiple) { return (n + multiple - 1) / multiple * multiple; }

  /// Bins a piece's polygons, run by run (begin is a multiple of
  /// kClusterPolygons): a run whose cone faces away is skipped whole.
  int64_t BinPolygons(int64_t begin, int64_t end, int piece, ThreadState& state);

  /// Bins polygons [begin, end): four triangles at a time where they are
  /// (BinFour.h), the others one by one.
  int64_t BinRun(int64_t begin, int64_t end, std::vector<int64_t>* lists, ThreadState& state);

  /// Bins polygon p alone.
  int64_t BinOne(int64_t p, std::vector<int64_t>* lists, ThreadState& state);

  /// Bins polygon p (its n vertices from connectivity[first]; N = n known
  /// at compile time, or 0); returns 1 when it has no pixel row and is
  /// degenerate.
  template<int N>
  int64_t BinPolygon(int64_t p, int64_t first, int n, std::vector<int64_t>* lists,
    ThreadState& state);

  /// Rows [rowBegin, rowEnd) that polygon `first`'s part in front of the
  /// near plane may reach, by DrawSourcePolygon's clipping on positions
  /// only, widened by kClipRowMargin (the bins need a superset of the rows:
  /// DrawSourcePolygon finds the exact ones). Empty when no part is in front.
  void ClippedRows(int64_t first, int n, int& rowBegin, int& rowEnd) const;

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
    Facing facing, std::vector<int64_t>* lists, ThreadState& state);

  /// Draws the pixels of a bin entry's polygon in one band.
  void DrawSourcePolygon(int64_t entry, int band, ThreadState& state);

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
    raster::OnePixel onePixel = {});

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
  /// (Compact screen records) the slots of the entry this far ahead, read
  /// between its connectivity and its vertices.
  static constexpr size_t kAheadSlots = 6;
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
  UninitializedVector<ProjectedVertex>& Projected;
  UninitializedVector<ScreenVertex>& Screen;
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

// The stages' definitions, a file each.
#include "RasterizerVertices.h" // IWYU pragma: keep
#include "RasterizerBinning.h"  // IWYU pragma: keep
#include "RasterizerDraw.h"     // IWYU pragma: keep
