// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/assembly_simulation.hpp"

#include "blockdyn/base/number_text.hpp"

#include "blockdyn/base/range_check.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "blockdyn/model/assembly/assembly_model.hpp"
#include "blockdyn/model/assembly/rigid_assembly_model.hpp"
#include "blockdyn/simulation/assembly_columns.hpp"
#include "blockdyn/simulation/observer.hpp"
#include "blockdyn/simulation/rigid_assembly_run.hpp"
#include "blockdyn/simulation/run.hpp"
#include "blockdyn/simulation/trajectory_rows.hpp"

namespace blockdyn {

const char* to_string(AssemblyScheme s) {
  return s == AssemblyScheme::EventDriven    ? "event-driven"
         : s == AssemblyScheme::TimeStepping ? "time-stepping"
                                             : "auto";
}

AssemblyScheme effective_scheme(const Assembly& a, const AssemblyRunOptions& o) {
  if (a.rock_only_on_ground) return AssemblyScheme::TimeStepping;
  if (o.scheme != AssemblyScheme::Auto) return o.scheme;
  return int(a.blocks.size()) > kEventDrivenMaxBlocks ? AssemblyScheme::TimeStepping : AssemblyScheme::EventDriven;
}

void validate(const AssemblyRunOptions& o) {
  validate(static_cast<const RunOptions&>(o));
  if (o.t_start != 0.0) throw std::invalid_argument("t-start: an assembly's run starts at t = 0");
  require_in_range("output-interval", o.output_interval, 0, 1e7);
  require_in_range("step", o.step, 1e-7, 1e-2);
  if (!(o.t_end / o.step <= 2e9)) throw std::invalid_argument("t-end / step must be at most 2e9 steps");
}

namespace {

// The event function an event belongs to; for a switch made at a breakpoint of the input (the
// rigid law's exit from rest, found on the ground motion itself), the first contact point whose
// state it changed (the normal event of that point).
template <class Event>
int event_index(const Event& e) {
  if (e.index >= 0) return e.index;
  for (std::size_t p = 0; p < e.from.point.size(); ++p)
    if (e.from.point[p] != e.to.point[p]) return int(p);
  return 0;
}

// Largest rotations and slidings, the event list and counts, the failure.
template <class M>
class AssemblyRecorder final : public Observer<M> {
 public:
  BLOCKDYN_OBSERVER_TYPES(M);
  static constexpr int MaxBlocks = M::kBlocks;

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
    if (e.kind == kAssemblyInputBreakpoint) return true;
    ++r_.event_counts[e.kind];
    ++r_.events_total;
    if (e.kind == kAssemblyImpact) ++r_.impacts;
    AssemblyEventRecord rec;
    rec.t = e.t;
    rec.kind = AssemblyEventKind(e.kind);
    const int idx = event_index(e);
    if (idx < M::ev_wzero(0)) {
      const int p = idx % M::kPoints;
      rec.interface = p / 2;
      rec.end = p % 2;
      rec.block = m.assembly().interfaces[p / 2].upper;
      if (e.kind == kAssemblyContactOpens) ++r_.interfaces[p / 2].opens;
      if (e.kind == kAssemblySlipStarts) ++r_.interfaces[p / 2].slips;
    } else if (idx < M::ev_bearing(0)) {
      rec.block = (idx - M::ev_wzero(0)) % MaxBlocks;
    } else {
      rec.interface = idx - M::ev_bearing(0);
      rec.block = m.assembly().interfaces[rec.interface].upper;
    }
    if (e.kind == kAssemblyRotationCollapse || e.kind == kAssemblyBearingCollapse) {
      rec.collapse_mode = e.kind == kAssemblyRotationCollapse ? 1 : 2;
      r_.collapse_mode = rec.collapse_mode;
      r_.t_failure = e.t;
      r_.failed_block = rec.block;
      r_.failed_interface = rec.interface;
      r_.status = SimStatus::Collapsed;
    }
    if (e.kind == kAssemblyOutsideModel) {
      r_.status = SimStatus::Invalid;
      if constexpr (requires { m.problem(); })
        r_.note = m.problem();
      else
        r_.note = "contact interpenetration beyond the model's limit (2% of the smallest block size) at interface " +
                  std::to_string(rec.interface);
    }
    if (rec.block >= 0) rec.pose = {e.z[M::ix(rec.block)], e.z[M::ix(rec.block) + 1], e.z[M::ix(rec.block) + 2]};
    if (o_.events) o_.events->on_event(rec);
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
  std::array<double, MaxBlocks + 1> s0_{};
  bool started_ = false;
};

// Contact end states as table texts: open, stick (K), slip +, slip -.
const char* const kEndState[] = {"O", "K", "P", "N"};

// The trajectory table: one row per output instant (dense output) and one per event.
template <class M>
class AssemblyTrajectory final : public TrajectoryRows<M, AssemblyTrajectory<M>> {
  using Base = TrajectoryRows<M, AssemblyTrajectory<M>>;

