// SPDX-License-Identifier: Apache-2.0
// Rocking periodic orbits of the Housner block under harmonic forcing (seed 001 sec. 4.1), the
// tangent dynamics across impacts and mode switches they rest on, and the forced Lyapunov exponent:
//  - the saltation-corrected tangent map over an impact against central differences of the flow;
//  - the symmetric (1, 1) and (1, 3) orbits found by shooting against the closed form of the
//    linearised model (impact phase and velocity, Floquet multipliers), converging as alpha^2;
//  - the multipliers from the variational monodromy against those of the shooting Jacobian;
//  - the largest Lyapunov exponent (variational + saltation + Benettin) of a stable orbit against
//    log max |multiplier| / period;
//  - continuation: fold and symmetry breaking against the closed form;
//  - the tangent map of the 3-DOF block and of a deformable-contact block against finite differences;
//  - superstable rest, sensitive dependence (two orbits) against the exponent, the chaos map's
//    thread invariance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "blockdyn/analysis/dynamics/tangent_lyapunov.hpp"
#include "blockdyn/analysis/forced/block_tangent_traits.hpp"
#include "blockdyn/analysis/forced/chaos_map.hpp"
#include "blockdyn/analysis/forced/forced_lyapunov.hpp"
#include "blockdyn/analysis/forced/housner_periodic_orbits.hpp"
#include "blockdyn/analysis/forced/linear_rocking_orbits.hpp"
#include "blockdyn/analysis/forced/orbit_continuation.hpp"
#include "blockdyn/model/assembly/assembly_model.hpp"
#include "blockdyn/model/rigid_ground/housner_block.hpp"
#include "blockdyn/model/rigid_ground/rigid_block.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"

using namespace blockdyn;

namespace {

// A block of slenderness alpha (height 1 m) forced at beta = K_s / alpha, omega = Omega / p.
RockingForcing forcing(double alpha, double beta, double omega, double e) {
  RockingForcing f;
  f.shape = BlockShape{std::tan(alpha), 1.0, 1.0, 9.81};
  f.restitution = e;
  f.ks = beta * alpha;
  f.omega = omega;
  return f;
}

double phase_gap(double a, double b) {
  double d = std::fabs(std::fmod(a - b, 2 * M_PI));
  return std::fmin(d, 2 * M_PI - d);
}

HousnerBlock forced_block(const RockingForcing& f) {
  GroundMotion g;
  g.horizontal.amplitude = f.ks;
  g.horizontal.frequency = f.Omega() / (2 * M_PI);
  return HousnerBlock(f.shape, f.e(), g);
}

struct Quiet {
  int impacts = 0;
  bool on_step(const DenseSegment<HousnerBlock::kDim>&, double, double, const HousnerMode&) { return true; }
  bool on_event(const EventInfo<HousnerMode, HousnerBlock::kDim>& e) {
    impacts += e.index == HousnerBlock::kEvImpact;
    return true;
  }
};

HousnerBlock::State flow(const HousnerBlock& m, double t0, double t1, HousnerBlock::State z, int* impacts = nullptr) {
  HousnerMode md = m.initial_mode(t0, z);
  HybridIntegrator<HousnerBlock> hi(m, IntegratorOptions{1e-13, 1e-15});
  Quiet q;
  double t = t0;
  EXPECT_EQ(hi.run(t, t1, md, z, q), RunStatus::ReachedEnd);
  if (impacts) *impacts = q.impacts;
  return z;
}

}  // namespace

