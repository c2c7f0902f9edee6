// SPDX-License-Identifier: Apache-2.0
#pragma once
// A model-neutral view of one run for the forced-response analyses (cycles, impact maps): the
// state of every block at evenly spaced instants t0 + period j / per_period (j = 0, 1, ...;
// j = k per_period is exactly t0 + k period), the state at every step end, and the facts from
// which each model family defines its impacts (analysis/forced/forced_trace.hpp): velocity jumps,
// passages of a block's rotation through 0, contact ends closing and opening under a block.
// The runs call it; it never changes the motion.
#include <array>
#include <cstddef>

namespace blockdyn {

struct ProbeEvent {
  enum Kind : int {
    Impact,   // a velocity jump (rigid-ground block: a corner hits the ground)
    Passage,  // the block's rotation passes 0 (with the velocities across the step for the rigid law)
    Close,    // a contact end under the block closes (the block is the interface's upper block)
    Open      // a contact end under the block opens
  };
  double t = 0;
  int block = 0;
  Kind kind = Impact;
  int side = 0;  // Close, Open: the end of the interface, -1 its left end (end 0), +1 its right end
  double theta = 0, omega_before = 0, omega_after = 0;
};

class RunProbe {
 public:
  static constexpr int kMaxBlocks = 24;      // kMaxDynamicBlocks (assembly_params.hpp)
  using BlockState = std::array<double, 6>;  // x, y, theta, vx, vy, omega (ground frame of the model)

  // period <= 0: no samples, only step ends and events.
  RunProbe(double t0, double period, int per_period)
      : t0_(t0), period_(period), per_(per_period > 0 ? per_period : 1) {}
  virtual ~RunProbe() = default;

  double sample_time(long j) const { return t0_ + period_ * (double(j) / double(per_)); }
  double period() const { return period_; }
  int per_period() const { return per_; }
  double t0() const { return t0_; }

  // A piece of trajectory ending at t1: eval(t, BlockState* out) fills the blocks' states at any
  // t up to t1. Samples every instant not yet sampled up to t1, then reports the state at t1.
  template <class Eval>
  void advance(double t1, int blocks, Eval&& eval) {
    std::array<BlockState, kMaxBlocks> s{};
    while (period_ > 0 && next_t_ <= t1) {
      eval(next_t_, s.data());
      sample(next_j_, next_t_, blocks, s.data());
      ++next_j_;
      next_t_ = sample_time(next_j_);
    }
    eval(t1, s.data());
    step_end(t1, blocks, s.data());
  }
  virtual void event(const ProbeEvent&) {}
  // The run ended at t (t_end, failure or an invalid state).
  virtual void finish(double /*t*/) {}

 protected:
  virtual void sample(long j, double t, int blocks, const BlockState* s) = 0;
  virtual void step_end(double /*t*/, int /*blocks*/, const BlockState* /*s*/) {}

 private:
  double t0_, period_;
  int per_;
  long next_j_ = 0;
  double next_t_ = t0_;
};

}  // namespace blockdyn
