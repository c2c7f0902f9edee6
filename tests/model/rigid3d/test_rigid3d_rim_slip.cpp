// SPDX-License-Identifier: Apache-2.0
// The rigid3d cylinder slipping on its rim (model/rigid3d/rim_rolling.hpp, body_rim_slip.cpp),
// each check against something independent: on a ground without friction the centroid falls
// straight down and the tilt's rate is the energy's closed form, the landing at the quadrature's
// time; the slip starts where the rocking's friction reaches mu_s; the landing time converges
// under refinement; the balance closes under two record components.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "blockdyn/excitation/accelerogram.hpp"
#include "blockdyn/simulation/rigid3d_simulation.hpp"
#include "model/rigid3d/body3d_run.hpp"

namespace rim_slip_test {

using blockdyn::Body3dResult;
using blockdyn::BodyContact;
using blockdyn::BodyOnGround;
using blockdyn::Vec3;

using blockdyn::test::kG;
constexpr double kA = 0.2, kH = 1.0, kC = 0.5;  // radius, height, half height (m)

BodyOnGround cylinder(double mu, const blockdyn::GroundMotion3d& g = {}) {
  blockdyn::BodyOnGroundOptions o;
  o.mu_s = o.mu_k = mu;
  return BodyOnGround(blockdyn::cylinder_body(kA, kH, 100), g, o);
}

double tilt_of(const BodyOnGround::State& z) {
  return std::acos(blockdyn::rotation(
      {z[BodyOnGround::kQw], z[BodyOnGround::kQx], z[BodyOnGround::kQy], z[BodyOnGround::kQz]})[2][2]);
}

// Without friction the centroid's horizontal position holds and the tilt theta (in its plane)
// has (I_d / m + z'(theta)^2) theta'^2 = 2 g (z(theta0) - z(theta)), z = c cos + a sin the
// centroid's height, I_d = m (3 a^2 + h^2) / 12 the inertia about a diameter.
double height(double th) { return kC * std::cos(th) + kA * std::sin(th); }
double height_rate(double th) { return -kC * std::sin(th) + kA * std::cos(th); }
double inertia_ratio() { return (3 * kA * kA + kH * kH) / 12; }
double tilt_rate(double th0, double th) {
  const double drop = std::fmax(0.0, height(th0) - height(th));  // 0 at the start, to rounding
  return std::sqrt(2 * kG * drop / (inertia_ratio() + height_rate(th) * height_rate(th)));
}
// The time to fall to the tilt th1, t = int_th1^th0 dth / theta'(th), with th = th0 - s^2 (the
// integrand 2 s / theta' is smooth; at s = 0 its limit), by Simpson's rule.
double fall_time(double th0, double th1) {
  const int n = 4000;
  const double s_end = std::sqrt(th0 - th1), step = s_end / n;
  const double z1 = height_rate(th0);
  auto f = [&](double s) {
    if (s == 0) return 2 / std::sqrt(2 * kG * z1 / (inertia_ratio() + z1 * z1));
    return 2 * s / tilt_rate(th0, th0 - s * s);
  };
  double sum = f(0) + f(s_end);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(i * step);
  return sum * step / 3;
}

std::vector<blockdyn::Body3dSample> rows_until(const BodyOnGround& m, const blockdyn::Body3dStart& s, double t_end,
                                               double every, Body3dResult& r, double rtol = 1e-12,
                                               bool slip_start = false) {
  std::vector<blockdyn::Body3dSample> rows;
  blockdyn::Body3dRunOptions o;
  o.slip_start = slip_start;
  o.t_end = t_end;
  o.integ.rtol = rtol;
  o.integ.atol = rtol * 1e-2;
  o.output_interval = every;
  o.on_sample = [&](const blockdyn::Body3dSample& row) { rows.push_back(row); };
  r = blockdyn::simulate_body3d(m, blockdyn::initial_state(m.body(), s), o);
  return rows;
}

double first_impact(const Body3dResult& r) {
  for (const auto& e : r.events)
    if (e.kind == blockdyn::Body3dEventKind::Impact) return e.t;
  return NAN;
}

// Released at 0.15 rad towards 30 degrees on a ground without friction, thrown along it at
// `velocity` (a velocity given: the rim slips from the start): up to its first landing the
// centroid moves at that velocity (no horizontal force), the rim slips, no spin, and the tilt
// falls as the closed form above (the throw a Galilean change of frame), landing at the
// quadrature's time. Returns the rows (every 5 ms to 0.5 s) and the run. `spin`: the spin allowed
// (the friction left, 1e-12, twists a thrown body by about 1e-11 rad/s over the fall).
std::vector<blockdyn::Body3dSample> frictionless_fall(const BodyOnGround& m, const Vec3& velocity, Body3dResult& r,
                                                      double spin = 1e-12) {
  const double th0 = 0.15;
  blockdyn::Body3dStart s;
  s.tilt = th0;
  s.tilt_azimuth = 30 * M_PI / 180;
  s.velocity = velocity;
  const auto rows = rows_until(m, s, 0.5, 0.005, r, 1e-12, true);
  const double t_land = first_impact(r);
  EXPECT_TRUE(std::isfinite(t_land));
  // Rolling or slipping on its rim the base lands where its tilt falls to 1e-7 rad
  // (body_roll.cpp: a contact racing round the rim is not followed closer to flat).
  EXPECT_NEAR(t_land, fall_time(th0, std::asin(1e-7)), 1e-9);
  int checked = 0;
  for (const auto& row : rows) {
    if (row.t >= t_land || row.event) continue;
    EXPECT_EQ(row.mode.contact, BodyContact::Roll);
    EXPECT_TRUE(row.mode.slips());
    EXPECT_NEAR(row.z[BodyOnGround::kX], velocity[0] * row.t, 1e-11);
    EXPECT_NEAR(row.z[BodyOnGround::kY], velocity[1] * row.t, 1e-11);
    const Vec3 w = {row.z[BodyOnGround::kWx], row.z[BodyOnGround::kWy], row.z[BodyOnGround::kWz]};
    EXPECT_NEAR(std::sqrt(blockdyn::dot(w, w)), tilt_rate(th0, tilt_of(row.z)), 1e-9 * (1 + tilt_rate(th0, 0)));
    EXPECT_NEAR(w[2], 0.0, spin);  // no spin: it stays in its plane
    ++checked;
  }
  EXPECT_GT(checked, 20);
  EXPECT_LT(r.max_abs_energy_error, 1e-9 * m.body().mass * kG * kH);
  return rows;
}

TEST(Rigid3dRimSlip, WithoutFrictionTheCentroidFallsStraightAndTheTiltMeetsTheEnergy) {
  Body3dResult r;
  frictionless_fall(cylinder(1e-12), {0, 0, 0}, r);
}

TEST(Rigid3dRimSlip, AThrownStartOnTheRimSlipsFromTheStart) {
  // Thrown along the ground: before, the start dropped the throw (the contact took the velocities
  // the rim allows: the centroid stood still), and Housner's law at the landing took most of it
  // (0.4 -> 0.086 m/s). Newton's impulses at the landings, normal only without friction, keep it:
  // after them the base lands flat (their accumulation) and slides on at the throw's velocity.
  const double v0 = 0.4, heading = -50 * M_PI / 180;
  const Vec3 v{v0 * std::cos(heading), v0 * std::sin(heading), 0};
  Body3dResult r;
  for (const auto& row : frictionless_fall(cylinder(1e-12), v, r, 1e-10)) {
    EXPECT_NEAR(row.z[BodyOnGround::kX], v[0] * row.t, 1e-11) << row.t;
    EXPECT_NEAR(row.z[BodyOnGround::kY], v[1] * row.t, 1e-11) << row.t;
  }
  EXPECT_EQ(r.mode.contact, BodyContact::Slide);
  EXPECT_NEAR(r.z[BodyOnGround::kVx], v[0], 1e-11);
  EXPECT_NEAR(r.z[BodyOnGround::kVy], v[1], 1e-11);
}

TEST(Rigid3dRimSlip, AThrownStartWithFrictionSticksAndTurnsWithItsStart) {
  // With friction the thrown rim slips until friction stops it, then rocks on; the start turned
  // about the vertical (its tilt's azimuth and its throw) gives the turned motion.
  const double th0 = 0.1, v0 = 0.3;
  Vec3 end[2];
  double stick[2] = {NAN, NAN};
  for (int k = 0; k < 2; ++k) {
    const double turn = k == 0 ? 0.0 : 57 * M_PI / 180;
    const BodyOnGround m = cylinder(0.3);
    blockdyn::Body3dStart s;
    s.tilt = th0;
    s.tilt_azimuth = turn;
    s.velocity = {v0 * std::cos(turn), v0 * std::sin(turn), 0};
    const Body3dResult r = blockdyn::test::run_body(m, s, 1.0, true);
    ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
    ASSERT_FALSE(r.events.empty());
    EXPECT_EQ(r.events[0].kind, blockdyn::Body3dEventKind::Stick);
    EXPECT_TRUE(r.events[0].from_slipping);
    stick[k] = r.events[0].t;
    const double c = std::cos(turn), sn = std::sin(turn);
    const double x = r.z[BodyOnGround::kX], y = r.z[BodyOnGround::kY];
    end[k] = {c * x + sn * y, -sn * x + c * y, r.z[BodyOnGround::kZ]};  // turned back
    EXPECT_GT(r.max_slide, 1e-3);
    EXPECT_LT(r.max_abs_energy_error, 1e-11 * m.body().mass * kG * kH);
  }
  EXPECT_NEAR(stick[1], stick[0], 1e-12);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(end[1][std::size_t(i)], end[0][std::size_t(i)], 1e-12) << i;
}

TEST(Rigid3dRimSlip, TheRimStartsSlippingWhereItsRockingNeedsMuS) {
  // Released at rest the rim point holds at first; the friction the rocking needs grows as the
  // body falls back; the slip starts where it reaches mu_s N (the rocking run's own forces).
  const double mu = 0.2;
  blockdyn::Body3dStart s;
  s.tilt = 0.15;
  Body3dResult slipping, holding;
  rows_until(cylinder(mu), s, 0.5, 0, slipping);
  double t_slip = NAN;
  for (const auto& e : slipping.events)
    if (e.kind == blockdyn::Body3dEventKind::Slip) {
      t_slip = e.t;
      break;
    }
  ASSERT_TRUE(std::isfinite(t_slip));
  EXPECT_GT(t_slip, 0.05);
  const BodyOnGround rocking = cylinder(10);
  const auto rows = rows_until(rocking, s, t_slip, t_slip, holding);
  ASSERT_FALSE(rows.empty());
  const auto& at = rows.back();
  ASSERT_NEAR(at.t, t_slip, 1e-12);
  const Vec3 f = rocking.contact_forces(at.t, at.mode, at.z)[0];
  EXPECT_NEAR(std::hypot(f[0], f[1]) / f[2], mu, 1e-9);
}

TEST(Rigid3dRimSlip, TheLandingConvergesUnderRefinement) {
  blockdyn::Body3dStart s;
  s.tilt = 0.15;
  s.tilt_azimuth = 1.0;
  Body3dResult fine, coarse;
  rows_until(cylinder(0.1), s, 0.5, 0, fine, 1e-12);
  rows_until(cylinder(0.1), s, 0.5, 0, coarse, 1e-9);
  const double tf = first_impact(fine), tc = first_impact(coarse);
  ASSERT_TRUE(std::isfinite(tf));
  EXPECT_NEAR(tc, tf, 1e-7);
  EXPECT_GT(fine.max_slide, 1e-3);
}

TEST(Rigid3dRimSlip, TwoRecordComponentsSlipOnTheRimWithTheBalanceClosed) {
  blockdyn::GroundMotion3d g;
  g.azimuth = 30;
  g.h.record = g.h2.record = blockdyn::test::fixture_record();
  g.h.scale = 2.0;
  // Just above the friction at which the base would slide before it rocks (2 a / h = 0.4).
  const BodyOnGround m = cylinder(0.41, g);
  const Body3dResult r = blockdyn::test::run_body(m, {}, 20.0);
  int slips = 0;
  for (const auto& e : r.events) slips += e.to == BodyContact::Roll && e.kind == blockdyn::Body3dEventKind::Slip;
  EXPECT_GT(slips, 0);
  EXPECT_STRNE(to_string(r.status), "invalid") << r.note;
  EXPECT_LT(r.max_abs_energy_error, 1e-9 * m.body().mass * kG * kH);
}

TEST(Rigid3dRimSlip, LandingsWhileTheRimSlipsEndWithTheBaseFlatAndTheBalanceClosed) {
  // Released on low friction the rim slips from the start and the base lands, the body rocking
  // onto the other side, slipping there. Under Housner's law, where a landing leaves the other side
  // of the base coming down at the same instant the base lands flat (docs/3d.md) and rests; under
  // Newton's and Coulomb's (the default) the landings' impulses leave the rim slipping and
  // accumulate, their gaps shrinking until the base lands flat; either way the balance closed.
  for (const auto law : {blockdyn::Body3dImpactLaw::Housner, blockdyn::Body3dImpactLaw::Newton})
    for (const double mu : {0.05, 0.2}) {
      blockdyn::Body3dStart s;
      s.tilt = 0.15;
      blockdyn::BodyOnGroundOptions o;
      o.mu_s = o.mu_k = mu;
      o.impact = law;
      const BodyOnGround m(blockdyn::cylinder_body(kA, kH, 100), {}, o);
      const Body3dResult r = blockdyn::test::run_body(m, s, 3.0);
      ASSERT_STREQ(to_string(r.status), "t_end") << mu << " " << r.note;
      int impacts = 0;
      for (const auto& e : r.events) impacts += e.kind == blockdyn::Body3dEventKind::Impact;
      EXPECT_GE(impacts, 2) << mu;
      ASSERT_FALSE(r.events.empty());
      const auto& last = r.events.back();
      EXPECT_EQ(last.to, BodyContact::Rest) << mu;
      if (law == blockdyn::Body3dImpactLaw::Housner) {
        // The base lands flat at a landing's own instant (the second crossing located within its
        // rounding, 1e-15 s), at rest or sliding on with what friction leaves of the rim's slip.
        bool flat_at_landing = false;
        for (std::size_t k = 1; k < r.events.size(); ++k) {
          const auto& e = r.events[k];
          flat_at_landing = flat_at_landing || (e.kind == blockdyn::Body3dEventKind::Impact &&
                                                (e.to == BodyContact::Rest || e.to == BodyContact::Slide) &&
                                                std::fabs(e.t - r.events[k - 1].t) <= 1e-13);
        }
        EXPECT_TRUE(flat_at_landing) << mu;
      }
      EXPECT_LT(r.max_abs_energy_error, 1e-9 * m.body().mass * kG * kH) << mu;
    }
}

}  // namespace rim_slip_test
