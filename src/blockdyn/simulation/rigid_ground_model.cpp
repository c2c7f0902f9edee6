// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/rigid_ground_model.hpp"

namespace blockdyn {

const RigidGroundModel& housner_on_rigid_ground() {
  static const RigidGroundModel m{
      "housner", false, "theta: atol, theta': atol p, works: atol m g R",
      [](const RigidBlockParams& p, const GroundMotion& g, const RigidInitial& init, const RigidRunOptions& o) {
        return simulate_housner(p.shape, p.restitution, g, init, o);
      },
      [](const RigidBlockParams& p, const GroundMotion& g, const RigidInitial& init) {
        (void)housner_initial_state(HousnerBlock(p.shape, p.e(), g), init);
      }};
  return m;
}

const RigidGroundModel& three_dof_on_rigid_ground() {
  static const RigidGroundModel m{
      "rigid", true, "x, y: atol h, x', y': atol sqrt(g h), theta: atol, theta': atol p, works: atol m g h",
      [](const RigidBlockParams& p, const GroundMotion& g, const RigidInitial& init, const RigidRunOptions& o) {
        return simulate_rigid(p, g, init, o);
      },
      [](const RigidBlockParams& p, const GroundMotion& g, const RigidInitial& init) {
        (void)rigid_initial_state(RigidBlock(p, g), init);
      }};
  return m;
}

nlohmann::ordered_json parameters_json(const RigidBlockParams& p, const RigidGroundModel& m) {
  const BlockShape& s = p.shape;
  nlohmann::ordered_json j = {{"model", m.name},
                              {"width", s.width},
                              {"height", s.height},
                              {"mass", s.mass},
                              {"g", s.g},
                              {"alpha", s.alpha()},
                              {"half_diagonal", s.half_diagonal()},
                              {"p", s.p()},
                              {"inertia_centre", s.inertia_centre()},
                              {"housner_restitution", s.housner_restitution()}};
  if (m.friction) {
    j["mu_s"] = p.interface.mu_s;
    j["mu_k"] = p.interface.mu_k;
    j["impact"] = to_string(p.impact);
  }
  // Housner's block: its own restitution unless one is given (the impact law is not its option).
  j["restitution"] = m.friction ? p.e() : p.restitution.value_or(s.housner_restitution());
  return j;
}

}  // namespace blockdyn