// The tangent map across impacts (state jump theta' -> e theta' and the pivot switch) equals the
// central-difference Jacobian of the flow map z(t0) -> z(t1).
TEST(TangentMap, HousnerSaltationMatchesFiniteDifferencesOverImpacts) {
  const RockingForcing f = forcing(0.2, 2.0, 3.0, 0.85);
  const HousnerBlock m = forced_block(f);
  const double p = f.p();
  const HousnerBlock::State z0{0.05, -0.3, 0, 0};
  const double t0 = 0.1, t1 = t0 + 2.5 / p;
  int impacts = 0;
  flow(m, t0, t1, z0, &impacts);
  ASSERT_GE(impacts, 1);  // the window holds impacts
  std::array<HousnerBlock::State, 2> dirs{};
  dirs[0][HousnerBlock::kTheta] = 1.0;
  dirs[1][HousnerBlock::kOmega] = p;
  HousnerMode md = m.initial_mode(t0, z0);
  const auto tm = tangent_map<HousnerBlock, 2>(m, md, z0, t0, t1, dirs, IntegratorOptions{1e-13, 1e-15});
  ASSERT_EQ(tm.status, RunStatus::ReachedEnd);
  EXPECT_GE(tm.stats.saltations, 2);
  for (int j = 0; j < 2; ++j) {
    const double h = 1e-6;
    HousnerBlock::State a = z0, b = z0;
    for (std::size_t i = 0; i < 2; ++i) {
      a[i] += h * dirs[j][i];
      b[i] -= h * dirs[j][i];
    }
    const auto za = flow(m, t0, t1, a), zb = flow(m, t0, t1, b);
    for (std::size_t i = 0; i < 2; ++i) {
      const double fd = (za[i] - zb[i]) / (2 * h);
      const double sc = i == 0 ? 1.0 : p;
      EXPECT_NEAR(tm.v[j][i] / sc, fd / sc, 2e-6 * std::fmax(1.0, std::fabs(fd / sc)))
          << "column " << j << " row " << i;
    }
  }
}

// Impact phase and velocity of the symmetric (1, n) orbits against the linearised closed form,
// the error shrinking as alpha^2.
TEST(PeriodicOrbits, SymmetricOrbitsConvergeToTheLinearisedClosedForm) {
  struct Case {
    double beta, omega, e;
    int n;
  };
  for (const Case c : {Case{1.2, 2.0, 0.9, 1}, Case{3.0, 2.0, 0.7, 1}, Case{2.0, 4.0, 0.8, 3}}) {
    const auto lin = linear_symmetric_orbits(c.beta, c.omega, c.e, c.n);
    ASSERT_EQ(lin.size(), 2u);
    const LinearRockingOrbit* ref = nullptr;
    for (const auto& l : lin)
      if (l.valid && (!ref || l.velocity > ref->velocity)) ref = &l;
    ASSERT_NE(ref, nullptr);
    double err_prev = 0;
    for (double alpha : {0.04, 0.02}) {
      const RockingForcing f = forcing(alpha, c.beta, c.omega, c.e);
      const PeriodicOrbit o = find_periodic_orbit(f, OrbitType{1, c.n, true}, ref->phase, ref->velocity);
      ASSERT_TRUE(o.converged) << o.failure;
      const double err = std::fmax(phase_gap(o.phase, ref->phase), std::fabs(o.velocity - ref->velocity));
      EXPECT_LT(err, 2.0 * alpha * alpha) << "beta " << c.beta << " alpha " << alpha;
      for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(std::abs(o.multipliers[k]), std::abs(ref->multipliers[k]),
                    0.05 * std::abs(ref->multipliers[0]) * alpha / 0.04)
            << "beta " << c.beta << " alpha " << alpha;
      if (err_prev > 0) {
        EXPECT_LT(err, 0.4 * err_prev);  // ~ alpha^2: a quarter per halving
      }
      err_prev = err;
    }
  }
}

// Floquet multipliers: the monodromy of the stroboscopic map (variational equation and saltation
// matrices) against the eigenvalues of the shooting Jacobian (central differences of the impact map).
TEST(PeriodicOrbits, MonodromyMultipliersMatchTheShootingJacobian) {
  for (double beta : {1.2, 2.2, 2.6}) {
    const RockingForcing f = forcing(0.15, beta, 2.0, 0.9);
    const auto orbits = find_periodic_orbits(f, OrbitType{1, 1, true},
                                             orbit_guesses(f, OrbitType{1, 1, true}, ShootingOptions{}.integrator));
    ASSERT_FALSE(orbits.empty());
    for (const auto& o : orbits) {
      // The determinant is e^4 (two impacts, each det e^2; the flow preserves area).
      const double det = std::abs(o.multipliers[0] * o.multipliers[1]);
      EXPECT_NEAR(det, std::pow(0.9, 4), 1e-7);
      for (int k = 0; k < 2; ++k) {
        const double scale = std::fmax(1.0, std::abs(o.multipliers[k]));
        EXPECT_NEAR(o.multipliers[k].real(), o.multipliers_fd[k].real(), 1e-5 * scale);
        EXPECT_NEAR(std::fabs(o.multipliers[k].imag()), std::fabs(o.multipliers_fd[k].imag()), 1e-5 * scale);
      }
    }
  }
}

