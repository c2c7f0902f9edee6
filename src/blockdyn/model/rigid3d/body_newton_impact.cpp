// SPDX-License-Identifier: Apache-2.0
// A box's impact by Newton's and Coulomb's laws (body_on_ground.hpp): the base corners that touch
// the ground (the one that hits and those still in contact) take impulses p_i with
//   u_i+ = u_i- + sum_j W_ij p_j,  W_ij = I/m - [a_i]x J^-1 [a_j]x  (a_i the corner's arm, J the
// inertia in the world's axes), each corner's normal velocity after the impact -e times the one
// before where it hits (at least zero where it stays), each impulse in Coulomb's cone: sticking
// within mu_s, slipping against its slip with mu_k (numerics/spatial_contact.hpp). With e = 0 and
// friction enough, a corner or an edge that hits sticks and the body turns about it: Housner's law
// in 3D. A corner whose impulse friction cannot hold leaves the impact slipping; the contact goes
// on with its points moving as the impulses left them. Where no impulses in the cones solve the
// problem (Painleve at the impulse level: a slender body's edge landing sliding) the impulses are
// the normal ones alone, the slip going on under Coulomb's friction at the acceleration level.
// A cylinder's rim landing on a rim point: the same problem for that one point (sticking, it is
// Housner's rim law; else the rim leaves slipping or bounces).
#include <cmath>

#include "blockdyn/model/rigid3d/body_on_ground.hpp"
#include "blockdyn/model/rigid3d/body_state.hpp"
#include "blockdyn/model/rigid3d/slip_reference.hpp"  // kSlipNoise
#include "blockdyn/model/rigid_ground/rigid_params.hpp"
#include "blockdyn/numerics/spatial_contact.hpp"

namespace blockdyn {

namespace {

using S = BodyOnGround;
using Tr = Transition<BodyOnGroundMode>;

// A touch where no corner moves into the ground, the body this slow (relative to sqrt(g size)):
// an accumulation ended.
constexpr double kNewtonStill = 1e-6;

// [a]x M [b]x as the product of the cross-product matrices.
Mat3 cross_matrix(const Vec3& a) { return {Vec3{0, -a[2], a[1]}, Vec3{a[2], 0, -a[0]}, Vec3{-a[1], a[0], 0}}; }

Mat3 product(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  return c;
}

}  // namespace

Tr BodyOnGround::start(double t, State& z, bool slipping) const {
  const Mode m = mode_of(t, z, slipping);
  const bool on_points = m.contact == BodyContact::Line || m.contact == BodyContact::Point;
  // Without a velocity of its own (`slipping` false) the contact takes the velocities it allows:
  // its points are at rest, none moves into the ground.
  if (!slipping || opt_.impact != Body3dImpactLaw::Newton || body_.shape != BodyShape3d::Box || !on_points)
    return {m, false, int(Body3dEventKind::Mode)};
  // A touching corner moving into the ground: the start is an impact at t (from flight: every
  // touching corner takes part). Otherwise the contact takes the velocities it allows (mode_of):
  // a start sliding along the ground would need a tangential impulse that Coulomb's law without
  // a normal one does not give, and its slip under a large friction is too stiff to follow.
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 v = vec_at(z, kVx), w = vec_at(z, kWx);
  double approach = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3 a = r * corner(i);
    if (z[kZ] + a[2] <= kImpactTouch * size_) approach = std::fmin(approach, plus(v, cross(w, a))[2]);
  }
  if (approach >= -kSlipNoise * std::sqrt(body_.g * size_)) return {m, false, int(Body3dEventKind::Mode)};
  Tr tr = newton_impact(t, Mode{BodyContact::Flight}, z);
  if (!tr.stop) tr.kind = int(Body3dEventKind::Mode);
  return tr;
}

const char* to_string(Body3dImpactLaw l) {
  return to_string(l == Body3dImpactLaw::Housner ? ImpactLaw::Housner : ImpactLaw::Newton);  // one vocabulary
}

Mat3 BodyOnGround::world_inverse_inertia(const Mat3& r) const {
  Mat3 inv{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) inv[i][j] += r[i][k] * r[j][k] / inertia_[std::size_t(k)];
  return inv;
}

