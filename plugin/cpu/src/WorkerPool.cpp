// SPDX-License-Identifier: BSD-3-Clause
#include "WorkerPool.h"

#include <chrono>
#include <stdexcept>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace shadinglab::cpu
{

namespace
{

/// How long a thread spins for the event it waits for (a worker: the next
/// run; the caller: the workers' end) before it sleeps on a condition
/// variable. A frame's phases follow each other within ~0.1 ms, and a
/// sleeping thread woken by the kernel started ~0.1 ms late on the test
/// VMs, which the phase then waited for (the 100k torus's hash, 0.43 ms on
/// one thread, took 0.35 ms on two). 200 us covers the gap between phases
/// and bounds what a waiting thread burns once a frame is over.
constexpr auto kSpin = std::chrono::microseconds(200);

inline void CpuRelax()
{
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#else
  std::this_thread::yield();
#endif
}

/// Spins until done() or kSpin has passed; returns done().
template<typename Pred>
bool SpinFor(Pred&& done)
{
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (int k = 0; !done(); ++k)
  {
    CpuRelax();
    if ((k & 63) == 63 && std::chrono::steady_clock::now() > until)
    {
      return done();
    }
  }
  return true;
}

constexpr uint64_t kTaskBits = 16;
constexpr uint64_t kTaskMask = (uint64_t(1) << kTaskBits) - 1;

} // namespace

WorkerPool::~WorkerPool()
{
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Stopping.store(true);
  }
  this->Wake.notify_all();
  for (auto& t : this->Threads)
  {
    t.join();
  }
}

void WorkerPool::Call(int t)
{
  try
  {
    (*this->Task)(t);
  }
  catch (...)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    if (!this->Error)
    {
      this->Error = std::current_exception();
    }
  }
}

void WorkerPool::Run(int n, const std::function<void(int)>& task)
{
  if (n <= 1)
  {
    if (n == 1)
    {
      task(0);
    }
    return;
  }
  if (static_cast<uint64_t>(n) > kTaskMask)
  {
    // The run's word has 16 bits for its width; the renderer asks for at
    // most its thread count (<= 256), so this is a caller's error, said,
    // never a silently shorter run.
    throw std::length_error("WorkerPool::Run: more than 65535 tasks in one run");
  }
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    while (static_cast<int>(this->Threads.size()) < n - 1)
    {
      const int index = static_cast<int>(this->Threads.size()) + 1;
      this->Threads.emplace_back([this, index] { this->WorkerLoop(index); });
    }
    this->Task = &task;
    this->Pending.store(n - 1, std::memory_order_relaxed);
    this->Error = nullptr;
    // Published last (release): a worker that sees the new run sees the rest.
    const uint64_t generation = (this->Current.load(std::memory_order_relaxed) >> kTaskBits) + 1;
    this->Current.store(generation << kTaskBits | static_cast<uint64_t>(n), std::memory_order_release);
  }
  this->Wake.notify_all(); // for the workers asleep; spinning ones have seen it
  this->Call(0);
  auto allDone = [this] { return this->Pending.load(std::memory_order_acquire) == 0; };
  std::unique_lock<std::mutex> lock(this->Mutex, std::defer_lock);
  if (!SpinFor(allDone))
  {
    lock.lock();
    this->Done.wait(lock, allDone);
  }
  else
  {
    lock.lock(); // for Error
  }
  this->Task = nullptr;
  if (this->Error)
  {
    std::exception_ptr error = this->Error;
    this->Error = nullptr;
    lock.unlock();
    std::rethrow_exception(error);
  }
}

void WorkerPool::WorkerLoop(int index)
{
  // A worker started by a run must not skip it. It is started under the
  // mutex, which the run publishes before letting go, and the run cannot
  // end without it: what it reads under the mutex is that run.
  uint64_t seen = 0;
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    seen = (this->Current.load(std::memory_order_relaxed) >> kTaskBits) - 1;
  }
  for (;;)
  {
    uint64_t current = 0;
    auto newRun = [&]
    {
      current = this->Current.load(std::memory_order_acquire);
      return this->Stopping.load(std::memory_order_acquire) || (current >> kTaskBits) != seen;
    };
    if (!SpinFor(newRun))
    {
      std::unique_lock<std::mutex> lock(this->Mutex);
      this->Wake.wait(lock, newRun);
    }
    if (this->Stopping.load(std::memory_order_acquire))
    {
      return;
    }
    seen = current >> kTaskBits;
    if (static_cast<uint64_t>(index) >= (current & kTaskMask))
    {
      continue; // this run needs fewer workers
    }
    this->Call(index);
    if (this->Pending.fetch_sub(1, std::memory_order_acq_rel) == 1)
    {
      // Under the mutex: the caller, if asleep, checked Pending holding it.
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Done.notify_one();
    }
  }
}

} // namespace shadinglab::cpu
