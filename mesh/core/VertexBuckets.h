// SPDX-License-Identifier: BSD-3-Clause
// The corners of every vertex as one table (CSR), built by two threads in
// the order one pass over the faces lists them: the orientation check's
// outgoing edges and the normals' corner table.
#pragma once

#include "Geometry.h"
#include "TwoThreads.h"

#include <cstdint>
#include <vector>

namespace shadinglab::mesh
{

/// Corners below which the table is built by one thread: a thread's start
/// (~50 us) is more than half the work of 2^16 corners (~0.2 ms).
constexpr int64_t kParallelBucketCorners = int64_t(1) << 16;

/**
 * Buckets the corners of `m` by vertex: afterwards vertex v's corners take
 * the slots [start[v], start[v + 1]) (start: numberOfPoints + 1 entries,
 * Slot wide enough for the corner count), and fill(f, b, e, c, slot) has
 * been called once for each corner c of each face f (whose corners are
 * [b, e)) with its slot. Within a bucket, corners are in face order then
 * corner order, as one serial pass puts them: the result does not depend
 * on the threads. The faces are split in two halves, each counted and
 * filled by one thread with its own cursor per vertex (one extra table of
 * numberOfPoints + 1 entries). fill must be safe to call from two threads
 * for different corners.
 */
template <typename Real, typename Id, typename Slot, typename Fill>
void BucketCornersByVertex(const MeshViewOf<Real, Id>& m, std::vector<Slot>& start, Fill&& fill)
{
  const int64_t nv = m.numberOfPoints, np = m.numberOfPolygons;
  const int64_t nc = np > 0 ? m.offsets[np] : 0;
  const int64_t split = nc < kParallelBucketCorners ? np : np / 2;
  // Counts: faces [0, split) into `start`, the rest into `second`.
  start.assign(static_cast<size_t>(nv + 1), 0);
  std::vector<Slot> second(static_cast<size_t>(nv + 1), 0);
  auto count = [&](std::vector<Slot>& counts, int64_t c0, int64_t c1) {
    for (int64_t c = c0; c < c1; ++c)
    {
      ++counts[static_cast<size_t>(m.connectivity[c])];
    }
  };
  const int64_t middle = m.offsets[split];
  RunBoth(split < np, [&] { count(start, 0, middle); }, [&] { count(second, middle, nc); });
  // Cursors: the first half's corners of v from the bucket's start, the
  // second half's after them.
  Slot running = 0;
  for (int64_t v = 0; v < nv; ++v)
  {
    const Slot a = start[static_cast<size_t>(v)], b = second[static_cast<size_t>(v)];
    start[static_cast<size_t>(v)] = running;
    second[static_cast<size_t>(v)] = static_cast<Slot>(running + a);
    running = static_cast<Slot>(running + a + b);
  }
  auto place = [&](std::vector<Slot>& cursor, int64_t f0, int64_t f1) {
    for (int64_t f = f0; f < f1; ++f)
    {
      const int64_t b = m.offsets[f], e = m.offsets[f + 1];
      for (int64_t c = b; c < e; ++c)
      {
        fill(f, b, e, c, static_cast<int64_t>(cursor[static_cast<size_t>(m.connectivity[c])]++));
      }
    }
  };
  RunBoth(split < np, [&] { place(start, 0, split); }, [&] { place(second, split, np); });
  // The second cursors ended at their buckets' ends: start[v + 1].
  for (int64_t v = nv; v > 0; --v)
  {
    start[static_cast<size_t>(v)] = second[static_cast<size_t>(v - 1)];
  }
  start[0] = 0;
}

} // namespace shadinglab::mesh
