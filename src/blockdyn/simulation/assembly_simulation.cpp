// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/assembly_simulation.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "blockdyn/simulation/output_clock.hpp"
#include "blockdyn/model/assembly/assembly_model.hpp"
#include "blockdyn/model/assembly/moreau_jean.hpp"
#include "blockdyn/simulation/observer.hpp"
#include "blockdyn/simulation/run.hpp"

namespace blockdyn {

void validate(const AssemblyRunOptions& o) {
  if (!(o.t_end > 0 && o.t_end <= 1e7)) throw std::invalid_argument("t-end must be in (0, 1e7] s");
  if (!(o.integrator.rtol >= 1e-14 && o.integrator.rtol <= 1e-2)) throw std::invalid_argument("rtol must be in [1e-14, 1e-2]");
  if (!(o.integrator.atol >= 1e-16 && o.integrator.atol <= 1e-2)) throw std::invalid_argument("atol must be in [1e-16, 1e-2]");
  if (!(o.output_interval >= 0 && o.output_interval <= 1e7)) throw std::invalid_argument("output-interval must be in [0, 1e7] s");
  if (!(o.step >= 1e-7 && o.step <= 1e-2)) throw std::invalid_argument("step must be in [1e-7, 1e-2] s");
  if (!(o.t_end / o.step <= 2e9)) throw std::invalid_argument("t-end / step must be at most 2e9 steps");
}

namespace {

template <int Cap>
using Model = AssemblyModel<Cap>;

// Largest rotations and slidings, the event list and counts, the failure.
template <int Cap>
class AssemblyRecorder final : public Observer<Model<Cap>> {
 public:
  using M = Model<Cap>;
  using typename Observer<M>::Mode;
  using typename Observer<M>::State;
  using typename Observer<M>::Event;
  using typename Observer<M>::Segment;

  AssemblyRecorder(AssemblyResult& r, const AssemblyRunOptions& o) : r_(r), o_(o) {}

  void on_start(const M& m, double t, const Mode&, const State& z) override {
    r_.blocks.resize(m.blocks());
    r_.interfaces.resize(m.interfaces());
    for (int b = 0; b < m.blocks(); ++b) {
      r_.blocks[b].name = m.assembly().blocks[b].name;
      r_.blocks[b].rotation_limit = m.rotation_limit(b);
    }
    for (int i = 0; i < m.interfaces(); ++i) {
      r_.interfaces[i].lower = m.assembly().interfaces[i].lower;
      r_.interfaces[i].upper = m.assembly().interfaces[i].upper;
    }
    track(m, t, z);
  }
  bool on_segment(const M& m, const Segment& s, double, double t1, const Mode&) override {
    State z;
    s.eval(t1, z);
    track(m, t1, z);
    return true;
  }
  bool needs_dense() const override { return false; }  // step ends only
  bool on_event(const M& m, const Event& e) override {
    track(m, e.t, e.z_before);
    if (e.kind == kAsmBreakpoint) return true;
    ++r_.event_counts[e.kind];
    ++r_.events_total;
    AssemblyEventRecord rec;
    rec.t = e.t;
    rec.kind = assembly_event_name(e.kind);
    const int idx = e.index;
    if (idx < M::ev_wzero(0)) {
      const int p = idx % M::kPoints;
      rec.interface = p / 2;
      rec.end = p % 2;
      rec.block = m.assembly().interfaces[p / 2].upper;
      if (e.kind == kAsmOpen) ++r_.interfaces[p / 2].opens;
      if (e.kind == kAsmSlip) ++r_.interfaces[p / 2].slips;
    } else if (idx < M::ev_bearing(0)) {
      rec.block = (idx - M::ev_wzero(0)) % Cap;
    } else {
      rec.interface = idx - M::ev_bearing(0);
      rec.block = m.assembly().interfaces[rec.interface].upper;
    }
    if (e.kind == kAsmCollapse1 || e.kind == kAsmCollapse2) {
      rec.collapse_mode = e.kind == kAsmCollapse1 ? 1 : 2;
      r_.collapse_mode = rec.collapse_mode;
      r_.t_failure = e.t;
      r_.failed_block = rec.block;
      r_.failed_interface = rec.interface;
      r_.status = "collapsed";
    }
    if (e.kind == kAsmInvalid) {
      r_.status = "invalid";
      r_.note = "contact interpenetration beyond the model's limit (2% of the smallest block size) at interface " +
                std::to_string(rec.interface);
    }
    if (rec.block >= 0)
      rec.pose = {e.z[M::ix(rec.block)], e.z[M::ix(rec.block) + 1], e.z[M::ix(rec.block) + 2]};
    if (o_.on_event) o_.on_event(rec);
    if (o_.record_events && long(r_.events.size()) < o_.max_events) r_.events.push_back(rec);
    return true;
  }

