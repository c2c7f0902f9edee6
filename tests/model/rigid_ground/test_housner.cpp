// SPDX-License-Identifier: Apache-2.0
// Housner's rocking block (issue 7, sec. 3) against independent references: first integrals of
// the exact equation evaluated by double-exponential quadrature (housner_reference.hpp), the
// linearised closed forms of the spec in the small-alpha limit, energy, symmetry and the
// accumulation of impacts.
#include <gtest/gtest.h>

#include <cmath>

#include "blockdyn/simulation/rigid_simulation.hpp"
#include "housner_reference.hpp"
#include "test_support.hpp"

using namespace blockdyn;
using namespace blockdyn::test;

namespace {

BlockShape slender(double b_over_h, double h = 1.0) {
  BlockShape s;
  s.height = h;
  s.width = b_over_h * h;
  s.mass = 3.0;
  return s;
}

RigidRunOptions housner_run_to(double t_end) {
  RigidRunOptions o;
  o.t_end = t_end;
  return o;
}

std::vector<RigidEventRecord> impacts(const RigidResult& r) {
  std::vector<RigidEventRecord> v;
  for (const auto& e : r.events)
    if (e.kind == RigidEventKind::Impact) v.push_back(e);
  return v;
}

GroundMotion rect_pulse(double A, double tp) {
  GroundMotion g;
  g.horizontal.pulse = PulseShape::Rect;
  g.horizontal.amplitude = A;
  g.horizontal.duration = tp;
  return g;
}

}  // namespace

// Free rocking from rest: the first ten impact times and rates equal the quadrature of the energy
// integral (t_{k+1} = t_k + 2 tau(a_k), a_k the amplitude reached after impact k).
TEST(Housner, FreeRockingImpactsMatchQuadrature) {
  for (double bh : {0.1, 0.25, 0.5}) {
    for (double frac : {0.2, 0.6, 0.95}) {
      const BlockShape s = slender(bh, 2.0);
      const double alpha = s.alpha(), p = s.p(), e = s.housner_restitution();
      RigidInitial in;
      in.w0 = frac * alpha;
      const auto ref = housner_free_impacts(alpha, p, in.w0, e, 10);
      const RigidResult r = simulate_housner(s, std::nullopt, {}, in, housner_run_to(ref[9].t + 0.5 / p));
      const auto got = impacts(r);
      ASSERT_GE(got.size(), 10u) << "b/h " << bh;
      double max_dt = 0, max_dw = 0;
      for (int k = 0; k < 10; ++k) {
        max_dt = std::fmax(max_dt, std::fabs(got[k].t - ref[k].t));
        max_dw = std::fmax(max_dw, std::fabs(std::fabs(got[k].vw_before) - ref[k].w_before) / ref[k].w_before);
        EXPECT_NEAR(got[k].vw_after / got[k].vw_before, e, 1e-14);  // Housner's coefficient, exactly
        EXPECT_EQ(got[k].corner, k % 2 == 0 ? -1 : 1);              // released on A, lands on B first
      }
      EXPECT_LT(max_dt, 1e-8) << "b/h " << bh << " theta0/alpha " << frac;
      EXPECT_LT(max_dw, 1e-8) << "b/h " << bh << " theta0/alpha " << frac;
      record(("housner_impact_time_error_bh" + std::to_string(bh) + "_f" + std::to_string(frac)).c_str(), max_dt);
    }
  }
}

// Linearised closed form t1 = acosh(1/(1 - theta0/alpha)) / p is the small-alpha limit of the exact
// first impact: the relative difference shrinks like alpha^2.
TEST(Housner, FirstImpactTendsToLinearisedClosedForm) {
  double prev = 0;
  for (double bh : {0.08, 0.04, 0.02}) {
    const BlockShape s = slender(bh);
    const double alpha = s.alpha(), p = s.p();
    RigidInitial in;
    in.w0 = 0.5 * alpha;
    const RigidResult r = simulate_housner(s, std::nullopt, {}, in, housner_run_to(20.0 / p));
    const double t1 = impacts(r).at(0).t;
    const double lin = std::acosh(1.0 / (1.0 - 0.5)) / p;
    const double rel = std::fabs(t1 - lin) / lin;
    if (prev > 0) {
      EXPECT_NEAR(prev / rel, 4.0, 0.4) << "alpha^2 convergence at b/h " << bh;
    }
    EXPECT_LT(rel, 0.2 * alpha * alpha);
    prev = rel;
  }
}

