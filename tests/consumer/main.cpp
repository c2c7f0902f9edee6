// SPDX-License-Identifier: Apache-2.0
// Links against an installed blockdyn: one Housner run, printed as its first impact time.
#include <cstdio>

#include "blockdyn/simulation/rigid_simulation.hpp"

int main() {
  blockdyn::BlockShape s;
  s.width = 0.2;
  s.height = 1.0;
  blockdyn::RigidInitial in;
  in.w0 = 0.1;
  blockdyn::RigidRunOptions o;
  o.t_end = 1.0;
  const auto r = blockdyn::simulate_housner(s, std::nullopt, {}, in, o);
  if (r.impacts < 1) return 1;
  std::printf("first impact at t = %.6f s\n", r.events.front().t);
  return 0;
}
