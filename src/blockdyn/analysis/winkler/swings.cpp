// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/winkler/swings.hpp"

#include "blockdyn/base/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "blockdyn/integrate/root_bracket.hpp"
#include "blockdyn/model/common/coulomb.hpp"  // sign_of

namespace blockdyn {

void validate(const SwingOptions& o) {
  auto bad = [](const std::string& f, const std::string& range, double v) {
    throw std::invalid_argument(f + " = " + number_text(v) + " is out of range: must be " + range);
  };
  if (!std::isfinite(o.quadrature_dt) || o.quadrature_dt <= 0) bad("quadrature-dt", "finite and > 0", o.quadrature_dt);
  if (o.min_samples_per_step < 1 || o.min_samples_per_step > 1000)
    bad("min-samples-per-step", "in [1, 1000]", o.min_samples_per_step);
  if (!std::isfinite(o.phase_dt) || o.phase_dt < 0) bad("phase-dt", "finite and >= 0", o.phase_dt);
  if (!std::isfinite(o.late_start) || o.late_start < 0) bad("late-start", "finite and >= 0", o.late_start);
}

namespace {

// acc += w (a + sb b), component by component.
void add_scaled(Energy& acc, const Energy& a, const Energy& b, double w, double sb = 1.0) {
  acc.kinetic_x += w * (a.kinetic_x + sb * b.kinetic_x);
  acc.kinetic_y += w * (a.kinetic_y + sb * b.kinetic_y);
  acc.rotation += w * (a.rotation + sb * b.rotation);
  acc.gravity += w * (a.gravity + sb * b.gravity);
  acc.springs += w * (a.springs + sb * b.springs);
}

}  // namespace

SwingAccumulator::SwingAccumulator(const WinklerParams& p, SwingOptions opt) : p_(p), opt_(opt) {
  validate(opt_);
  swings_.reserve(1024);
}

SwingAccumulator::Sample SwingAccumulator::sample_at(const DenseSegment<kStateDim>& seg, const WinklerBlock& m,
                                                     const WinklerMode& mode, double t, WinklerState& z) const {
  seg.eval(t, z);
  m.complete(mode, z);
  return Sample{t, z[kVW], energy(p_, z), m.energy_rates(t, mode, z)};
}

SwingAccumulator::Sample SwingAccumulator::end_sample(const DenseSegment<kStateDim>& seg, const WinklerBlock& m,
                                                      const WinklerMode& mode, double t1, WinklerState& z) const {
  seg.completed_end(t1, z, [&](WinklerState& y) { m.complete(mode, y); });
  // Rates from the step's side of t1 (the ground motion just before it).
  return Sample{t1, z[kVW], energy(p_, z), m.energy_rates(std::nextafter(t1, -INFINITY), mode, z)};
}

void SwingAccumulator::on_start(const WinklerBlock& m, double t, const WinklerMode& mode, const WinklerState& z) {
  last_ = Sample{t, z[kVW], energy(p_, z), m.energy_rates(t, mode, z)};
  last_mode_ = mode;
  if (opt_.late_start <= t) {
    late_captured_ = true;
    late_energy_ = last_.e.total();
    late_work_friction_ = z[kWorkFriction];
  }
  sign_ = sign_of(z[kVW]);
  in_swing_ = (sign_ == 0);  // released from rest: a turning point
  swing_t0_ = t;
  integral_ = Energy{};
  max_abs_w_ = std::fabs(z[kW]);
  swing_flight_ = 0;
  if (opt_.phase_dt > 0) {
    phase_.push_back(PhaseSample{t, to_state(z), mode.regime});
    phase_t0_ = t;
    n_phase_ = 1;
    next_phase_t_ = t + opt_.phase_dt;
  }
}

// The trapezoidal rule with its end correction (h^2 / 12) (E'(a) - E'(b)): exact for cubics, so
// the step-end samples alone integrate each component to O(h^5) per step.
void SwingAccumulator::integrate(const Sample& a, const Sample& b) {
  if (!in_swing_) return;
  const double h = b.t - a.t;
  add_scaled(integral_, a.e, b.e, 0.5 * h);
  add_scaled(integral_, a.rate, b.rate, h * h / 12.0, -1.0);
}

void SwingAccumulator::close_swing(double t) {
  if (in_swing_ && t > swing_t0_) {
    const double len = t - swing_t0_;
    SwingRecord s;
    s.t_start = swing_t0_;
    s.t_end = t;
    s.average = integral_;
    s.average.kinetic_x /= len;
    s.average.kinetic_y /= len;
    s.average.rotation /= len;
    s.average.gravity /= len;
    s.average.springs /= len;
    s.max_abs_w = max_abs_w_;
    s.flight_time = swing_flight_;
    swings_.push_back(s);
  }
  in_swing_ = true;
  swing_t0_ = t;
  integral_ = Energy{};
  max_abs_w_ = 0;
  swing_flight_ = 0;
}

void SwingAccumulator::on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double t0, double t1,
                                  const WinklerMode& mode) {
  if (!(t1 > t0)) return;
  const bool flight = mode.regime == Regime::Flight;
  if (flight) {
    flight_time_ += t1 - t0;
    late_flight_time_ += std::max(0.0, t1 - std::max(t0, opt_.late_start));
  }
  WinklerState z;
  // The energy rates at the step start on this step's side: those of the last sample unless the
  // mode changed there (an event) or the ground moves (an input breakpoint may fall there).
  const bool same_mode = last_mode_.regime == mode.regime && last_mode_.side == mode.side &&
                         last_mode_.friction_sign == mode.friction_sign;
  if (!(last_.t == t0 && same_mode && m.ground().is_zero())) {
    seg.eval(t0, z);
    m.complete(mode, z);
    last_.rate = m.energy_rates(t0, mode, z);
  }
  last_mode_ = mode;
  const int n = std::max(opt_.min_samples_per_step, int(std::ceil((t1 - t0) / opt_.quadrature_dt)));
  const bool late_here = !late_captured_ && opt_.late_start >= t0 && opt_.late_start <= t1;
  const bool phase_here = opt_.phase_dt > 0 && next_phase_t_ <= t1;
  // Interior points need the full dense output (the cubic of the step ends is exact only there).
  bool full = n > 1 || late_here || phase_here;
  // With one sample (n = 1) the end is taken first; z then holds its state.
  const bool end_first = !full;
  Sample end;
  if (end_first) {
    end = end_sample(seg, m, mode, t1, z);
    // A turning point inside: located on the full dense output.
    full = sign_ != 0 && sign_of(end.vw) == -sign_;
    if (!full) {
      max_abs_w_ = std::max(max_abs_w_, std::fabs(z[kW]));
      if (sign_ == 0) sign_ = sign_of(end.vw);
      integrate(last_, end);
      if (flight) swing_flight_ += t1 - last_.t;
      last_ = end;
      return;
    }
  }
  seg.ensure_full();
  if (late_here) {
    seg.eval(opt_.late_start, z);
    m.complete(mode, z);
    late_captured_ = true;
    late_energy_ = energy(p_, z).total();
    late_work_friction_ = z[kWorkFriction];
  }
  // Phase-portrait samples at fixed multiples of phase_dt (no drift from repeated addition).
  if (opt_.phase_dt > 0) {
    while (next_phase_t_ <= t1) {
      if (next_phase_t_ >= t0) {
        seg.eval(next_phase_t_, z);
        m.complete(mode, z);
        phase_.push_back(PhaseSample{next_phase_t_, to_state(z), mode.regime});
      }
      next_phase_t_ = phase_t0_ + double(++n_phase_) * opt_.phase_dt;
    }
  }
  for (int j = 1; j <= n; ++j) {
    const double tj = (j == n) ? t1 : t0 + (t1 - t0) * double(j) / n;
    Sample sj;
    if (j < n)
      sj = sample_at(seg, m, mode, tj, z);
    else
      sj = end_first ? end : end_sample(seg, m, mode, t1, z);  // z holds the end state either way
    max_abs_w_ = std::max(max_abs_w_, std::fabs(z[kW]));
    const int s = sign_of(sj.vw);
    if (sign_ == 0) {
      sign_ = s;
    } else if (s == -sign_) {
      // Turning point inside (last_.t, tj]: locate it on the dense output.
      const int sg = sign_;
      auto g = [&](double tt) {
        WinklerState zz;
        seg.eval(tt, zz);
        m.complete(mode, zz);
        return sg * zz[kVW];
      };
      const double ts = locate_root(g, last_.t, tj, sg * last_.vw, sg * sj.vw);
      WinklerState zs;
      const Sample star = sample_at(seg, m, mode, ts, zs);
      integrate(last_, star);
      if (flight) swing_flight_ += ts - last_.t;
      close_swing(ts);
      max_abs_w_ = std::fabs(zs[kW]);
      last_ = star;
      sign_ = s;
    }
    integrate(last_, sj);
    if (flight) swing_flight_ += tj - last_.t;
    last_ = sj;
  }
}

