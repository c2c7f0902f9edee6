// SPDX-License-Identifier: Apache-2.0
// Links against an installed blockdyn and runs, through its typed C++ API: one Housner run, a
// fragility study of the same block under a synthetic suite, and the limit analysis of an arch.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "blockdyn/analysis/forced/fragility_study.hpp"
#include "blockdyn/analysis/masonry/limit_analysis.hpp"
#include "blockdyn/excitation/stochastic_motion.hpp"
#include "blockdyn/simulation/rigid_ground_model.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"

using namespace blockdyn;

int main() {
  // A free-rocking block.
  BlockShape s;
  s.width = 0.2;
  s.height = 1.0;
  RigidInitial in;
  in.w0 = 0.1;
  RigidRunOptions o;
  o.t_end = 1.0;
  const RigidResult r = simulate_housner(s, std::nullopt, {}, in, o);
  if (r.impacts < 1) return 1;
  std::printf("first impact at t = %.6f s\n", r.events.front().t);

  // Its fragility: 6 synthetic records (Rezaeian's model, seed 7), each scaled to 5 levels of pga.
  RezaeianParams rp;
  rp.arias = 1.0, rp.d5_95 = 10, rp.t_mid = 8, rp.f_mid = 3, rp.f_slope = -0.05, rp.t_end = 20;
  const Modulation q = fit_modulation(rp.arias, rp.d5_95, rp.t_mid, rp.g);
  std::vector<std::string> names;
  std::vector<std::shared_ptr<const Accelerogram>> records;
  for (int k = 0; k < 6; ++k) {
    names.push_back("record " + std::to_string(k + 1));
    records.push_back(std::make_shared<const Accelerogram>(rezaeian_record(rp, q, 7, k).a, rp.dt, names.back()));
  }
  RigidBlockParams block;
  block.shape = s;
  const ForcedModel model = forced_block_model(block, housner_on_rigid_ground());
  const FragilitySuite suite = fragility_suite(names, records, IntensityMeasure::pga(), 9.81, model.alpha);
  const FragilityResult f = run_fragility(model, suite, {.levels = {0.1, 0.2, 0.3, 0.4, 0.5}, .bootstrap = 0});
  if (f.runs.size() != 30) return 1;
  if (f.fit.ok)
    std::printf("fragility: median pga %.3f g, beta %.3f\n", f.fit.median, f.fit.beta);
  else
    std::printf("fragility: no fit (%s)\n", f.fit.why.c_str());

  // The collapse multiplier of a 9-voussoir semicircular arch, t/R = 0.15.
  const LimitAnalysis la = limit_analysis(make_preset("arch", PresetOptions{}), +1);
  if (la.status != "ok") return 1;
  std::printf("arch: collapse multiplier %.4f\n", la.lambda);
  return 0;
}
