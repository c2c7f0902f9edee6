// SPDX-License-Identifier: Apache-2.0
// The rigid3d body's impacts (body_on_ground.hpp): a base point reaching the ground makes it the
// new contact; the angular momentum about that contact is conserved through the impact (a point:
// all three components; a line: the one along it), the generalisation of Housner's law. If an old
// contact point would then move into the ground the new contact takes it in too (a corner and its
// neighbour make an edge); a base landing flat, or impacts that accumulate, end at rest.
#include <cmath>
#include <vector>

#include "blockdyn/model/rigid3d/body_on_ground.hpp"
#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/model/rigid3d/body_state.hpp"

namespace blockdyn {

namespace {

using S = BodyOnGround;
using Tr = Transition<BodyOnGroundMode>;

bool holds(const BodyOnGroundMode& m, int corner) { return corner == m.corner_a || corner == m.corner_b; }

}  // namespace

void BodyOnGround::conserve_momentum_about(const Mode& m, State& z) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 pa = m.contact == BodyContact::Line ? plus(m.pivot, scaled(m.axis, m.half_length)) : m.pivot;
  const Vec3 arm = minus(vec_at(z, kX), pa);
  const Vec3 h = angular_momentum_about(inertia_, body_.mass, r, arm, vec_at(z, kVx), vec_at(z, kWx));
  const Mat3 j = inertia_about(inertia_, body_.mass, transposed_times(r, arm));
  Vec3 w;
  if (m.contact == BodyContact::Point) {
    w = r * (solve_matrix(j) * transposed_times(r, h));
  } else {
    const Vec3 eb = transposed_times(r, m.axis);
    w = scaled(m.axis, dot(m.axis, h) / dot(eb, j * eb));
  }
  set_vec_at(z, kWx, w);
  set_vec_at(z, kVx, cross(w, arm));
}

Tr BodyOnGround::landed_flat(double t, State& z) const {
  // The base lands flat: plastic along the normal on the whole base (the normal impulse m |v_z|
  // stops its fall and its tilting), with Coulomb's friction impulse, at most mu m |v_z|, against
  // its slide. Where that cannot stop the slide it slides on flat with what is left, its spin kept
  // (the twist of the landing's friction neglected); else rest (or the exit from it).
  const Vec3 v = vec_at(z, kVx);
  const double fall = std::fmax(0.0, -v[2]), slide = std::hypot(v[0], v[1]);
  if (slide > opt_.mu_s * fall && slide > kSlipNoise * std::sqrt(body_.g * size_)) {
    const double before = energy(z), keep = 1 - mu_k_ * fall / slide;
    const Mat3 r = rotation(quat_at(z, S::kQw));
    set_quat_at(z, kQw, axis_angle({0, 0, 1}, std::atan2(r[1][0], r[0][0])));
    set_vec_at(z, kVx, {keep * v[0], keep * v[1], 0});
    set_vec_at(z, kWx, {0, 0, z[kWz]});
    z[kWorkImpact] += energy(z) - before;
    return {sliding(z), false, int(Body3dEventKind::Impact)};
  }
  Tr tr = settle(t, z);
  if (!tr.stop && tr.kind == int(Body3dEventKind::Rest)) tr.kind = int(Body3dEventKind::Impact);
  return tr;
}

Tr BodyOnGround::transition(double t, const Mode& m, State& z, int event) const {
  Tr tr = mode_change(t, m, z, event);
  if (!tr.stop && tr.next.contact == BodyContact::Roll) {
    lower_onto_rim(tr.next, z);
    tr.next.lifting = rim_below_landing(tr.next, z);
  }
  if (!tr.stop && tr.next.contact != BodyContact::Flight) {
    // The new contact's constraints applied here, what they change booked with the impacts (near
    // flat a rim contact moving to the rim's lowest point projects the velocity: an impulse).
    const double before = energy(z);
    complete(tr.next, z);
    z[kWorkImpact] += energy(z) - before;
  }
  const bool impact_event =
      m.contact != BodyContact::Slide && ((event >= kEvTouch0 && event <= kEvTouch3) || event == kEvTouchdown);
  if (!impact_event) {
    // The count of impacts at an instant carries through the mode changes between them.
    tr.next.impact_t = m.impact_t;
    tr.next.rapid_impacts = m.rapid_impacts;
  }
  return tr;
}