Tr BodyOnGround::newton_rim_impact(double t, const Mode& from, State& z) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  if (from.contact == BodyContact::Flight && r[2][2] >= 1 - 1e-12) return landed_flat(t, z);
  // The rim point that lands: the lowest from flight, else the one opposite the contact.
  const Vec3 p = from.contact == BodyContact::Flight ? lowest_point(body_, r).body
                                                     : Vec3{-from.point_a[0], -from.point_a[1], from.point_a[2]};
  const Vec3 v = vec_at(z, kVx), w = vec_at(z, kWx), arm = r * p;
  const Vec3 u = plus(v, cross(w, arm));
  if (!(u[2] < 0)) return housner_impact(t, from, z);  // a graze: the contact turns onto the point
  const Mat3 inv = world_inverse_inertia(r), k = product(cross_matrix(arm), product(inv, cross_matrix(arm)));
  double wm[9], q[3] = {u[0], u[1], u[2]}, pulse[3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) wm[3 * a + b] = (a == b ? 1.0 / body_.mass : 0.0) - k[a][b];
  const double v_normal = -opt_.restitution * u[2];
  // No impulse in the cone (Painleve at the impulse level): the normal impulse alone.
  if (!solve_contact_3x3(wm, q, v_normal, opt_.mu_s, mu_k_, pulse)) solve_contact_3x3(wm, q, v_normal, 0, 0, pulse);
  const double before = energy(z), w_before = std::sqrt(dot(w, w));
  const Vec3 impulse{pulse[0], pulse[1], pulse[2]};
  // Within the cone and at rest after it (e = 0, friction enough): the point sticks, which is
  // Housner's law about it (the rim rocking on its tangent, as the impact Housner's law makes).
  const Vec3 rest = plus(u, {(wm[0] * pulse[0] + wm[1] * pulse[1] + wm[2] * pulse[2]),
                             (wm[3] * pulse[0] + wm[4] * pulse[1] + wm[5] * pulse[2]),
                             (wm[6] * pulse[0] + wm[7] * pulse[1] + wm[8] * pulse[2])});
  if (std::sqrt(dot(rest, rest)) <= kSlipNoise * std::sqrt(body_.g * size_)) return housner_impact(t, from, z);
  set_vec_at(z, kVx, plus(v, scaled(impulse, 1.0 / body_.mass)));
  set_vec_at(z, kWx, plus(w, inv * cross(arm, impulse)));
  const Vec3 after = plus(vec_at(z, kVx), cross(vec_at(z, kWx), arm));
  const double scale = std::fmax(std::sqrt(dot(v, v)), w_before * size_);
  if (after[2] > kImpactLeaving * scale) {  // it bounces off (e > 0)
    z[kWorkImpact] += energy(z) - before;
    return {Mode{BodyContact::Flight}, false, int(Body3dEventKind::Impact)};
  }
  // The point stays: at rest (rocking on it, or rolling), or slipping the way the impulse left it.
  const Vec3 slip{after[0], after[1], 0};
  const double speed = std::sqrt(dot(slip, slip));
  Mode next = rim_or_roll(z, p);
  if (speed > kSlipNoise * std::sqrt(body_.g * size_)) {
    next = roll_mode(z, true);
    next.point_a = p;
    next.slip_ref = scaled(slip, 1.0 / speed);
  }
  complete(next, z);
  z[kWorkImpact] += energy(z) - before;  // the loss, and the height the contact's rounding gives up
  if (!next.slips()) return after_impact(t, from, next, z, w_before);
  const RimSlip rs = rim_slipping(t, next, z);
  if (rs.force[2] < 0) return {Mode{BodyContact::Flight}, false, int(Body3dEventKind::Impact)};
  if (!(rs.consistency > 0)) return {from, true, int(Body3dEventKind::Painleve)};
  return {next, false, int(Body3dEventKind::Impact)};
}

SpatialContactProblem BodyOnGround::point_problem(const Mat3& r, const Vec3& v, const Vec3& w, const Vec3* points,
                                                  int n, Vec3* arm) const {
  const Mat3 inv = world_inverse_inertia(r);
  SpatialContactProblem pr;
  pr.n = n;
  pr.mu_s = opt_.mu_s;
  pr.mu_k = mu_k_;
  for (int i = 0; i < n; ++i) {
    arm[i] = r * points[i];
    const Vec3 u = plus(v, cross(w, arm[i]));
    for (int c = 0; c < 3; ++c) pr.q[std::size_t(3 * i + c)] = u[std::size_t(c)];
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Mat3 k = product(cross_matrix(arm[i]), product(inv, cross_matrix(arm[j])));
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          pr.w[std::size_t((3 * i + a) * 3 * n + 3 * j + b)] = (a == b ? 1.0 / body_.mass : 0.0) - k[a][b];
    }
  return pr;
}

SpatialContactProblem BodyOnGround::corner_problem(const Mat3& r, const Vec3& v, const Vec3& w, const int* corners,
                                                   int n, Vec3* arm) const {
  Vec3 points[4];
  for (int i = 0; i < n; ++i) points[i] = corner(corners[i]);
  return point_problem(r, v, w, points, n, arm);
}

