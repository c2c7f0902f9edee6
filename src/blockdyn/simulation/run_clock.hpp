// SPDX-License-Identifier: Apache-2.0
#pragma once
// Wall and CPU time of one integration (the CPU time of the calling thread, so that runs on the
// threads of a sweep are timed each on its own), for the `timing` member of the JSON summaries.
#include <time.h>

#include <chrono>

namespace blockdyn {

struct RunTiming {
  double wall_s = 0.0;
  double cpu_s = 0.0;
};

class RunClock {
 public:
  RunClock() : wall0_(std::chrono::steady_clock::now()), cpu0_(thread_cpu()) {}
  RunTiming elapsed() const {
    const std::chrono::duration<double> w = std::chrono::steady_clock::now() - wall0_;
    return {w.count(), thread_cpu() - cpu0_};
  }

 private:
  static double thread_cpu() {
    timespec ts{};
    ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
  }
  std::chrono::steady_clock::time_point wall0_;
  double cpu0_;
};

}  // namespace blockdyn
