// SPDX-License-Identifier: Apache-2.0
// The rigid3d body's mode changes (body_on_ground.hpp): which contact a state has, the exit from
// rest, a contact point's load reaching zero, and impacts by the angular momentum about the new
// contact (Housner's law in 3D), with the accumulation of impacts ended at rest.
#include <cmath>
#include <stdexcept>
#include <vector>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/model/rigid3d/body_on_ground.hpp"
#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/model/rigid3d/body_state.hpp"

namespace blockdyn {

namespace {

using S = BodyOnGround;
using Tr = Transition<BodyOnGroundMode>;

Vec3 unit(const Vec3& v) { return scaled(v, 1.0 / std::sqrt(dot(v, v))); }
Vec3 horizontal(Vec3 v) {
  v[2] = 0;
  return v;
}
Tr stop(const BodyOnGroundMode& m, Body3dEventKind k) { return {m, true, int(k)}; }

// Base points this close to the ground (in body sizes) touch it.
constexpr double kTouchTolerance = 1e-11;

}  // namespace

BodyOnGroundMode BodyOnGround::line_mode(const Mat3& r, const Vec3& x, const Vec3& pa, const Vec3& pb, int ca,
                                         int cb) const {
  Mode m;
  m.contact = BodyContact::Line;
  m.corner_a = ca;
  m.corner_b = cb;
  m.point_a = pa;
  m.point_b = pb;
  // The contact points where they are (on the ground to within the touch tolerance): moving
  // them onto it would move the body, and its potential energy, at the event.
  const Vec3 wa = plus(x, r * pa), wb = plus(x, r * pb);
  m.pivot = scaled(plus(wa, wb), 0.5);
  m.axis = unit(minus(wa, wb));
  m.half_length = 0.5 * std::sqrt(dot(minus(wa, wb), minus(wa, wb)));
  return m;
}

BodyOnGroundMode BodyOnGround::point_mode(const Mat3& r, const Vec3& x, const Vec3& p, int c) const {
  Mode m;
  m.contact = BodyContact::Point;
  m.corner_a = c;
  m.point_a = m.point_b = p;
  m.pivot = plus(x, r * p);
  return m;
}

BodyOnGroundMode BodyOnGround::rim_mode(const Mat3& r, const Vec3& x, const Vec3& p) const {
  // The rim point's tangent (e3 x p in the body frame) is the line it rocks about.
  Mode m;
  m.contact = BodyContact::Line;
  m.point_a = m.point_b = p;
  m.pivot = plus(x, r * p);
  m.axis = unit(horizontal(r * Vec3{-p[1], p[0], 0}));
  return m;
}

bool BodyOnGround::pulls_away(double t, const Mode& m, const State& z) const {
  std::array<double, kNumEvents> g;
  events(t, m, z, g);
  return g[kEvLiftOff] < 0;
}

Vec3 BodyOnGround::point_acceleration(const State& z, const State& dz, const Vec3& arm) const {
  const Vec3 w = vec_at(z, kWx);
  return plus(vec_at(dz, kVx), plus(cross(vec_at(dz, kWx), arm), cross(w, cross(w, arm))));
}

Vec3 BodyOnGround::up_rate(const Mat3& r, const State& z) const {
  const Vec3 up{r[2][0], r[2][1], r[2][2]};
  return scaled(cross(transposed_times(r, vec_at(z, kWx)), up), -1.0);
}

double BodyOnGround::instant_slip() const { return kInstantSlip * std::sqrt(size_ / body_.g) * mu_k_ * body_.g; }

BodyOnGroundMode BodyOnGround::sliding(const State& z) const {
  const Vec3 u = slip_of(z);
  return slide_mode(z, scaled(u, 1.0 / std::sqrt(dot(u, u))));
}

bool BodyOnGround::sinks_in_flight(double t, const Mode& m, const State& z) const {
  State dz{};
  rhs(t, Mode{BodyContact::Flight}, z, dz);
  const Mat3 r = rotation(quat_at(z, S::kQw));
  for (int i : {m.corner_a, m.corner_b})
    if (i >= 0 && point_acceleration(z, dz, r * corner(i))[2] < -kLoadTie * body_.g) return true;
  return false;
}

BodyOnGroundMode BodyOnGround::mode_of(double t, const State& z, bool slipping) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 x = vec_at(z, kX);
  const double tol = kTouchTolerance * size_, lowest = z[kZ] - lowest_point(body_, r).depth;
  if (lowest < -tol)
    throw std::invalid_argument("the body is " + number_text(-lowest) + " m below the ground (initial state)");
  Mode rest;
  rest.yaw = std::atan2(r[1][0], r[0][0]);
  if (lowest > tol) {
    rest.contact = BodyContact::Flight;
    return rest;
  }
  if (body_.shape == BodyShape3d::Cylinder) {
    if (r[2][2] >= 1 - 1e-15) {
      // Standing flat and moving along the ground: sliding.
      const Vec3 u = slip_of(z);
      return dot(u, u) > 0 ? sliding(z) : rest;
    }
    const Mode held = rim_or_roll(z, lowest_point(body_, r).body);
    // Its rim point moving along the ground: it slips from the start (unless friction would stop
    // it at once, as a box's contact below), else it slips if friction cannot hold it.
    if (const auto moving = slipping ? moving_rim(t, z) : std::nullopt) return *moving;
    const Tr tr = rim_contact_holds_or_slips(t, held, z, int(Body3dEventKind::Mode), true);
    return tr.stop ? held : tr.next;
  }
  std::vector<int> touching;
  for (int i = 0; i < 4; ++i)
    if (z[kZ] + dot(r[2], corner(i)) <= tol) touching.push_back(i);
  if (touching.size() >= 3) {
    // Standing flat and moving along the ground: sliding.
    const Vec3 u = slip_of(z);
    if (dot(u, u) > 0) return sliding(z);
    return rest;
  }
  const Mode contact = touching.size() == 2
                           ? line_mode(r, x, corner(touching[0]), corner(touching[1]), touching[0], touching[1])
                           : point_mode(r, x, corner(touching[0]), touching[0]);
  const Tr tr = contact_motion(t, contact, z, slipping);
  return tr.stop ? contact : tr.next;
}

