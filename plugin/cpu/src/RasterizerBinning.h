// SPDX-License-Identifier: BSD-3-Clause
// Rasterizer's binning: each polygon's rows, tests (area, culling, near plane, the
// one-pixel triangle) and its entries in the row bands' lists.
// Included by Rasterizer.h at its end, after the class: not on its own.
// (inline: as the definitions in the class were, for the inliner.)
#pragma once

namespace shadinglab::cpu
{

template<typename StageT>
inline int64_t Rasterizer<StageT>::BinPolygons(int64_t begin, int64_t end, int piece, ThreadState& state)
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

template<typename StageT>
inline int64_t Rasterizer<StageT>::BinRun(int64_t begin, int64_t end, std::vector<int64_t>* lists, ThreadState& state)
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

template<typename StageT>
inline int64_t Rasterizer<StageT>::BinOne(int64_t p, std::vector<int64_t>* lists, ThreadState& state)
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

template<typename StageT>
template<int N>
inline int64_t Rasterizer<StageT>::BinPolygon(int64_t p, int64_t first, int n, std::vector<int64_t>* lists,
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

template<typename StageT>
inline void Rasterizer<StageT>::ClippedRows(int64_t first, int n, int& rowBegin, int& rowEnd) const
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

template<typename StageT>
inline int64_t Rasterizer<StageT>::BinTested(int64_t p, const int64_t* ids, int count, const PolygonTests& t,
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

} // namespace shadinglab::cpu
