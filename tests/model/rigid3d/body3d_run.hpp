// SPDX-License-Identifier: Apache-2.0
#pragma once
// One run of the rigid3d body for the tests: from its initial state, at tight tolerances.
#include "blockdyn/simulation/rigid3d_simulation.hpp"

namespace blockdyn::test {

inline Body3dResult run_body(const BodyOnGround& m, const Body3dStart& s, double t_end) {
  Body3dRunOptions o;
  o.t_end = t_end;
  o.integ.rtol = 1e-12;
  o.integ.atol = 1e-14;
  return simulate_body3d(m, initial_state(m.body(), s), o);
}

}  // namespace blockdyn::test
