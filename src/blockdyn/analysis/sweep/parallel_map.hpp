// SPDX-License-Identifier: Apache-2.0
#pragma once
// Deterministic parallel map over indices 0..n-1: results land at their own index, so the
// output is identical for any thread count. Work is handed out dynamically (an atomic
// counter), which keeps both cores busy when run times differ wildly between points.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace blockdyn {

// Number of worker threads to use: `requested` if > 0, else the hardware concurrency.
inline int resolve_threads(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw ? int(hw) : 1;
}

// Calls fn(i) for every i in [0, n) on `threads` threads. `done(i)` (optional) is called under
// a lock after each completed index, e.g. for progress or incremental output. The first
// exception thrown by fn stops the hand-out of new work and is rethrown.
inline void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& fn,
                         const std::function<void(std::size_t)>& done = {}) {
  const int nt = std::max(1, std::min<int>(resolve_threads(threads), int(std::max<std::size_t>(n, 1))));
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex mu;
  auto worker = [&] {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= n || failed.load()) return;
      try {
        fn(i);
        if (done) {
          std::lock_guard<std::mutex> lock(mu);
          done(i);
        }
      } catch (...) {
        std::lock_guard<std::mutex> lock(mu);
        if (!error) error = std::current_exception();
        failed = true;
        return;
      }
    }
  };
  if (nt == 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    pool.reserve(nt);
    for (int t = 0; t < nt; ++t) pool.emplace_back(worker);
    for (auto& th : pool) th.join();
  }
  if (error) std::rethrow_exception(error);
}

template <class R, class F>
std::vector<R> parallel_map(std::size_t n, int threads, F&& fn) {
  std::vector<R> out(n);
  parallel_for(n, threads, [&](std::size_t i) { out[i] = fn(i); });
  return out;
}

}  // namespace blockdyn