Tr BodyOnGround::mode_change(double t, const Mode& m, State& z, int event) const {
  if (m.contact == BodyContact::Slide)
    return event == kBreakpoint ? Tr{m, false, int(Body3dEventKind::GroundBreak)} : slide_change(t, m, z, event);
  if (m.contact == BodyContact::Roll) return m.slips() ? rim_slip_change(t, m, z, event) : roll_change(t, m, z, event);
  if (m.slips()) return contact_slip_change(t, m, z, event);
  switch (event) {
    case kBreakpoint:
      if (m.contact == BodyContact::Rest && !rest_holds(t, m.yaw)) return leave_rest(t, z);
      return {m, false, int(Body3dEventKind::GroundBreak)};
    case kEvLiftOff:
    case kEvLoadA:
    case kEvLoadB:
      return after_load_zero(t, m, z, event);
    case kEvOverturn:
      return {m, true, int(Body3dEventKind::Overturn)};
    case kEvSlipA:
    case kEvSlipB:
      // A box's edge or corner slips, or a cylinder's rim point.
      if (body_.shape != BodyShape3d::Box)
        return rim_contact_holds_or_slips(t, m, z, int(Body3dEventKind::Slip), false);
      return stick_or_slip(t, m, z, int(Body3dEventKind::Slip), false);
    default:
      return impact(t, m, z, event);
  }
}

Tr BodyOnGround::impact(double t, const Mode& from, State& z, int event) const {
  const bool rapid = from.impact_t >= 0 && t - from.impact_t <= kInstant * std::fmax(1.0, std::fabs(t));
  const int rapid_impacts = rapid ? from.rapid_impacts + 1 : 0;
  // A cylinder's rim landing again within kRimAccumulation sqrt(size / g) of its last landing (an
  // accumulation of landings shrinking geometrically, the base within 1e-7 rad of flat at each):
  // the base lands flat, the accumulation's last swings (shorter together than that) skipped.
  if (body_.shape == BodyShape3d::Cylinder && from.impact_t >= 0 &&
      t - from.impact_t < kRimAccumulation * std::sqrt(size_ / body_.g))
    return landed_flat(t, z);
  // Impacts taking turns at one instant with the base flat (a box's opposite edges, each impact
  // driving the other down): the base lands flat, plastic on the whole base.
  if (rapid && body_.shape == BodyShape3d::Box) {
    const Mat3 r = rotation(quat_at(z, S::kQw));
    int flat = 0;
    for (int i = 0; i < 4; ++i) flat += z[kZ] + dot(r[2], corner(i)) <= kImpactTouch * size_;
    if (flat == 4) return landed_flat(t, z);
  }
  if (rapid_impacts > kMaxRapid) return {from, true, int(Body3dEventKind::NotModelled)};
  Tr tr = contact_after_impact(t, from, z, event);
  tr.next.impact_t = t;
  tr.next.rapid_impacts = rapid_impacts;
  return tr;
}

Tr BodyOnGround::contact_after_impact(double t, const Mode& from, State& z, int) const {
  if (opt_.impact == Body3dImpactLaw::Newton)
    return body_.shape == BodyShape3d::Box ? newton_impact(t, from, z) : newton_rim_impact(t, from, z);
  return housner_impact(t, from, z);
}

Tr BodyOnGround::housner_impact(double t, const Mode& from, State& z) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 x = vec_at(z, kX);
  const double e_before = energy(z);
  const double w_before = std::sqrt(dot(vec_at(z, kWx), vec_at(z, kWx)));
  Mode next;
  std::vector<int> fresh, others;
  if (body_.shape == BodyShape3d::Cylinder) {
    if (from.contact == BodyContact::Flight && r[2][2] >= 1 - 1e-12) return landed_flat(t, z);
    const Vec3 p = from.contact == BodyContact::Flight ? lowest_point(body_, r).body
                                                       : Vec3{-from.point_a[0], -from.point_a[1], from.point_a[2]};
    next = rim_mode(r, x, p);
  } else {
    for (int i = 0; i < 4; ++i) {
      if (z[kZ] + dot(r[2], corner(i)) > kImpactTouch * size_) continue;
      (holds(from, i) ? others : fresh).push_back(i);
    }
    if (fresh.size() >= 3 || fresh.empty()) return landed_flat(t, z);
    next = fresh.size() == 2 ? line_mode(r, x, corner(fresh[0]), corner(fresh[1]), fresh[0], fresh[1])
                             : point_mode(r, x, corner(fresh[0]), fresh[0]);
  }
  const State before = z;
  conserve_momentum_about(next, z);
  // An old contact that the new motion drives into the ground joins the new contact.
  const double v_tol = kImpactLeaving * w_before * size_;
  auto sinking = [&]() {
    for (int i : others)
      if (!holds(next, i) && (z[kVz] + cross(vec_at(z, kWx), r * corner(i))[2]) < v_tol) return i;
    return -1;
  };
  if (const int i = sinking(); i >= 0) {
    if (next.contact == BodyContact::Line) {
      // A line landing drives the old line back into the ground (a slipping body lands with its
      // sliding velocity): the old line's impact follows at the same instant, as in the planar
      // block; if that drives the new one down again, the base lands flat.
      if (from.contact != BodyContact::Line || from.half_length == 0) return settle(t, z = before);
      const Mode old = line_mode(r, x, from.point_a, from.point_b, from.corner_a, from.corner_b);
      conserve_momentum_about(old, z);
      for (int c : fresh)
        if ((z[kVz] + cross(vec_at(z, kWx), r * corner(c))[2]) < -v_tol) return settle(t, z = before);
      next = old;
    } else {
      next = line_mode(r, x, corner(fresh[0]), corner(i), fresh[0], i);
      z = before;
      conserve_momentum_about(next, z);
      if (sinking() >= 0) return settle(t, z = before);
    }
  }
  complete(next, z);
  z[kWorkImpact] += energy(z) - e_before;  // the loss, and the height the completion gives up
  return after_impact(t, from, next, z, w_before);
}

