// SPDX-License-Identifier: Apache-2.0
#pragma once
// One run of the rigid3d body for the tests: from its initial state, at tight tolerances.
#include "blockdyn/simulation/rigid3d_simulation.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/excitation/accelerogram.hpp"

namespace blockdyn::test {

// Standard gravity (m/s^2), the bodies' default g.
inline constexpr double kG = 9.81;

// The 60 s synthetic record of tests/fixtures, read once.
inline std::shared_ptr<const Accelerogram> fixture_record() {
  static const auto rec = std::make_shared<const Accelerogram>(
      load_accelerogram(std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2", "record"));
  return rec;
}

inline BodyOnGroundOptions friction(double mu_s, double mu_k) {
  BodyOnGroundOptions o;
  o.mu_s = mu_s;
  o.mu_k = mu_k;
  return o;
}

// The times of the run's events of kind k.
inline std::vector<double> times_of(const Body3dResult& r, Body3dEventKind k) {
  std::vector<double> t;
  for (const auto& e : r.events)
    if (e.kind == k) t.push_back(e.t);
  return t;
}

// The closed balance's largest drift, in m g (size).
inline double balance_error(const Body3dResult& r, const BodyOnGround& m) {
  return r.max_abs_energy_error / (m.body().mass * m.body().g * m.size());
}

inline Body3dResult run_body(const BodyOnGround& m, const Body3dStart& s, double t_end, bool slip_start = false) {
  Body3dRunOptions o;
  o.t_end = t_end;
  o.slip_start = slip_start;
  o.integ.rtol = 1e-12;
  o.integ.atol = 1e-14;
  return simulate_body3d(m, initial_state(m.body(), s), o);
}

// The planar 3-DOF block of a b x h section (mass, friction, impact law) under g from init, at
// the same tight tolerances: the planar limit's reference.
inline RigidResult planar_block_run(double b, double h, double mass, double mu_s, double mu_k, const GroundMotion& g,
                                    const RigidInitial& init, double t_end, ImpactLaw impact = ImpactLaw::Housner,
                                    std::optional<double> restitution = std::nullopt) {
  RigidBlockParams p;
  p.restitution = restitution;
  p.shape.width = b;
  p.shape.height = h;
  p.shape.mass = mass;
  p.interface = {mu_s, mu_k};
  p.impact = impact;
  RigidRunOptions o;
  o.t_end = t_end;
  o.integrator.rtol = 1e-12;
  o.integrator.atol = 1e-14;
  return simulate_rigid(p, g, init, o);
}

}  // namespace blockdyn::test
