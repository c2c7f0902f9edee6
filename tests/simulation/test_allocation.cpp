// SPDX-License-Identifier: Apache-2.0
// The integration loop must not touch the heap: count global allocations around simulate().
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "blockdyn/model/winkler/initial_conditions.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

// The replaced operator new allocates with malloc and the replaced delete frees with free: a
// matched pair by construction, which GCC 12 at -O1 takes for a mismatch.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace blockdyn;

// Setup (validation messages, ...) may allocate a fixed amount; what must not happen is any
// allocation that grows with the number of steps or events. A short and a long run must
// therefore allocate exactly the same number of times.
TEST(Allocation, NoHeapAllocationWhileIntegrating) {
  for (double k : {1e4, 1e6, 1e8}) {
    const WinklerParams p{0.2, 0.2, k};
    const WinklerState z0 = ic1(p);
    auto count = [&](double t_end, WinklerResult& r) {
      WinklerRunOptions o;
      o.t_end = t_end;
      o.record_events = false;  // the event list is the only thing that would grow
      const long before = g_allocations.load();
      r = simulate(p, {}, z0, o);
      return g_allocations.load() - before;
    };
    WinklerResult short_run, long_run;
    const long a_short = count(0.5, short_run);
    const long a_long = count(30.0, long_run);
    EXPECT_EQ(a_short, a_long) << "k = " << k;
    EXPECT_GT(long_run.stats.accepted, 10 * short_run.stats.accepted) << "the long run must integrate";
    EXPECT_GT(long_run.event_counts[int(WinklerEventKind::WZero)], 5);
  }
}
