// SPDX-License-Identifier: Apache-2.0
// Issue 8 benchmark: seed 002's trilith (lambda = 4, deformable contacts k_N = 1e7 N/m) under a
// harmonic ground motion for 300 s, at the default tolerances and at the seed's looser ones, and
// the same trilith at rest; the same with the rigid law (Moreau-Jean, h = 1e-4 s). Counters: steps,
// contact events, rhs evaluations, ns per rhs and per step; the rigid law's direct and Gauss-Seidel
// contact solves. Times are CPU times of one core (`CPU` column).
#include <benchmark/benchmark.h>

#include <cmath>

#include "blockdyn/simulation/assembly_simulation.hpp"

using namespace blockdyn;

namespace {

Assembly trilith(double phi_deg, bool rigid = false) {
  PresetOptions o;
  o.contact = rigid ? blockdyn::ContactKind::Rigid : blockdyn::ContactKind::Deformable;
  if (rigid) o.ground_law.restitution = o.block_law.restitution = 0.0;
  o.ground_law.mu_s = o.ground_law.mu_k = o.block_law.mu_s = o.block_law.mu_k =
      phi_deg >= 90 ? kNoSlipFriction : std::tan(phi_deg * M_PI / 180);
  return make_preset("trilith", o);
}

// a_H = beta alpha g cos(Omega t), omega = Omega / p (seed 002); p = 5.4535 rad/s, alpha = 14.04 deg.
GroundMotion seed_harmonic(double beta, double omega) {
  const double alpha = std::atan(0.25), p = 5.4535;
  GroundMotion g;
  g.horizontal.amplitude = beta * alpha;
  g.horizontal.frequency = omega * p / (2 * M_PI);
  g.horizontal.phase = 0.5 * M_PI;
  return g;
}

void run(benchmark::State& state, const Assembly& a, const GroundMotion& g, double rtol, double atol, double t_end,
         double step = 1e-4, AssemblyScheme scheme = AssemblyScheme::TimeStepping) {
  AssemblyRunOptions o;
  o.scheme = scheme;
  o.step = step;
  o.t_end = t_end;
  o.integrator.rtol = rtol;
  o.integrator.atol = atol;
  o.record_events = false;
  AssemblyResult r;
  for (auto _ : state) r = simulate_assembly(a, g, o);
  state.counters["steps"] = double(r.stats.accepted);
  state.counters["rhs_evals"] = double(r.stats.rhs_evals);
  state.counters["events"] = double(r.events_total);
  state.counters["t_final"] = r.t_final;
  const auto inv = benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert;
  state.counters["ns_per_rhs"] = benchmark::Counter(double(r.stats.rhs_evals), inv);
  state.counters["ns_per_step"] = benchmark::Counter(double(r.stats.accepted), inv);
  if (blockdyn::info(a.contact).schemes) {  // the rigid law
    state.counters["direct"] = double(r.direct_solves);
    state.counters["gauss_seidel"] = double(r.gauss_seidel_solves);
  } else {
    state.counters["rejected"] = double(r.stats.rejected);
  }
}

// Seed 002 Figs. 12-14: phi = 90, beta = 4, omega = 10 (a (1,3) cycle for t < 280 s).
void BM_TrilithHarmonic300s(benchmark::State& s) { run(s, trilith(90), seed_harmonic(4, 10), 1e-8, 1e-10, 300); }
void BM_TrilithHarmonic300sLoose(benchmark::State& s) { run(s, trilith(90), seed_harmonic(4, 10), 1e-6, 1e-8, 300); }
void BM_TrilithFriction300s(benchmark::State& s) { run(s, trilith(20), seed_harmonic(1.5, 3), 1e-8, 1e-10, 300); }
void BM_TrilithAtRest100s(benchmark::State& s) { run(s, trilith(90), {}, 1e-8, 1e-10, 100); }
// The rigid law (Moreau-Jean, h = 1e-4 s): the seed's harmonic case and the trilith at rest.
void BM_RigidTrilithHarmonic300s(benchmark::State& s) {
  run(s, trilith(90, true), seed_harmonic(4, 10), 1e-8, 1e-10, 300);
}
void BM_RigidTrilithAtRest100s(benchmark::State& s) { run(s, trilith(90, true), {}, 1e-8, 1e-10, 100); }
// The rigid law, event-driven (issue 25): the same two cases, default tolerances.
void BM_RigidEventDrivenTrilithHarmonic300s(benchmark::State& s) {
  run(s, trilith(90, true), seed_harmonic(4, 10), 1e-8, 1e-10, 300, 1e-4, AssemblyScheme::EventDriven);
}
void BM_RigidEventDrivenTrilithAtRest100s(benchmark::State& s) {
  run(s, trilith(90, true), {}, 1e-8, 1e-10, 100, 1e-4, AssemblyScheme::EventDriven);
}

}  // namespace

BENCHMARK(BM_TrilithHarmonic300s)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_TrilithHarmonic300sLoose)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_TrilithFriction300s)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_TrilithAtRest100s)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RigidTrilithHarmonic300s)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RigidTrilithAtRest100s)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RigidEventDrivenTrilithHarmonic300s)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RigidEventDrivenTrilithAtRest100s)->Unit(benchmark::kMillisecond)->Iterations(1);