 private:
  void track(const M& m, double t, const State& z) {
    for (int b = 0; b < m.blocks(); ++b) {
      const double a = std::fabs(z[M::ix(b) + 2]);
      if (a > r_.blocks[b].max_abs_rotation) {
        r_.blocks[b].max_abs_rotation = a;
        r_.blocks[b].t_max_abs_rotation = t;
      }
    }
    typename M::Geometry geo;
    m.geometry(z, geo);
    for (int i = 0; i < m.interfaces(); ++i) {
      const double s = base_position(geo.lower[i], geo.upper[i]);
      if (!started_) s0_[i] = s;
      r_.interfaces[i].max_abs_sliding = std::fmax(r_.interfaces[i].max_abs_sliding, std::fabs(s - s0_[i]));
    }
    started_ = true;
  }
  AssemblyResult& r_;
  const AssemblyRunOptions& o_;
  std::array<double, Cap + 1> s0_{};
  bool started_ = false;
};

// The assembly's trajectory columns (both contact laws): per block its pose and velocity, the
// ground acceleration, per contact end its point, forces and state, the energy terms.
std::vector<std::string> assembly_columns(int blocks, int interfaces) {
  std::vector<std::string> n{"t", "event"};
  for (int b = 0; b < blocks; ++b)
    for (const char* c : {"x", "y", "theta", "vx", "vy", "omega"}) n.push_back(std::string(c) + '_' + std::to_string(b));
  n.emplace_back("a_h");
  n.emplace_back("a_v");
  for (int p = 0; p < 2 * interfaces; ++p)
    for (const char* c : {"px", "py", "fn", "ft", "state"})
      n.push_back(std::string(c) + '_' + std::to_string(p / 2) + '_' + std::to_string(p % 2));
  for (const char* c : {"E_kin", "E_grav", "E_spring_n", "E_spring_t", "E_total", "W_ground", "W_normal", "W_friction",
                        "W_switch", "energy_balance"})
    n.emplace_back(c);
  return n;
}

// Contact end states as table texts: open, stick (K), slip +, slip -.
const char* const kEndState[] = {"O", "K", "P", "N"};
const char* end_state_text(char c) { return c == 'K' ? "K" : c == 'P' ? "P" : c == 'N' ? "N" : "O"; }

// The trajectory table: one row per output instant (dense output) and one per event.
template <int Cap>
class AssemblyTrajectory final : public Observer<Model<Cap>> {
 public:
  using M = Model<Cap>;
  using typename Observer<M>::Mode;
  using typename Observer<M>::State;
  using typename Observer<M>::Event;
  using typename Observer<M>::Segment;

  AssemblyTrajectory(TrajectoryTable& out, double interval) : out_(out), interval_(interval) {}

