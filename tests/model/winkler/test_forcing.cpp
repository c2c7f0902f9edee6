// SPDX-License-Identifier: Apache-2.0
// The ground-motion path (issue 2, item 8). In the frame moving with the ground a horizontal
// ground acceleration a acts as x'' = Rx - a and a vertical one as y'' = Ry - 1 - a_v.
//
// Truths used (derived here):
// * a < mu: static friction can hold the base, so no slide events. The pseudo-force a at the
//   centre (height 1/2 above the base) tilts the block backwards about its rear corner. For a
//   step load on the linearised upright block (rotational spring k r^2/12 about the centre, less
//   the gravity term 1/2) the tilt swings between 0 and 2 w_eq, w_eq = (a/2) / (k r^2/12 - 1/2).
//   On rigid ground the block would not tilt at all (a < r); on springs w stays O(a / k).
// * a > mu: the base slides with friction Rx = +mu Ry (it lags behind the ground). Then
//   x'' = mu Ry - a and y'' = Ry - 1 give the exact identity (x - mu y)'' = -(a - mu): with Ry = 1
//   on average, the relative acceleration is -(a - mu).
// * Constant a_v: the static reaction is 1 + a_v, the static sink (1 + a_v)/k; released from
//   the unloaded sink 1/k the block oscillates harmonically about the new one (omega = sqrt k).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "blockdyn/simulation/winkler_simulation.hpp"

#include "test_support.hpp"

using namespace blockdyn;
using namespace blockdyn::test;

namespace {

// A constant ground acceleration, horizontal or vertical, from t = 0 on.
GroundMotion horizontal_ground(double a) {
  GroundMotion g;
  g.horizontal.constant = a;
  return g;
}

GroundMotion vertical_ground(double av) {
  GroundMotion g;
  g.vertical.constant = av;
  return g;
}

// Calls a check on the completed state at a few points of every accepted piece of trajectory.
struct Probe : WinklerSink {
  std::function<void(double, const WinklerMode&, const WinklerState&, const BlockForces&)> check;
  void on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double t0, double t1,
                  const WinklerMode& mode) override {
    sample_segment(m, seg, t0, t1, mode, 1, 8,
                   [&](double t, const WinklerState& z) { check(t, mode, z, m.forces(t, mode, z)); });
  }
};

}  // namespace

TEST(Forcing, HorizontalBelowFrictionSticks) {
  const WinklerParams p{0.5, 0.3, 1e5};
  const double a = 0.1;
  const GroundMotion g = horizontal_ground(a);
  const WinklerRunOptions o = sim_options(1.0);
  const double rear_corner_x0 = -p.r / 2;
  double w_min = 1, w_max = -1, corner_drift = 0, min_margin = 1;
  bool always_contact = true;
  Probe probe;
  probe.check = [&](double, const WinklerMode& mode, const WinklerState& z, const BlockForces& f) {
    always_contact &= mode.regime == Regime::Contact && mode.side == 1;
    w_min = std::fmin(w_min, z[kW]);
    w_max = std::fmax(w_max, z[kW]);
    const double corner_x = z[kX] - corner_arms(p.r, z[kW], 1).A;  // lower-left corner
    corner_drift = std::fmax(corner_drift, std::fabs(corner_x - rear_corner_x0));
    min_margin = std::fmin(min_margin, f.margin);
  };
  const WinklerResult r = simulate(p, g, upright_at_rest(-1.0 / p.k), o, &probe);
  ASSERT_EQ(r.status, SimStatus::TEnd);
  EXPECT_EQ(r.initial_mode.regime, Regime::Contact);
  EXPECT_EQ(r.event_counts[int(WinklerEventKind::ContactToSlide)], 0);
  EXPECT_EQ(r.event_counts[int(WinklerEventKind::SlideToContact)], 0);
  EXPECT_EQ(r.event_counts[int(WinklerEventKind::SlideReversal)], 0);
  EXPECT_TRUE(always_contact);
  EXPECT_GT(min_margin, 0.0);
  EXPECT_LT(corner_drift, 1e-12);  // the base corner stays where it was: no sliding
  // Tilt backwards (w > 0), between 0 and 2 w_eq of the linearised step response.
  const double w_eq = (a / 2) / (p.k * p.r * p.r / 12 - 0.5);
  EXPECT_GT(w_min, -1e-3 * w_eq);
  EXPECT_NEAR(w_max, 2 * w_eq, 0.02 * 2 * w_eq);
  EXPECT_LT(r.max_abs_energy_error, 1e-12);  // balance with the ground's work
}

