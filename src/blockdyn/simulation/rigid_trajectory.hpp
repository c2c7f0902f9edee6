// SPDX-License-Identifier: Apache-2.0
#pragma once
// The trajectory table of a rigid-ground run (HousnerBlock or RigidBlock), SI units: one row per
// output instant (fixed interval, from the dense output) and one row per event (the state after
// it; impacts also get a row with the state before, event "pre_impact").
// Columns: t, x, y, w, vx, vy, vw, mode, event, a_h, a_v (g), N_A, T_A, N_B, T_B (N),
// E_kin, E_pot, E_total, W_friction, W_ground, W_impact, energy_balance (J).
#include "blockdyn/model/rigid_ground/mechanism.hpp"
#include "blockdyn/simulation/trajectory_rows.hpp"

namespace blockdyn {

template <class Model>
class RigidTrajectory final : public TrajectoryRows<Model, RigidTrajectory<Model>> {
  using Base = TrajectoryRows<Model, RigidTrajectory<Model>>;

 public:
  BLOCKDYN_OBSERVER_TYPES(Model);

  using Base::Base;

  std::vector<std::string> columns(const Model&) const {
    return {"t",          "x",
            "y",          "w",
            "vx",         "vy",
            "vw",         "mode",
            "event",      "a_h",
            "a_v",        "N_A",
            "T_A",        "N_B",
            "T_B",        "E_kin",
            "E_pot",      "E_total",
            "W_friction", "W_ground",
            "W_impact",   "energy_balance"};
  }
  void started(const Model& m, const Mode& md, const State& z) { e0_ = m.energy(md, z) - m.work(z); }
  bool on_event(const Model& m, const Event& e) override {
    const auto kind = RigidEventKind(e.kind);
    if (kind == RigidEventKind::GroundBreak && m.mechanism(e.from) == m.mechanism(e.to)) return true;
    if (kind == RigidEventKind::Impact) this->row(m, e.t, e.from, e.z_before, "pre_impact");
    this->row(m, e.t, e.to, e.z, to_string(kind));
    return true;
  }
  void fill(RowBuffer& c, const Model& m, double t, const Mode& md, const State& z, const char* event) const {
    const auto q = m.pose(md, z);
    const auto a = m.ground_acceleration(t);
    const auto f = m.contact_forces(t, md, z);
    const double ek = m.kinetic_energy(z), e = m.energy(md, z);
    double wf = 0.0;
    if constexpr (requires { Model::kWorkFriction; }) wf = z[Model::kWorkFriction];
    c.number(t);
    for (double v : q) c.number(v);
    c.text(to_string(m.mechanism(md)));
    c.text(event);
    for (double v : {a[0], a[1], f[0], f[1], f[2], f[3], ek, e - ek, e, wf, z[Model::kWorkGround],
                     z[Model::kWorkImpact], e - m.work(z) - e0_})
      c.number(v);
  }

 private:
  double e0_ = 0;
};

}  // namespace blockdyn
