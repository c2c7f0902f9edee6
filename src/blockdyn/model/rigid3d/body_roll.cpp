// SPDX-License-Identifier: Apache-2.0
// The rigid3d cylinder rolling on its rim without slipping (body_on_ground.hpp, rim_rolling.hpp):
// its motion, its events (take-off, the friction it needs reaching mu_s, the base landing flat,
// overturn) and its mode changes.
#include <cmath>

#include "blockdyn/model/rigid3d/body_on_ground.hpp"
#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/model/rigid3d/body_state.hpp"

namespace blockdyn {

namespace {
using S = BodyOnGround;
using Tr = Transition<BodyOnGroundMode>;
// A contact carrying less than this share of the weight is about to lift: not checked for slip.
constexpr double kRollUncheckedShare = 1e-2;
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

void BodyOnGround::roll_events(double t, const State& z, std::array<double, kNumEvents>& g) const {
  const RimRolling rr = rolling(t, z);
  const double weight = body_.mass * body_.g;
  g[kEvLiftOff] = rr.force[2] / weight;
  g[kEvSlipA] = rr.force[2] < kRollUncheckedShare * weight
                    ? 1.0
                    : (opt_.mu_s * rr.force[2] - std::hypot(rr.force[0], rr.force[1])) / weight;
  // The opposite rim point's height above the contact (2 a sin(tilt)): zero where the base lands.
  const Mat3 r = rotation(quat_at(z, S::kQw));
  g[kEvTouch0] = dot(r[2], {-2 * rr.contact_body[0], -2 * rr.contact_body[1], 0});
  g[kEvOverturn] = r[2][2];
}

void BodyOnGround::roll_complete(State& z) const {
  // On the ground at its rim's lowest point, that point's material velocity zero.
  const Quat q = normalized(quat_at(z, S::kQw));
  z[kQw] = q.w;
  z[kQx] = q.x;
  z[kQy] = q.y;
  z[kQz] = q.z;
  const Mat3 r = rotation(q);
  const Vec3 arm = r * rim_lowest_point(body_.radius, body_.half_height(), r);
  z[kZ] = -arm[2];
  set_vec_at(z, kVx, cross(arm, vec_at(z, kWx)));
}

Tr BodyOnGround::roll_change(double t, const Mode& m, State& z, int event) const {
  switch (event) {
    case kBreakpoint:
      return {m, false, int(Body3dEventKind::GroundBreak)};
    case kEvLiftOff:
      return {Mode{BodyContact::Flight}, false, int(Body3dEventKind::LiftOff)};
    case kEvSlipA:
      return {m, true, int(Body3dEventKind::SlipOnset)};
    case kEvOverturn:
      return {m, true, int(Body3dEventKind::Overturn)};
    default: {
      // The base lands: the impact about the opposite rim point, as from rocking on this one.
      const Mat3 r = rotation(quat_at(z, S::kQw));
      const Mode rim = rim_mode(r, vec_at(z, kX), rim_lowest_point(body_.radius, body_.half_height(), r));
      return impact(t, rim, z, kEvTouch0);
    }
  }
}

}  // namespace blockdyn
