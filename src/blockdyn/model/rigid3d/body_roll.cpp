// SPDX-License-Identifier: Apache-2.0
// The rigid3d cylinder rolling on its rim without slipping (body_on_ground.hpp, rim_rolling.hpp):
// its motion, its events (take-off, the friction it needs reaching mu_s, the base landing flat,
// overturn) and its mode changes.
#include <cmath>
#include <optional>

#include "blockdyn/model/rigid3d/body_on_ground.hpp"
#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/model/rigid3d/body_state.hpp"

namespace blockdyn {

namespace {
using S = BodyOnGround;
using Tr = Transition<BodyOnGroundMode>;
// The contact's travel along the rim is not followed below this tilt (sin): near the vertical its
// direction turns fast for a path that misses the vertical by a rounding, and the base lands
// where the tilt towards the reference side falls to kRimLanding (its rim then within
// 2 a kRimLanding of the ground): rolling or slipping on a rim point of a base that flat would
// follow a contact racing round the rim.
constexpr double kRimTurnFloor = 1e-6;
constexpr double kRimLanding = 1e-7;
// A contact carrying less than this share of the weight is about to lift: not checked for slip.
constexpr double kRollUncheckedShare = 1e-2;
// sin(tilt) towards the reference rim point `side` (body frame) of a rim of radius a: the
// world's up seen in the base plane (r[2]) against the side.
double tilt_towards(const Mat3& r, const Vec3& side, double a) { return -(r[2][0] * side[0] + r[2][1] * side[1]) / a; }
}  // namespace

RimRolling BodyOnGround::rolling(double t, const State& z) const {
  return rim_rolling_motion(inertia_, body_.mass, body_.radius, body_.half_height(), rotation(quat_at(z, S::kQw)),
                            vec_at(z, kWx), specific_force(t));
}

void BodyOnGround::roll_rhs(double t, const State& z, State& dz) const {
  const RimRolling rr = rolling(t, z);
  set_kinematic_rates(t, z, dz);
  set_vec_at(dz, kVx, rr.accel);
  set_vec_at(dz, kWx, rr.domega);
}

void BodyOnGround::roll_events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const {
  const RimRolling rr = rolling(t, z);
  const double weight = body_.mass * body_.g;
  g[kEvLiftOff] = rr.force[2] / weight;
  g[kEvSlipA] = rr.force[2] < kRollUncheckedShare * weight
                    ? 1.0
                    : (opt_.mu_s * rr.force[2] - std::hypot(rr.force[0], rr.force[1])) / weight;
  const Mat3 r = rotation(quat_at(z, S::kQw));
  rim_side_events(m, r, g);
  g[kEvOverturn] = r[2][2];
}

double BodyOnGround::rim_flat_ahead(const Mode& m, const State& z) const {
  // The rim's contact jumps to the other side where the base passes flat (the landing's event
  // comes just before): its tilt towards the reference side, d/dt of R^T Z = -Omega x R^T Z,
  // extrapolated linearly.
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 du = up_rate(r, z);
  const double along = tilt_towards(r, m.point_a, body_.radius);
  const double rate = -(du[0] * m.point_a[0] + du[1] * m.point_a[1]) / body_.radius;
  // Aimed at half the landing's tilt: the step ends before the kink, the landing in the next.
  const double ahead = along - 0.5 * kRimLanding;
  return ahead > 0 && rate < 0 ? ahead / -rate : INFINITY;
}

BodyOnGroundMode BodyOnGround::rim_or_roll(const State& z, const Vec3& point) const {
  // Turning about more than the rim point's tangent (a spin, a wobble): it rolls; else it rocks
  // on that rim point.
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Mode rim = rim_mode(r, vec_at(z, kX), point);
  const Vec3 w = vec_at(z, kWx), off = minus(w, scaled(rim.axis, dot(rim.axis, w)));
  if (std::sqrt(dot(off, off)) <= kRollStart * std::sqrt(body_.g / size_)) return rim;
  Mode roll = roll_mode(z, false);
  roll.point_a = point;
  return roll;
}

BodyOnGroundMode BodyOnGround::roll_mode(const State& z, bool slipping) const {
  Mode m{BodyContact::Roll};
  m.slipping = slipping ? 1 : 0;
  const Mat3 r = rotation(quat_at(z, S::kQw));
  if (std::hypot(r[2][0], r[2][1]) >= kRimFlat) m.point_a = rim_lowest_point(body_.radius, body_.half_height(), r);
  return m;
}

void BodyOnGround::rim_side_events(const Mode& m, const Mat3& r, std::array<double, kNumEvents>& g) const {
  // r[2] is the world's up in the body frame, (w, u_z); the contact lies along -w, the reference
  // side along point_a: 2 a |w| cos(angle between them) (the opposite point's height), and
  // |w| (cos(angle) - cos 60 degrees), offset below kRimTurnFloor.
  const Vec3 w{r[2][0], r[2][1], 0};
  const double along = tilt_towards(r, m.point_a, body_.radius);
  g[kEvTouch0] = 2 * body_.radius * (along - kRimLanding);
  g[kEvTouch0 + 1] = along - 0.5 * std::sqrt(dot(w, w)) + kRimTurnFloor;
  if (m.lifting) {
    // Started below the landing's tilt (after a landing, or tipped up from flat): the landing is
    // looked for once the tilt has risen past twice it, a fall back below the start meanwhile.
    g[kEvTouch0] = 2 * body_.radius * (along + kRimLanding);
    g[kEvTouch0 + 2] = 2 * body_.radius * (2 * kRimLanding - along);
  }
}

bool BodyOnGround::rim_below_landing(const Mode& m, const State& z) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  return tilt_towards(r, m.point_a, body_.radius) < kRimLanding;
}