// The largest Lyapunov exponent of a stable periodic orbit (variational equation, saltation at
// every impact, renormalised every period) equals log max |multiplier| / period.
TEST(TangentLyapunov, StableOrbitExponentIsTheFloquetRate) {
  const RockingForcing f = forcing(0.15, 2.2, 2.0, 0.9);
  const auto orbits = find_periodic_orbits(f, OrbitType{1, 1, true},
                                           orbit_guesses(f, OrbitType{1, 1, true}, ShootingOptions{}.integrator));
  const PeriodicOrbit* st = nullptr;
  for (const auto& o : orbits)
    if (o.stable) st = &o;
  ASSERT_NE(st, nullptr);
  // Real multipliers: the exponent is set by the larger one, not by the determinant alone.
  ASSERT_EQ(st->multipliers[0].imag(), 0.0);
  const HousnerBlock m = forced_block(f);
  HousnerBlock::State z{0.0, st->velocity * f.alpha() * f.p(), 0, 0};
  TangentLyapunovOptions o;
  o.t_start = st->phase / f.Omega();
  // Measured from half-way to the first impact: the renormalisations (every period) then never
  // fall on an impact.
  o.t_measure = o.t_start + 0.5 * st->impacts.front().t;
  o.t_end = o.t_measure + 100 * st->period;
  o.interval = st->period;
  o.integrator = IntegratorOptions{1e-12, 1e-14};
  const auto r = tangent_lyapunov(m, HousnerMode{Mechanism::Rock, 1, false}, z, o);
  ASSERT_EQ(r.status, TangentStatus::Completed) << r.note;
  // The multipliers of the shooting Jacobian: central differences of the impact map, independent
  // of the variational machinery measured here.
  const double expected =
      std::log(std::fmax(std::abs(st->multipliers_fd[0]), std::abs(st->multipliers_fd[1]))) / st->period;
  EXPECT_LT(expected, 0.0);
  // The monodromy is far from normal and its multipliers close (0.88, 0.75): the tangent aligns
  // slowly, so the tail after 40 periods is compared.
  EXPECT_NEAR(tail_exponent(r, o.t_measure + 40 * st->period), expected, 1e-3 * std::fabs(expected));
  EXPECT_EQ(r.stats.saltations, 200);  // two impacts per period
  EXPECT_EQ(r.stats.one_sided + r.stats.unmatched + r.stats.grazing, 0);
}

// The continuation meets the fold of the symmetric (1, 1) branch and its symmetry-breaking point
// (the half map's multiplier through -1) where the linearised closed form puts them (small alpha).
TEST(PeriodicOrbits, ContinuationFindsTheFoldAndSymmetryBreakingOfTheClosedForm) {
  const double alpha = 0.04, omega = 2.0, e = 0.9;
  const RockingForcing f = forcing(alpha, 1.2, omega, e);
  const auto orbits = find_periodic_orbits(f, OrbitType{1, 1, true},
                                           orbit_guesses(f, OrbitType{1, 1, true}, ShootingOptions{}.integrator));
  ASSERT_EQ(orbits.size(), 2u);
  const PeriodicOrbit& upper = orbits.back();
  ASSERT_TRUE(upper.stable);
  // Closed form: the fold, and the symmetry breaking by bisection on the half multiplier.
  const double fold = linear_symmetric_fold_beta(omega, e);
  auto half_min = [&](double beta) {
    double best = 0;
    for (const auto& l : linear_symmetric_orbits(beta, omega, e))
      if (l.valid && l.velocity > 0.5) best = std::fmin(l.half_multipliers[0].real(), l.half_multipliers[1].real());
    return best;
  };
  double lo = 1.2, hi = 4.0;
  ASSERT_GT(half_min(lo), -1.0);
  ASSERT_LT(half_min(hi), -1.0);
  for (int k = 0; k < 60; ++k) (half_min(0.5 * (lo + hi)) > -1.0 ? lo : hi) = 0.5 * (lo + hi);
  const double breaking = 0.5 * (lo + hi);
  double found_fold = NAN, found_breaking = NAN;
  for (int dir : {-1, 1}) {
    ContinuationOptions o;
    o.parameter = "ks";
    o.min = 0.01 * alpha;
    o.max = 5.0 * alpha;
    o.direction = dir;
    o.ds = 0.01;
    o.ds_max = 0.05;  // events are located to within a step
    const Branch b = continue_orbit(f, OrbitType{1, 1, true}, upper.phase, upper.velocity, o);
    for (const auto& p : b.points) {
      if (p.event.find("fold") != std::string::npos) found_fold = p.ks / alpha;
      if (p.event.find("symmetry_breaking") != std::string::npos && p.velocity > 0.5) found_breaking = p.ks / alpha;
    }
  }
  EXPECT_NEAR(found_fold, fold, 0.03 * fold);
  EXPECT_NEAR(found_breaking, breaking, 0.03 * breaking);
}

