// SPDX-License-Identifier: Apache-2.0
// A box's Moreau-Jean step (body_on_ground.hpp, docs/3d.md): the stepping strategy that crosses a
// span where no state of the contact is consistent at the acceleration level (Painleve: with two
// contact points this happens at moderate friction, e.g. a slender box's edge rocking and
// twisting at mu 0.7, whose sticking needs more than mu_s while every slip makes a load negative).
// There the rigid body's motion has impulsive contact forces (Stewart, SIAM Review 42, 2000), and
// the velocity-level step, whose frictional contact problem has a solution, converges to it as
// the step shrinks. Per step of length h from (t, z):
//   free velocities    v' = v + h f(t + h/2),  w' = w + h J^-1 (J w x w)
//   impulses p_i       at the base corners near the ground: the problem of the Newton impact
//                      (numerics/spatial_contact.hpp), e = the options' restitution for a corner
//                      approaching, 0 for one at rest
//   velocities         v+ = v' + sum p_i / m,  w+ = w' + J^-1 sum a_i x p_i
//   positions          the centroid by h (v + v+) / 2, the orientation by the rotation h (w + w+) / 2
// The work of the ground on the centroid m (f + g Z) . h (v + v+) / 2 and the contact's p_i . u_i at
// the corner's mean velocity keep the balance to the step's own error, O(h^2) a step.
#include <cmath>

#include "blockdyn/model/rigid3d/body_on_ground.hpp"
#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/model/rigid3d/body_state.hpp"
#include "blockdyn/numerics/spatial_contact.hpp"

namespace blockdyn {

namespace {

using S = BodyOnGround;
using Tr = Transition<BodyOnGroundMode>;

// A corner whose height, a step ahead at its velocity, is below this (in body sizes) takes part in
// the step's contact problem.
constexpr double kStepTouch = 1e-9;

}  // namespace

int BodyOnGround::base_points(const Mat3& r, Vec3* points) const {
  if (body_.shape == BodyShape3d::Box) {
    for (int i = 0; i < 4; ++i) points[i] = corner(i);
    return 4;
  }
  // The lowest rim point: opposite the world's up seen in the base's plane (any where flat).
  const double ux = r[2][0], uy = r[2][1];
  const double lowest = std::hypot(ux, uy) > 0 ? std::atan2(-uy, -ux) : 0.0;
  for (int i = 0; i < 4; ++i) {
    const double phi = lowest + 0.5 * M_PI * i;
    points[i] = {body_.radius * std::cos(phi), body_.radius * std::sin(phi), -body_.half_height()};
  }
  return 4;
}

BodyOnGround::TimeStep BodyOnGround::time_step(double t, double h, State& z) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 v = vec_at(z, kVx), w = vec_at(z, kWx), f = specific_force(t + 0.5 * h);
  const Vec3 vf = plus(v, scaled(f, h)), wf = plus(w, scaled(free_angular_acceleration(inertia_, r, w), h));
  Vec3 base[4], near[4];
  const int count = base_points(r, base);
  int touching[4], n = 0;
  for (int i = 0; i < count; ++i) {
    const Vec3 a = r * base[i];
    const double approach = plus(v, cross(w, a))[2];
    if (z[kZ] + a[2] + h * std::fmin(0.0, approach) <= kStepTouch * size_) {
      near[n] = base[i];
      touching[n++] = i;
    }
  }
  // The points' problem at the free velocities; a point approaching bounces by e.
  Vec3 arm[4];
  SpatialContactProblem pr = point_problem(r, vf, wf, near, n, arm);
  for (int i = 0; i < n; ++i) {
    const double approach = plus(v, cross(w, arm[i]))[2];
    pr.v_normal[std::size_t(i)] = approach < 0 ? -opt_.restitution * approach : 0.0;
  }
  const Mat3 inv = world_inverse_inertia(r);
  TimeStep out;
  SpatialContactSolution sol;
  if (pr.n > 0) {
    sol = solve_spatial_contact(pr);
    if (!sol.solved) {
      // No impulses in the cones (Painleve at the impulse level): the normal ones alone.
      SpatialContactProblem frictionless = pr;
      frictionless.mu_s = frictionless.mu_k = 0;
      sol = solve_spatial_contact(frictionless);
      out.frictionless = true;
    }
    if (!sol.solved) {
      // Rebounds no rigid motion of the base's points can give together (e > 0 on a flat base,
      // its points approaching at different speeds): the step plastic, with friction if it can.
      pr.v_normal.fill(0);
      sol = solve_spatial_contact(pr);
      out.frictionless = !sol.solved;
      if (!sol.solved) {
        pr.mu_s = pr.mu_k = 0;
        sol = solve_spatial_contact(pr);
      }
    }
    if (!sol.solved) return {0, false, true};
  }
  Vec3 force{}, moment{};
  for (int i = 0; i < pr.n; ++i) {
    const Vec3 p{sol.p[std::size_t(3 * i)], sol.p[std::size_t(3 * i + 1)], sol.p[std::size_t(3 * i + 2)]};
    force = plus(force, p);
    moment = plus(moment, cross(arm[i], p));
    if (p[2] > 0) out.loaded |= 1u << unsigned(touching[i]);
  }
  const Vec3 v1 = plus(vf, scaled(force, 1.0 / body_.mass)), w1 = plus(wf, inv * moment);
  const Vec3 vm = scaled(plus(v, v1), 0.5), wm = scaled(plus(w, w1), 0.5);
  // The contact's work at each corner's mean velocity: its normal part as impact, the rest friction.
  for (int i = 0; i < pr.n; ++i) {
    const Vec3 p{sol.p[std::size_t(3 * i)], sol.p[std::size_t(3 * i + 1)], sol.p[std::size_t(3 * i + 2)]};
    const Vec3 u = plus(vm, cross(wm, arm[i]));
    z[kWorkImpact] += p[2] * u[2];
    z[kWorkFriction] += p[0] * u[0] + p[1] * u[1];
  }
  z[kWorkGround] += h * body_.mass * (f[0] * vm[0] + f[1] * vm[1] + (f[2] + body_.g) * vm[2]);
  set_vec_at(z, kX, plus(vec_at(z, kX), scaled(vm, h)));
  const double turn = std::sqrt(dot(wm, wm)) * h;
  if (turn > 0) set_quat_at(z, kQw, normalized(axis_angle(scaled(wm, h / turn), turn) * quat_at(z, S::kQw)));
  set_vec_at(z, kVx, v1);
  set_vec_at(z, kWx, w1);
  out.solved = true;
  return out;
}

