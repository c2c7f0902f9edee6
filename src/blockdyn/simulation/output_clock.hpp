// SPDX-License-Identifier: Apache-2.0
#pragma once
// Output instants t0 + n * interval of a trajectory writer, computed from n so that no rounding
// drift accumulates; each instant is handed out once, in order, as the run's pieces arrive.
#include <functional>

namespace blockdyn {

class OutputClock {
 public:
  void start(double t0, double interval) {
    t0_ = t0;
    interval_ = interval;
    n_ = 1;
    next_ = t0 + interval;
  }
  bool every_step() const { return interval_ <= 0.0; }
  // Calls f(t) for the output instants of a piece of trajectory ending at t1: its end when every
  // step is written, else the fixed instants up to t1.
  template <class F>
  void emit(double t1, F&& f) {
    if (every_step())
      f(t1);
    else
      emit_until(t1, f);
  }
  // Calls f(t) for every output instant in (previous piece, t1].
  template <class F>
  void emit_until(double t1, F&& f) {
    while (next_ <= t1) {
      f(next_);
      ++n_;
      next_ = t0_ + double(n_) * interval_;
    }
  }

 private:
  double t0_ = 0, interval_ = 0, next_ = 0;
  long n_ = 0;
};

}  // namespace blockdyn