namespace {

RigidBlock::State rigid_flow(const RigidBlock& m, double t0, double t1, RigidBlock::State z, int* impacts = nullptr) {
  auto md = m.initial_mode(t0, z);
  EXPECT_TRUE(md.has_value());
  HybridIntegrator<RigidBlock> hi(m, IntegratorOptions{1e-12, 1e-14});
  struct Count {
    int impacts = 0;
    bool on_step(const DenseSegment<RigidBlock::kDim>&, double, double, const RigidMode&) { return true; }
    bool on_event(const EventInfo<RigidMode, RigidBlock::kDim>& e) {
      impacts += e.kind == int(RigidEventKind::Impact);
      return true;
    }
  } c;
  double t = t0;
  EXPECT_EQ(hi.run(t, t1, *md, z, c), RunStatus::ReachedEnd);
  if (impacts) *impacts = c.impacts;
  return z;
}

}  // namespace

// The 3-DOF block (rocking with impacts, finite-difference Jacobian-vector products, tangents
// projected onto the rocking constraints by complete()) against central differences of its flow.
TEST(TangentMap, RigidBlockMatchesFiniteDifferencesOverImpacts) {
  RigidBlockParams p;
  p.shape = BlockShape{0.3, 1.5, 1.0, 9.81};
  p.interface = {2.0, 2.0};
  GroundMotion g;
  g.horizontal.amplitude = 0.35;
  g.horizontal.frequency = 2.0;
  const RigidBlock m(p, g);
  const double t0 = 0.0, t1 = 2.0, h = 1e-6;
  auto state = [&](double w0, double vw0) {
    RigidInitial in;
    in.w0 = w0;
    in.vw0 = vw0;
    return rigid_initial_state(m, in);
  };
  const double w0 = 0.04, vw0 = -0.2;
  int impacts = 0;
  rigid_flow(m, t0, t1, state(w0, vw0), &impacts);
  ASSERT_GE(impacts, 2);
  const auto sc = TangentTraits<RigidBlock>::scale(m);
  for (int j = 0; j < 2; ++j) {
    const double dw = j == 0 ? h : 0.0, dv = j == 1 ? h * m.p() : 0.0;
    const auto za = state(w0 + dw, vw0 + dv), zb = state(w0 - dw, vw0 - dv);
    std::array<RigidBlock::State, 1> dir{};
    for (std::size_t i = 0; i < RigidBlock::kDim; ++i) dir[0][i] = (za[i] - zb[i]) / (2 * h);
    RigidBlock::State z0 = state(w0, vw0);
    const auto md = m.initial_mode(t0, z0);
    ASSERT_TRUE(md.has_value());
    const auto tm = tangent_map<RigidBlock, 1>(m, *md, z0, t0, t1, dir, IntegratorOptions{1e-12, 1e-14});
    ASSERT_EQ(tm.status, RunStatus::ReachedEnd);
    EXPECT_EQ(tm.stats.unmatched, 0);
    const auto ya = rigid_flow(m, t0, t1, za), yb = rigid_flow(m, t0, t1, zb);
    for (std::size_t i : {RigidBlock::kY, RigidBlock::kTheta, RigidBlock::kVX, RigidBlock::kVY, RigidBlock::kOmega}) {
      const double fd = (ya[i] - yb[i]) / (2 * h) / sc[i];
      EXPECT_NEAR(tm.v[0][i] / sc[i], fd, 1e-4 * std::fmax(1.0, std::fabs(fd)))
          << "direction " << j << " component " << i;
    }
  }
}

