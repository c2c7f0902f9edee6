// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/moreau_jean_run.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "blockdyn/model/assembly/assembly_model.hpp"
#include "blockdyn/model/assembly/moreau_jean.hpp"
#include "blockdyn/simulation/assembly_columns.hpp"

namespace blockdyn {
namespace {

// A passage through theta = 0 counts once theta is this far on the other side (rounding).
constexpr double kBand = 1e-12;

class MoreauJeanRun {
 public:
  MoreauJeanRun(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o, TrajectoryTable* csv,
                RunProbe* probe);
  AssemblyResult run();

 private:
  static MoreauJeanOptions options_of(const AssemblyRunOptions& o) {
    MoreauJeanOptions mo;
    mo.h = o.step;
    return mo;
  }
  void start();
  bool step(long k);  // false: the run ends
  void contact_events(long k, double t1);
  bool ground_left(double t1);
  bool rotations(double t1);
  bool bearings(double t1, bool stopped);
  void outputs();
  void finish();

  void add_event(double t, int kind_code, const char* kind, int block, int iface, int end, int mode);
  void flush_step_events();
  void write_row(double t, const char* ev);
  void probe_states(double tau, double t_lo, RunProbe::BlockState* s) const;
  void probe_event(double te, int b, ProbeEvent::Kind kind, int end = -1);

