// SPDX-License-Identifier: Apache-2.0
#pragma once
// One whole run of any hybrid model from a mode and state to t_end, with its observers
// (simulation.hpp: the event-driven Simulation), and where it ended.
#include "blockdyn/simulation/simulation.hpp"

namespace blockdyn {

template <class Model>
struct RunOutcome {
  RunStatus status = RunStatus::ReachedEnd;
  double t = 0;
  typename Model::Mode mode{};
  Vec<Model::kDim> z{};
  StepperStats stats;
};

template <HybridModel Model>
RunOutcome<Model> run_model(const Model& m, typename Model::Mode mode, Vec<Model::kDim> z, double t0, double t_end,
                            const IntegratorOptions& opt, Observer<Model>& obs) {
  Simulation<Model> sim(m, opt, t0, mode, z);
  RunOutcome<Model> out;
  out.status = sim.run(t_end, obs);
  out.t = sim.t();
  out.mode = sim.mode();
  out.z = sim.state();
  out.stats = sim.stats();
  return out;
}

}  // namespace blockdyn
