// SPDX-License-Identifier: Apache-2.0
// Validation against the thesis's periodic test solution (sec. 3.3, "Periodic solution"; issue 2,
// item 3): the upright block dropped from y0 = 1/2 - 3/k at rest oscillates vertically, with
// flights in between, and never rotates.
//
// Closed form (derived here). With the whole base submerged the Region is a rectangle of depth
// -h (h = y - 1/2), so Ry = k (-h) and y'' = -k h - 1: harmonic about h = -1/k with omega =
// sqrt(k). Starting from rest at h = -3/k, u = h + 1/k = -(2/k) cos(omega t). The base leaves
// the springs when h = 0, i.e. u = 1/k, cos(omega t) = -1/2: take-off at omega t = 2 pi / 3 with
// h' = (2/sqrt k) sin(2 pi / 3) = sqrt(3/k) =: v. Flight is free fall: apex h = v^2 / 2 = 3/(2k)
// after v, landing after 2 v with speed v. By symmetry the next submerged phase runs from
// phase -2 pi / 3 to 2 pi / 3: period T = 4 pi / (3 omega) + 2 v. Energy E = 3/(2k).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "blockdyn/simulation/winkler_simulation.hpp"

#include "test_support.hpp"

using namespace blockdyn;
using namespace blockdyn::test;

namespace {

struct Closed {
  double k, om, v, t_off, T;
  explicit Closed(double k_) : k(k_), om(std::sqrt(k_)), v(std::sqrt(3.0 / k_)) {
    t_off = 2 * M_PI / (3 * om);
    T = 4 * M_PI / (3 * om) + 2 * v;
  }
  double takeoff(int n) const { return t_off + n * T; }
  double landing(int n) const { return t_off + 2 * v + n * T; }
  // h(t) of the periodic solution.
  double h(double t) const {
    const int n = int(std::floor((t - t_off) / T));  // last take-off index (-1 before the first)
    if (n >= 0 && t <= landing(n)) {
      const double s = t - takeoff(n);
      return v * s - 0.5 * s * s;
    }
    return -1.0 / k - 2.0 / k * std::cos(om * (t - (n + 1) * T));
  }
};

// Checks the trajectory between events against the closed form, and that it never rotates.
struct Check : WinklerSink {
  Closed c;
  double max_h_err = 0;
  bool rotated = false;
  double x0 = 0;
  std::vector<double> apex_h;
  explicit Check(double k) : c(k) {}
  void on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double t0, double t1,
                  const WinklerMode& mode) override {
    sample_segment(m, seg, t0, t1, mode, 0, 4, [&](double t, const WinklerState& z) {
      max_h_err = std::fmax(max_h_err, std::fabs(z[kH] - c.h(t)));
      rotated |= z[kW] != 0.0 || z[kVW] != 0.0 || z[kX] != x0 || z[kVX] != 0.0;
    });
    if (mode.regime == Regime::Flight) {  // apex inside this piece?
      for (int n = 0; n < 100; ++n) {
        const double ta = c.takeoff(n) + c.v;
        if (ta > t1) break;
        if (ta < t0) continue;
        WinklerState z;
        seg.eval(ta, z);
        apex_h.push_back(z[kH]);
      }
    }
  }
};

