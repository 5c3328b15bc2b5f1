// SPDX-License-Identifier: BSD-3-Clause
// Two pieces of work at once: the mesh kernels' one form of parallelism
// (the machines this runs on have two cores; each kernel splits its work
// in halves whose results it joins in order, so they do not depend on it).
#pragma once

#include <thread>

namespace shadinglab::mesh
{

/// Runs second() on a thread of its own while first() runs here, when
/// `together`; else first() then second(). Returns when both have.
template <typename First, typename Second>
void RunBoth(bool together, First&& first, Second&& second)
{
  if (!together)
  {
    first();
    second();
    return;
  }
  std::thread other(second);
  first();
  other.join();
}

} // namespace shadinglab::mesh
