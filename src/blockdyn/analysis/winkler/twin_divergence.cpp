// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/winkler/twin_divergence.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace blockdyn {

RotationSampler::RotationSampler(double t_end, const TwinOptions& o) {
  if (!(o.samples >= 2) || !(o.late_fraction >= 0 && o.late_fraction < 1))
    throw std::invalid_argument("twin divergence: samples must be >= 2 and late_fraction in [0, 1)");
  const double t0 = o.late_fraction * t_end;
  for (int i = 0; i < o.samples; ++i) times_.push_back(t0 + (t_end - t0) * double(i) / double(o.samples - 1));
  w_.assign(times_.size(), 0.0);
}

void RotationSampler::on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double t0, double t1,
                                 const WinklerMode& mode) {
  const auto w_at = [&](double t) {
    WinklerState z;
    seg.eval(t, z);
    m.complete(mode, z);  // contact mode integrates a reduced state
    return z[kW];
  };
  amplitude_ = std::max(amplitude_, std::fabs(w_at(t1)));
  for (; next_ < times_.size() && times_[next_] <= t1; ++next_) {
    if (times_[next_] < t0) continue;  // before the run's first segment: cannot happen after t = 0
    w_[next_] = w_at(times_[next_]);
    amplitude_ = std::max(amplitude_, std::fabs(w_[next_]));
  }
}

namespace {

bool ended_normally(SimStatus s) { return s == SimStatus::TEnd || s == SimStatus::EarlyStop; }

}  // namespace

TwinDivergence twin_divergence(const WinklerParams& p, const GroundMotion& g, const WinklerState& z0,
                               const WinklerRunOptions& sim, const TwinOptions& o, const RotationSampler& reference,
                               SimStatus reference_status) {
  if (!(o.delta != 0 && std::isfinite(o.delta)) || !(o.threshold > 0))
    throw std::invalid_argument("twin divergence: delta must be finite and non-zero, threshold > 0");
  WinklerState z1 = z0;
  z1[kVY] += o.delta;
  WinklerRunOptions s = sim;
  s.record_events = false;
  RotationSampler twin(sim.t_end, o);
  const WinklerResult r = simulate(p, g, z1, s, &twin);
  TwinDivergence d;
  d.outcome_differs = ended_normally(reference_status) != ended_normally(r.status);
  d.compared = std::min(reference.filled(), twin.filled());
  double diff = 0;
  for (std::size_t i = 0; i < d.compared; ++i) diff = std::max(diff, std::fabs(reference.w()[i] - twin.w()[i]));
  const double amp = std::max(reference.amplitude(), twin.amplitude());
  d.separation = amp > 0 ? diff / amp : 0.0;
  d.divergent = d.outcome_differs || (d.compared > 0 && d.separation >= o.threshold);
  return d;
}

TwinDivergence twin_divergence(const WinklerParams& p, const GroundMotion& g, const WinklerState& z0,
                               const WinklerRunOptions& sim, const TwinOptions& o) {
  WinklerRunOptions s = sim;
  s.record_events = false;
  RotationSampler ref(sim.t_end, o);
  const WinklerResult r = simulate(p, g, z0, s, &ref);
  return twin_divergence(p, g, z0, sim, o, ref, r.status);
}

}  // namespace blockdyn
