// SPDX-License-Identifier: BSD-3-Clause
#include "HiddenBackFaces.h"

#include "Geometry.h"
#include "Raster.h"

#include <cstring>
#include <limits>
#include <numeric>
#include <vector>

namespace shadinglab::cpu
{

namespace
{

/// Union-find over vertices (mesh/core/Geometry.h).
uint32_t Root(std::vector<uint32_t>& parent, uint32_t v)
{
  return mesh::UnionFindRoot(parent, v);
}

/// Four independent multiply-xor lanes over 64-bit words (one chain would
/// be bound by the multiply's latency), folded at the end.
uint64_t HashWords(const void* data, size_t bytes, uint64_t seed)
{
  constexpr uint64_t kMul = 0x9E3779B97F4A7C15ull;
  uint64_t h[4] = { seed, seed ^ 0x1234567ull, seed ^ 0x89abcdefull, seed ^ 0x5555aaaaull };
  const auto* p = static_cast<const unsigned char*>(data);
  size_t i = 0;
  for (; i + 32 <= bytes; i += 32)
  {
    for (int k = 0; k < 4; ++k)
    {
      uint64_t w;
      std::memcpy(&w, p + i + 8 * k, 8);
      h[k] = (h[k] ^ w) * kMul;
      h[k] ^= h[k] >> 29;
    }
  }
  // The last 0-31 bytes: whole words, then the 0-7 left over.
  for (; i + 8 <= bytes; i += 8)
  {
    uint64_t w;
    std::memcpy(&w, p + i, 8);
    h[0] = (h[0] ^ w) * kMul;
    h[0] ^= h[0] >> 29;
  }
  uint64_t tail = 0;
  if (bytes > i)
  {
    std::memcpy(&tail, p + i, bytes - i);
  }
  uint64_t out = (h[0] ^ tail) * kMul;
  for (int k = 1; k < 4; ++k)
  {
    out = (out ^ h[k]) * kMul;
    out ^= out >> 31;
  }
  return out ^ bytes;
}

} // namespace

uint64_t MeshFingerprint(const render::Mesh& mesh, int threads)
{
  // Each array in `threads` slices of whole 32-byte blocks; the slices'
  // hashes are folded in order, so the value does not depend on timing.
  const struct
  {
    const void* data;
    size_t bytes;
  } arrays[3] = { { mesh.points.data(), mesh.points.size() * sizeof(float) },
    { mesh.offsets.data(), mesh.offsets.size() * sizeof(int64_t) },
    { mesh.connectivity.data(), mesh.connectivity.size() * sizeof(int64_t) } };
  const int slices = std::max(1, threads);
  uint64_t h = 1;
  for (const auto& a : arrays)
  {
    std::vector<uint64_t> part(static_cast<size_t>(slices), 0);
    const size_t blocks = a.bytes / 32, per = (blocks + slices - 1) / slices;
    raster::ParallelFor(slices, slices,
      [&](int64_t b, int64_t e, int)
      {
        for (int64_t s = b; s < e; ++s)
        {
          const size_t first = std::min(blocks, s * per) * 32;
          const size_t last = s + 1 == slices ? a.bytes : std::min(blocks, (s + 1) * per) * 32;
          part[s] = HashWords(static_cast<const unsigned char*>(a.data) + first, last - first,
            static_cast<uint64_t>(s) + 1);
        }
      });
    for (const uint64_t p : part)
    {
      h = HashWords(&p, sizeof(p), h);
    }
    h ^= a.bytes;
  }
  return h;
}

bool IsClosedOutwardTriangleMesh(const render::Mesh& mesh)
{
  const int64_t nv = mesh.NumberOfPoints(), np = mesh.NumberOfPolygons();
  const int64_t corners = static_cast<int64_t>(mesh.connectivity.size());
  // 32-bit tables: a mesh with 2^31 points or corners is not looked at.
  if (np == 0 || nv >= std::numeric_limits<int32_t>::max() ||
    corners >= std::numeric_limits<int32_t>::max() || corners != 3 * np)
  {
    return false;
  }
  for (int64_t p = 0; p < np; ++p)
  {
    if (mesh.offsets[p + 1] - mesh.offsets[p] != 3)
    {
      return false;
    }
  }
  const int64_t* conn = mesh.connectivity.data();
  // Directed edges a -> b grouped by a (CSR).
  std::vector<uint32_t> start(static_cast<size_t>(nv) + 1, 0);
  for (int64_t k = 0; k < corners; ++k)
  {
    if (conn[k] < 0 || conn[k] >= nv)
    {
      return false;
    }
    ++start[conn[k] + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<uint32_t> head(static_cast<size_t>(corners));
  {
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (int64_t t = 0; t < np; ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int64_t a = conn[3 * t + k], b = conn[3 * t + (k + 1) % 3];
        if (a == b)
        {
          return false; // a collapsed edge
        }
        head[fill[a]++] = static_cast<uint32_t>(b);
      }
    }
  }
  // Each directed edge exactly once, its reverse exactly once.
  auto count = [&](uint32_t a, uint32_t b)
  {
    int c = 0;
    for (uint32_t k = start[a]; k < start[a + 1]; ++k)
    {
      c += head[k] == b;
    }
    return c;
  };
  for (uint32_t a = 0; a < static_cast<uint32_t>(nv); ++a)
  {
    for (uint32_t k = start[a]; k < start[a + 1]; ++k)
    {
      if (count(a, head[k]) != 1 || count(head[k], a) != 1)
      {
        return false;
      }
    }
  }
  // Components (by shared vertices) and their signed volumes, from the
  // bounding-box centre (divergence theorem: sum of det(p0, p1, p2) / 6).
  std::vector<uint32_t> parent(static_cast<size_t>(nv));
  std::iota(parent.begin(), parent.end(), 0u);
  double lo[3], hi[3];
  for (int c = 0; c < 3; ++c)
  {
    lo[c] = std::numeric_limits<double>::infinity();
    hi[c] = -lo[c];
  }
  for (int64_t v = 0; v < nv; ++v)
  {
    for (int c = 0; c < 3; ++c)
    {
      lo[c] = std::min(lo[c], double(mesh.points[3 * v + c]));
      hi[c] = std::max(hi[c], double(mesh.points[3 * v + c]));
    }
  }
  const double centre[3] = { 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]) };
  for (int64_t k = 0; k < corners; k += 3)
  {
    const uint32_t a = Root(parent, static_cast<uint32_t>(conn[k]));
    parent[Root(parent, static_cast<uint32_t>(conn[k + 1]))] = a;
    parent[Root(parent, static_cast<uint32_t>(conn[k + 2]))] = a;
  }
  std::vector<double> volume(static_cast<size_t>(nv), 0.0);
  for (int64_t t = 0; t < np; ++t)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        p[k][c] = double(mesh.points[3 * conn[3 * t + k] + c]) - centre[c];
      }
    }
    const double det = p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
      p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
      p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
    volume[Root(parent, static_cast<uint32_t>(conn[3 * t]))] += det;
  }
  for (uint32_t v = 0; v < static_cast<uint32_t>(nv); ++v)
  {
    // A component's volume sits at its root; vertices used by no triangle
    // are their own roots with volume 0 and do not count.
    if (parent[v] == v && start[v + 1] > start[v] && !(volume[v] > 0.0))
    {
      return false;
    }
  }
  return true;
}

bool ClosedMeshCache::IsClosedOutward(const render::Mesh& mesh, bool mayTest, int threads)
{
  const uint64_t fingerprint = MeshFingerprint(mesh, threads);
  if (!this->Known || fingerprint != this->Fingerprint)
  {
    if (!mayTest)
    {
      return false;
    }
    this->Closed = IsClosedOutwardTriangleMesh(mesh);
    this->Fingerprint = fingerprint;
    this->Known = true;
  }
  return this->Closed;
}

} // namespace shadinglab::cpu