Tr BodyOnGround::newton_impact(double t, const Mode& from, State& z) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 x = vec_at(z, kX), v = vec_at(z, kVx), w = vec_at(z, kWx);
  // Touching: at the ground, or with the lowest corner where a contact left it above it (a
  // contact is kept where it touched, within the stepping's tolerance after a Moreau-Jean span).
  double height[4], level = INFINITY;
  for (int i = 0; i < 4; ++i) level = std::fmin(level, height[i] = z[kZ] + dot(r[2], corner(i)));
  level = std::fmax(level, 0.0) + kImpactTouch * size_;
  int touching[4], n = 0;
  for (int i = 0; i < 4; ++i)
    if (height[i] <= level) touching[n++] = i;
  // A base landing flat from flight: plastic, at rest (as Housner's law has it).
  if (n == 0 || (n >= 3 && from.contact == BodyContact::Flight)) return landed_flat(t, z);
  const Mat3 inv = world_inverse_inertia(r);
  Vec3 arm[4];
  SpatialContactProblem pr = corner_problem(r, v, w, touching, n, arm);
  // A bounce that would rise less than kUnresolvedRise of the size (below the rounding of the
  // centroid's height) is plastic, as the planar `rigid` block's: an accumulation of bounces ends.
  for (int i = 0; i < n; ++i) {
    const double u = pr.q[std::size_t(3 * i + 2)], bounce = -opt_.restitution * u;
    pr.v_normal[std::size_t(i)] = u < 0 && bounce >= v_unresolved_ ? bounce : 0.0;
  }
  // No corner moving into the ground: the base flat at the end of an accumulation (the swings at a
  // rounding's size), at rest; a tilted body's corner arriving at rest (an edge's end that lifted
  // at rounding, the body turning about the edge) makes the contact the events can go on with;
  // else a graze, the motion goes on.
  double speed = 0;
  bool hits = false;
  for (int i = 0; i < n; ++i) hits = hits || pr.q[std::size_t(3 * i + 2)] < 0;
  for (int k = 0; k < 3 * n; ++k) speed = std::fmax(speed, std::fabs(pr.q[std::size_t(k)]));
  if (!hits) {
    if (speed > kNewtonStill * std::sqrt(body_.g * size_)) return Tr{from, false, int(Body3dEventKind::Mode)};
    if (n >= 3) return settle(t, z);
    unsigned mask = 0;
    for (int i = 0; i < n; ++i) mask |= 1u << unsigned(touching[i]);
    if (auto joined = resume_contact(t, z, mask)) return *joined;
    return Tr{from, false, int(Body3dEventKind::Mode)};
  }
  SpatialContactSolution sol = solve_spatial_contact(pr);
  if (!sol.solved) {
    // No impulses in Coulomb's cones (Painleve at the impulse level, seen where a slender body's
    // edge lands sliding): the normal impulses alone, the slip going on under Coulomb's friction
    // at the acceleration level.
    SpatialContactProblem frictionless = pr;
    frictionless.mu_s = frictionless.mu_k = 0;
    sol = solve_spatial_contact(frictionless);
  }
  if (!sol.solved) return housner_impact(t, from, z);  // not even the normal impulses: Housner's
  // The impulses' loss, and the height the contact's completion gives up (its rounding).
  const double before = energy(z);
  const double w_before = std::sqrt(dot(w, w));
  Vec3 force{}, moment{};
  for (int i = 0; i < n; ++i) {
    const Vec3 p{sol.p[std::size_t(3 * i)], sol.p[std::size_t(3 * i + 1)], sol.p[std::size_t(3 * i + 2)]};
    force = plus(force, p);
    moment = plus(moment, cross(arm[i], p));
  }
  set_vec_at(z, kVx, plus(v, scaled(force, 1.0 / body_.mass)));
  set_vec_at(z, kWx, plus(w, inv * moment));
  // The corners that stay: those left at rest along the normal (pressed with e = 0, or in contact
  // and not pulled away); a corner that bounces (e > 0) or lifts leaves.
  const double scale = std::fmax(std::sqrt(dot(v, v)), w_before * size_);
  int stay[4], m = 0;
  for (int i = 0; i < n; ++i)
    if (sol.u[std::size_t(3 * i + 2)] <= kImpactLeaving * scale) stay[m++] = touching[i];
  if (m >= 3) return landed_flat(t, z);  // the base stays flat: at rest
  if (m == 0) {
    z[kWorkImpact] += energy(z) - before;
    return {Mode{BodyContact::Flight}, false, int(Body3dEventKind::Impact)};
  }
  Mode c = m == 2 ? line_mode(r, x, corner(stay[0]), corner(stay[1]), stay[0], stay[1])
                  : point_mode(r, x, corner(stay[0]), stay[0]);
  if (m == 1 && from.contact == BodyContact::Line && (from.corner_a == stay[0] || from.corner_b == stay[0])) {
    c.released = from.corner_a == stay[0] ? from.corner_b : from.corner_a;
    c.released_t = t;
  }
  // Its points slipping the way the impulses left them moving (at rest: sticking).
  const Mode next = moving_contact(c, z);
  complete(next, z);
  z[kWorkImpact] += energy(z) - before;
  return after_impact(t, from, next, z, w_before);
}

}  // namespace blockdyn
