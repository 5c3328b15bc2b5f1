// SPDX-License-Identifier: BSD-3-Clause
// The CPU renderer's kept threads (plugin/cpu/src/WorkerPool.h): every task
// runs once per Run, on as many threads as asked, the pool grows and shrinks
// its use between runs, and a task's exception reaches the caller.
#include "WorkerPool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace cpu = shadinglab::cpu;

TEST(WorkerPoolTest, EveryTaskRunsOnceAcrossManyRunsOfChangingWidth)
{
  cpu::WorkerPool pool;
  for (int run = 0; run < 2000; ++run)
  {
    const int n = 1 + run % 5; // 1..5: workers started, then used partly
    std::vector<std::atomic<int>> calls(static_cast<size_t>(n));
    pool.Run(n, [&](int t) { calls[static_cast<size_t>(t)].fetch_add(1); });
    for (int t = 0; t < n; ++t)
    {
      ASSERT_EQ(calls[static_cast<size_t>(t)].load(), 1) << "run " << run << " task " << t;
    }
  }
  EXPECT_EQ(pool.Workers(), 4); // the widest run's n - 1, kept
}

TEST(WorkerPoolTest, TaskZeroOnTheCallerOthersOnDistinctThreads)
{
  cpu::WorkerPool pool;
  std::vector<std::thread::id> ids(4);
  pool.Run(4, [&](int t) { ids[static_cast<size_t>(t)] = std::this_thread::get_id(); });
  EXPECT_EQ(ids[0], std::this_thread::get_id());
  EXPECT_EQ(std::set<std::thread::id>(ids.begin(), ids.end()).size(), 4u);
}

TEST(WorkerPoolTest, ExceptionOfAWorkerReachesTheCallerAndThePoolGoesOn)
{
  cpu::WorkerPool pool;
  EXPECT_THROW(pool.Run(3,
                 [](int t)
                 {
                   if (t == 2)
                   {
                     throw std::runtime_error("task 2");
                   }
                 }),
    std::runtime_error);
  std::atomic<int> sum{ 0 };
  pool.Run(3, [&](int t) { sum += t + 1; });
  EXPECT_EQ(sum.load(), 6);
}

TEST(WorkerPoolTest, ParallelForCoversTheRangeOnceInContiguousPieces)
{
  cpu::WorkerPool pool;
  for (int64_t count : { 0, 1, 2, 3, 7, 1000, 1001 })
  {
    for (int threads : { 1, 2, 3, 8 })
    {
      std::vector<std::atomic<int>> hits(static_cast<size_t>(count));
      std::atomic<int> maxWorker{ -1 };
      cpu::ParallelFor(pool, count, threads,
        [&](int64_t b, int64_t e, int w)
        {
          for (int64_t i = b; i < e; ++i)
          {
            hits[static_cast<size_t>(i)].fetch_add(1);
          }
          int m = maxWorker.load();
          while (w > m && !maxWorker.compare_exchange_weak(m, w))
          {
          }
        });
      for (int64_t i = 0; i < count; ++i)
      {
        ASSERT_EQ(hits[static_cast<size_t>(i)].load(), 1) << count << " " << threads;
      }
      EXPECT_LT(maxWorker.load(), threads);
    }
  }
}

// Workers spin a moment after a task and then sleep on the condition
// variable (WorkerPool.cpp, kSpin = 200 us): runs that follow at once (the
// spinning hand-off) and runs after a pause long enough for every worker
// to have gone to sleep (the sleeping hand-off) both run every task once
// and see what the caller wrote before the run.
TEST(WorkerPoolTest, RunsAfterSpinningAndAfterSleepingWorkersSeeTheCallersWrites)
{
  cpu::WorkerPool pool;
  std::vector<int> input(3, 0);
  for (int run = 0; run < 40; ++run)
  {
    for (int t = 0; t < 3; ++t)
    {
      input[static_cast<size_t>(t)] = run * 10 + t; // plain writes, before the run
    }
    std::vector<int> seen(3, -1);
    pool.Run(3, [&](int t) { seen[static_cast<size_t>(t)] = input[static_cast<size_t>(t)]; });
    for (int t = 0; t < 3; ++t)
    {
      ASSERT_EQ(seen[static_cast<size_t>(t)], run * 10 + t) << "run " << run;
    }
    if (run % 4 == 3)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(3)); // past the spin: workers asleep
    }
  }
}

TEST(WorkerPoolTest, MoreTasksThanARunCanCountIsAnErrorNotAShorterRun)
{
  cpu::WorkerPool pool;
  std::atomic<int> calls{ 0 };
  EXPECT_THROW(pool.Run(70000, [&](int) { calls.fetch_add(1); }), std::length_error);
  EXPECT_EQ(calls.load(), 0);
  pool.Run(2, [&](int) { calls.fetch_add(1); }); // and the pool goes on
  EXPECT_EQ(calls.load(), 2);
}

TEST(WorkerPoolTest, ParallelChunksCoversTheRangeOnceInNumberedPieces)
{
  cpu::WorkerPool pool;
  for (int64_t count : { 0, 1, 5, 4096, 10000 })
  {
    for (int threads : { 1, 2, 3 })
    {
      for (int64_t chunk : { 1, 7, 1000 })
      {
        std::vector<std::atomic<int>> hits(static_cast<size_t>(count));
        std::atomic<bool> wrongPiece{ false }, wrongWorker{ false };
        cpu::ParallelChunks(pool, count, threads, chunk,
          [&](int64_t piece, int64_t b, int64_t e, int w)
          {
            // Piece k is [k chunk, (k + 1) chunk) on any number of threads.
            if (b != piece * chunk || e != std::min(count, b + chunk))
            {
              wrongPiece = true;
            }
            if (w < 0 || w >= std::max(1, threads))
            {
              wrongWorker = true;
            }
            for (int64_t i = b; i < e; ++i)
            {
              hits[static_cast<size_t>(i)].fetch_add(1);
            }
          });
        EXPECT_FALSE(wrongPiece.load()) << count << " " << threads << " " << chunk;
        EXPECT_FALSE(wrongWorker.load());
        for (int64_t i = 0; i < count; ++i)
        {
          ASSERT_EQ(hits[static_cast<size_t>(i)].load(), 1) << "item " << i;
        }
      }
    }
  }
}
