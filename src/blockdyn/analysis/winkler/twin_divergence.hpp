// SPDX-License-Identifier: Apache-2.0
#pragma once
// Sensitive dependence on initial conditions, measured directly (thesis sec. 5.2, Table 5.1): the
// run is repeated from a start whose y'(0) differs by `delta`, and the rotations of the two runs
// are compared on a fixed time grid over the late window. The two starts are called divergent when
// the largest difference of w there reaches `threshold` times the amplitude of w over the whole
// run, i.e. the two motions differ by as much as the block rocked (a 1e-8 start grown by > 1e6).
// The whole run, not the late window: a block that came to rest keeps a vibration of ~1e-6 rad
// whose phase may differ between the two runs; that is not a different motion. Without sensitive
// dependence the difference stays near delta times a slowly growing factor (phase drift). This
// costs one extra run per point; the Lyapunov exponent (lyapunov.hpp) measures the growth rate,
// this only whether it took the two starts apart within t_end.
#include <vector>

#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

struct TwinOptions {
  double delta = 1e-8;         // added to y'(0) of the second start
  double late_fraction = 0.5;  // compare over [late_fraction t_end, t_end] (the response's late window)
  int samples = 1000;          // grid points in that window
  double threshold = 0.1;      // divergent: max late |w_a - w_b| >= threshold * max over the run of |w|
};

// Samples w on the dense output at the grid times of the late window, and the amplitude of w over
// the whole run (at every step end and sample).
class RotationSampler : public WinklerSink {
 public:
  RotationSampler(double t_end, const TwinOptions& o);
  void on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double t0, double t1,
                  const WinklerMode& mode) override;
  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& w() const { return w_; }
  std::size_t filled() const { return next_; }  // samples reached (fewer if the run stopped early)
  double amplitude() const { return amplitude_; }

 private:
  std::vector<double> times_, w_;
  std::size_t next_ = 0;
  double amplitude_ = 0;
};

struct TwinDivergence {
  bool divergent = false;
  bool outcome_differs = false;  // one run overturned (or failed) and the other did not
  double separation = 0;         // max |w_a - w_b| over the common late samples / amplitude of w
  std::size_t compared = 0;      // samples compared
};

// Compares the reference run (its sampler and status) with the twin started from z0 + delta e_y'.
TwinDivergence twin_divergence(const WinklerParams& p, const GroundMotion& g, const WinklerState& z0,
                               const WinklerRunOptions& sim, const TwinOptions& o, const RotationSampler& reference,
                               SimStatus reference_status);

// Both runs: the reference and its twin.
TwinDivergence twin_divergence(const WinklerParams& p, const GroundMotion& g, const WinklerState& z0,
                               const WinklerRunOptions& sim, const TwinOptions& o = {});

}  // namespace blockdyn
