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
#include "blockdyn/model/rigid3d/slip_reference.hpp"

namespace blockdyn {

namespace {
using S = BodyOnGround;
using Tr = Transition<BodyOnGroundMode>;

using namespace slip_reference;

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
                     vec_at(z, kVx), z[kWz], f, m.slip_ref, kSlipNoise * std::sqrt(body_.g * size_), m.unloaded),
          f};
}

void BodyOnGround::slide_rhs(double t, const Mode& m, const State& z, State& dz) const {
  if (body_.shape == BodyShape3d::Cylinder) return disc_slide_rhs(t, m, z, dz);
  const SlideState s = slide_state(t, m, z);
  set_slide_kinematics(z, dz);
  const Vec3 v = vec_at(z, kVx);
  dz[kVx] = s.motion.accel[0];
  dz[kVy] = s.motion.accel[1];
  dz[kWz] = s.motion.spin_accel;
  dz[kWorkGround] = body_.mass * (s.f[0] * v[0] + s.f[1] * v[1]);
  dz[kWorkFriction] = s.motion.friction_power;
}

void BodyOnGround::set_slide_kinematics(const State& z, State& dz) const {
  const Vec3 v = vec_at(z, kVx);
  const Quat dq = Quat{0, 0, 0, z[kWz]} * quat_at(z, S::kQw);
  dz[kX] = v[0];
  dz[kY] = v[1];
  dz[kQw] = 0.5 * dq.w;
  dz[kQx] = 0.5 * dq.x;
  dz[kQy] = 0.5 * dq.y;
  dz[kQz] = 0.5 * dq.z;
}

void BodyOnGround::slide_events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const {
  if (body_.shape == BodyShape3d::Cylinder) return disc_slide_events(t, m, z, g);
  const SlideState s = slide_state(t, m, z);
  const double weight = body_.mass * body_.g, vs = std::sqrt(body_.g * size_);
  double load = 0;
  for (int i = 0; i < 4; ++i) {
    g[kEvTouch0 + i] = s.motion.load[i] / weight;
    load += s.motion.load[i];
  }
  g[kEvLiftOff] = load / weight;
  if (m.unloaded >= 0) {
    // On three corners: the fourth bears again where the linear pressure would load it.
    Mode four = m;
    four.unloaded = -1;
    g[kEvTouch0 + m.unloaded] = 1;
    g[kEvLoadA] = -slide_state(t, four, z).motion.load[m.unloaded] / weight;
  }
  const Vec3 u = slip_of(z);
  g[kEvSlipA] = along(u, m.slip_ref, vs);
  g[kEvSlipB] = turn_near_stick(u, m.slip_ref, vs);
}

double BodyOnGround::kink_ahead(double t, const Mode& m, const State& z, const State& dz) const {
  if (m.contact == BodyContact::Roll) return m.slips() ? rim_slip_kink_ahead(t, m, z) : INFINITY;
  if (m.slips()) {
    // The first of the slipping points' sticks ahead.
    const ContactSlip c = contact_slip_of(m, z);
    const std::array<Vec3, 2> a = contact_slip_rates(t, c, z);
    double tau = INFINITY;
    for (int i = 0; i < c.points.n; ++i)
      if (!c.points.sticks[i]) tau = std::fmin(tau, stick_ahead(c.slip[i], a[i]));
    (void)dz;
    return tau;
  }
  if (m.contact != BodyContact::Slide) return INFINITY;
  return stick_ahead(slip_of(z), {dz[kVx], dz[kVy], reach_ * dz[kWz]});
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
  if (body_.shape == BodyShape3d::Cylinder && event == kEvTouch0) return tip_disc_from_slide(t, m, z);
  if (event >= kEvTouch0 && event <= kEvTouch3) return unload_in_slide(t, m, z, event - kEvTouch0);
  if (event == kEvLoadA) {
    Mode four = m;
    four.unloaded = -1;
    return {four, false, int(Body3dEventKind::Mode)};
  }
  return slide_ends_or_turns(t, m, z, event);
}

Tr BodyOnGround::slide_ends_or_turns(double t, const Mode& m, State& z, int event) const {
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

Tr BodyOnGround::unload_in_slide(double t, const Mode& m, const State& z, int k) const {
  // The corners without load: k, the one already unloaded, and any other at zero with k (to the
  // tie). One alone, or a diagonal pair: the base bears on the other three; else it tips onto
  // the corners still loaded.
  constexpr double kLoadTieShare = 1e-9;
  std::array<double, kNumEvents> g;
  events(t, m, z, g);
  unsigned off = 1u << unsigned(k);
  if (m.unloaded >= 0) off |= 1u << unsigned(m.unloaded);
  for (int i = 0; i < 4; ++i)
    if (i != m.unloaded && g[kEvTouch0 + i] < kLoadTieShare) off |= 1u << unsigned(i);
  const bool diagonal = off == 0b1001u || off == 0b0110u;
  if (off == (1u << unsigned(k)) || diagonal) {
    Mode three = m;
    three.unloaded = k;
    return {three, false, int(Body3dEventKind::Mode)};
  }
  int support[4], n = 0;
  for (int i = 0; i < 4; ++i)
    if (!(off & (1u << unsigned(i)))) support[n++] = i;
  return tip_from_slide(t, m, z, support, n);
}

Tr BodyOnGround::tip_from_slide(double t, const Mode& m, const State& z, const int* support, int n) const {
  // Onto the edge still loaded (or one of its ends), or onto the corner (or one of its edges):
  // the first that keeps the other corners from sinking, its loads and friction consistent.
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 x = vec_at(z, kX);
  Mode candidates[3];
  int count = 0;
  if (n == 2) {
    const int p = support[0], q = support[1];
    candidates[count++] = line_mode(r, x, corner(p), corner(q), p, q);
  } else if (n == 1) {
    const int o = support[0];
    candidates[count++] = point_mode(r, x, corner(o), o);
    candidates[count++] = line_mode(r, x, corner(o), corner(o ^ 1), o, o ^ 1);
    candidates[count++] = line_mode(r, x, corner(o), corner(o ^ 2), o, o ^ 2);
  }
  for (int i = 0; i < count; ++i) {
    const Tr tr = stick_or_slip(t, moving_contact(candidates[i], z), z, int(Body3dEventKind::Mode));
    if (!tr.stop && other_corners_rise(t, tr.next, z, kFlatTouch)) return tr;
  }
  return {m, true, int(Body3dEventKind::Painleve)};
}

BodyOnGroundMode BodyOnGround::moving_contact(const Mode& c, const State& z) const {
  // The points in contact go on slipping as the base did; one at rest (the base spinning about
  // it) holds or slips as friction decides.
  Mode moving = c;
  moving.slipping = c.contact == BodyContact::Line ? 3 : 1;
  const ContactSlip s = contact_slip_of(moving, z);
  unsigned mask = 0;
  const double still = kSlipNoise * std::sqrt(body_.g * size_);
  for (int k = 0; k < s.points.n; ++k) {
    const double speed = std::sqrt(dot(s.slip[k], s.slip[k]));
    if (speed <= still) continue;
    mask |= 1u << unsigned(k);
    (k == 0 ? moving.slip_ref : moving.slip_ref_b) = scaled(s.slip[k], 1.0 / speed);
  }
  if (mask == 0) return c;
  moving.slipping = static_cast<unsigned char>(mask);
  const Mat3 r = rotation(quat_at(z, S::kQw));
  if (s.points.n == 2 && mask != 3) moving.pivot = plus(vec_at(z, kX), r * (mask == 1 ? c.point_b : c.point_a));
  return moving;
}

}  // namespace blockdyn
