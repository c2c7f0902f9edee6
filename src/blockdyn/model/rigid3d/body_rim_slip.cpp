// SPDX-License-Identifier: Apache-2.0
// The rigid3d cylinder slipping on its rim (body_on_ground.hpp, rim_rolling.hpp): the contact's
// material point moves along the ground against Coulomb's friction while the rim's lowest point
// stays on it. Its slip is followed against a reference direction (slip_reference.hpp) as a box
// corner's; where it ends the rim rolls on if mu_s holds it, else slips the other way. A rolling
// or rocking rim whose friction reaches mu_s starts slipping the way its slip accelerates.
#include <cmath>
#include <optional>

#include "blockdyn/model/rigid3d/body_on_ground.hpp"
#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/model/rigid3d/body_state.hpp"
#include "blockdyn/model/rigid3d/slip_reference.hpp"

namespace blockdyn {

namespace {

using S = BodyOnGround;
using Tr = Transition<BodyOnGroundMode>;
using namespace slip_reference;

// Loads (in m g) and accelerations along the slip (in g) this far below zero still count as
// consistent (the rounding of a switch).
constexpr double kRimTie = 1e-9;

Vec3 unit_horizontal(const Vec3& v) {
  const double n = std::hypot(v[0], v[1]);
  return n > 0 ? Vec3{v[0] / n, v[1] / n, 0} : Vec3{1, 0, 0};
}

}  // namespace

RimSlip BodyOnGround::rim_slipping(double t, const Vec3& d, const State& z, const Vec3& side) const {
  return rim_slip_motion(inertia_, body_.mass, body_.radius, body_.half_height(), rotation(quat_at(z, S::kQw)),
                         vec_at(z, kVx), vec_at(z, kWx), specific_force(t), mu_k_, d, side);
}

RimSlip BodyOnGround::rim_slipping(double t, const Mode& m, const State& z) const {
  // The friction's direction from the slip the state has (slip_reference.hpp): the contact's
  // material velocity, as rim_slip_motion finds it.
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 arm = r * rim_contact_point(body_.radius, body_.half_height(), r, m.point_a);
  const Vec3 s = plus(vec_at(z, kVx), cross(vec_at(z, kWx), arm));
  const Vec3 d = friction_direction({s[0], s[1], 0}, m.slip_ref, kSlipNoise * std::sqrt(body_.g * size_));
  return rim_slipping(t, d, z, m.point_a);
}

void BodyOnGround::rim_slip_rhs(double t, const Mode& m, const State& z, State& dz) const {
  const RimSlip rs = rim_slipping(t, m, z);
  set_kinematic_rates(t, z, dz);
  set_vec_at(dz, kVx, rs.accel);
  set_vec_at(dz, kWx, rs.domega);
  dz[kWorkFriction] = rs.force[0] * rs.slip[0] + rs.force[1] * rs.slip[1];
}

void BodyOnGround::rim_slip_events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const {
  const RimSlip rs = rim_slipping(t, m, z);
  const double vs = std::sqrt(body_.g * size_);
  g[kEvLiftOff] = rs.force[2] / (body_.mass * body_.g);
  g[kEvSlipA] = along(rs.slip, m.slip_ref, vs);
  g[kEvTurnA] = turn_near_stick(rs.slip, m.slip_ref, vs);
  g[kEvPainleve] = rs.consistency;
  const Mat3 r = rotation(quat_at(z, S::kQw));
  rim_side_events(m, r, g);
  g[kEvOverturn] = r[2][2];
}

void BodyOnGround::rim_slip_complete(const Mode& m, State& z) const {
  // The rim's lowest point on the ground, its material point not moving vertically.
  const Quat q = normalized(quat_at(z, S::kQw));
  set_quat_at(z, kQw, q);
  const Mat3 r = rotation(q);
  const Vec3 arm = r * rim_contact_point(body_.radius, body_.half_height(), r, m.point_a);
  z[kZ] = -arm[2];
  z[kVz] = -cross(vec_at(z, kWx), arm)[2];
}

double BodyOnGround::rim_slip_kink_ahead(double t, const Mode& m, const State& z) const {
  const RimSlip rs = rim_slipping(t, m, z);
  return std::fmin(stick_ahead(rs.slip, rs.slip_rate), rim_flat_ahead(m, z));
}

Tr BodyOnGround::start_rim_slip(double t, const State& z, const Vec3& ref, const Vec3& side, int kind) const {
  // The direction the slip accelerates in under the friction it makes (slip_reference.hpp).
  auto accel_of = [&](const Vec3& d) { return rim_slipping(t, d, z, side).slip_rate; };
  Mode m = roll_mode(z, true);
  if (rim_on_side(rotation(quat_at(z, S::kQw)), side)) m.point_a = side;
  m.slip_ref = slip_start_root(accel_of, unit_horizontal(ref));
  const RimSlip rs = rim_slipping(t, m.slip_ref, z, m.point_a);
  const double weight = body_.mass * body_.g;
  const bool accelerates = dot(rs.slip_rate, m.slip_ref) >= -kRimTie * body_.g;
  if (rs.consistency > 0 && rs.force[2] >= -kRimTie * weight && accelerates)
    return {m, false, kind == int(Body3dEventKind::Mode) ? int(Body3dEventKind::Slip) : kind};
  // No slip is consistent: the body flies if the contact rises without a load, else Painleve.
  const RimSlip free =
      rim_slip_motion(inertia_, body_.mass, body_.radius, body_.half_height(), rotation(quat_at(z, S::kQw)),
                      vec_at(z, kVx), vec_at(z, kWx), specific_force(t), 0.0, m.slip_ref, m.point_a);
  const double rising = -free.force[2];  // the load it would need, reversed: the free contact's rise
  if (rising >= 0) return {Mode{BodyContact::Flight}, false, int(Body3dEventKind::LiftOff)};
  return {m, true, int(Body3dEventKind::Painleve)};
}

std::optional<BodyOnGroundMode> BodyOnGround::moving_rim(double t, const State& z) const {
  Mode m = roll_mode(z, true);
  m.slip_ref = {1, 0, 0};
  const Vec3 u = rim_slipping(t, m, z).slip;
  const double speed = std::sqrt(dot(u, u));
  if (speed < instant_slip()) return std::nullopt;
  m.slip_ref = scaled(u, 1.0 / speed);
  const RimSlip rs = rim_slipping(t, m, z);
  if (!(rs.consistency > 0) || rs.force[2] < -kRimTie * body_.mass * body_.g) return std::nullopt;
  return m;
}

Tr BodyOnGround::rim_contact_holds_or_slips(double t, const Mode& stick, const State& z, int kind,
                                            bool may_stick) const {
  // A rim contact at rest on the ground (rocking on a rim point, or rolling): it holds if its
  // friction is within mu_s N, else starts slipping against the friction it needed.
  const Vec3 need = stick.contact == BodyContact::Roll ? rolling(t, z).force : contact_forces(t, stick, z)[0];
  const double weight = body_.mass * body_.g;
  if (need[2] < 0) return {Mode{BodyContact::Flight}, false, int(Body3dEventKind::LiftOff)};
  if (may_stick && opt_.mu_s * need[2] - std::hypot(need[0], need[1]) >= -kRimTie * weight) return {stick, false, kind};
  return start_rim_slip(t, z, {-need[0], -need[1], 0}, stick.point_a, kind);
}

Tr BodyOnGround::rim_slip_change(double t, const Mode& m, State& z, int event) const {
  const double vs = std::sqrt(body_.g * size_);
  if (const auto tr = moving_contact_ends(m, event)) return *tr;
  switch (event) {
    case kEvSlipA:
    case kEvTurnA:
      break;
    default:
      return rim_side_change(t, m, z, event);
  }
  const Vec3 s = rim_slipping(t, m, z).slip;
  if (event == kEvTurnA && std::sqrt(dot(s, s)) > kStickSlip * vs) {
    Mode next = m;
    next.slip_ref = scaled(s, 1.0 / std::sqrt(dot(s, s)));
    return {next, false, int(Body3dEventKind::SlipTurn)};
  }
  // The slip ends: what is left of it (the event's rounding) is lost to friction; the rim rolls
  // on if mu_s holds it, else slips the other way.
  const double ke = energy(z);
  set_vec_at(z, kVx, minus(vec_at(z, kVx), s));
  z[kWorkFriction] += energy(z) - ke;
  // Still below the landing's tilt (the rim's rolling is singular that flat): the base lands.
  if (m.lifting) return landed_flat(t, z);
  Tr tr = rim_contact_holds_or_slips(t, rim_or_roll(z, m.point_a), z, int(Body3dEventKind::Stick), true);
  if (!tr.stop && tr.next.slips()) tr.kind = int(Body3dEventKind::Slip);
  return tr;
}

}  // namespace blockdyn