Tr BodyOnGround::contact_motion(double t, const Mode& contact, const State& z, bool slipping) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 x = vec_at(z, kX);
  const bool line = contact.contact == BodyContact::Line;
  // Its points moving along the ground: they slip from the start, on the edge or on either of its
  // corners (the other rising), the first consistent; unless friction would stop them at once (in
  // less than kInstantSlip sqrt(size / g) at mu_k g: the limit of a sticking contact, whose slip is
  // too stiff to follow), where the start takes the velocities the contact allows.
  const Mode candidates[3] = {contact, point_mode(r, x, contact.point_a, contact.corner_a),
                              point_mode(r, x, contact.point_b, contact.corner_b)};
  for (int i = 0; i < (!slipping ? 0 : line ? 3 : 1); ++i) {
    const Mode moving = moving_contact(candidates[i], z);
    if (!moving.slips() || slip_stops_at_once(moving, z)) break;
    State on = z;
    complete(moving, on);
    const int lifted = i == 0 ? -1 : i == 1 ? contact.corner_b : contact.corner_a;
    if (consistent_contact(t, moving, on, lifted)) return {moving, false, int(Body3dEventKind::Mode)};
  }
  // Else (docs/3d.md) it slips if friction cannot hold it.
  State still = z;
  complete(contact, still);
  return stick_or_slip(t, contact, still, int(Body3dEventKind::Mode));
}

bool BodyOnGround::slip_stops_at_once(const Mode& m, const State& z) const {
  const ContactSlip c = contact_slip_of(m, z);
  const double fastest =
      std::fmax(std::sqrt(dot(c.slip[0], c.slip[0])), c.points.n > 1 ? std::sqrt(dot(c.slip[1], c.slip[1])) : 0.0);
  return fastest < instant_slip();
}

std::string BodyOnGround::stop_reason(const Mode& from, int event, Body3dEventKind kind) {
  if (kind == Body3dEventKind::Invalid)
    return "the ground accelerates downwards faster than g: the body resting on it would leave it";
  if (kind == Body3dEventKind::Painleve)
    return from.slips() ? "Painleve: no normal load is consistent with the slipping contact (a rigid contact with "
                          "this much friction has no solution there)"
                        : "Painleve: no state of the contact is consistent at the acceleration level (sticking "
                          "needs more than mu_s or pulls on the ground, slipping or lifting a point makes a load "
                          "negative or sinks it)";
  if (kind != Body3dEventKind::NotModelled) return "";
  if (event == kEvLoadA && from.contact == BodyContact::Line && from.half_length == 0)
    return "a cylinder tipped from its base exactly flat onto a rim point that needs a moment would roll from flat, "
           "where its rolling contact is not defined (not modelled)";
  if (event < 0)
    return "the contact changes mode repeatedly at one instant (an edge and a corner, or a rim point, taking turns: "
           "it would need the contact problem of both at once, not modelled yet)";
  return "impacts accumulate at one instant (a sequence of corner impacts that does not end)";
}

