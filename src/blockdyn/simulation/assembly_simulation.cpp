// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/assembly_simulation.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "blockdyn/io/output_clock.hpp"
#include "blockdyn/model/assembly/assembly_model.hpp"
#include "blockdyn/simulation/observer.hpp"
#include "blockdyn/simulation/run.hpp"

namespace blockdyn {

void validate(const AssemblyRunOptions& o) {
  if (!(o.t_end > 0 && o.t_end <= 1e7)) throw std::invalid_argument("t-end must be in (0, 1e7] s");
  if (!(o.integrator.rtol >= 1e-14 && o.integrator.rtol <= 1e-2)) throw std::invalid_argument("rtol must be in [1e-14, 1e-2]");
  if (!(o.integrator.atol >= 1e-16 && o.integrator.atol <= 1e-2)) throw std::invalid_argument("atol must be in [1e-16, 1e-2]");
  if (!(o.output_interval >= 0 && o.output_interval <= 1e7)) throw std::invalid_argument("output-interval must be in [0, 1e7] s");
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
    for (int i = 0; i < m.interfaces(); ++i) {
      const double s = std::fmax(std::fabs(z[M::is(2 * i)]), std::fabs(z[M::is(2 * i + 1)]));
      r_.interfaces[i].max_abs_sliding = std::fmax(r_.interfaces[i].max_abs_sliding, s);
    }
  }
  AssemblyResult& r_;
  const AssemblyRunOptions& o_;
};

// Trajectory CSV: one row per output instant (dense output) and one per event.
template <int Cap>
class AssemblyCsv final : public Observer<Model<Cap>> {
 public:
  using M = Model<Cap>;
  using typename Observer<M>::Mode;
  using typename Observer<M>::State;
  using typename Observer<M>::Event;
  using typename Observer<M>::Segment;

  AssemblyCsv(std::ostream& out, double interval) : out_(out), interval_(interval) {}

  void on_start(const M& m, double t, const Mode& md, const State& z) override {
    out_ << "t,event";
    for (int b = 0; b < m.blocks(); ++b)
      for (const char* c : {"x", "y", "theta", "vx", "vy", "omega"}) out_ << ',' << c << '_' << b;
    out_ << ",a_h,a_v";
    for (int p = 0; p < 2 * m.interfaces(); ++p)
      for (const char* c : {"px", "py", "fn", "ft", "state"}) out_ << ',' << c << '_' << p / 2 << '_' << p % 2;
    out_ << ",E_kin,E_grav,E_spring_n,E_spring_t,E_total,W_ground,W_normal,W_friction,W_switch,energy_balance\n";
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
    char buf[64];
    auto put = [&](double v) {
      const int n = std::snprintf(buf, sizeof buf, ",%.17g", v);
      out_.write(buf, n);
    };
    std::snprintf(buf, sizeof buf, "%.17g,%s", t, ev);
    out_ << buf;
    for (int b = 0; b < m.blocks(); ++b) {
      for (int k = 0; k < 3; ++k) put(z[M::ix(b) + k]);
      for (int k = 0; k < 3; ++k) put(z[M::iv(b) + k]);
    }
    const auto a = m.ground_acceleration(t);
    put(a[0]);
    put(a[1]);
    static const char* kState = "OKPN";  // open, stick (K), slip +, slip -
    for (int p = 0; p < 2 * m.interfaces(); ++p) {
      const auto f = m.point_force(md, z, p);
      put(f.c.P.x);
      put(f.c.P.y);
      put(f.fn);
      put(f.ft);
      out_ << ',' << kState[int(md.point[p])];
    }
    const auto e = m.energy_terms(md, z);
    for (double v : {e.kinetic, e.gravity, e.normal_spring, e.tangential_spring, e.total(), z[M::kWGround],
                     z[M::kWNormal], z[M::kWFriction], z[M::kWSwitch], e.total() - m.work(z) - e0_})
      put(v);
    out_ << '\n';
  }
  std::ostream& out_;
  double interval_;
  OutputClock clock_;
  double e0_ = 0;
};

template <int Cap>
AssemblyEnergy energy_of(const Model<Cap>& m, const typename Model<Cap>::Mode& md, const typename Model<Cap>::State& z) {
  const auto e = m.energy_terms(md, z);
  return {e.kinetic, e.gravity, e.normal_spring, e.tangential_spring, e.total()};
}

template <int Cap>
AssemblyResult run(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o, std::ostream* csv_out) {
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
  std::unique_ptr<AssemblyCsv<Cap>> csv;
  FanOut<M> fan;
  fan.add(&rec).add(&balance);
  if (csv_out) {
    csv = std::make_unique<AssemblyCsv<Cap>>(*csv_out, o.output_interval);
    fan.add(csv.get());
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

}  // namespace

AssemblyResult simulate_assembly(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o,
                                 std::ostream* trajectory) {
  validate(a);
  validate(o);
  const int n = int(a.blocks.size());
  if (n == 1 && a.interfaces.size() <= 2) return run<1>(a, g, o, trajectory);
  if (n <= 3 && a.interfaces.size() <= 4) return run<3>(a, g, o, trajectory);
  return run<8>(a, g, o, trajectory);
}

}  // namespace blockdyn
