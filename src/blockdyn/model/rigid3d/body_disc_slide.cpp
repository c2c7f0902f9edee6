// SPDX-License-Identifier: Apache-2.0
// The rigid3d cylinder sliding flat on its base (body_on_ground.hpp, disc_slide.hpp): its motion,
// its events and the tip onto its rim. The slip's generalised velocity (vx, vy, a omega_z) is
// followed against the mode's reference as the box's base's (body_slide.cpp); the base tips where
// the pressure's resultant reaches the rim (all the load on that rim point), onto it.
#include <cmath>

#include "blockdyn/model/rigid3d/body_on_ground.hpp"
#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/model/rigid3d/body_state.hpp"
#include "blockdyn/model/rigid3d/slip_reference.hpp"

namespace blockdyn {

namespace {
using S = BodyOnGround;
using Tr = Transition<BodyOnGroundMode>;
using namespace slip_reference;

// Loads (in m g) this far below zero still count as consistent at the tip (its rounding).
constexpr double kTipTie = 1e-9;
}  // namespace

DiscSlide BodyOnGround::disc_slide_state(double t, const Mode& m, const State& z) const {
  return disc_slide(body_.radius, body_.half_height(), body_.mass, inertia_[2], mu_k_, vec_at(z, kVx), z[kWz],
                    specific_force(t), m.slip_ref, kSlipNoise * std::sqrt(body_.g * size_));
}

void BodyOnGround::disc_slide_rhs(double t, const Mode& m, const State& z, State& dz) const {
  const DiscSlide s = disc_slide_state(t, m, z);
  const Vec3 v = vec_at(z, kVx), f = specific_force(t);
  set_slide_kinematics(z, dz);
  dz[kVx] = s.accel[0];
  dz[kVy] = s.accel[1];
  dz[kWz] = s.spin_accel;
  dz[kWorkGround] = body_.mass * (f[0] * v[0] + f[1] * v[1]);
  dz[kWorkFriction] = s.friction_power;
}

void BodyOnGround::disc_slide_events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const {
  const DiscSlide s = disc_slide_state(t, m, z);
  const double vs = std::sqrt(body_.g * size_);
  // The share of the load on the rim point the resultant leans to: at one, the base tips.
  g[kEvTouch0] = 1 - std::hypot(s.offset[0], s.offset[1]);
  const Vec3 u = slip_of(z);
  g[kEvSlipA] = along(u, m.slip_ref, vs);
  g[kEvSlipB] = turn_near_stick(u, m.slip_ref, vs);
}

Tr BodyOnGround::tip_disc_from_slide(double t, const Mode& m, const State& z) const {
  // All the load on the rim point P along the offset: the body rocks on it, P slipping as the
  // base's material point there moves (held if it does not, as friction decides).
  const DiscSlide s = disc_slide_state(t, m, z);
  const double w = std::hypot(s.offset[0], s.offset[1]), a = body_.radius;
  const Vec3 arm = {a * s.offset[0] / w, a * s.offset[1] / w, 0};  // world, from the base's centre
  const Mat3 r = rotation(quat_at(z, S::kQw));
  Vec3 side = transposed_times(r, arm);
  side[2] = -body_.half_height();
  const Vec3 slip = {z[kVx] - z[kWz] * arm[1], z[kVy] + z[kWz] * arm[0], 0};
  const double speed = std::hypot(slip[0], slip[1]);
  if (speed <= kSlipNoise * std::sqrt(body_.g * size_))
    return rim_contact_holds_or_slips(t, rim_mode(r, vec_at(z, kX), side), z, int(Body3dEventKind::Mode), true);
  Mode next = roll_mode(z, true);
  next.point_a = side;
  next.slip_ref = scaled(slip, 1 / speed);
  const RimSlip rs = rim_slipping(t, next, z);
  if (rs.consistency > 0 && rs.force[2] >= -kTipTie * body_.mass * body_.g)
    return {next, false, int(Body3dEventKind::Mode)};
  return {m, true, int(Body3dEventKind::Painleve)};
}

}  // namespace blockdyn