 public:
  BLOCKDYN_OBSERVER_TYPES(M);

  using Base::Base;

  std::vector<std::string> columns(const M& m) const { return assembly_columns(m.blocks(), m.interfaces()); }
  void started(const M& m, const Mode& md, const State& z) { e0_ = m.energy(md, z) - m.work(z); }
  bool on_event(const M& m, const Event& e) override {
    if (e.kind == kAssemblyInputBreakpoint) return true;
    this->row(m, e.t, e.to, e.z, assembly_event_name(e.kind));
    return true;
  }
  void fill(RowBuffer& c, const M& m, double t, const Mode& md, const State& z, const char* ev) const {
    c.number(t);
    c.text(ev);
    for (int b = 0; b < m.blocks(); ++b) {
      for (int k = 0; k < 3; ++k) c.number(z[M::ix(b) + k]);
      for (int k = 0; k < 3; ++k) c.number(z[M::iv(b) + k]);
    }
    const auto a = m.ground_acceleration(t);
    c.number(a[0]);
    c.number(a[1]);
    std::array<typename M::PointForce, M::kPoints> forces;
    m.point_forces(md, z, t, forces);
    for (int p = 0; p < 2 * m.interfaces(); ++p) {
      const auto& f = forces[p];
      for (double v : {f.c.P.x, f.c.P.y, f.fn, f.ft}) c.number(v);
      c.text(kEndState[int(md.point[p])]);
    }
    const auto e = m.energy_terms(md, z);
    for (double v : {e.kinetic, e.gravity, e.normal_spring, e.tangential_spring, e.total(), z[M::kWGround],
                     z[M::kWNormal], z[M::kWFriction], z[M::kWSwitch], e.total() - m.work(z) - e0_})
      c.number(v);
  }