  void on_start(const M& m, double t, const Mode& md, const State& z) override {
    const auto names = assembly_columns(m.blocks(), m.interfaces());
    cells_.resize(names.size());
    out_.columns(names);
    e0_ = m.energy(md, z) - m.work(z);
    row(m, t, md, z, "start");
    clock_.start(t, interval_);
  }
  bool on_segment(const M& m, const Segment& seg, double, double t1, const Mode& md) override {
    clock_.emit(t1, [&](double t) {
      State z;
      seg.eval(t, z);
      m.complete(md, z);
      row(m, t, md, z, "");
    });
    return true;
  }
  bool on_event(const M& m, const Event& e) override {
    if (e.kind == kAsmBreakpoint) return true;
    row(m, e.t, e.to, e.z, assembly_event_name(e.kind));
    return true;
  }

 private:
  void row(const M& m, double t, const Mode& md, const State& z, const char* ev) {
    RowBuffer& c = cells_;
    c.clear();
    c.number(t);
    c.text(ev);
    for (int b = 0; b < m.blocks(); ++b) {
      for (int k = 0; k < 3; ++k) c.number(z[M::ix(b) + k]);
      for (int k = 0; k < 3; ++k) c.number(z[M::iv(b) + k]);
    }
    const auto a = m.ground_acceleration(t);
    c.number(a[0]);
    c.number(a[1]);
    for (int p = 0; p < 2 * m.interfaces(); ++p) {
      const auto f = m.point_force(md, z, p);
      for (double v : {f.c.P.x, f.c.P.y, f.fn, f.ft}) c.number(v);
      c.text(kEndState[int(md.point[p])]);
    }
    const auto e = m.energy_terms(md, z);
    for (double v : {e.kinetic, e.gravity, e.normal_spring, e.tangential_spring, e.total(), z[M::kWGround],
                     z[M::kWNormal], z[M::kWFriction], z[M::kWSwitch], e.total() - m.work(z) - e0_})
      c.number(v);
    c.write_to(out_);
  }
  TrajectoryTable& out_;
  double interval_;
  OutputClock clock_;
  RowBuffer cells_;
  double e0_ = 0;
};

// The forced analyses' probe (run_probe.hpp): block states from the dense output, passages of
// each rotation through 0, contact ends closing and opening under each block.
template <int Cap>
class AssemblyProbe final : public Observer<Model<Cap>> {
 public:
  using M = Model<Cap>;
  using typename Observer<M>::Mode;
  using typename Observer<M>::State;
  using typename Observer<M>::Event;
  using typename Observer<M>::Segment;

  explicit AssemblyProbe(RunProbe& p) : p_(p) {}

  void on_start(const M& m, double t, const Mode&, const State& z) override {
    p_.advance(t, m.blocks(), [&](double, RunProbe::BlockState* s) { fill(m, z, s); });
  }
  bool on_segment(const M& m, const Segment& seg, double, double t1, const Mode& md) override {
    p_.advance(t1, m.blocks(), [&](double t, RunProbe::BlockState* s) {
      State z;
      seg.eval(t, z);
      m.complete(md, z);
      fill(m, z, s);
    });
    return true;
  }
  bool on_event(const M& m, const Event& e) override {
    ProbeEvent pe;
    pe.t = e.t;
    const int idx = e.index;
    if (e.kind == kAsmWZero) {
      pe.kind = ProbeEvent::Passage;
      pe.block = (idx - M::ev_wzero(0)) % Cap;
    } else if ((e.kind == kAsmClose || e.kind == kAsmOpen) && idx < M::ev_wzero(0)) {
      pe.kind = e.kind == kAsmClose ? ProbeEvent::Close : ProbeEvent::Open;
      pe.block = m.assembly().interfaces[(idx % M::kPoints) / 2].upper;
      pe.side = (idx % M::kPoints) % 2 == 0 ? -1 : 1;
    } else {
      return true;
    }
    pe.theta = e.z[M::ix(pe.block) + 2];
    pe.omega_before = e.z_before[M::iv(pe.block) + 2];
    pe.omega_after = e.z[M::iv(pe.block) + 2];
    p_.event(pe);
    return true;
  }
  void on_finish(const M&, double t, const Mode&, const State&) override { p_.finish(t); }