// With e = 1 nothing is lost: the motion is periodic with period 4 t1 (t1 from quadrature).
TEST(Housner, ElasticRockingIsPeriodic) {
  const BlockShape s = slender(0.3);
  RigidInitial in;
  in.w0 = 0.7 * s.alpha();
  // Tight tolerances: the amplitude check below asks for 1e-12 rad over four swings.
  RigidRunOptions o = housner_run_to(8.0);
  o.integrator.rtol = 1e-13;
  o.integrator.atol = 1e-15;
  const RigidResult r = simulate_housner(s, 1.0, {}, in, o);
  const double t1 = housner_quarter_swing(s.alpha(), s.p(), in.w0);
  const auto im = impacts(r);
  ASSERT_GE(im.size(), 6u);
  for (std::size_t k = 0; k < im.size(); ++k) EXPECT_NEAR(im[k].t, t1 * (1 + 2 * double(k)), 1e-8);
  EXPECT_LT(r.max_abs_energy_error, 1e-10 * s.mass * s.g * s.half_diagonal());
  EXPECT_NEAR(r.max_abs_rotation, in.w0, 1e-12);
}

// Impacts accumulate in finite time: the block comes to rest at the accumulation point of the
// quadrature chain, after a finite number of impacts, and stays at rest.
TEST(Housner, ImpactAccumulationEndsAtRest) {
  for (double bh : {0.2, 0.5}) {
    const BlockShape s = slender(bh);
    RigidInitial in;
    in.w0 = 0.5 * s.alpha();
    const double e = s.housner_restitution();
    const RigidResult r = simulate_housner(s, std::nullopt, {}, in, housner_run_to(60.0));
    EXPECT_EQ(r.status, SimStatus::TEnd);
    EXPECT_EQ(r.final_mode, Mechanism::Rest);
    const double t_rest_ref = housner_rest_time(s.alpha(), s.p(), in.w0, e);
    double t_rest = -1;
    for (const auto& ev : r.events)
      if (ev.kind == RigidEventKind::Mode && ev.to == Mechanism::Rest) t_rest = ev.t;
    EXPECT_NEAR(t_rest, t_rest_ref, 1e-7) << "b/h " << bh;
    EXPECT_LT(r.impacts, 5000);
    EXPECT_EQ(r.final_state[5], 0.0);
    record(("housner_rest_time_error_bh" + std::to_string(bh)).c_str(), t_rest - t_rest_ref);
  }
}

// Rectangular pulse: the smallest overturning amplitude equals the exact reference (quadrature of
// the pulse phase + energy barrier of the free phase), and the linearised closed form
// a_p / (g alpha) = 1 / (1 - exp(-p t_p)) is its small-alpha limit.
TEST(Housner, RectangularPulseOverturningThreshold) {
  for (double bh : {0.2, 0.05}) {
    const BlockShape s = slender(bh, 1.5);
    const double alpha = s.alpha(), p = s.p();
    for (double ptp : {0.5, 1.0, 3.0}) {
      const double tp = ptp / p;
      const double ref = housner_rect_pulse_threshold(alpha, p, tp);
      // Bisection on the simulator's outcome.
      double lo = std::tan(alpha), hi = 2.0 * ref;
      RigidInitial in;
      auto overturns = [&](double A) {
        return simulate_housner(s, std::nullopt, rect_pulse(A, tp), in, housner_run_to(tp + 20.0 / p)).status ==
               SimStatus::Overturned;
      };
      ASSERT_TRUE(overturns(hi));
      for (int it = 0; it < 45; ++it) {
        const double mid = 0.5 * (lo + hi);
        (overturns(mid) ? hi : lo) = mid;
      }
      EXPECT_NEAR(hi / ref, 1.0, 1e-7) << "b/h " << bh << " p tp " << ptp;
      const double lin = alpha / (1.0 - std::exp(-ptp));
      const double dev = std::fabs(ref / lin - 1.0);
      EXPECT_LT(dev, 0.5 * alpha * alpha + 1e-9) << "linearised limit, b/h " << bh << " p tp " << ptp;
      record(("housner_rect_threshold_rel_to_linear_bh" + std::to_string(bh) + "_ptp" + std::to_string(ptp)).c_str(),
             ref / lin - 1.0);
    }
  }
}