void BodyOnGround::lower_onto_rim(const Mode& m, State& z) const {
  // A rim point rocked on since a landing at kRimLanding stands up to 2 a kRimLanding above the
  // ground; rolling or slipping, the rim's lowest point is on it: the body is lowered there, the
  // potential energy it gives up booked with the impacts' loss (the landing's approximation).
  State on = z;
  complete(m, on);
  const double drop = z[kZ] - on[kZ];
  if (!(drop > 0)) return;
  z[kZ] = on[kZ];
  z[kWorkImpact] -= body_.mass * body_.g * drop;
}

Vec3 BodyOnGround::rim_point_before_landing(const State& z) const {
  // Near the landing w = R^T Z passes through zero at the rate dw/dt = -Omega x u: the contact was
  // on the side the axis came from, along dw/dt.
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 dw = up_rate(r, z);
  const double n = std::hypot(dw[0], dw[1]);
  if (!(n > 0)) return rim_lowest_point(body_.radius, body_.half_height(), r);
  return {body_.radius * dw[0] / n, body_.radius * dw[1] / n, -body_.half_height()};
}

Tr BodyOnGround::rim_side_change(double t, const Mode& m, State& z, int event) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 w{r[2][0], r[2][1], 0};
  const double rho = std::sqrt(dot(w, w)), along = tilt_towards(r, m.point_a, body_.radius);
  if (m.lifting && event == kEvTouch0 + 2) {
    Mode next = m;
    next.lifting = false;
    return {next, false, int(Body3dEventKind::SlipTurn)};
  }
  if (event == kEvTouch0 + 1 && along > 0 && along < 0.75 * rho) {
    // The contact has travelled 60 degrees along the rim (cos = 0.5; where the tilt passes
    // through zero both functions vanish with the contact still on the reference side, cos = 1):
    // a new reference side (no event).
    Mode next = m;
    next.point_a = rim_lowest_point(body_.radius, body_.half_height(), r);
    return {next, false, int(Body3dEventKind::SlipTurn)};
  }
  // Rising through the landing's tilt (after a landing, or slipping up from flat): no event.
  const Vec3 dw = up_rate(r, z);
  if (-(dw[0] * m.point_a[0] + dw[1] * m.point_a[1]) > 0) return {m, false, int(Body3dEventKind::SlipTurn)};
  // Falling through it at the landing's own instant (to its rounding) with the new contact slipping: the landing
  // about the opposite point left the other side coming down too (a base landing all but flat):
  // the base lands flat. Rolling, the new contact starts below the landing's tilt: no event.
  if (m.impact_t >= 0 && t - m.impact_t <= kInstant * std::fmax(1.0, std::fabs(t)))
    return m.slips() ? landed_flat(t, z) : Tr{m, false, int(Body3dEventKind::SlipTurn)};
  // The tilt falls through it: the base lands about the rim point opposite the contact.
  Mode landing = rim_mode(r, vec_at(z, kX), rim_point_before_landing(z));
  landing.impact_t = m.impact_t;  // an accumulation's count carries through
  landing.rapid_impacts = m.rapid_impacts;
  return impact(t, landing, z, kEvTouch0);
}

void BodyOnGround::roll_complete(State& z) const {
  // On the ground at its rim's lowest point, that point's material velocity zero.
  const Quat q = normalized(quat_at(z, S::kQw));
  set_quat_at(z, kQw, q);
  const Mat3 r = rotation(q);
  const Vec3 arm = r * rim_lowest_point(body_.radius, body_.half_height(), r);
  z[kZ] = -arm[2];
  set_vec_at(z, kVx, cross(arm, vec_at(z, kWx)));
}

std::optional<Tr> BodyOnGround::moving_contact_ends(const Mode& m, int event) const {
  switch (event) {
    case kBreakpoint:
      return Tr{m, false, int(Body3dEventKind::GroundBreak)};
    case kEvLiftOff:
      return Tr{Mode{BodyContact::Flight}, false, int(Body3dEventKind::LiftOff)};
    case kEvOverturn:
      return Tr{m, true, int(Body3dEventKind::Overturn)};
    case kEvPainleve:
      return Tr{m, true, int(Body3dEventKind::Painleve)};
    default:
      return std::nullopt;
  }
}

Tr BodyOnGround::roll_change(double t, const Mode& m, State& z, int event) const {
  if (const auto tr = moving_contact_ends(m, event)) return *tr;
  if (event == kEvSlipA) return rim_contact_holds_or_slips(t, m, z, int(Body3dEventKind::Slip), false);
  return rim_side_change(t, m, z, event);
}

}  // namespace blockdyn