TEST(Forcing, HorizontalAboveFrictionSlides) {
  const WinklerParams p{0.5, 0.3, 1e5};
  const double a = 0.5;
  const GroundMotion g = horizontal_ground(a);
  const WinklerRunOptions o = sim_options(1.0);
  // Find the onset of sliding first, then check the identity from that state on.
  const WinklerResult r = simulate(p, g, upright_at_rest(-1.0 / p.k), o);
  ASSERT_EQ(r.status, SimStatus::TEnd);
  ASSERT_GE(r.events.size(), 1u);
  const WinklerEventRecord& s = r.events.front();
  ASSERT_EQ(s.kind, WinklerEventKind::ContactToSlide);
  EXPECT_LT(s.t, 0.05);  // the springs take up the overturning moment within a few periods
  EXPECT_EQ(s.to.friction_sign, +1);
  for (const WinklerEventRecord& e : r.events) {  // slides backwards all the time, never stops
    EXPECT_NE(e.kind, WinklerEventKind::SlideToContact);
    EXPECT_NE(e.kind, WinklerEventKind::SlideReversal);
  }
  const double c0 = s.z[kX] - p.mu * s.z[kH], c1 = s.z[kVX] - p.mu * s.z[kVY];
  double worst = 0, max_dvy = 0;
  bool sliding = true;
  Probe probe;
  probe.check = [&](double t, const WinklerMode& mode, const WinklerState& z, const BlockForces&) {
    if (t <= s.t) return;
    sliding &= mode.regime == Regime::Slide && mode.friction_sign == 1;
    const double tau = t - s.t;
    const double exact = c0 + c1 * tau - 0.5 * (a - p.mu) * tau * tau;
    worst = std::fmax(worst, std::fabs(z[kX] - p.mu * z[kH] - exact));
    max_dvy = std::fmax(max_dvy, std::fabs(z[kVY] - s.z[kVY]));
  };
  const WinklerResult r2 = simulate(p, g, upright_at_rest(-1.0 / p.k), o, &probe);
  EXPECT_TRUE(sliding);
  EXPECT_LT(worst, 1e-10);
  // Averaged over the slide, Ry = 1 + (change of y') / duration: the relative acceleration is
  // -(a - mu) up to mu times that small term.
  const double tau = o.t_end - s.t;
  const double mean_ax = (r2.final_state[kVX] - s.z[kVX]) / tau;
  EXPECT_NEAR(mean_ax, -(a - p.mu), p.mu * max_dvy / tau + 1e-9);
  EXPECT_LT(max_dvy / tau, 0.02);  // the vertical rocking is a small correction
  EXPECT_LT(r2.max_abs_energy_error, 1e-9);
}

TEST(Forcing, VerticalShiftsStaticSink) {
  const WinklerParams p{0.5, 0.2, 1e5};
  const double av = 0.2;
  const GroundMotion g = vertical_ground(av);
  const WinklerRunOptions o = sim_options(0.5);
  const double om = std::sqrt(p.k);
  // At the new static sink nothing moves (to the tolerance: with nothing to resolve the steps
  // grow until error control alone keeps rounding-level disturbances at rtol).
  {
    const WinklerResult r = simulate(p, g, upright_at_rest(-(1 + av) / p.k), o);
    EXPECT_TRUE(r.events.empty());
    const double rtol = o.integrator.rtol, hs = (1 + av) / p.k;
    EXPECT_NEAR(r.final_state[kH], -hs, 10 * rtol * hs);
    EXPECT_NEAR(r.final_state[kVY], 0.0, 10 * rtol * om * hs);
    EXPECT_EQ(r.final_state[kW], 0.0);
  }
  // Released from the unloaded sink: h = -(1 + av)/k + (av/k) cos(omega t), 25 periods.
  double errs[2];
  for (int i = 0; i < 2; ++i) {
    WinklerRunOptions oi = o;
    oi.integrator.rtol = i == 0 ? 1e-10 : 1e-12;
    oi.integrator.atol = oi.integrator.rtol * 1e-2;
    double worst = 0;
    bool upright = true;
    Probe probe;
    probe.check = [&](double t, const WinklerMode&, const WinklerState& z, const BlockForces&) {
      worst = std::fmax(worst, std::fabs(z[kH] - (-(1 + av) / p.k + av / p.k * std::cos(om * t))));
      upright &= z[kW] == 0.0 && z[kX] == 0.0;
    };
    const WinklerResult r = simulate(p, g, upright_at_rest(-1.0 / p.k), oi, &probe);
    EXPECT_TRUE(r.events.empty());
    EXPECT_TRUE(upright);
    EXPECT_LT(worst, 1e3 * oi.integrator.rtol * av / p.k);
    EXPECT_LT(r.max_abs_energy_error, 1e3 * oi.integrator.rtol * av * av / p.k);
    errs[i] = worst;
  }
  EXPECT_GT(errs[0] / errs[1], 20.0);
}

TEST(Forcing, VerticalPulseWithBreakpoints) {
  // a_v = 0.2 only on [t1, t1 + d): static before, harmonic about the loaded sink during, and a
  // free oscillation about the unloaded sink after, continuing from the state at the end.
  const WinklerParams p{0.5, 0.0, 1e5};
  const double av = 0.2, t1 = 0.013, d = 0.0071;
  GroundMotion g = vertical_ground(av);
  g.vertical.t_start = t1;
  g.vertical.duration = d;
  const WinklerRunOptions o = sim_options(0.05);
  const double om = std::sqrt(p.k);
  auto exact = [&](double t) {
    if (t < t1) return -1.0 / p.k;
    if (t < t1 + d) return -(1 + av) / p.k + av / p.k * std::cos(om * (t - t1));
    const double u2 = -av / p.k + av / p.k * std::cos(om * d), v2 = -av / p.k * om * std::sin(om * d);
    return -1.0 / p.k + u2 * std::cos(om * (t - t1 - d)) + v2 / om * std::sin(om * (t - t1 - d));
  };
  double worst = 0;
  Probe probe;
  probe.check = [&](double t, const WinklerMode&, const WinklerState& z, const BlockForces&) {
    worst = std::fmax(worst, std::fabs(z[kH] - exact(t)));
  };
  const WinklerResult r = simulate(p, g, upright_at_rest(-1.0 / p.k), o, &probe);
  ASSERT_EQ(r.status, SimStatus::TEnd);
  EXPECT_EQ(r.event_counts[int(WinklerEventKind::Takeoff)], 0);
  EXPECT_LT(worst, 1e-8 * av / p.k);
  // The ground's work: it acts only during the pulse, and closes the energy balance.
  EXPECT_NE(r.work_ground(), 0.0);
  EXPECT_LT(r.max_abs_energy_error, 1e-8 * av * av / p.k);
}