 private:
  static void fill(const M& m, const State& z, RunProbe::BlockState* s) {
    for (int b = 0; b < m.blocks(); ++b)
      s[b] = {z[M::ix(b)], z[M::ix(b) + 1], z[M::ix(b) + 2], z[M::iv(b)], z[M::iv(b) + 1], z[M::iv(b) + 2]};
  }
  RunProbe& p_;
};

template <int Cap>
AssemblyEnergy energy_of(const Model<Cap>& m, const typename Model<Cap>::Mode& md, const typename Model<Cap>::State& z) {
  const auto e = m.energy_terms(md, z);
  return {e.kinetic, e.gravity, e.normal_spring, e.tangential_spring, e.total()};
}

template <int Cap>
AssemblyResult run(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o, TrajectoryTable* csv_out,
                   RunProbe* probe) {
  using M = Model<Cap>;
  // Passages through theta = 0 and contact-end switches count beyond the integration error.
  const M m(a, g, std::fmax(1e-12, 10.0 * o.integrator.atol));
  AssemblyResult r;
  for (int i = 0; i < m.interfaces(); ++i) r.damping.push_back(m.law(i).cn);
  typename M::State z = m.initial_state();
  typename M::Mode md = m.initial_mode(z);
  m.complete(md, z);
  if (auto why = m.validity_problem(md, z)) throw std::invalid_argument("initial state: " + *why);
  r.energy_initial = energy_of(m, md, z);
  AssemblyRecorder<Cap> rec(r, o);
  EnergyBalance<M> balance;
  std::unique_ptr<AssemblyTrajectory<Cap>> csv;
  FanOut<M> fan;
  fan.add(&rec).add(&balance);
  if (csv_out) {
    csv = std::make_unique<AssemblyTrajectory<Cap>>(*csv_out, o.output_interval);
    fan.add(csv.get());
  }
  std::unique_ptr<AssemblyProbe<Cap>> probe_obs;
  if (probe) {
    probe_obs = std::make_unique<AssemblyProbe<Cap>>(*probe);
    fan.add(probe_obs.get());
  }
  const RunOutcome<M> out = run_model(m, md, z, 0.0, o.t_end, o.integrator, fan);
  r.integrator_status = to_string(out.status);
  r.t_final = out.t;
  if (out.status != RunStatus::ReachedEnd && out.status != RunStatus::ModelStop) {
    r.status = "invalid";
    r.note = std::string("integration stopped: ") + to_string(out.status);
  }
  for (int b = 0; b < m.blocks(); ++b) {
    for (int k = 0; k < 3; ++k) {
      r.blocks[b].final_state[k] = out.z[M::ix(b) + k];
      r.blocks[b].final_state[3 + k] = out.z[M::iv(b) + k];
    }
    for (int i = 0; i < m.interfaces(); ++i)
      if (a.interfaces[i].upper == b)
        r.blocks[b].max_abs_sliding = std::fmax(r.blocks[b].max_abs_sliding, r.interfaces[i].max_abs_sliding);
  }
  for (int i = 0; i < m.interfaces(); ++i) r.interfaces[i].final_overlap = m.overlap_of(out.z, i);
  r.energy_final = energy_of(m, out.mode, out.z);
  r.work_ground = out.z[M::kWGround];
  r.work_normal = out.z[M::kWNormal];
  r.work_friction = out.z[M::kWFriction];
  r.work_switch = out.z[M::kWSwitch];
  r.max_abs_energy_error = balance.max_abs_error();
  r.max_abs_energy_change = balance.max_abs_change();
  r.steps = out.stats.accepted;
  r.rejected_steps = out.stats.rejected;
  r.rhs_evals = out.stats.rhs_evals;
  if (r.collapse_mode)
    r.motion = "collapse";
  else if (r.event_counts[kAsmOpen] > 0 || r.event_counts[kAsmSlip] > 0 || r.event_counts[kAsmClose] > 0)
    r.motion = "stable";
  else
    r.motion = "rest";
  return r;
}


// The rigid law: Moreau-Jean time-stepping (model/assembly/moreau_jean.hpp). Events are found
// between consecutive steps: contact ends opening and closing (an impact when the end
// approached), stick and slip, passages of theta through 0 and the collapse criteria, the
// crossings of theta interpolated linearly within the step.
AssemblyResult run_rigid(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o, TrajectoryTable* csv,
                         RunProbe* probe) {
  MoreauJeanOptions mo;
  mo.h = o.step;
  MoreauJean mj(a, g, mo);
  const int nb = mj.blocks(), ni = mj.interfaces(), np = 2 * ni;
  AssemblyResult r;
  r.damping.assign(ni, 0.0);
  r.blocks.resize(nb);
  r.interfaces.resize(ni);
  std::vector<double> q(3 * nb), v(3 * nb), theta_prev(nb), s0(ni), overlaps(ni), base(ni);
  std::vector<int> side(nb, 1);
  // A passage through theta = 0 counts once theta is this far on the other side (rounding).
  constexpr double kBand = 1e-12;
  for (int b = 0; b < nb; ++b) {
    const AssemblyBlock& k = a.blocks[b];
    q[3 * b] = k.x, q[3 * b + 1] = k.y, q[3 * b + 2] = k.theta;
    v[3 * b] = k.vx, v[3 * b + 1] = k.vy, v[3 * b + 2] = k.omega;
    r.blocks[b].name = k.name;
    r.blocks[b].rotation_limit = mj.rotation_limit(b);
    r.blocks[b].max_abs_rotation = std::fabs(k.theta);
    side[b] = k.theta < 0 ? -1 : 1;
  }
  mj.measure_interfaces(q, overlaps, s0);
  for (int i = 0; i < ni; ++i) {
    r.interfaces[i].lower = a.interfaces[i].lower;
    r.interfaces[i].upper = a.interfaces[i].upper;
  }
  // Contact end states: 'O' open, 'K' stick, 'P'/'N' slip.
  std::vector<char> state(np, 'O'), next(np, 'O');
  const double e0 = mj.kinetic_energy(v) + mj.gravity_energy(q);
  r.energy_initial.kinetic = mj.kinetic_energy(v);
  r.energy_initial.total = e0;
  double w_ground = 0, w_normal = 0, w_tangent = 0, max_err = 0, max_change = 0;
  std::vector<AssemblyEventRecord> step_events;
  step_events.reserve(4 * std::size_t(np + nb) + 4);
  auto add_event = [&](double t, int kind_code, const char* kind, int block, int iface, int end, int mode) {
    ++r.events_total;
    if (kind_code >= 0) ++r.event_counts[kind_code];
    if (!o.record_events && !o.on_event) return;
    AssemblyEventRecord e;
    e.t = t;
    e.kind = kind;
    e.block = block;
    e.interface = iface;
    e.end = end;
    e.collapse_mode = mode;
    if (block >= 0) e.pose = {q[3 * block], q[3 * block + 1], q[3 * block + 2]};
    step_events.push_back(e);
  };
  // A step's contact events carry the step's end time, its passages and failures the time
  // interpolated inside it: passed on in time order at the end of each step.
  // (A stable insertion sort of the few events of a step: std::stable_sort would allocate.)
  auto flush_step_events = [&] {
    for (std::size_t i = 1; i < step_events.size(); ++i)
      for (std::size_t j = i; j > 0 && step_events[j].t < step_events[j - 1].t; --j)
        std::swap(step_events[j], step_events[j - 1]);
    for (const AssemblyEventRecord& e : step_events) {
      if (o.on_event) o.on_event(e);
      if (o.record_events && long(r.events.size()) < o.max_events) r.events.push_back(e);
    }
    step_events.clear();
  };
  RowBuffer cells;
  auto write_row = [&](double t, const char* ev) {
    if (!csv) return;
    cells.clear();
    cells.number(t);
    cells.text(ev);
    for (int b = 0; b < nb; ++b) {
      for (int k = 0; k < 3; ++k) cells.number(q[3 * b + k]);
      for (int k = 0; k < 3; ++k) cells.number(v[3 * b + k]);
    }
    const auto acc = mj.ground_acceleration(t);
    cells.number(acc[0]);
    cells.number(acc[1]);
    for (int p = 0; p < np; ++p) {
      const auto& e = mj.ends()[p];
      // The step's mean contact forces.
      for (double x : {e.c.P.x, e.c.P.y, e.pn / o.step, e.pt / o.step}) cells.number(x);
      cells.text(end_state_text(state[p]));
    }
    const double ek = mj.kinetic_energy(v), eg = mj.gravity_energy(q);
    for (double x : {ek, eg, 0.0, 0.0, ek + eg, w_ground, w_normal, w_tangent, 0.0, ek + eg - e0 - w_ground - w_normal - w_tangent})
      cells.number(x);
    cells.write_to(*csv);
  };
  if (csv) {
    const auto names = assembly_columns(nb, ni);
    cells.resize(names.size());
    csv->columns(names);
    write_row(0.0, "start");
  }
  // The probe's states between step ends: linear in time (the scheme is first order).
  std::vector<double> q_prev, v_prev;
  auto probe_states = [&](double tau, double t_lo, RunProbe::BlockState* s) {
    const double w = o.step > 0 ? std::clamp((tau - t_lo) / o.step, 0.0, 1.0) : 1.0;
    for (int b = 0; b < nb; ++b)
      for (int k = 0; k < 3; ++k) {
        s[b][k] = q_prev[3 * b + k] + w * (q[3 * b + k] - q_prev[3 * b + k]);
        s[b][3 + k] = v_prev[3 * b + k] + w * (v[3 * b + k] - v_prev[3 * b + k]);
      }
  };
  auto probe_event = [&](double te, int b, ProbeEvent::Kind kind, double w_before, double w_after, int end = -1) {
    ProbeEvent pe;
    pe.t = te;
    pe.block = b;
    pe.kind = kind;
    pe.side = end < 0 ? 0 : end == 0 ? -1 : 1;
    pe.theta = q[3 * b + 2];
    pe.omega_before = w_before;
    pe.omega_after = w_after;
    probe->event(pe);
  };
  if (probe) {
    q_prev = q;
    v_prev = v;
    probe->advance(0.0, nb, [&](double tau, RunProbe::BlockState* s) { probe_states(tau, 0.0, s); });
  }
  const long steps = long(std::ceil(o.t_end / o.step - 1e-9));
  long next_out = 1;
  double t = 0;
  // An end closes with an impact when it approaches faster than one step of free fall.
  const double v_tol = a.g * o.step;
  for (long k = 0; k < steps; ++k) {
    flush_step_events();
    for (int b = 0; b < nb; ++b) theta_prev[b] = q[3 * b + 2];
    if (probe) {
      q_prev = q;
      v_prev = v;
    }
    if (!mj.step(t, q, v)) {
      r.status = "invalid";
      r.note = "the contact problem (LCP) has no solution at t = " + std::to_string(t) + " s";
      add_event(t, kAsmInvalid, "invalid", -1, -1, -1, 0);
      break;
    }
    const double t1 = (k + 1) * o.step;
    for (int p = 0; p < np; ++p) {
      const auto& e = mj.ends()[p];
      // An end is closed while it touches (active), whether or not this step needed an impulse.
      next[p] = !e.active ? 'O' : !e.slipping ? 'K' : (e.slip > 0 ? 'P' : 'N');
      const int blk = a.interfaces[p / 2].upper;
      if (k == 0) {
        // The contacts the assembly starts on are not events; a slip from the start is.
        if (next[p] == 'P' || next[p] == 'N') {
          add_event(t1, kAsmSlip, "slip", blk, p / 2, p % 2, 0);
          ++r.interfaces[p / 2].slips;
        }
      } else if (next[p] != 'O' && state[p] == 'O') {
        const bool impact = e.un_before < -v_tol;
        add_event(t1, impact ? kAsmImpact : kAsmClose, impact ? "impact" : "close", blk, p / 2, p % 2, 0);
        if (impact) ++r.impacts;
        if (probe) probe_event(t1, blk, ProbeEvent::Close, v_prev[3 * blk + 2], v[3 * blk + 2], p % 2);
      } else if (next[p] == 'O' && state[p] != 'O') {
        add_event(t1, kAsmOpen, "open", blk, p / 2, p % 2, 0);
        ++r.interfaces[p / 2].opens;
        if (probe) probe_event(t1, blk, ProbeEvent::Open, v_prev[3 * blk + 2], v[3 * blk + 2], p % 2);
      } else if ((next[p] == 'P' || next[p] == 'N') && state[p] == 'K') {
        add_event(t1, kAsmSlip, "slip", blk, p / 2, p % 2, 0);
        ++r.interfaces[p / 2].slips;
      } else if (next[p] == 'K' && (state[p] == 'P' || state[p] == 'N')) {
        add_event(t1, kAsmStick, "stick", blk, p / 2, p % 2, 0);
      }
      state[p] = next[p];
    }
    w_ground += mj.work_ground;
    w_normal += mj.work_normal;
    w_tangent += mj.work_tangential;
    const double ek = mj.kinetic_energy(v), eg = mj.gravity_energy(q);
    max_err = std::fmax(max_err, std::fabs(ek + eg - e0 - w_ground - w_normal - w_tangent));
    max_change = std::fmax(max_change, std::fabs(ek + eg - e0));
    bool stop = false;
    if (a.rock_only_on_ground)
      for (int i = 0; i < ni && !stop; ++i)
        if (a.interfaces[i].lower < 0 && state[2 * i] == 'O' && state[2 * i + 1] == 'O') {
          r.status = "invalid";
          r.note = "block " + std::to_string(a.interfaces[i].upper) + " left the ground at t = " + std::to_string(t1) +
                   " s: outside seed 001's 5-DOF restriction (blocks on the ground only rock)";
          add_event(t1, kAsmInvalid, "invalid", a.interfaces[i].upper, i, -1, 0);
          stop = true;
        }
    for (int b = 0; b < nb && !stop; ++b) {
      const double th0 = theta_prev[b], th1 = q[3 * b + 2];
      if (side[b] * th1 < -kBand) {
        const double tc = t + o.step * (th0 / (th0 - th1));  // linear within the step
        add_event(std::clamp(tc, t, t1), kAsmWZero, "w_zero", b, -1, -1, 0);
        if (probe) probe_event(std::clamp(tc, t, t1), b, ProbeEvent::Passage, v_prev[3 * b + 2], v[3 * b + 2]);
        side[b] = -side[b];
      }
      if (std::fabs(th1) > r.blocks[b].max_abs_rotation) {
        r.blocks[b].max_abs_rotation = std::fabs(th1);
        r.blocks[b].t_max_abs_rotation = t1;
      }
      const double lim = r.blocks[b].rotation_limit;
      if (std::fabs(th1) >= lim) {
        const double s = th1 > 0 ? 1.0 : -1.0;
        const double tf = t + o.step * (lim - s * th0) / (s * th1 - s * th0);
        add_event(tf, kAsmCollapse1, "failure", b, -1, -1, 1);
        r.collapse_mode = 1;
        r.t_failure = tf;
        r.failed_block = b;
        stop = true;
      }
    }
    mj.measure_interfaces(q, overlaps, base);
    for (int i = 0; i < ni && !stop; ++i) {
      if (a.interfaces[i].lower < 0) continue;
      if (overlaps[i] <= a.min_bearing) {
        add_event(t1, kAsmCollapse2, "failure", a.interfaces[i].upper, i, -1, 2);
        r.collapse_mode = 2;
        r.t_failure = t1;
        r.failed_block = a.interfaces[i].upper;
        r.failed_interface = i;
        stop = true;
      }
    }
    for (int i = 0; i < ni; ++i)
      r.interfaces[i].max_abs_sliding = std::fmax(r.interfaces[i].max_abs_sliding, std::fabs(base[i] - s0[i]));
    if (probe) probe->advance(t1, nb, [&](double tau, RunProbe::BlockState* s) { probe_states(tau, t, s); });
    t = t1;
    if (csv) {
      while (o.output_interval > 0 && next_out * o.output_interval <= t + 1e-12 * o.step) {
        write_row(t, "");
        ++next_out;
      }
      if (o.output_interval <= 0) write_row(t, "");
    }
    if (stop) {
      if (r.status != "invalid") r.status = "collapsed";
      break;
    }
  }
  flush_step_events();
  r.t_final = t;
  if (probe) probe->finish(t);
  r.steps = long(std::lround(t / o.step));
  r.direct_solves = mj.solve_stats().direct;
  r.gauss_seidel_solves = mj.solve_stats().gauss_seidel;
  r.gauss_seidel_sweeps = mj.solve_stats().sweeps;
  r.rhs_evals = r.steps;
  for (int b = 0; b < nb; ++b) {
    for (int k = 0; k < 3; ++k) {
      r.blocks[b].final_state[k] = q[3 * b + k];
      r.blocks[b].final_state[3 + k] = v[3 * b + k];
    }
    for (int i = 0; i < ni; ++i)
      if (a.interfaces[i].upper == b)
        r.blocks[b].max_abs_sliding = std::fmax(r.blocks[b].max_abs_sliding, r.interfaces[i].max_abs_sliding);
  }
  for (int i = 0; i < ni; ++i) r.interfaces[i].final_overlap = mj.overlap_of(q, i);
  r.energy_final.kinetic = mj.kinetic_energy(v);
  r.energy_final.gravity = mj.gravity_energy(q);
  r.energy_final.total = r.energy_final.kinetic + r.energy_final.gravity;
  r.work_ground = w_ground;
  r.work_normal = w_normal;
  r.work_friction = w_tangent;
  r.max_abs_energy_error = max_err;
  r.max_abs_energy_change = max_change;
  r.integrator_status = r.status == "invalid" ? "lcp_failure" : r.status == "collapsed" ? "model_stop" : "t_end";
  if (r.collapse_mode)
    r.motion = "collapse";
  else if (r.event_counts[kAsmOpen] > 0 || r.event_counts[kAsmSlip] > 0 || r.event_counts[kAsmClose] > 0 ||
           r.event_counts[kAsmImpact] > 0)
    r.motion = "stable";
  else
    r.motion = "rest";
  return r;
}

}  // namespace

AssemblyResult simulate_assembly(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o,
                                 TrajectoryTable* trajectory, RunProbe* probe) {
  validate(a);
  validate(o);
  if (probe && a.blocks.size() > std::size_t(RunProbe::kMaxBlocks))
    throw std::invalid_argument("a probed run takes at most " + std::to_string(RunProbe::kMaxBlocks) + " blocks");
  if (a.contact == "rigid") return run_rigid(a, g, o, trajectory, probe);
  const int n = int(a.blocks.size());
  if (n == 1 && a.interfaces.size() <= 2) return run<1>(a, g, o, trajectory, probe);
  if (n <= 3 && a.interfaces.size() <= 4) return run<3>(a, g, o, trajectory, probe);
  return run<8>(a, g, o, trajectory, probe);
}

}  // namespace blockdyn