 private:
  double e0_ = 0;
};

// The forced analyses' probe (run_probe.hpp): block states from the dense output, passages of
// each rotation through 0, contact ends closing and opening under each block.
template <class M>
class AssemblyProbe final : public Observer<M> {
 public:
  BLOCKDYN_OBSERVER_TYPES(M);
  static constexpr int MaxBlocks = M::kBlocks;

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
    // The rigid law's impact and exit from rest change several points at once (the old pivot
    // lifts as the new one lands): one probe event per point that changed.
    if (e.kind == kAssemblyImpact || (e.index < 0 && e.kind != kAssemblyInputBreakpoint)) {
      for (int p = 0; p < 2 * m.interfaces(); ++p) {
        const bool was = is_closed(e.from.point[p]), is = is_closed(e.to.point[p]);
        if (e.kind == kAssemblyImpact && p == e.index) {
          // The hitting corner: closes, and leaves again at once if it bounced (restitution).
          contact_event(m, e, p, ProbeEvent::Close);
          if (!is) contact_event(m, e, p, ProbeEvent::Open);
          continue;
        }
        if (was != is) contact_event(m, e, p, is ? ProbeEvent::Close : ProbeEvent::Open);
      }
      return true;
    }
    ProbeEvent pe;
    pe.t = e.t;
    const int idx = event_index(e);
    if (e.kind == kAssemblyUprightPassage) {
      pe.kind = ProbeEvent::Passage;
      pe.block = (idx - M::ev_wzero(0)) % MaxBlocks;
    } else if ((e.kind == kAssemblyContactCloses || e.kind == kAssemblyImpact || e.kind == kAssemblyContactOpens) &&
               idx < M::ev_wzero(0)) {
      pe.kind = e.kind == kAssemblyContactOpens ? ProbeEvent::Open : ProbeEvent::Close;
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
  void contact_event(const M& m, const Event& e, int p, ProbeEvent::Kind kind) {
    ProbeEvent pe;
    pe.t = e.t;
    pe.kind = kind;
    pe.block = m.assembly().interfaces[p / 2].upper;
    pe.side = p % 2 == 0 ? -1 : 1;
    pe.theta = e.z[M::ix(pe.block) + 2];
    pe.omega_before = e.z_before[M::iv(pe.block) + 2];
    pe.omega_after = e.z[M::iv(pe.block) + 2];
    p_.event(pe);
  }
  static void fill(const M& m, const State& z, RunProbe::BlockState* s) {
    for (int b = 0; b < m.blocks(); ++b)
      s[b] = {z[M::ix(b)], z[M::ix(b) + 1], z[M::ix(b) + 2], z[M::iv(b)], z[M::iv(b) + 1], z[M::iv(b) + 2]};
  }
  RunProbe& p_;
};

template <class M>
AssemblyEnergy energy_of(const M& m, const typename M::Mode& md, const typename M::State& z) {
  const auto e = m.energy_terms(md, z);
  return {e.kinetic, e.gravity, e.normal_spring, e.tangential_spring, e.total()};
}

// Whether a block ended away from its start by more than the start's contact tolerance (2 % of its
// size, or 1e-3 rad): such a run is not at rest, whatever its events.
bool moved_from_start(const Assembly& a, const AssemblyResult& r) {
  for (std::size_t b = 0; b < a.blocks.size(); ++b) {
    const AssemblyBlock& k = a.blocks[b];
    const double size = std::fmin(k.width, k.height);
    const auto& z = r.blocks[b].final_state;
    if (std::fabs(z[0] - k.x) > 0.02 * size || std::fabs(z[1] - k.y) > 0.02 * size || std::fabs(z[2] - k.theta) > 1e-3)
      return true;
  }
  return false;
}

// A block whose centre ends more than its own size below its start has passed through what should
// carry it: the run is outside the model, never at rest.
std::string fell_through(const Assembly& a, const AssemblyResult& r) {
  for (std::size_t b = 0; b < a.blocks.size(); ++b) {
    const AssemblyBlock& k = a.blocks[b];
    const double drop = k.y - r.blocks[b].final_state[1];
    if (drop > std::fmax(k.width, k.height))
      return "block " + std::to_string(b) + " (" + k.name + ") fell " + number_text(drop, 6) +
             " m below its start: nothing carried it";
  }
  return "";
}

template <class M>
AssemblyResult run(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o, TrajectoryTable* csv_out,
                   RunProbe* probe) {
  // Passages through theta = 0 and contact-end switches count beyond the integration error.
  const M m(a, g, std::fmax(1e-12, 10.0 * o.integrator.atol));
  AssemblyResult r;
  if constexpr (requires { m.law(0).cn; })
    for (int i = 0; i < m.interfaces(); ++i) r.damping.push_back(m.law(i).cn);
  else
    r.damping.assign(std::size_t(m.interfaces()), 0.0);
  typename M::State z = m.initial_state();
  typename M::Mode md = m.initial_mode(z);
  m.complete(md, z);
  if (auto why = m.validity_problem(md, z)) throw std::invalid_argument("initial state: " + *why);
  r.energy_initial = energy_of(m, md, z);
  AssemblyRecorder<M> rec(r, o);
  EnergyBalance<M> balance;
  std::unique_ptr<AssemblyTrajectory<M>> csv;
  FanOut<M> fan;
  fan.add(&rec).add(&balance);
  if (csv_out) {
    csv = std::make_unique<AssemblyTrajectory<M>>(*csv_out, o.output_interval);
    fan.add(csv.get());
  }
  std::unique_ptr<AssemblyProbe<M>> probe_obs;
  if (probe) {
    probe_obs = std::make_unique<AssemblyProbe<M>>(*probe);
    fan.add(probe_obs.get());
  }
  RunOutcome<M> out;
  if constexpr (requires { m.wants_time_stepping(); }) {
    TimeSteppingWindows w;
    out = run_rigid_assembly(m, md, z, o, fan, w);
    r.time_stepping_windows = w.count;
    r.time_stepping_time = w.time;
    r.time_stepping_steps = w.steps;
    r.time_stepping_reason = w.first;
    r.direct_solves = w.direct;
    r.gauss_seidel_solves = w.gauss_seidel;
    r.lemke_solves = w.lemke;
    r.active_set_iterations = w.active_set_iterations;
    r.gauss_seidel_sweeps = w.sweeps;
    if (effective_scheme(a, o) == AssemblyScheme::TimeStepping) r.impacts = r.event_counts[kAssemblyImpact];
    if (w.count > 0 && r.note.empty())
      r.note = std::to_string(w.count) + " window(s), " + number_text(w.time, 6) +
               " s in all, integrated by Moreau-Jean time-stepping (h = " + number_text(o.step, 6) + " s): " + w.first;
  } else {
    out = run_model(m, md, z, 0.0, o.t_end, o.integrator, fan);
  }
  r.run_status = out.status;
  r.t_final = out.t;
  if (out.status != RunStatus::ReachedEnd && out.status != RunStatus::ModelStop) {
    r.status = SimStatus::Invalid;
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
  r.stats = out.stats;
  if (r.collapse_mode)
    r.motion = "collapse";
  else if (r.event_counts[kAssemblyContactOpens] > 0 || r.event_counts[kAssemblySlipStarts] > 0 ||
           r.event_counts[kAssemblyContactCloses] > 0 || r.event_counts[kAssemblyImpact] > 0 || moved_from_start(a, r))
    r.motion = "stable";
  else
    r.motion = "rest";
  // (A collapse stops the run where it is found; its blocks may have fallen by then.)
  if (const std::string why = fell_through(a, r); !why.empty() && !r.collapse_mode && r.status != SimStatus::Invalid) {
    r.status = SimStatus::Invalid;
    r.note = why;
  }
  return r;
}

}  // namespace

AssemblyResult simulate_assembly(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o,
                                 TrajectoryTable* trajectory, RunProbe* probe) {
  validate(a);
  validate(o);
  if (probe && a.blocks.size() > std::size_t(RunProbe::kMaxBlocks))
    throw std::invalid_argument("a probed run takes at most " + std::to_string(RunProbe::kMaxBlocks) + " blocks");
  const bool rigid = !info(a.contact).springs;  // the rigid law's model, else the springs'
  const int n = int(a.blocks.size());
  const std::size_t ni = a.interfaces.size();
  const int cap = (n == 1 && ni <= 2) ? 1 : (n <= 3 && ni <= 4) ? 3 : (n <= 8 && ni <= 9) ? 8 : 24;
  switch (cap) {
    case 1:
      return rigid ? run<RigidAssemblyModel<1>>(a, g, o, trajectory, probe)
                   : run<AssemblyModel<1>>(a, g, o, trajectory, probe);
    case 3:
      return rigid ? run<RigidAssemblyModel<3>>(a, g, o, trajectory, probe)
                   : run<AssemblyModel<3>>(a, g, o, trajectory, probe);
    case 8:
      return rigid ? run<RigidAssemblyModel<8>>(a, g, o, trajectory, probe)
                   : run<AssemblyModel<8>>(a, g, o, trajectory, probe);
    default:
      return rigid ? run<RigidAssemblyModel<24>>(a, g, o, trajectory, probe)
                   : run<AssemblyModel<24>>(a, g, o, trajectory, probe);
  }
}

}  // namespace blockdyn