  const Assembly& a_;
  const AssemblyRunOptions& o_;
  TrajectoryTable* csv_;
  RunProbe* probe_;
  MoreauJean mj_;
  const int nb_, ni_, np_;
  AssemblyResult r_;
  std::vector<double> q_, v_, theta_prev_, s0_, overlaps_, base_, q_prev_, v_prev_;
  std::vector<int> side_;
  std::vector<char> state_, next_;  // contact end states: 'O' open, 'K' stick, 'P'/'N' slip
  std::vector<AssemblyEventRecord> step_events_;
  RowBuffer cells_;
  double e0_ = 0, w_ground_ = 0, w_normal_ = 0, w_tangent_ = 0, max_err_ = 0, max_change_ = 0;
  double t_ = 0;
  long next_out_ = 1;
};

MoreauJeanRun::MoreauJeanRun(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o,
                             TrajectoryTable* csv, RunProbe* probe)
    : a_(a),
      o_(o),
      csv_(csv),
      probe_(probe),
      mj_(a, g, options_of(o)),
      nb_(mj_.blocks()),
      ni_(mj_.interfaces()),
      np_(2 * ni_),
      q_(3 * nb_),
      v_(3 * nb_),
      theta_prev_(nb_),
      s0_(ni_),
      overlaps_(ni_),
      base_(ni_),
      side_(nb_, 1),
      state_(np_, 'O'),
      next_(np_, 'O') {}

void MoreauJeanRun::start() {
  r_.damping.assign(ni_, 0.0);
  r_.blocks.resize(nb_);
  r_.interfaces.resize(ni_);
  for (int b = 0; b < nb_; ++b) {
    const AssemblyBlock& k = a_.blocks[b];
    q_[3 * b] = k.x, q_[3 * b + 1] = k.y, q_[3 * b + 2] = k.theta;
    v_[3 * b] = k.vx, v_[3 * b + 1] = k.vy, v_[3 * b + 2] = k.omega;
    r_.blocks[b].name = k.name;
    r_.blocks[b].rotation_limit = mj_.rotation_limit(b);
    r_.blocks[b].max_abs_rotation = std::fabs(k.theta);
    side_[b] = k.theta < 0 ? -1 : 1;
  }
  mj_.measure_interfaces(q_, overlaps_, s0_);
  for (int i = 0; i < ni_; ++i) {
    r_.interfaces[i].lower = a_.interfaces[i].lower;
    r_.interfaces[i].upper = a_.interfaces[i].upper;
  }
  e0_ = mj_.kinetic_energy(v_) + mj_.gravity_energy(q_);
  r_.energy_initial.kinetic = mj_.kinetic_energy(v_);
  r_.energy_initial.total = e0_;
  step_events_.reserve(4 * std::size_t(np_ + nb_) + 4);
  if (csv_) {
    const auto names = assembly_columns(nb_, ni_);
    cells_.resize(names.size());
    csv_->columns(names);
    write_row(0.0, "start");
  }
  if (probe_) {
    q_prev_ = q_;
    v_prev_ = v_;
    probe_->advance(0.0, nb_, [&](double tau, RunProbe::BlockState* s) { probe_states(tau, 0.0, s); });
  }
}

void MoreauJeanRun::add_event(double t, int kind_code, const char* kind, int block, int iface, int end, int mode) {
  ++r_.events_total;
  if (kind_code >= 0) ++r_.event_counts[kind_code];
  if (!o_.record_events && !o_.on_event) return;
  AssemblyEventRecord e;
  e.t = t;
  e.kind = kind;
  e.block = block;
  e.interface = iface;
  e.end = end;
  e.collapse_mode = mode;
  if (block >= 0) e.pose = {q_[3 * block], q_[3 * block + 1], q_[3 * block + 2]};
  step_events_.push_back(e);
}

// A step's contact events carry the step's end time, its passages and failures the time
// interpolated inside it: passed on in time order at the end of each step. (A stable insertion
// sort of the few events of a step: std::stable_sort would allocate.)
void MoreauJeanRun::flush_step_events() {
  auto& ev = step_events_;
  for (std::size_t i = 1; i < ev.size(); ++i)
    for (std::size_t j = i; j > 0 && ev[j].t < ev[j - 1].t; --j) std::swap(ev[j], ev[j - 1]);
  for (const AssemblyEventRecord& e : ev) {
    if (o_.on_event) o_.on_event(e);
    if (o_.record_events && long(r_.events.size()) < o_.max_events) r_.events.push_back(e);
  }
  ev.clear();
}

void MoreauJeanRun::write_row(double t, const char* ev) {
  RowBuffer& c = cells_;
  c.clear();
  c.number(t);
  c.text(ev);
  for (int b = 0; b < nb_; ++b) {
    for (int k = 0; k < 3; ++k) c.number(q_[3 * b + k]);
    for (int k = 0; k < 3; ++k) c.number(v_[3 * b + k]);
  }
  const auto acc = mj_.ground_acceleration(t);
  c.number(acc[0]);
  c.number(acc[1]);
  for (int p = 0; p < np_; ++p) {
    const auto& e = mj_.ends()[p];
    // The step's mean contact forces.
    for (double x : {e.c.P.x, e.c.P.y, e.pn / o_.step, e.pt / o_.step}) c.number(x);
    c.text(end_state_text(state_[p]));
  }
  const double ek = mj_.kinetic_energy(v_), eg = mj_.gravity_energy(q_);
  for (double x : {ek, eg, 0.0, 0.0, ek + eg, w_ground_, w_normal_, w_tangent_, 0.0,
                   ek + eg - e0_ - w_ground_ - w_normal_ - w_tangent_})
    c.number(x);
  c.write_to(*csv_);
}

// The probe's states between step ends: linear in time (the scheme is first order).
void MoreauJeanRun::probe_states(double tau, double t_lo, RunProbe::BlockState* s) const {
  const double w = o_.step > 0 ? std::clamp((tau - t_lo) / o_.step, 0.0, 1.0) : 1.0;
  for (int b = 0; b < nb_; ++b)
    for (int k = 0; k < 3; ++k) {
      s[b][k] = q_prev_[3 * b + k] + w * (q_[3 * b + k] - q_prev_[3 * b + k]);
      s[b][3 + k] = v_prev_[3 * b + k] + w * (v_[3 * b + k] - v_prev_[3 * b + k]);
    }
}

void MoreauJeanRun::probe_event(double te, int b, ProbeEvent::Kind kind, int end) {
  ProbeEvent pe;
  pe.t = te;
  pe.block = b;
  pe.kind = kind;
  pe.side = end < 0 ? 0 : end == 0 ? -1 : 1;
  pe.theta = q_[3 * b + 2];
  pe.omega_before = v_prev_[3 * b + 2];
  pe.omega_after = v_[3 * b + 2];
  probe_->event(pe);
}

void MoreauJeanRun::contact_events(long k, double t1) {
  // An end closes with an impact when it approaches faster than one step of free fall.
  const double v_tol = a_.g * o_.step;
  for (int p = 0; p < np_; ++p) {
    const auto& e = mj_.ends()[p];
    // An end is closed while it touches (active), whether or not this step needed an impulse.
    next_[p] = !e.active ? 'O' : !e.slipping ? 'K' : (e.slip > 0 ? 'P' : 'N');
    const char now = next_[p], was = state_[p];
    const int blk = a_.interfaces[p / 2].upper, iface = p / 2, end = p % 2;
    if (k == 0) {
      // The contacts the assembly starts on are not events; a slip from the start is.
      if (now == 'P' || now == 'N') {
        add_event(t1, kAsmSlip, "slip", blk, iface, end, 0);
        ++r_.interfaces[iface].slips;
      }
    } else if (now != 'O' && was == 'O') {
      const bool impact = e.un_before < -v_tol;
      add_event(t1, impact ? kAsmImpact : kAsmClose, impact ? "impact" : "close", blk, iface, end, 0);
      if (impact) ++r_.impacts;
      if (probe_) probe_event(t1, blk, ProbeEvent::Close, end);
    } else if (now == 'O' && was != 'O') {
      add_event(t1, kAsmOpen, "open", blk, iface, end, 0);
      ++r_.interfaces[iface].opens;
      if (probe_) probe_event(t1, blk, ProbeEvent::Open, end);
    } else if ((now == 'P' || now == 'N') && was == 'K') {
      add_event(t1, kAsmSlip, "slip", blk, iface, end, 0);
      ++r_.interfaces[iface].slips;
    } else if (now == 'K' && (was == 'P' || was == 'N')) {
      add_event(t1, kAsmStick, "stick", blk, iface, end, 0);
    }
    state_[p] = now;
  }
}

// Seed 001's 5-DOF restriction: a block standing on the ground that leaves it is reported.
bool MoreauJeanRun::ground_left(double t1) {
  if (!a_.rock_only_on_ground) return false;
  for (int i = 0; i < ni_; ++i)
    if (a_.interfaces[i].lower < 0 && state_[2 * i] == 'O' && state_[2 * i + 1] == 'O') {
      r_.status = "invalid";
      r_.note = "block " + std::to_string(a_.interfaces[i].upper) + " left the ground at t = " + std::to_string(t1) +
                " s: outside seed 001's 5-DOF restriction (blocks on the ground only rock)";
      add_event(t1, kAsmInvalid, "invalid", a_.interfaces[i].upper, i, -1, 0);
      return true;
    }
  return false;
}

// Passages of theta through 0, the largest rotations and collapse mode 1.
bool MoreauJeanRun::rotations(double t1) {
  const double t = t_;
  for (int b = 0; b < nb_; ++b) {
    const double th0 = theta_prev_[b], th1 = q_[3 * b + 2];
    if (side_[b] * th1 < -kBand) {
      const double tc = std::clamp(t + o_.step * (th0 / (th0 - th1)), t, t1);  // linear within the step
      add_event(tc, kAsmWZero, "w_zero", b, -1, -1, 0);
      if (probe_) probe_event(tc, b, ProbeEvent::Passage);
      side_[b] = -side_[b];
    }
    if (std::fabs(th1) > r_.blocks[b].max_abs_rotation) {
      r_.blocks[b].max_abs_rotation = std::fabs(th1);
      r_.blocks[b].t_max_abs_rotation = t1;
    }
    const double lim = r_.blocks[b].rotation_limit;
    if (std::fabs(th1) >= lim) {
      const double s = th1 > 0 ? 1.0 : -1.0;
      const double tf = t + o_.step * (lim - s * th0) / (s * th1 - s * th0);
      add_event(tf, kAsmCollapse1, "failure", b, -1, -1, 1);
      r_.collapse_mode = 1;
      r_.t_failure = tf;
      r_.failed_block = b;
      return true;
    }
  }
  return false;
}

// Collapse mode 2 (an interface between blocks lost its bearing; not looked for once the run
// stops) and the slidings.
bool MoreauJeanRun::bearings(double t1, bool stopped) {
  mj_.measure_interfaces(q_, overlaps_, base_);
  bool stop = stopped;
  for (int i = 0; i < ni_ && !stop; ++i) {
    if (a_.interfaces[i].lower < 0) continue;
    if (overlaps_[i] <= a_.min_bearing) {
      add_event(t1, kAsmCollapse2, "failure", a_.interfaces[i].upper, i, -1, 2);
      r_.collapse_mode = 2;
      r_.t_failure = t1;
      r_.failed_block = a_.interfaces[i].upper;
      r_.failed_interface = i;
      stop = true;
    }
  }
  for (int i = 0; i < ni_; ++i)
    r_.interfaces[i].max_abs_sliding = std::fmax(r_.interfaces[i].max_abs_sliding, std::fabs(base_[i] - s0_[i]));
  return stop;
}

void MoreauJeanRun::outputs() {
  if (!csv_) return;
  while (o_.output_interval > 0 && next_out_ * o_.output_interval <= t_ + 1e-12 * o_.step) {
    write_row(t_, "");
    ++next_out_;
  }
  if (o_.output_interval <= 0) write_row(t_, "");
}

bool MoreauJeanRun::step(long k) {
  flush_step_events();
  for (int b = 0; b < nb_; ++b) theta_prev_[b] = q_[3 * b + 2];
  if (probe_) {
    q_prev_ = q_;
    v_prev_ = v_;
  }
  if (!mj_.step(t_, q_, v_)) {
    r_.status = "invalid";
    r_.note = "the contact problem (LCP) has no solution at t = " + std::to_string(t_) + " s";
    add_event(t_, kAsmInvalid, "invalid", -1, -1, -1, 0);
    return false;
  }
  const double t1 = double(k + 1) * o_.step;
  contact_events(k, t1);
  w_ground_ += mj_.work_ground;
  w_normal_ += mj_.work_normal;
  w_tangent_ += mj_.work_tangential;
  const double ek = mj_.kinetic_energy(v_), eg = mj_.gravity_energy(q_);
  max_err_ = std::fmax(max_err_, std::fabs(ek + eg - e0_ - w_ground_ - w_normal_ - w_tangent_));
  max_change_ = std::fmax(max_change_, std::fabs(ek + eg - e0_));
  bool stop = ground_left(t1);
  if (!stop) stop = rotations(t1);
  stop = bearings(t1, stop);
  if (probe_) probe_->advance(t1, nb_, [&](double tau, RunProbe::BlockState* s) { probe_states(tau, t_, s); });
  t_ = t1;
  outputs();
  if (stop && r_.status != "invalid") r_.status = "collapsed";
  return !stop;
}

void MoreauJeanRun::finish() {
  flush_step_events();
  r_.t_final = t_;
  if (probe_) probe_->finish(t_);
  r_.steps = long(std::lround(t_ / o_.step));
  r_.direct_solves = mj_.solve_stats().direct;
  r_.gauss_seidel_solves = mj_.solve_stats().gauss_seidel;
  r_.gauss_seidel_sweeps = mj_.solve_stats().sweeps;
  r_.rhs_evals = r_.steps;
  for (int b = 0; b < nb_; ++b) {
    for (int k = 0; k < 3; ++k) {
      r_.blocks[b].final_state[k] = q_[3 * b + k];
      r_.blocks[b].final_state[3 + k] = v_[3 * b + k];
    }
    for (int i = 0; i < ni_; ++i)
      if (a_.interfaces[i].upper == b)
        r_.blocks[b].max_abs_sliding = std::fmax(r_.blocks[b].max_abs_sliding, r_.interfaces[i].max_abs_sliding);
  }
  for (int i = 0; i < ni_; ++i) r_.interfaces[i].final_overlap = mj_.overlap_of(q_, i);
  r_.energy_final.kinetic = mj_.kinetic_energy(v_);
  r_.energy_final.gravity = mj_.gravity_energy(q_);
  r_.energy_final.total = r_.energy_final.kinetic + r_.energy_final.gravity;
  r_.work_ground = w_ground_;
  r_.work_normal = w_normal_;
  r_.work_friction = w_tangent_;
  r_.max_abs_energy_error = max_err_;
  r_.max_abs_energy_change = max_change_;
  r_.integrator_status = r_.status == "invalid" ? "lcp_failure" : r_.status == "collapsed" ? "model_stop" : "t_end";
  const auto& n = r_.event_counts;
  if (r_.collapse_mode)
    r_.motion = "collapse";
  else if (n[kAsmOpen] > 0 || n[kAsmSlip] > 0 || n[kAsmClose] > 0 || n[kAsmImpact] > 0)
    r_.motion = "stable";
  else
    r_.motion = "rest";
}

AssemblyResult MoreauJeanRun::run() {
  start();
  const long steps = long(std::ceil(o_.t_end / o_.step - 1e-9));
  for (long k = 0; k < steps && step(k);) ++k;
  finish();
  return std::move(r_);
}

}  // namespace

AssemblyResult run_moreau_jean(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o,
                               TrajectoryTable* trajectory, RunProbe* probe) {
  return MoreauJeanRun(a, g, o, trajectory, probe).run();
}

}  // namespace blockdyn