// Mirrored ground motion mirrors the motion: theta(t) -> -theta(t), same event times.
TEST(Housner, MirroredGroundMotionMirrorsTheMotion) {
  const BlockShape s = slender(0.25, 1.2);
  GroundMotion g;
  g.horizontal.amplitude = 0.4;
  g.horizontal.frequency = 1.5;
  g.horizontal.phase = 0.3;
  GroundMotion gm = g;
  gm.horizontal.amplitude = -0.4;
  RigidInitial in;
  const RigidResult a = simulate_housner(s, std::nullopt, g, in, housner_run_to(8.0));
  const RigidResult b = simulate_housner(s, std::nullopt, gm, in, housner_run_to(8.0));
  ASSERT_EQ(a.events.size(), b.events.size());
  ASSERT_GT(a.impacts, 3);
  for (std::size_t k = 0; k < a.events.size(); ++k) {
    EXPECT_EQ(a.events[k].kind, b.events[k].kind);
    EXPECT_NEAR(a.events[k].t, b.events[k].t, 1e-12);
    EXPECT_NEAR(a.events[k].state[2], -b.events[k].state[2], 1e-12);
    if (a.events[k].kind == RigidEventKind::Impact) {
      EXPECT_EQ(a.events[k].corner, -b.events[k].corner);
    }
  }
}

// Under harmonic forcing the closed balance E - E0 - W_ground - W_impact stays at the
// integration error, between and across impacts.
TEST(Housner, EnergyBalanceUnderForcing) {
  const BlockShape s = slender(0.2, 2.0);
  GroundMotion g;
  g.horizontal.amplitude = 0.25;
  g.horizontal.frequency = 1.0;
  g.vertical.amplitude = 0.1;
  g.vertical.frequency = 2.3;
  RigidInitial in;
  const RigidResult r = simulate_housner(s, std::nullopt, g, in, housner_run_to(20.0));
  ASSERT_EQ(r.status, SimStatus::TEnd);
  ASSERT_GT(r.impacts, 5);
  const double scale = s.mass * s.g * s.half_diagonal();
  EXPECT_LT(r.max_abs_energy_error, 1e-8 * scale);
  EXPECT_GT(std::fabs(r.work_ground), 1e-3 * scale);
  EXPECT_LT(r.work_impact, 0.0);
  record("housner_energy_balance_error_rel", r.max_abs_energy_error / scale);
}

// A block carried past alpha by a pulse whose second half pushes it back recovers: beyond_alpha
// then within_alpha, no overturn (overturn is |theta| = pi/2).
TEST(Housner, PassingAlphaIsNotOverturning) {
  const BlockShape s = slender(0.2, 1.0);
  const double p = s.p();
  GroundMotion g;
  g.horizontal.pulse = PulseShape::OneSine;
  g.horizontal.duration = 0.76 / p;
  RigidInitial in;
  // Scan the amplitude for a run that passes alpha and survives.
  bool found = false;
  for (double A = 2.0; A < 4.0 && !found; A += 0.05) {
    g.horizontal.amplitude = A;
    const RigidResult r = simulate_housner(s, std::nullopt, g, in, housner_run_to(20.0));
    if (r.event_counts[int(RigidEventKind::BeyondAlpha)] > 0 && r.status == SimStatus::TEnd) {
      found = true;
      EXPECT_GT(r.event_counts[int(RigidEventKind::WithinAlpha)], 0);
      EXPECT_GT(r.max_abs_rotation, s.alpha());
      EXPECT_FALSE(r.overturn_time);
    }
  }
  EXPECT_TRUE(found);
}

