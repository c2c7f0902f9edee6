// SPDX-License-Identifier: Apache-2.0
#pragma once
// The trajectory table of a rigid-ground run (HousnerBlock or RigidBlock), SI units: one row per
// output instant (fixed interval, from the dense output) and one row per event (the state after
// it; impacts also get a row with the state before, event "pre_impact").
// Columns: t, x, y, w, vx, vy, vw, mode, event, a_h, a_v (g), N_A, T_A, N_B, T_B (N),
// E_kin, E_pot, E_total, W_friction, W_ground, W_impact, energy_balance (J).
#include "blockdyn/model/rigid/mechanism.hpp"
#include "blockdyn/simulation/observer.hpp"
#include "blockdyn/simulation/output_clock.hpp"
#include "blockdyn/simulation/trajectory_table.hpp"

namespace blockdyn {

template <class Model>
class RigidTrajectory final : public Observer<Model> {
 public:
  using typename Observer<Model>::Mode;
  using typename Observer<Model>::State;
  using typename Observer<Model>::Event;
  using typename Observer<Model>::Segment;

  RigidTrajectory(TrajectoryTable& out, double interval) : out_(out), interval_(interval) {}

  void on_start(const Model& m, double t, const Mode& md, const State& z) override {
    const std::vector<std::string> names{"t",     "x",     "y",     "w",     "vx",         "vy",       "vw",       "mode",
                                         "event", "a_h",   "a_v",   "N_A",   "T_A",        "N_B",      "T_B",      "E_kin",
                                         "E_pot", "E_total", "W_friction", "W_ground", "W_impact", "energy_balance"};
    cells_.resize(names.size());
    out_.columns(names);
    e0_ = m.energy(md, z) - m.work(z);
    row(m, t, md, z, "start");
    clock_.start(t, interval_);
  }
  bool on_segment(const Model& m, const Segment& seg, double, double t1, const Mode& md) override {
    clock_.emit(t1, [&](double t) {
      State z;
      seg.eval(t, z);
      m.complete(md, z);
      row(m, t, md, z, "");
    });
    return true;
  }
  bool on_event(const Model& m, const Event& e) override {
    const auto kind = RigidEventKind(e.kind);
    if (kind == RigidEventKind::GroundBreak && m.mechanism(e.from) == m.mechanism(e.to)) return true;
    if (kind == RigidEventKind::Impact) row(m, e.t, e.from, e.z_before, "pre_impact");
    row(m, e.t, e.to, e.z, to_string(kind));
    return true;
  }

 private:
  void row(const Model& m, double t, const Mode& md, const State& z, const char* event) {
    const auto q = m.pose(md, z);
    const auto a = m.ground_acceleration(t);
    const auto f = m.contact_forces(t, md, z);
    const double ek = m.kinetic_energy(z), e = m.energy(md, z);
    double wf = 0.0;
    if constexpr (requires { Model::kWorkFriction; }) wf = z[Model::kWorkFriction];
    RowBuffer& c = cells_;
    c.clear();
    c.number(t);
    for (double v : q) c.number(v);
    c.text(to_string(m.mechanism(md)));
    c.text(event);
    for (double v : {a[0], a[1], f[0], f[1], f[2], f[3], ek, e - ek, e, wf, z[Model::kWorkGround],
                     z[Model::kWorkImpact], e - m.work(z) - e0_})
      c.number(v);
    c.write_to(out_);
  }

  TrajectoryTable& out_;
  double interval_;
  OutputClock clock_;
  RowBuffer cells_;
  double e0_ = 0;
};

}  // namespace blockdyn