void SwingAccumulator::on_event(const WinklerBlock&, const WinklerEventRecord& e) {
  if (e.kind == WinklerEventKind::Takeoff) {
    ++takeoffs_;
    if (e.t >= opt_.late_start) ++late_takeoffs_;
  }
}

CellTable swings_table(const std::vector<SwingRecord>& swings) {
  CellTable t;
  t.columns = {"index",         "t_start",       "t_end",        "length",      "max_abs_w",   "flight_time",
               "ave_kinetic_x", "ave_kinetic_y", "ave_rotation", "ave_gravity", "ave_springs", "ave_total"};
  for (std::size_t i = 0; i < swings.size(); ++i) {
    const SwingRecord& s = swings[i];
    const Energy& e = s.average;
    t.rows.push_back({i, s.t_start, s.t_end, s.length(), s.max_abs_w, s.flight_time, e.kinetic_x, e.kinetic_y,
                      e.rotation, e.gravity, e.springs, e.total()});
  }
  return t;
}

CellTable phase_table(const std::vector<PhaseSample>& phase) {
  CellTable t;
  t.columns = {"t", "x", "y", "w", "vx", "vy", "vw", "regime"};
  for (const PhaseSample& p : phase)
    t.rows.push_back({p.t, p.s.x, p.s.y, p.s.w, p.s.vx, p.s.vy, p.s.vw, to_string(p.regime)});
  return t;
}

}  // namespace blockdyn
