// SPDX-License-Identifier: Apache-2.0
// Rocking periodic orbits of the Housner block under harmonic forcing (seed 001 sec. 4.1) and the
// tangent dynamics across impacts they rest on:
//  - the saltation-corrected tangent map over an impact against central differences of the flow;
//  - the symmetric (1, 1) and (1, 3) orbits found by shooting against the closed form of the
//    linearised model (impact phase and velocity, Floquet multipliers), converging as alpha^2;
//  - the multipliers from the variational monodromy against those of the shooting Jacobian;
//  - the largest Lyapunov exponent (variational + saltation + Benettin) of a stable orbit against
//    log max |multiplier| / period.
#include <gtest/gtest.h>

#include <cmath>

#include "blockdyn/analysis/dynamics/tangent_lyapunov.hpp"
#include "blockdyn/analysis/forced/block_tangent_traits.hpp"
#include "blockdyn/analysis/forced/housner_periodic_orbits.hpp"
#include "blockdyn/analysis/forced/linear_rocking_orbits.hpp"
#include "blockdyn/model/rigid/housner_block.hpp"

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
      EXPECT_NEAR(tm.v[j][i] / sc, fd / sc, 2e-6 * std::fmax(1.0, std::fabs(fd / sc))) << "column " << j << " row " << i;
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
    const auto orbits = find_periodic_orbits(f, OrbitType{1, 1, true}, orbit_guesses(f, OrbitType{1, 1, true}));
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
  const auto orbits = find_periodic_orbits(f, OrbitType{1, 1, true}, orbit_guesses(f, OrbitType{1, 1, true}));
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
  const double expected = std::log(std::abs(st->multipliers[0])) / st->period;
  EXPECT_LT(expected, 0.0);
  // The monodromy is far from normal and its multipliers close (0.88, 0.75): the tangent aligns
  // slowly, so the tail after 40 periods is compared.
  EXPECT_NEAR(tail_exponent(r, o.t_measure + 40 * st->period), expected, 1e-3 * std::fabs(expected));
  EXPECT_EQ(r.stats.saltations, 200);  // two impacts per period
  EXPECT_EQ(r.stats.one_sided + r.stats.unmatched + r.stats.grazing, 0);
}
