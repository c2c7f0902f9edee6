// SPDX-License-Identifier: Apache-2.0
#include <benchmark/benchmark.h>

#include "blockdyn/model/winkler/initial_conditions.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

using namespace blockdyn;

// Issue 2 benchmark: ic1, r = 0.2, mu = 0.2, to t = 30, k = 1e4, 1e6, 1e8.
static void BM_Ic1(benchmark::State& state) {
  const WinklerParams p{0.2, 0.2, double(state.range(0))};
  WinklerRunOptions o;
  o.t_end = 30;
  o.track_energy = false;
  o.record_events = false;
  WinklerResult r;
  for (auto _ : state) {
    r = simulate(p, {}, ic1(p), o);
    benchmark::DoNotOptimize(r.t_final);
  }
  const double sec_per_run = 1.0;  // placeholder for counters below (per-iteration averages)
  (void)sec_per_run;
  state.counters["steps"] = double(r.stats.accepted);
  state.counters["rhs_evals"] = double(r.stats.rhs_evals);
  state.counters["ns_per_step"] = benchmark::Counter(
      double(r.stats.accepted), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["ns_per_rhs"] = benchmark::Counter(
      double(r.stats.rhs_evals), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Ic1)->Arg(10000)->Arg(1000000)->Arg(100000000)->Unit(benchmark::kMillisecond);

// One right-hand side of the Winkler block in contact (arg 0) or slide (arg 1), both bottom
// corners submerged (the micro-bouncing late regime of the costliest map points): the model's
// share of the cost of a step (twelve of these per DOP853 step).
static void BM_WinklerRhs(benchmark::State& state) {
  const WinklerParams p{1.0, 0.2, 1e7};
  const WinklerBlock block(p);
  const WinklerMode mode =
      state.range(0) == 0 ? WinklerMode{Regime::Contact, 1, 0, 0.0} : WinklerMode{Regime::Slide, 1, 1, 0.0};
  WinklerState z{0.5, -2e-7, 2e-10, 0.0, 3e-4, 1e-8, 0.0, 0.0, 0.0};
  WinklerState dz{};
  for (auto _ : state) {
    z[kH] += 1e-22;  // a new state each time, so nothing is hoisted out of the loop
    block.rhs(0.0, mode, z, dz);
    benchmark::DoNotOptimize(dz);
  }
}
BENCHMARK(BM_WinklerRhs)->Arg(0)->Arg(1);