// A deformable-contact block (contacts open, close, stick and slip: the vector field switches at
// every event, the state is continuous) against central differences of its flow.
TEST(TangentMap, AssemblyMatchesFiniteDifferencesOverContactSwitches) {
  using M = AssemblyModel<1>;
  PresetOptions po;
  po.ground_law.mu_s = po.ground_law.mu_k = 0.6;
  const Assembly a = make_preset("block", po);
  GroundMotion g;
  g.horizontal.amplitude = 0.45;
  g.horizontal.frequency = 2.0;
  const M m(a, g);
  M::State z = m.initial_state();
  M::Mode md = m.initial_mode(z);
  m.complete(md, z);
  struct Count {
    int events = 0;
    bool on_step(const DenseSegment<M::kDim>&, double, double, const M::Mode&) { return true; }
    bool on_event(const EventInfo<M::Mode, M::kDim>&) {
      ++events;
      return true;
    }
  };
  const IntegratorOptions io{1e-10, 1e-12};
  // Into the motion first (the block rocks and its contacts switch), then the window.
  double t = 0;
  {
    HybridIntegrator<M> hi(m, io);
    Count c;
    ASSERT_EQ(hi.run(t, 0.3, md, z, c), RunStatus::ReachedEnd);
  }
  const double t0 = t, t1 = t0 + 0.15, h = 1e-5;
  auto flow_of = [&](M::State y, int* events) {
    M::Mode mm = md;
    HybridIntegrator<M> hi(m, io);
    Count c;
    double tt = t0;
    EXPECT_EQ(hi.run(tt, t1, mm, y, c), RunStatus::ReachedEnd);
    if (events) *events = c.events;
    return y;
  };
  int events = 0;
  flow_of(z, &events);
  ASSERT_GE(events, 2);
  const auto sc = TangentTraits<M>::scale(m);
  const auto metric = TangentTraits<M>::metric(m);
  for (std::size_t j : {M::iv(0), M::iv(0) + 2}) {  // x' and theta' of the block
    std::array<M::State, 1> dir{};
    dir[0][j] = sc[j];
    const auto tm = tangent_map<M, 1>(m, md, z, t0, t1, dir, io);
    ASSERT_EQ(tm.status, RunStatus::ReachedEnd);
    M::State za = z, zb = z;
    za[j] += h * sc[j];
    zb[j] -= h * sc[j];
    const auto ya = flow_of(za, nullptr), yb = flow_of(zb, nullptr);
    for (std::size_t i = 0; i < M::kDim; ++i) {
      if (!metric[i]) continue;
      const double fd = (ya[i] - yb[i]) / (2 * h) / sc[i];
      EXPECT_NEAR(tm.v[0][i] / sc[i], fd, 2e-3 * std::fmax(1.0, std::fabs(fd)))
          << "direction " << j << " component " << i;
    }
  }
}

// A free block released from a tilt comes to rest after an accumulation of impacts: every nearby
// orbit merges with it, the tangent is annihilated (superstable, exponent -infinity).
TEST(TangentLyapunov, FreeRockingComesToRestSuperstable) {
  RigidInitial in;
  in.w0 = 0.1;
  ForcedLyapunovOptions o;
  o.t_end = 30;
  o.interval = 0.5;
  const auto r = housner_lyapunov(BlockShape{0.3, 1.5, 1.0, 9.81}, std::nullopt, GroundMotion{}, in, o);
  EXPECT_EQ(r.tangent.status, TangentStatus::Superstable) << r.tangent.note;
  EXPECT_EQ(r.tangent.exponent, -INFINITY);
  EXPECT_GT(r.impacts, 10);
}

