// SPDX-License-Identifier: Apache-2.0
// Issue 40 benchmark: the rigid3d box under the 60 s synthetic record (6000 samples, every one a
// breakpoint) along its x axis, beside Housner's planar block of the same width and height under
// the same record (the planar limit: the same impacts) and the planar 3-DOF `rigid` block (the
// issue's reference), the box with Housner's law at the impacts
// instead of Newton's (the default), and the box under the record in two horizontal components at
// once. Counters: steps, impacts, ns per step.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "blockdyn/simulation/rigid3d_simulation.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"

using namespace blockdyn;

namespace {

std::shared_ptr<const Accelerogram> fixture() {
  static const auto rec = std::make_shared<const Accelerogram>(
      load_accelerogram(std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2", "record"));
  return rec;
}

void run_box(benchmark::State& state, double h2_share, Body3dImpactLaw law = Body3dImpactLaw::Newton) {
  GroundMotion3d g;
  g.h.record = fixture();
  g.h.scale = double(state.range(0)) / 10.0;
  if (h2_share > 0) {
    g.h2.record = fixture();
    g.h2.scale = h2_share * g.h.scale;
    g.azimuth = 30;
  }
  BodyOnGroundOptions mo;
  mo.mu_s = 1e6;  // sticking, as Housner's block
  mo.impact = law;
  const BodyOnGround m(box_body(0.3, 0.3, 1.2, 500), g, mo);
  Body3dRunOptions o;
  o.t_end = 60;
  o.output_interval = 0;
  o.track_energy = false;
  o.track_tilt = false;
  auto ignore = [](const Body3dEventRecord&) {};
  blockdyn::EventCallback<Body3dEventRecord, decltype(ignore)> sink(ignore);
  o.events = &sink;  // counted, not kept
  Body3dResult r;
  for (auto _ : state) {
    r = simulate_body3d(m, initial_state(m.body(), {}), o);
    benchmark::DoNotOptimize(r.t_final);
  }
  state.counters["steps"] = double(r.stats.accepted);
  state.counters["impacts"] = double(r.impacts);
  const auto inv = benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert;
  state.counters["ns_per_step"] = benchmark::Counter(double(r.stats.accepted > 0 ? r.stats.accepted : 1), inv);
  state.SetLabel(to_string(r.status));
}

}  // namespace

static void BM_Rigid3dBoxRecordAlongX(benchmark::State& state) { run_box(state, 0.0); }
BENCHMARK(BM_Rigid3dBoxRecordAlongX)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);

// The same box with Housner's law at the impacts (the option): what Newton's impact problem costs.
static void BM_Rigid3dBoxRecordAlongXHousnerLaw(benchmark::State& state) {
  run_box(state, 0.0, Body3dImpactLaw::Housner);
}
BENCHMARK(BM_Rigid3dBoxRecordAlongXHousnerLaw)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);

// A planar block of the box's section (0.3 x 1.2 m, 500 kg) under the same record, by `run`.
template <class Run>
void planar_same_block(benchmark::State& state, Run&& run) {
  GroundMotion g;
  g.horizontal.record = fixture();
  g.horizontal.scale = double(state.range(0)) / 10.0;
  RigidBlockParams p;
  p.shape = BlockShape{0.3, 1.2, 500, 9.81};
  p.interface = {1e3, 1e3};  // sticking (the planar model's largest friction)
  p.impact = ImpactLaw::Newton;
  RigidRunOptions o;
  o.t_end = 60;
  o.record_events = false;
  o.track_energy = false;
  RigidResult r;
  for (auto _ : state) {
    r = run(p, g, o);
    benchmark::DoNotOptimize(r.t_final);
  }
  state.counters["steps"] = double(r.stats.accepted);
  state.counters["impacts"] = double(r.impacts);
  state.SetLabel(to_string(r.status));
}

static void BM_HousnerSameBlockSameRecord(benchmark::State& state) {
  planar_same_block(state, [](const RigidBlockParams& p, const GroundMotion& g, const RigidRunOptions& o) {
    return simulate_housner(p.shape, std::nullopt, g, {}, o);
  });
}
BENCHMARK(BM_HousnerSameBlockSameRecord)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);

// The planar 3-DOF `rigid` block, the reference: the same friction (sticking) and
// Newton's law with e = 0 at the impacts, as the box has them.
static void BM_RigidSameBlockSameRecord(benchmark::State& state) {
  planar_same_block(state, [](const RigidBlockParams& p, const GroundMotion& g, const RigidRunOptions& o) {
    return simulate_rigid(p, g, {}, o);
  });
}
BENCHMARK(BM_RigidSameBlockSameRecord)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);

static void BM_Rigid3dBoxRecordTwoComponents(benchmark::State& state) { run_box(state, 0.6); }
BENCHMARK(BM_Rigid3dBoxRecordTwoComponents)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);