std::optional<Tr> BodyOnGround::resume_on(double t, State& z, const Mode& contact) const {
  // Its points sticking, or slipping the way they move; the start's rule first (a slip friction
  // would stop at once sticks), the other where that is not consistent (an end the step loads at
  // rounding, its friction at the cone's edge, slips on a large mu_s). Consistent at the
  // acceleration level, and no other corner at the ground accelerating into it.
  // The contact's lowest corner put on the ground (the steps leave it within kStepTouch of it):
  // the events measure heights from the contact, an impact from the ground.
  State at_ground = z;
  const Mat3 r = rotation(quat_at(z, S::kQw));
  double lowest = dot(r[2], corner(contact.corner_a));
  if (contact.contact == BodyContact::Line) lowest = std::fmin(lowest, dot(r[2], corner(contact.corner_b)));
  at_ground[kZ] = -lowest;
  Mode at = contact;
  at.pivot[2] -= z[kZ] - at_ground[kZ];
  const Mode moving = moving_contact(at, at_ground);
  const bool stops = moving.slips() && slip_stops_at_once(moving, at_ground);
  const Mode tries[2] = {stops ? at : moving, stops ? moving : at};
  for (int k = 0; k < (moving.slips() ? 2 : 1); ++k) {
    const Mode& next = tries[k];
    State on = at_ground;
    complete(next, on);
    if (consistent_contact(t, next, on, -1) && other_corners_rise(t, next, on, kStepTouch))
      return hand_back(z, on, next);
  }
  return std::nullopt;
}

Tr BodyOnGround::hand_back(State& z, const State& on, const Mode& next) const {
  const double before = energy(z);
  z = on;
  z[kWorkImpact] += energy(z) - before;  // the contact's velocities the step's rounding left
  return Tr{next, false, int(next.slips() ? Body3dEventKind::Slip : Body3dEventKind::Mode)};
}

