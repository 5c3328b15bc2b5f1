// SPDX-License-Identifier: BSD-3-Clause
#include "WorkerPool.h"

namespace shadinglab::cpu
{

WorkerPool::~WorkerPool()
{
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Stopping = true;
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
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    while (static_cast<int>(this->Threads.size()) < n - 1)
    {
      const int index = static_cast<int>(this->Threads.size()) + 1;
      this->Threads.emplace_back([this, index] { this->WorkerLoop(index); });
    }
    this->Task = &task;
    this->Tasks = n;
    this->Pending = n - 1;
    this->Error = nullptr;
    ++this->Generation;
  }
  this->Wake.notify_all();
  this->Call(0);
  std::unique_lock<std::mutex> lock(this->Mutex);
  this->Done.wait(lock, [this] { return this->Pending == 0; });
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
  uint64_t seen = 0;
  std::unique_lock<std::mutex> lock(this->Mutex);
  // A worker started by this Run must not skip it: it has seen the runs
  // before its birth only.
  seen = this->Generation - 1;
  for (;;)
  {
    this->Wake.wait(lock, [&] { return this->Stopping || this->Generation != seen; });
    if (this->Stopping)
    {
      return;
    }
    seen = this->Generation;
    if (index >= this->Tasks)
    {
      continue; // this run needs fewer workers
    }
    lock.unlock();
    this->Call(index);
    lock.lock();
    if (--this->Pending == 0)
    {
      this->Done.notify_one();
    }
  }
}

} // namespace shadinglab::cpu
