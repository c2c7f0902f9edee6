// SPDX-License-Identifier: Apache-2.0
#pragma once
// The record of one run under periodic forcing for the cycle and impact-map analyses (issue 9
// items 4-5): the blocks' states at t0 + period j / per_period (the stroboscopic samples are
// j = k per_period, exactly t0 + k period), the largest |theta| and |theta'| of each block per
// forcing period, and the passages, contact closings/openings and velocity jumps the run reports.
//
// What an impact is, per model family (docs/cycles.md):
// - a block on rigid ground (housner, rigid): every velocity jump the model applies - at theta = 0
//   the pivot changes (Housner), or a corner lands (3-DOF block); theta' before and after are the
//   jump's sides, exact;
// - an assembly (deformable or rigid contacts): a passage of the block's rotation through 0 after
//   the block lifted (a contact end under it opened since the previous impact), i.e. the rocking
//   pivot changed sides; passages while every end stays closed (elastic vibration) are not
//   impacts. theta' before is the block's angular velocity when the hitting base corner (the
//   right one when theta decreases through 0) closed its contact: the last such closing since
//   the previous impact, else the first one after the passage (the rigid law closes it in the
//   time step after the crossing); after is the velocity after that closing's impulse (rigid
//   law) or at the passage (deformable law: inside the contact phase, about a millisecond long).
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/analysis/forced/cycle_detection.hpp"
#include "blockdyn/simulation/run_probe.hpp"

namespace blockdyn {

enum class ImpactRule { VelocityJump, Passage };

struct Impact {
  double t = 0;
  double omega_before = 0, omega_after = 0;  // the block's angular velocity (rad/s)
};

class ForcedTrace final : public RunProbe {
 public:
  using RunProbe::RunProbe;

  // Samples (per_period per forcing period) and their block states, blocks() states per sample.
  int blocks() const { return blocks_; }
  std::size_t samples() const { return t_.size(); }
  double sample_t(std::size_t i) const { return t_[i]; }
  const BlockState& state(std::size_t i, int block) const { return s_[i * blocks_ + block]; }
  // Stroboscopic samples: every per_period-th sample (k = 0, 1, ...).
  std::size_t strobes() const { return t_.empty() ? 0 : (t_.size() - 1) / per_period() + 1; }
  double strobe_t(std::size_t k) const { return t_[k * per_period()]; }
  const BlockState& strobe(std::size_t k, int block) const { return state(k * per_period(), block); }
  // Largest |theta| and |theta'| of a block over forcing period k ([t0 + k T, t0 + (k+1) T)),
  // from every step end and sample (0 for periods the run did not reach).
  double theta_amplitude(std::size_t k, int block) const;
  double omega_amplitude(std::size_t k, int block) const;
  const std::vector<ProbeEvent>& events() const { return ev_; }
  double t_final() const { return t_final_; }

  // Keep the events of this block only (-1: all; the default). A long assembly run reports
  // thousands of contact events per minute and block; the analyses look at one block.
  void keep_events_of(int block) { keep_ = block; }
  void event(const ProbeEvent& e) override;
  void finish(double t) override { t_final_ = t; }

 protected:
  void sample(long j, double t, int blocks, const BlockState* s) override;
  void step_end(double t, int blocks, const BlockState* s) override;

 private:
  void track(double t, int blocks, const BlockState* s);
  int blocks_ = 0;
  std::vector<double> t_;
  std::vector<BlockState> s_;
  std::vector<double> amp_;  // per period, per block: |theta|max, |theta'|max
  std::vector<ProbeEvent> ev_;
  double t_final_ = 0;
  int keep_ = -1;
};

// The impacts of `block` under `rule` (see above), in time order.
std::vector<Impact> impacts_of(const ForcedTrace& tr, int block, ImpactRule rule);
// The stroboscopic series of `block` (theta, theta' and the amplitudes per forcing period).
StrobeSeries strobe_series(const ForcedTrace& tr, int block);
// The cycles of `block` over the run (t_failure: the run failed then).
CycleReport cycles_of(const ForcedTrace& tr, int block, ImpactRule rule, const CycleOptions& o,
                      std::optional<double> t_failure = std::nullopt);
// The dominant cycle label of `block` with the window fitted to the run's length ("" when the run
// is too short for a window of 2 periods).
std::string dominant_cycle(const ForcedTrace& tr, int block, ImpactRule rule, const CycleOptions& o,
                           std::optional<double> t_failure = std::nullopt);

}  // namespace blockdyn