std::optional<Tr> BodyOnGround::resume_on_rim(double t, State& z, const Vec3& p) const {
  // As the rim's Newton impact leaves its point: slipping the way it moves where friction would
  // not stop that at once (the start's rule), else rocking or rolling on it, sticking if friction
  // holds it (else the slip it starts); not where it pulls on the ground, nor with the base flat
  // (no lowest point: the steps go on).
  State on = z;
  const Mat3 r = rotation(quat_at(z, S::kQw));
  if (!(std::hypot(r[2][0], r[2][1]) > 0)) return std::nullopt;
  on[kZ] = -dot(r[2], p);
  const Vec3 u = plus(vec_at(on, kVx), cross(vec_at(on, kWx), r * p));
  const Vec3 slip{u[0], u[1], 0};
  const double speed = std::sqrt(dot(slip, slip));
  Mode next;
  if (speed >= instant_slip()) {
    next = roll_mode(on, true);
    next.point_a = p;
    next.slip_ref = scaled(slip, 1.0 / speed);
    complete(next, on);
    const RimSlip rs = rim_slipping(t, next, on);
    if (rs.force[2] < 0 || !(rs.consistency > 0)) return std::nullopt;
  } else {
    const Mode still = rim_or_roll(on, p);
    complete(still, on);
    const Tr tr = rim_contact_holds_or_slips(t, still, on, int(Body3dEventKind::Mode), true);
    if (tr.stop || tr.next.contact == BodyContact::Flight) return std::nullopt;
    next = tr.next;
  }
  return hand_back(z, on, next);
}

std::optional<Tr> BodyOnGround::resume_contact(double t, State& z, unsigned loaded) const {
  // The contact the step left loaded, where the events can take over. No search for a slip's
  // start: where that is needed the state is the Painleve one, and the steps go on.
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 x = vec_at(z, kX);
  int corners[4], n = 0;
  for (int i = 0; i < 4; ++i)
    if (loaded & (1u << unsigned(i))) corners[n++] = i;
  if (n == 0) {
    // Free of the ground: flight, unless a corner is below it (the step's drift).
    if (z[kZ] - lowest_point(body_, r).depth < -kStepTouch * size_) return std::nullopt;
    return Tr{Mode{BodyContact::Flight}, false, int(Body3dEventKind::LiftOff)};
  }
  // A cylinder on its rim's lowest point alone rocks or rolls on it; on another rim point (the
  // lowest then within kStepTouch of the ground too: the base near flat), or on several, it lands.
  if (body_.shape != BodyShape3d::Box && n == 1 && corners[0] == 0) {
    Vec3 rim[4];
    base_points(r, rim);
    return resume_on_rim(t, z, rim[0]);
  }
  if (n >= 3 || body_.shape != BodyShape3d::Box) {
    // Flat (a box on three corners, a cylinder near flat): the base as a landing leaves it (at
    // rest, its exit from rest, or sliding on).
    State flat = z;
    const double before = energy(flat);
    set_quat_at(flat, kQw, axis_angle({0, 0, 1}, std::atan2(r[1][0], r[0][0])));
    flat[kZ] = body_.half_height();
    flat[kVz] = flat[kWx] = flat[kWy] = 0;
    flat[kWorkImpact] += energy(flat) - before;
    const Tr tr = landed_flat(t, flat);
    if (tr.stop) return std::nullopt;
    z = flat;
    return tr;
  }
  if (n == 1) return resume_on(t, z, point_mode(r, x, corner(corners[0]), corners[0]));
  if (auto edge = resume_on(t, z, line_mode(r, x, corner(corners[0]), corner(corners[1]), corners[0], corners[1])))
    return edge;
  // An edge whose one end the step loads only through friction's coupling (a load at rounding,
  // its friction at the cone's edge; large mu_s) pivots on the other end: each end alone.
  for (int j = 0; j < 2; ++j) {
    Mode end = point_mode(r, x, corner(corners[j]), corners[j]);
    end.released = corners[1 - j];  // at the ground: its touch looked for below the rounding
    end.released_t = t;
    if (auto point = resume_on(t, z, end)) return point;
  }
  return std::nullopt;
}

}  // namespace blockdyn