Tr BodyOnGround::after_impact(double t, const Mode& from, const Mode& next, State& z, double w_before) const {
  if (pulls_away(t, next, z)) {
    // Sticking would pull on the ground: the body flies if the contact point (at rest after the
    // impact) rises in flight, else the contact slips if a slip is consistent (a box); neither:
    // Painleve's paradox of a rigid contact with large friction. The run stops there.
    Mode flight{BodyContact::Flight};
    State d;
    rhs(t, flight, z, d);
    const double a_contact = point_acceleration(z, d, minus(next.pivot, vec_at(z, kX)))[2];
    if (a_contact >= 0) return {flight, false, int(Body3dEventKind::Impact)};
    const Tr slip = stick_or_slip(t, next, z, int(Body3dEventKind::Impact), false);
    return slip.stop || !slip.next.slips() ? Tr{from, true, int(Body3dEventKind::Painleve)} : slip;
  }
  // Impacts accumulate in finite time (a geometric series of swings shrinking by e each): once
  // the time they have left is below the accumulation horizon, the body is at rest. Each law ends
  // them as its planar reference does: Newton's also once the old edge leaves too slowly to rise
  // kUnresolvedRise of the size (below the rounding of the centroid's height: the 3-DOF block's
  // rule), Housner's by the horizon alone (Housner's block's, which resolves the swings below).
  if (from.contact == BodyContact::Line && next.contact == BodyContact::Line && w_before > 0) {
    const Vec3 w = vec_at(z, kWx);
    if (opt_.impact == Body3dImpactLaw::Newton && old_edge_rise_unresolved(from, next, z)) return impact_at_rest(t, z);
    const double e = std::sqrt(dot(w, w)) / w_before;
    State still = z;
    set_vec_at(still, kWx, {0, 0, 0});
    State d;
    rhs(t, next, still, d);
    const double sense = dot(w, next.axis) >= 0 ? 1.0 : -1.0;
    const double decel = -sense * dot(vec_at(d, kWx), next.axis);
    const double horizon = std::fmax(kAccumulationTime * std::sqrt(size_ / body_.g), 1e-12 * std::fabs(t) / (1 - e));
    if (e < 1 && decel > 0 && 2 * std::sqrt(dot(w, w)) / (decel * (1 - e)) < horizon) return impact_at_rest(t, z);
  }
  // The new contact, at rest after the impact, sticks if friction holds it, else slips.
  return stick_or_slip(t, next, z, int(Body3dEventKind::Impact));
}

Tr BodyOnGround::impact_at_rest(double t, State& z) const {
  // The impact that ends an accumulation is an impact (counted, as the planar blocks count it)
  // whose contact is the base at rest.
  Tr tr = settle(t, z);
  if (!tr.stop) tr.kind = int(Body3dEventKind::Impact);
  return tr;
}

bool BodyOnGround::old_edge_rise_unresolved(const Mode& from, const Mode& next, const State& z) const {
  if (from.corner_a < 0 || from.corner_b < 0) return false;  // a box's edge only
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 w = vec_at(z, kWx);
  int leaving = 0;
  for (const int c : {from.corner_a, from.corner_b}) {
    if (holds(next, c)) continue;  // the old edge's impact followed: it stays
    if (z[kVz] + cross(w, r * corner(c))[2] >= v_unresolved_) return false;
    ++leaving;
  }
  return leaving > 0;
}

BodyOnGround::State initial_state(const Body3d& b, const Body3dStart& s) {
  const Vec3 u{std::cos(s.tilt_azimuth), std::sin(s.tilt_azimuth), 0};
  const Quat q = axis_angle({-u[1], u[0], 0}, s.tilt) * axis_angle({0, 0, 1}, s.yaw);
  BodyOnGround::State z{};
  z[S::kZ] = lowest_point(b, rotation(q)).depth + s.lift;
  z[S::kQw] = q.w;
  z[S::kQx] = q.x;
  z[S::kQy] = q.y;
  z[S::kQz] = q.z;
  set_vec_at(z, S::kVx, s.velocity);
  set_vec_at(z, S::kWx, s.angular_velocity);
  return z;
}

}  // namespace blockdyn
