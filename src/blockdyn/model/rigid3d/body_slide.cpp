// SPDX-License-Identifier: Apache-2.0
// The rigid3d box sliding flat on its base (body_on_ground.hpp, base_slide.hpp): its motion, its
// events and its mode changes. The slide's generalised slip u = (vx, vy, L omega_z) (L the base's
// half diagonal) is followed against a reference direction kept in the mode: the slide ends where
// u . ref reaches zero, a crossing located like any other event (the friction reverses there, so
// the step control is told of it: kink_ahead), and a slip that turns by 60 degrees from its
// reference takes a new one (an event without a mode change), so that u . ref reaches zero only
// where u does.
#include <cmath>

#include "blockdyn/model/rigid3d/base_slide.hpp"
#include "blockdyn/model/rigid3d/body_on_ground.hpp"
#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/model/rigid3d/body_state.hpp"

namespace blockdyn {

namespace {
using S = BodyOnGround;
using Tr = Transition<BodyOnGroundMode>;

// The slip's turn from its reference that takes a new one: cos 60 degrees.
constexpr double kTurnCosine = 0.5;
// A slip below this (in sqrt(g size)) at a turn is a stick.
constexpr double kStickSlip = 1e-9;
// A slip's direction is not followed below this size (in sqrt(g size)): it is the integration's
// noise there (the velocities' absolute tolerance is 1e-12 of that scale), and a slip that small
// is about to stick. The turn's event function is offset by it.
constexpr double kSlipNoise = 1e-9;
// A kink predicted closer than this share of the slip's own size (its minimum along the
// linear extrapolation) is a stick ahead; farther, the slip only curves.
constexpr double kStickAhead = 1e-3;

double yaw_of(const Mat3& r) { return std::atan2(r[1][0], r[0][0]); }
}  // namespace

Vec3 BodyOnGround::slip_of(const State& z) const { return {z[kVx], z[kVy], reach_ * z[kWz]}; }

BodyOnGroundMode BodyOnGround::slide_mode(const State& z, const Vec3& slip_ref) const {
  Mode m;
  m.contact = BodyContact::Slide;
  m.yaw = yaw_of(rotation(quat_at(z, S::kQw)));
  m.slip_ref = slip_ref;
  return m;
}

BodyOnGround::SlideState BodyOnGround::slide_state(double t, const Mode& m, const State& z) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 f = specific_force(t);
  return {base_slide(body_.width, body_.depth, body_.half_height(), body_.mass, inertia_[2], mu_k_, yaw_of(r),
                     vec_at(z, kVx), z[kWz], f, m.slip_ref, kSlipNoise * std::sqrt(body_.g * size_)),
          f};
}

void BodyOnGround::slide_rhs(double t, const Mode& m, const State& z, State& dz) const {
  const SlideState s = slide_state(t, m, z);
  const Vec3 v = vec_at(z, kVx);
  const Quat dq = Quat{0, 0, 0, z[kWz]} * quat_at(z, S::kQw);
  dz[kX] = v[0];
  dz[kY] = v[1];
  dz[kQw] = 0.5 * dq.w;
  dz[kQx] = 0.5 * dq.x;
  dz[kQy] = 0.5 * dq.y;
  dz[kQz] = 0.5 * dq.z;
  dz[kVx] = s.motion.accel[0];
  dz[kVy] = s.motion.accel[1];
  dz[kWz] = s.motion.spin_accel;
  dz[kWorkGround] = body_.mass * (s.f[0] * v[0] + s.f[1] * v[1]);
  dz[kWorkFriction] = s.motion.friction_power;
}

void BodyOnGround::slide_events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const {
  const SlideState s = slide_state(t, m, z);
  const double weight = body_.mass * body_.g, vs = std::sqrt(body_.g * size_);
  double load = 0;
  for (int i = 0; i < 4; ++i) {
    g[kEvTouch0 + i] = s.motion.load[i] / weight;
    load += s.motion.load[i];
  }
  g[kEvLiftOff] = load / weight;
  const Vec3 u = slip_of(z);
  const double along = dot(u, m.slip_ref);
  g[kEvSlipA] = along / vs;
  g[kEvSlipB] = (along - kTurnCosine * std::sqrt(dot(u, u))) / vs + kSlipNoise;
}

double BodyOnGround::kink_ahead(double, const Mode& m, const State& z, const State& dz) const {
  if (m.contact != BodyContact::Slide) return INFINITY;
  const Vec3 u = slip_of(z), du = {dz[kVx], dz[kVy], reach_ * dz[kWz]};
  const double rate = dot(u, du), dd = dot(du, du);
  if (!(rate < 0) || !(dd > 0)) return INFINITY;
  const double tau = -rate / dd;
  const Vec3 closest = plus(u, scaled(du, tau));
  return dot(closest, closest) <= kStickAhead * kStickAhead * dot(u, u) ? tau : INFINITY;
}

Tr BodyOnGround::start_slide(double t, const State& z, const Vec3& towards) const {
  // The ground accelerating towards a_H: the base slides the other way relative to it.
  const double n = std::hypot(towards[0], towards[1]);
  Mode m = slide_mode(z, {-towards[0] / n, -towards[1] / n, 0});
  (void)t;
  return {m, false, int(Body3dEventKind::Mode)};
}

Tr BodyOnGround::slide_change(double t, const Mode& m, State& z, int event) const {
  if (event == kEvLiftOff) return {m, true, int(Body3dEventKind::Invalid)};
  if (event >= kEvTouch0 && event <= kEvTouch3) return {m, true, int(Body3dEventKind::NotModelled)};
  const Vec3 u = slip_of(z);
  // A turn located with the slip at its noise (a stick) is the stick.
  const double vs = std::sqrt(body_.g * size_);
  if (event == kEvSlipB && dot(u, u) > kStickSlip * kStickSlip * vs * vs) {
    Mode next = m;
    next.slip_ref = scaled(u, 1.0 / std::sqrt(dot(u, u)));
    return {next, false, int(Body3dEventKind::SlipTurn)};
  }
  // The slip ends: what is left of it (the event's rounding) is lost to friction.
  const Mat3 r = rotation(quat_at(z, S::kQw));
  z[kWorkFriction] -= 0.5 * body_.mass * (z[kVx] * z[kVx] + z[kVy] * z[kVy]) + 0.5 * inertia_[2] * z[kWz] * z[kWz];
  z[kVx] = z[kVy] = z[kWz] = 0;
  Mode rest;
  rest.yaw = yaw_of(r);
  if (rest_holds(t, rest.yaw)) return {rest, false, int(Body3dEventKind::Stick)};
  Tr tr = leave_rest(t, z);
  if (!tr.stop) tr.kind = int(Body3dEventKind::Stick);
  return tr;
}

}  // namespace blockdyn