Tr BodyOnGround::leave_rest(double t, const State& z) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  Mode m;  // rest
  m.yaw = std::atan2(r[1][0], r[0][0]);
  const RestFailure f = rest_search_.failure(t, m.yaw);
  if (f.way == RestExitWay::Lifts) return stop(m, Body3dEventKind::Invalid);
  if (f.way == RestExitWay::Slides) return start_slide(t, z, f.towards);
  if (f.way == RestExitWay::None) return {m, false, int(Body3dEventKind::GroundBreak)};
  // The ground accelerating towards u tips the body towards -u.
  const Vec3 x = vec_at(z, kX), ab = transposed_times(r, f.towards);  // body frame
  const double c = body_.half_height(), ah = std::hypot(ab[0], ab[1]);
  if (body_.shape == BodyShape3d::Cylinder)
    return {rim_mode(r, x, {-body_.radius * ab[0] / ah, -body_.radius * ab[1] / ah, -c}), false,
            int(Body3dEventKind::Mode)};
  const int bx = f.x_side > 0 ? 0 : 1, by = f.y_side > 0 ? 0 : 2;
  const int mode = int(Body3dEventKind::Mode);
  const Mode pivot = f.x_side != 0 && f.y_side != 0 ? point_mode(r, x, corner(bx | by), bx | by)
                     : f.x_side != 0                ? line_mode(r, x, corner(bx), corner(bx | 2), bx, bx | 2)
                                                    : line_mode(r, x, corner(by), corner(by | 1), by, by | 1);
  const Tr tr = stick_or_slip(t, pivot, z, mode);
  // A pivot that cannot hold and whose slip would press the other corners into the ground: the
  // base slides flat instead (the slide's own events tip it where its loads say so).
  if (!tr.stop && tr.next.slips() && !other_corners_rise(t, tr.next, z, kFlatTouch))
    return start_slide(t, z, f.towards);
  return tr;
}

Tr BodyOnGround::settle(double t, State& z) const {
  // At rest on the base: flat, at the yaw it has, no velocity; the kinetic energy left is lost.
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 om = transposed_times(r, vec_at(z, kWx)), v = vec_at(z, kVx);
  z[kWorkImpact] -= 0.5 * body_.mass * dot(v, v) +
                    0.5 * (inertia_[0] * om[0] * om[0] + inertia_[1] * om[1] * om[1] + inertia_[2] * om[2] * om[2]);
  const double yaw = std::atan2(r[1][0], r[0][0]);
  const Quat q = axis_angle({0, 0, 1}, yaw);
  set_quat_at(z, kQw, q);
  // The centroid stays where it is: on the ground to within the rounding the contacts gathered
  // (moving it would change the potential energy at the event).
  set_vec_at(z, kVx, {0, 0, 0});
  set_vec_at(z, kWx, {0, 0, 0});
  Mode rest;
  rest.yaw = yaw;
  if (rest_holds(t, yaw)) return {rest, false, int(Body3dEventKind::Rest)};
  Tr tr = leave_rest(t, z);
  if (!tr.stop) tr.kind = int(Body3dEventKind::Rest);
  return tr;
}

Tr BodyOnGround::after_load_zero(double t, const Mode& m, State& z, int event) const {
  if (event == kEvLiftOff) {
    // The load reaches zero while friction still holds the contact (the slip check is off near
    // zero load): where the corners would sink without friction, the contact slips instead.
    if (body_.shape == BodyShape3d::Box && !m.slips() && sinks_in_flight(t, m, z)) {
      const Tr tr = stick_or_slip(t, m, z, int(Body3dEventKind::Mode), false);
      if (!tr.stop) return tr;
    }
    return {Mode{BodyContact::Flight}, false, int(Body3dEventKind::LiftOff)};
  }
  // A rim point that would need a moment: the contact starts rolling along the rim; not from a
  // base exactly flat, whose lowest point is not defined (the rolling's equations divide by the
  // tilt's sine: the state would turn NaN).
  if (m.half_length == 0) {
    const Mat3 r = rotation(quat_at(z, S::kQw));
    if (!(std::hypot(r[2][0], r[2][1]) > 0)) return stop(m, Body3dEventKind::NotModelled);
    return {roll_mode(z, false), false, int(Body3dEventKind::Mode)};
  }
  // One end of the line lifts: the body pivots on the other, unless that one pulls away too.
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 x = vec_at(z, kX);
  const bool a_lifts = event == kEvLoadA;
  Mode next = a_lifts ? point_mode(r, x, m.point_b, m.corner_b) : point_mode(r, x, m.point_a, m.corner_a);
  next.released = a_lifts ? m.corner_a : m.corner_b;
  next.released_t = t;
  set_contact_velocity(next, z);
  if (pulls_away(t, next, z)) return {Mode{BodyContact::Flight}, false, int(Body3dEventKind::LiftOff)};
  return stick_or_slip(t, next, z, int(Body3dEventKind::Mode));
}

}  // namespace blockdyn