// At rest the block uplifts the instant |a_H| exceeds g tan(alpha), in the direction a_H drives.
TEST(Housner, UpliftAtTheStaticThreshold) {
  const BlockShape s = slender(0.25);
  GroundMotion g;
  g.horizontal.amplitude = 0.5;
  g.horizontal.frequency = 0.5;
  RigidInitial in;
  const RigidResult r = simulate_housner(s, std::nullopt, g, in, housner_run_to(0.9));
  ASSERT_TRUE(r.first_uplift_time);
  // 0.5 sin(2 pi 0.5 t) = tan(alpha) = 0.25  ->  t = asin(0.5) / pi
  EXPECT_NEAR(*r.first_uplift_time, std::asin(0.5) / M_PI, 1e-13);
  EXPECT_GT(r.final_state[2], 0.0);  // a_H > 0 tips it counter-clockwise, onto corner A
}

// A pulse whose peak barely exceeds the threshold (0.2099 g against tan(alpha) = 0.2): the uplift
// starts with zero rotation, rate and angular acceleration (the force balance tips through zero),
// and the rotation stays tiny (1e-4 rad). Before the integrator told a dip of its dense output's
// error (-1e-24) from a crossing, the impact function fired at the uplift instant, the block went
// back to rest there and uplifted again at the same instant until the run ended in chatter (or,
// at rtol 1e-8, numerical_failure). Reference: the rocking equation integrated from the uplift
// time by a fixed-step RK4 written here (independent of the engine) to the first impact.
TEST(Housner, UpliftFromZeroAccelerationRocksAtEveryTolerance) {
  const BlockShape s = slender(0.2, 1.5);
  const double A = 0.2099, T = 0.2586, alpha = s.alpha(), p = s.p();
  GroundMotion g;
  g.horizontal.pulse = PulseShape::OneSine;
  g.horizontal.amplitude = A;
  g.horizontal.duration = T;
  const double t0 = std::asin(std::tan(alpha) / A) * T / (2.0 * M_PI);
  auto acc = [&](double t, double th) {
    const double ah = t < T ? A * std::sin(2.0 * M_PI * t / T) : 0.0;
    return -p * p * (std::sin(alpha - th) - ah * std::cos(alpha - th));
  };
  double t = t0, th = 0.0, om = 0.0, th_max = 0.0, t_impact = 0.0;
  const double dt = 2e-6;
  for (int i = 0; i < 1000000; ++i) {
    const double k1t = om, k1o = acc(t, th);
    const double k2t = om + 0.5 * dt * k1o, k2o = acc(t + 0.5 * dt, th + 0.5 * dt * k1t);
    const double k3t = om + 0.5 * dt * k2o, k3o = acc(t + 0.5 * dt, th + 0.5 * dt * k2t);
    const double k4t = om + dt * k3o, k4o = acc(t + dt, th + dt * k3t);
    const double th_new = th + dt / 6.0 * (k1t + 2.0 * k2t + 2.0 * k3t + k4t);
    const double om_new = om + dt / 6.0 * (k1o + 2.0 * k2o + 2.0 * k3o + k4o);
    if (th > 0.0 && th_new <= 0.0) {  // back to zero: the first impact (linear interpolation)
      t_impact = t + dt * th / (th - th_new);
      break;
    }
    t += dt;
    th = th_new;
    om = om_new;
    th_max = std::fmax(th_max, th);
  }
  ASSERT_GT(t_impact, t0 + 0.01);
  ASSERT_GT(th_max, 1e-5);
  for (double rtol : {1e-6, 1e-8, 1e-10, 1e-12}) {
    SCOPED_TRACE(rtol);
    RigidRunOptions o = housner_run_to(t_impact + 1e-3);
    o.integrator.rtol = rtol;
    const RigidResult r = simulate_housner(s, std::nullopt, g, RigidInitial{}, o);
    EXPECT_EQ(r.status, SimStatus::TEnd);
    ASSERT_TRUE(r.first_uplift_time);
    EXPECT_NEAR(*r.first_uplift_time, t0, 1e-12);
    const auto imp = impacts(r);
    ASSERT_EQ(imp.size(), 1u);
    EXPECT_NEAR(imp[0].t, t_impact, 1e-6);
    EXPECT_NEAR(r.max_abs_rotation, th_max, 1e-5 * th_max);
  }
}
