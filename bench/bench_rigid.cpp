// SPDX-License-Identifier: Apache-2.0
// Issue 7 benchmark: a 60 s recorded motion (the synthetic fixture, 6000 samples at 0.01 s, every
// sample a breakpoint) on Housner's block and on the 3-DOF block. Counters: steps, events (impacts
// + mechanism changes), rhs evaluations, ns per step and per event.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "blockdyn/simulation/rigid_simulation.hpp"

using namespace blockdyn;

namespace {

GroundMotion record(double scale) {
  GroundMotion g;
  g.horizontal.record = std::make_shared<const Accelerogram>(
      load_accelerogram(std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2", "record"));
  g.horizontal.scale = scale;
  return g;
}

RigidBlockParams block() {
  RigidBlockParams p;
  p.shape.width = 0.3;
  p.shape.height = 1.2;
  p.shape.mass = 500.0;
  p.interface = {0.5, 0.4};
  return p;
}

void counters(benchmark::State& state, const RigidResult& r) {
  const double events = double(r.impacts + r.mode_changes);
  state.counters["steps"] = double(r.stats.accepted);
  state.counters["rhs_evals"] = double(r.stats.rhs_evals);
  state.counters["impacts"] = double(r.impacts);
  state.counters["mode_changes"] = double(r.mode_changes);
  const auto inv = benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert;
  state.counters["ns_per_step"] = benchmark::Counter(double(r.stats.accepted), inv);
  state.counters["ns_per_event"] = benchmark::Counter(events > 0 ? events : 1.0, inv);
  state.SetLabel(std::string(to_string(r.status)) + ", " + to_string(r.final_mode));
}

}  // namespace

namespace {
// 60 s of the synthetic record scaled by range(0) / 10, without events or energy: the run alone.
template <class Run>
void record_run(benchmark::State& state, Run&& run) {
  const GroundMotion g = record(double(state.range(0)) / 10.0);
  const RigidBlockParams p = block();
  RigidRunOptions o;
  o.t_end = 60.0;
  o.record_events = false;
  o.track_energy = false;
  RigidResult r;
  for (auto _ : state) {
    r = run(p, g, o);
    benchmark::DoNotOptimize(r.t_final);
  }
  counters(state, r);
}
}  // namespace

static void BM_HousnerRecord60s(benchmark::State& state) {
  record_run(state, [](const RigidBlockParams& p, const GroundMotion& g, const RigidRunOptions& o) {
    return simulate_housner(p.shape, std::nullopt, g, {}, o);
  });
}
BENCHMARK(BM_HousnerRecord60s)->Arg(10)->Arg(12)->Unit(benchmark::kMicrosecond);

static void BM_RigidRecord60s(benchmark::State& state) {
  record_run(state, [](const RigidBlockParams& p, const GroundMotion& g, const RigidRunOptions& o) {
    return simulate_rigid(p, g, {}, o);
  });
}
BENCHMARK(BM_RigidRecord60s)->Arg(10)->Arg(12)->Unit(benchmark::kMicrosecond);

// Free rocking to rest (the accumulation of impacts), no input breakpoints.
static void BM_HousnerFreeToRest(benchmark::State& state) {
  const RigidBlockParams p = block();
  RigidInitial in;
  in.w0 = 0.5 * p.shape.alpha();
  RigidRunOptions o;
  o.t_end = 60.0;
  o.record_events = false;
  o.track_energy = false;
  RigidResult r;
  for (auto _ : state) {
    r = simulate_housner(p.shape, std::nullopt, {}, in, o);
    benchmark::DoNotOptimize(r.t_final);
  }
  counters(state, r);
}
BENCHMARK(BM_HousnerFreeToRest)->Unit(benchmark::kMicrosecond);
