// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the flight and stability studies share: how each run is integrated, and one point of a
// critical curve (the boundary found at one aspect ratio).
#include "blockdyn/analysis/sweep/boundary_search.hpp"
#include "blockdyn/integrate/integrator_options.hpp"

namespace blockdyn {

struct StudyRunOptions {
  double t_end = 30;  // observation time of each run (the thesis uses 30 for stability)
  // A study runs thousands of simulations: a step cap turns a pathologically slow run (e.g.
  // tiny steps of a block creeping to rest on a very stiff foundation) into a reported
  // numerical failure instead of a stalled sweep.
  IntegratorOptions integrator = [] {
    IntegratorOptions o;
    o.max_steps = 5'000'000;
    return o;
  }();
};

struct CurvePoint {
  double r = 0;
  BoundaryResult result;
  int undecided = 0;  // predicate runs that reached t_end before the question was settled
};

}  // namespace blockdyn