void run_case(double mu) {
  const WinklerParams p{0.5, mu, 1e5};
  const Closed c(p.k);
  const WinklerState z0 = upright_at_rest(-3.0 / p.k);  // y0 = 1/2 - 3/k, all rates zero, w0 = 0
  const WinklerRunOptions o = sim_options(0.2);
  Check sink(p.k);
  const WinklerResult r = simulate(p, {}, z0, o, &sink);
  ASSERT_EQ(r.status, SimStatus::TEnd);

  // Rotation and horizontal motion stay exactly zero, in every regime.
  EXPECT_FALSE(sink.rotated);
  EXPECT_EQ(r.final_state[kW], 0.0);
  EXPECT_EQ(r.final_state[kVW], 0.0);
  EXPECT_EQ(r.final_state[kX], 0.0);
  EXPECT_EQ(r.upright_passages, 1);  // starts at w = 0, never passes through it again

  // Events: take-off and landing alternate at the closed-form times.
  const Regime submerged = mu > 0 ? Regime::Contact : Regime::Slide;
  int n_off = 0, n_land = 0;
  double worst = 0;
  for (const WinklerEventRecord& e : r.events) {
    EXPECT_EQ(e.z[kW], 0.0);
    if (e.kind == WinklerEventKind::Takeoff) {
      EXPECT_EQ(e.from.regime, submerged);
      EXPECT_EQ(e.to.regime, Regime::Flight);
      worst = std::fmax(worst, std::fabs(e.t - c.takeoff(n_off)) / c.takeoff(n_off));
      EXPECT_NEAR(e.z[kVY], c.v, 1e-8 * c.v);
      ++n_off;
    } else if (e.kind == WinklerEventKind::Landing) {
      EXPECT_EQ(e.from.regime, Regime::Flight);
      EXPECT_EQ(e.to.regime, submerged);
      EXPECT_EQ(n_land + 1, n_off);
      worst = std::fmax(worst, std::fabs(e.t - c.landing(n_land)) / c.landing(n_land));
      EXPECT_NEAR(e.z[kVY], -c.v, 1e-8 * c.v);
      ++n_land;
    } else {
      ADD_FAILURE() << "unexpected event " << to_string(e.kind) << " at t = " << e.t;
    }
  }
  int expect_off = 0, expect_land = 0;
  while (c.takeoff(expect_off) < o.t_end) ++expect_off;
  while (c.landing(expect_land) < o.t_end) ++expect_land;
  EXPECT_EQ(n_off, expect_off);
  EXPECT_EQ(n_land, expect_land);
  EXPECT_EQ(expect_off, 8);
  record("worst_rel_event_time", worst);
  record("max_h_error_times_k", sink.max_h_err * p.k);
  record("max_dE", r.max_abs_energy_change);
  // Default tolerance rtol = 1e-10: event times to a few 1e-10 relative after eight periods.
  EXPECT_LT(worst, 1e-9);

  // Period from consecutive take-offs, apex height, trajectory between events.
  std::vector<double> offs;
  for (const WinklerEventRecord& e : r.events)
    if (e.kind == WinklerEventKind::Takeoff) offs.push_back(e.t);
  for (std::size_t i = 1; i < offs.size(); ++i) EXPECT_NEAR(offs[i] - offs[i - 1], c.T, 1e-9 * c.T);
  ASSERT_EQ(sink.apex_h.size(), std::size_t(expect_land));
  for (double ha : sink.apex_h) EXPECT_NEAR(ha, 1.5 / p.k, 1e-8 / p.k);
  // The solution drifts in phase like the event times (relative 1e-9 at most): h errors are
  // bounded by the largest speed v times that shift.
  EXPECT_LT(sink.max_h_err, c.v * 1e-9 * o.t_end);

  // Energy 3/(2k), conserved (mu plays no role: no horizontal motion).
  EXPECT_NEAR(r.initial_energy.total(), 1.5 / p.k, 1e-15);
  EXPECT_LT(r.max_abs_energy_change, 1e-8 * r.initial_energy.total());
  EXPECT_EQ(r.work_friction(), 0.0);
  EXPECT_EQ(r.work_nonpotential(), 0.0);
}

}  // namespace

TEST(VerticalOscillation, FrictionlessMatchesClosedForm) { run_case(0.0); }

TEST(VerticalOscillation, WithFrictionMatchesClosedForm) { run_case(0.2); }

TEST(VerticalOscillation, EventTimesConvergeWithTolerance) {
  // The error of the last landing time shrinks in proportion to the tolerance.
  const WinklerParams p{0.5, 0.0, 1e5};
  const Closed c(p.k);
  const WinklerState z0 = upright_at_rest(-3.0 / p.k);
  std::vector<double> err;
  for (double rtol : {1e-8, 1e-10, 1e-12}) {
    const WinklerResult r = simulate(p, {}, z0, sim_options(0.2, rtol));
    ASSERT_EQ(r.events.size(), 16u);
    const WinklerEventRecord& last = r.events.back();
    ASSERT_EQ(last.kind, WinklerEventKind::Landing);
    err.push_back(std::fabs(last.t - c.landing(7)) / c.landing(7));
    record(("last_landing_rel_err_rtol" + rtol_tag(rtol)).c_str(), err.back());
    EXPECT_LT(err.back(), 20 * rtol) << rtol;
  }
  EXPECT_GT(err[0] / err[1], 20.0);
  EXPECT_GT(err[1] / err[2], 20.0);
}