// Sensitive dependence: with conservative impacts (e = 1) the forced block is chaotic; two orbits
// 1e-9 apart separate to 1e-3 in about the time the exponent predicts, and at a stable orbit
// (e_H) they converge.
TEST(TangentLyapunov, TwinOrbitsSeparateAsTheExponentPredicts) {
  const BlockShape shape{0.3, 1.5, 1.0, 9.81};
  SurvivalOptions so;
  ForcedLyapunovOptions o;
  o.t_end = 60;
  o.t_transient = 20;
  o.twin_d0 = 1e-9;
  o.interval = 2 * M_PI / (12 * shape.p());
  const auto chaotic = housner_lyapunov(shape, 1.0, survival_motion(so, 3.0, 12.0, shape.alpha(), shape.p()), {}, o);
  ASSERT_EQ(chaotic.tangent.status, TangentStatus::Completed) << chaotic.tangent.note;
  const double lam = chaotic.tangent.exponent;
  EXPECT_GT(lam / shape.p(), 0.2);
  // Over the stretch where the separation grows from 1e-7 to 1e-3 (linear regime, the tangent
  // aligned), its growth rate equals the tangent's growth over the same stretch (a finite-time
  // exponent, which fluctuates about the mean lam over so short a time).
  double t_a = NAN, t_b = NAN, s_a = NAN, s_b = NAN;
  for (const auto& s : chaotic.twin) {
    if (std::isnan(t_a) && s.separation > 1e-7) {
      t_a = s.t;
      s_a = s.separation;
    }
    if (std::isnan(t_b) && s.separation > 1e-3) {
      t_b = s.t;
      s_b = s.separation;
    }
  }
  ASSERT_TRUE(std::isfinite(t_a) && std::isfinite(t_b));
  const double rate = std::log(s_b / s_a) / (t_b - t_a);
  double growth = 0;
  for (const auto& h : chaotic.tangent.history)
    if (h.t > t_a + 1e-9 && h.t <= t_b + 1e-9) growth += h.growth;
  const double tangent_rate = growth / (t_b - t_a);
  EXPECT_NEAR(rate, tangent_rate, 0.15 * tangent_rate);
  EXPECT_GT(rate, 0.3 * lam);
  o.interval = 2 * M_PI / (3 * shape.p());
  const auto stable =
      housner_lyapunov(shape, std::nullopt, survival_motion(so, 1.5, 3.0, shape.alpha(), shape.p()), {}, o);
  ASSERT_EQ(stable.tangent.status, TangentStatus::Completed);
  EXPECT_LT(stable.tangent.exponent, 0.0);
  EXPECT_LT(stable.twin.back().separation, 1e-2 * o.twin_d0);
}

// The chaos map is the same for 1 and 2 threads, and classes where the answer is known: below
// uplift (a_H < g tan alpha) the block rests.
TEST(ChaosMap, IdenticalForAnyThreadCountAndRestBelowUplift) {
  const BlockShape shape{0.3, 1.5, 1.0, 9.81};
  const ForcedLyapunovRun run = [shape](const GroundMotion& g, const ForcedLyapunovOptions& fo) {
    return housner_lyapunov(shape, std::nullopt, g, {}, fo);
  };
  ChaosMapOptions o;
  o.grid.beta_min = 0.5;
  o.grid.beta_max = 2.0;
  o.grid.beta_points = 3;
  o.grid.omega_min = 3;
  o.grid.omega_max = 6;
  o.grid.omega_points = 3;
  o.total_periods = 40;
  o.transient_periods = 10;
  o.grid.threads = 1;
  const auto a = chaos_map(run, o, shape.alpha(), shape.p());
  o.grid.threads = 2;
  const auto b = chaos_map(run, o, shape.alpha(), shape.p());
  ASSERT_EQ(a.size(), 9u);
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].motion, b[k].motion);
    EXPECT_EQ(std::memcmp(&a[k].exponent, &b[k].exponent, sizeof(double)), 0);
    EXPECT_EQ(a[k].impacts, b[k].impacts);
    if (a[k].beta * shape.alpha() < std::tan(shape.alpha())) {
      EXPECT_EQ(a[k].motion, "rest");
    }
  }
  EXPECT_EQ(a[8].motion, "periodic");  // beta = 2, omega = 6: a stable rocking orbit
}
