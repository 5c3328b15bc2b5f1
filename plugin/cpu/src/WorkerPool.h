// SPDX-License-Identifier: BSD-3-Clause
// The CPU renderer's threads, started once and kept: a frame runs six
// parallel phases (bounds, hash, project, bin, light vertices, draw bands),
// and starting and joining fresh std::threads for each cost ~0.1 ms a phase
// on the test VMs, most of a small frame (BM_CpuSmallFrame: a 320x240 frame
// of 2,304 triangles took 1.2 ms with fresh threads). A worker that has
// finished a task spins a moment for the next before it sleeps, and so
// does the caller waiting for the workers (WorkerPool.cpp).
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace shadinglab::cpu
{

class WorkerPool
{
public:
  WorkerPool() = default;
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  ~WorkerPool();

  /// Calls task(t) for t = 0 .. n-1 and returns when all have returned:
  /// t = 0 on the calling thread, the others on kept workers (started on
  /// first need). The first exception a task throws is rethrown here.
  /// Not re-entrant: one Run at a time per pool.
  void Run(int n, const std::function<void(int)>& task);

  /// Workers started so far (not counting the caller).
  int Workers() const { return static_cast<int>(this->Threads.size()); }

private:
  void WorkerLoop(int index);
  void Call(int t);

  std::mutex Mutex;
  std::condition_variable Wake, Done;
  std::vector<std::thread> Threads;
  const std::function<void(int)>* Task = nullptr;
  /// The current run, as generation << 16 | tasks: one load gives a worker
  /// both, so it never pairs one run's number with another's task count.
  std::atomic<uint64_t> Current{ 0 };
  std::atomic<int> Pending{ 0 }; ///< workers of the current run not yet finished
  std::atomic<bool> Stopping{ false };
  std::exception_ptr Error;
};

/// Splits [0, count) into `threads` contiguous ranges and calls
/// fn(begin, end, worker) for each on the pool (inline for one thread).
template<typename Fn>
void ParallelFor(WorkerPool& pool, int64_t count, int threads, Fn&& fn)
{
  if (threads <= 1 || count < 2)
  {
    fn(int64_t(0), count, 0);
    return;
  }
  const int64_t per = (count + threads - 1) / threads;
  const int used = static_cast<int>((count + per - 1) / per);
  pool.Run(used,
    [&](int t)
    {
      const int64_t b = t * per;
      fn(b, std::min(count, b + per), t);
    });
}

/// Splits [0, count) into pieces of `chunk` (piece k is [k chunk, (k + 1)
/// chunk), the last one shorter) and lets `threads` threads take them from
/// one counter as they finish the last: for per-item work whose cost is
/// uneven along the range (a vertex's lighting runs only if binning marked
/// it, and the marked vertices cluster), where fixed ranges leave one
/// thread waiting for the other. fn(piece, begin, end, worker), worker in
/// [0, threads) the thread's index; on one thread, the pieces in order.
template<typename Fn>
void ParallelChunks(WorkerPool& pool, int64_t count, int threads, int64_t chunk, Fn&& fn)
{
  chunk = std::max<int64_t>(1, chunk);
  const int64_t pieces = (std::max<int64_t>(0, count) + chunk - 1) / chunk;
  if (threads <= 1 || pieces < 2)
  {
    for (int64_t k = 0; k < pieces; ++k)
    {
      fn(k, k * chunk, std::min(count, (k + 1) * chunk), 0);
    }
    return;
  }
  std::atomic<int64_t> next{ 0 };
  pool.Run(static_cast<int>(std::min<int64_t>(threads, pieces)),
    [&](int worker)
    {
      for (int64_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < pieces;)
      {
        fn(k, k * chunk, std::min(count, (k + 1) * chunk), worker);
      }
    });
}

/// A task runner over the pool (render::Mesh::TaskRunner's signature):
/// runs task(0) .. task(n - 1) on `threads` threads, each taking the next
/// task as it finishes one, so tasks of unequal size still end together.
inline std::function<void(int, const std::function<void(int)>&)> SpreadOver(
  WorkerPool& pool, int threads)
{
  return [&pool, threads](int n, const std::function<void(int)>& task)
  {
    ParallelChunks(pool, n, threads, 1,
      [&](int64_t k, int64_t, int64_t, int) { task(static_cast<int>(k)); });
  };
}

} // namespace shadinglab::cpu
