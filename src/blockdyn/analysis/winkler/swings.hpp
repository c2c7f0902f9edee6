// SPDX-License-Identifier: Apache-2.0
#pragma once
// Swings (thesis sec. 4.4): the motion between two successive sign changes of w'. For each swing:
// its length (Fig. 4.57) and the five energy components averaged over it (the trapezoidal rule
// with end corrections from the components' rates, over the step ends and samples at most
// quadrature_dt apart; divided by the length, reported at the swing end). Also samples the phase
// portraits (y, y'), (w, w'), (x, x') at constant time intervals (Figs. 4.41-4.56) and keeps the
// flight statistics the response classification needs.
#include <vector>

#include "blockdyn/io/table_cell.hpp"
#include "blockdyn/model/winkler/energy.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

struct SwingRecord {
  double t_start = 0, t_end = 0;  // turning points (w' = 0), located on the dense output
  Energy average;                 // swing-averaged components
  double max_abs_w = 0;           // amplitude reached during the swing (sampled)
  double flight_time = 0;         // time spent in flight during the swing
  double length() const { return t_end - t_start; }
};

struct PhaseSample {
  double t = 0;
  BlockState s;
  Regime regime = Regime::Slide;
};

struct SwingOptions {
  double quadrature_dt = 1e-3;   // largest spacing of the energy samples (trapezoidal rule)
  int min_samples_per_step = 1;  // and at least this many per integrator step
  double phase_dt = 0.0;         // phase-portrait sampling interval (<= 0: none)
  double late_start = 0.0;       // flight statistics are also kept for t >= late_start
};

void validate(const SwingOptions& o);

// A start with w' = 0 (ic1: released from rest) is a turning point, so the first swing begins
// there; otherwise the motion before the first sign change is not a swing and is not reported.
// The motion after the last turning point is not a (complete) swing either.
class SwingAccumulator : public WinklerSink {
 public:
  SwingAccumulator(const WinklerParams& p, SwingOptions opt);

  void on_start(const WinklerBlock& m, double t, const WinklerMode& mode, const WinklerState& z) override;
  void on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double t0, double t1,
                  const WinklerMode& mode) override;
  void on_event(const WinklerBlock& m, const WinklerEventRecord& e) override;
  // A step shorter than quadrature_dt is integrated from its two ends, which are exact on any
  // segment; a step with interior samples, a turning point, a phase sample or the late-statistics
  // start inside asks for the full dense output (DenseSegment::ensure_full()).
  bool needs_dense() const override { return false; }

  const std::vector<SwingRecord>& swings() const { return swings_; }
  const std::vector<PhaseSample>& phase() const { return phase_; }
  double flight_time() const { return flight_time_; }
  double late_flight_time() const { return late_flight_time_; }
  long takeoffs() const { return takeoffs_; }
  long late_takeoffs() const { return late_takeoffs_; }
  // Total energy and accumulated friction work at t = late_start (if the run got there).
  bool reached_late() const { return late_captured_; }
  double late_energy() const { return late_energy_; }
  double late_work_friction() const { return late_work_friction_; }
  const SwingOptions& options() const { return opt_; }

 private:
  struct Sample {
    double t = 0;
    double vw = 0;
    Energy e;
    Energy rate;  // dE/dt of each component
  };
  // The sample at t inside the piece, and at its end t1 (the step's own end state when given).
  Sample sample_at(const DenseSegment<kStateDim>& seg, const WinklerBlock& m, const WinklerMode& mode, double t,
                   WinklerState& z) const;
  Sample end_sample(const DenseSegment<kStateDim>& seg, const WinklerBlock& m, const WinklerMode& mode, double t1,
                    WinklerState& z) const;
  void integrate(const Sample& a, const Sample& b);
  void close_swing(double t);

  WinklerParams p_;
  SwingOptions opt_;
  std::vector<SwingRecord> swings_;
  std::vector<PhaseSample> phase_;
  Sample last_;
  WinklerMode last_mode_;  // the mode last_.rate was evaluated in
  int sign_ = 0;           // sign of w' since the last turning point (0: not yet known)
  bool in_swing_ = false;  // a turning point has been seen
  double swing_t0_ = 0;
  Energy integral_;  // running integrals of the components over the current swing
  double max_abs_w_ = 0, swing_flight_ = 0;
  double next_phase_t_ = 0, phase_t0_ = 0;
  long n_phase_ = 0;
  double flight_time_ = 0, late_flight_time_ = 0;
  long takeoffs_ = 0, late_takeoffs_ = 0;
  bool late_captured_ = false;
  double late_energy_ = 0, late_work_friction_ = 0;
};

// Tables: one row per swing / per phase sample.
CellTable swings_table(const std::vector<SwingRecord>& swings);
CellTable phase_table(const std::vector<PhaseSample>& phase);

}  // namespace blockdyn
