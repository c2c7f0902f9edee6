// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid3d/body_on_ground.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/model/rigid3d/base_slide.hpp"
#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/model/rigid3d/body_state.hpp"

namespace blockdyn {

namespace {

using S = BodyOnGround;

// A rim point carries no moment: one above this (in m g size) rolls the contact along the rim.
constexpr double kRimMomentTolerance = 1e-8;
// A contact point carrying less than this share of the load (a line's total, or the weight) is
// not checked for sliding: it is about to lift (its load-zero event follows).
constexpr double kUncheckedLoad = 1e-2;
// A corner that has just lifted off a line leaves the ground at third order (its velocity and
// acceleration are zero there): for a moment (kReleasedWindow of sqrt(size / g)) its touch is
// looked for below this height (in body sizes), so that rounding at the instant it lifts is not
// taken for an impact.
constexpr double kReleasedAllowance = 1e-12, kReleasedWindow = 1e-4;

// G - pivot in the body frame: from the corner, or from the line's midpoint (about which its
// moment is split between its ends).
Vec3 pivot_to_centroid(const BodyOnGroundMode& m) { return scaled(plus(m.point_a, m.point_b), -0.5); }

}  // namespace

const char* to_string(Body3dEventKind k) {
  switch (k) {
    case Body3dEventKind::Mode:
      return "mode";
    case Body3dEventKind::Impact:
      return "impact";
    case Body3dEventKind::LiftOff:
      return "lift_off";
    case Body3dEventKind::Rest:
      return "rest";
    case Body3dEventKind::Overturn:
      return "overturn";
    case Body3dEventKind::NotModelled:
      return "not_modelled";
    case Body3dEventKind::GroundBreak:
      return "ground_break";
    case Body3dEventKind::Invalid:
      return "invalid";
    case Body3dEventKind::Painleve:
      return "painleve";
    case Body3dEventKind::Stick:
      return "stick";
    case Body3dEventKind::SlipTurn:
      return "slip_turn";
    case Body3dEventKind::Slip:
      return "slip";
  }
  return "?";
}

BodyOnGround::BodyOnGround(const Body3d& body, const GroundMotion3d& ground, const BodyOnGroundOptions& opt)
    : body_(body), ground_(ground), opt_(opt), inertia_(body.inertia()) {
  validate(body_);
  validate(ground_);
  if (!(opt_.mu_s >= 0 && std::isfinite(opt_.mu_s)))
    throw std::invalid_argument("mu-s = " + number_text(opt_.mu_s) + " is out of range: finite and >= 0");
  const double len = body_.shape == BodyShape3d::Box ? std::fmax(body_.width, body_.depth) : 2 * body_.radius;
  size_ = std::fmax(len, body_.height);
  step_ = 0.05 * std::sqrt(size_ / body_.g);
  window_ = kReleasedWindow * std::sqrt(size_ / body_.g);
  v_unresolved_ = std::sqrt(2 * body_.g * kUnresolvedRise * size_);
  const double v = std::sqrt(body_.g * size_), w = std::sqrt(body_.g / size_), e = body_.mass * body_.g * size_;
  scale_ = {size_, size_, size_, 1, 1, 1, 1, v, v, v, w, w, w, e, e, e};
  mu_k_ = opt_.mu_k < 0 ? opt_.mu_s : opt_.mu_k;
  if (!(mu_k_ >= 0 && std::isfinite(mu_k_)))
    throw std::invalid_argument("mu-k = " + number_text(opt_.mu_k) + " is out of range: finite and >= 0");
  reach_ = body_.shape == BodyShape3d::Box ? base_reach(body_.width, body_.depth) : body_.radius;
  forced_ = !ground_.is_zero();
  azimuth_cos_ = std::cos(ground_.azimuth * (M_PI / 180));
  azimuth_sin_ = std::sin(ground_.azimuth * (M_PI / 180));
  rest_search_ = BodyRestSearch(body_, opt_.mu_s, ground_, opt_.rest_yaw);
}

Vec3 BodyOnGround::specific_force(double t) const {
  if (!forced_) return {0, 0, -body_.g};
  const std::array<double, 3> a = ground_.at(t, azimuth_cos_, azimuth_sin_);
  return {-body_.g * a[0], -body_.g * a[1], -body_.g * (1 + a[2])};
}

Vec3 BodyOnGround::corner(int i) const {
  return {(i & 1 ? 0.5 : -0.5) * body_.width, (i & 2 ? 0.5 : -0.5) * body_.depth, -body_.half_height()};
}

void BodyOnGround::set_kinematic_rates(double t, const State& z, State& dz) const {
  const Vec3 w = vec_at(z, kWx), v = vec_at(z, kVx), f = specific_force(t);
  const Quat dq = Quat{0, w[0], w[1], w[2]} * quat_at(z, S::kQw);
  set_vec_at(dz, kX, v);
  dz[kQw] = 0.5 * dq.w;
  dz[kQx] = 0.5 * dq.x;
  dz[kQy] = 0.5 * dq.y;
  dz[kQz] = 0.5 * dq.z;
  // The ground's inertial force m (f + g Z) does work on the centroid; a sticking or rolling
  // contact does none.
  dz[kWorkGround] = body_.mass * (f[0] * v[0] + f[1] * v[1] + (f[2] + body_.g) * v[2]);
}

void BodyOnGround::rhs(double t, const Mode& m, const State& z, State& dz) const {
  dz.fill(0.0);
  if (m.contact == BodyContact::Rest) return;
  if (m.contact == BodyContact::Slide) return slide_rhs(t, m, z, dz);
  if (m.contact == BodyContact::Roll) return m.slips() ? rim_slip_rhs(t, m, z, dz) : roll_rhs(t, z, dz);
  if (m.slips()) return contact_slip_rhs(t, m, z, dz);
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 w = vec_at(z, kWx), f = specific_force(t);
  set_kinematic_rates(t, z, dz);
  if (m.contact == BodyContact::Flight) {
    set_vec_at(dz, kVx, f);
    set_vec_at(dz, kWx, free_angular_acceleration(inertia_, r, w));
    return;
  }
  const Vec3 s = pivot_to_centroid(m);
  const PivotMotion pm = m.contact == BodyContact::Point ? point_pivot_motion(inertia_, body_.mass, r, s, w, f)
                                                         : line_pivot_motion(inertia_, body_.mass, r, s, m.axis, w, f);
  set_vec_at(dz, kVx, pm.accel);
  set_vec_at(dz, kWx, pm.domega);
}

void BodyOnGround::events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const {
  g.fill(1.0);
  if (m.contact == BodyContact::Rest) return;
  if (m.contact == BodyContact::Slide) return slide_events(t, m, z, g);
  if (m.contact == BodyContact::Roll) return m.slips() ? rim_slip_events(t, m, z, g) : roll_events(t, m, z, g);
  if (m.slips()) return contact_slip_events(t, m, z, g);
  const Mat3 r = rotation(quat_at(z, S::kQw));
  if (m.contact == BodyContact::Flight) {
    g[kEvTouchdown] = z[kZ] - lowest_point(body_, r).depth;
    // Turned over in flight (the base facing up): its other faces' contacts are not modelled, the
    // run ends as an overturn.
    g[kEvOverturn] = r[2][2];
    return;
  }
  const Vec3 w = vec_at(z, kWx), f = specific_force(t), s = pivot_to_centroid(m);
  const double weight = body_.mass * body_.g;
  const PivotMotion pm = m.contact == BodyContact::Point ? point_pivot_motion(inertia_, body_.mass, r, s, w, f)
                                                         : line_pivot_motion(inertia_, body_.mass, r, s, m.axis, w, f);
  g[kEvLiftOff] = pm.force[2] / weight;
  // A point about to lift (load below kUncheckedLoad of the reference) is not checked for sliding.
  auto slip = [&](const Vec3& load, double reference) {
    if (load[2] < kUncheckedLoad * reference) return 1.0;
    return (opt_.mu_s * load[2] - std::hypot(load[0], load[1])) / weight;
  };
  if (m.contact == BodyContact::Line && m.half_length > 0) {
    const LineLoads ll = split_line_reaction(pm.force, pm.moment, m.axis, m.half_length, opt_.mu_s);
    g[kEvLoadA] = ll.plus[2] / weight;
    g[kEvLoadB] = ll.minus[2] / weight;
    g[kEvSlipA] = slip(ll.plus, pm.force[2]);
    g[kEvSlipB] = slip(ll.minus, pm.force[2]);
  } else {
    // A rim point carries no moment: a motion that needs one rolls the contact along the rim.
    if (m.contact == BodyContact::Line)
      g[kEvLoadA] = kRimMomentTolerance - std::sqrt(dot(pm.moment, pm.moment)) / (weight * size_);
    g[kEvSlipA] = slip(pm.force, weight);
  }
  const Vec3& up = r[2];
  if (body_.shape == BodyShape3d::Box) {
    for (int i = 0; i < 4; ++i)
      if (i != m.corner_a && i != m.corner_b) g[kEvTouch0 + i] = corner_height(t, m, up, i);
  } else {
    g[kEvTouch0] = dot(up, {-2 * m.point_a[0], -2 * m.point_a[1], 0});
  }
  g[kEvOverturn] = up[2];
}

double BodyOnGround::corner_height(double t, const Mode& m, const Vec3& up, int i) const {
  // Heights above the contact point (on the ground): no cancellation against the centroid's
  // height, so swings far below its rounding stay resolved (the tail of an accumulation).
  return dot(up, minus(corner(i), m.point_a)) +
         (i == m.released && t - m.released_t < window_ ? kReleasedAllowance * size_ : 0.0);
}

double BodyOnGround::event_value(double t, const Mode& m, const State& z, int index) const {
  // A box rocking on an edge or pivoting on a corner: its other corners' heights and the
  // overturn alone, without the reactions (the impacts' searches); else all of them.
  const bool pivot = m.contact == BodyContact::Line || m.contact == BodyContact::Point;
  const bool cheap = index == kEvOverturn || (index >= kEvTouch0 && index <= kEvTouch3);
  if (body_.shape == BodyShape3d::Box && pivot && !m.slips() && cheap) {
    const Vec3 up = rotation(quat_at(z, S::kQw))[2];
    if (index == kEvOverturn) return up[2];
    const int i = index - kEvTouch0;
    return i == m.corner_a || i == m.corner_b ? 1.0 : corner_height(t, m, up, i);
  }
  std::array<double, kNumEvents> g;
  events(t, m, z, g);
  return g[std::size_t(index)];
}

void BodyOnGround::complete(const Mode& m, State& z) const {
  if (m.contact == BodyContact::Roll) return m.slips() ? rim_slip_complete(m, z) : roll_complete(z);
  if (m.slips()) return contact_slip_complete(m, z);
  Quat q = quat_at(z, S::kQw);
  if (m.contact == BodyContact::Slide) q.x = q.y = 0;  // flat: turned about the vertical only
  q = normalized(q);
  set_quat_at(z, kQw, q);
  if (m.contact == BodyContact::Slide) {
    z[kVz] = z[kWx] = z[kWy] = 0;
    return;
  }
  if (m.contact != BodyContact::Line && m.contact != BodyContact::Point) return;
  // The contact point stays where it touched: the centroid and its velocity follow the rotation.
  if (m.contact == BodyContact::Line) set_vec_at(z, kWx, scaled(m.axis, dot(m.axis, vec_at(z, kWx))));
  set_contact_velocity(m, z);
}

void BodyOnGround::set_contact_velocity(const Mode& m, State& z) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 pa = m.contact == BodyContact::Line ? plus(m.pivot, scaled(m.axis, m.half_length)) : m.pivot;
  const Vec3 arm = scaled(r * m.point_a, -1.0);
  set_vec_at(z, kX, plus(pa, arm));
  set_vec_at(z, kVx, cross(vec_at(z, kWx), arm));
}

double BodyOnGround::next_breakpoint(double t, const Mode& m) const {
  if (!forced_) return INFINITY;
  if (m.contact == BodyContact::Rest) return rest_search_.checkpoint(t, m.yaw);
  return ground_.next_break(t);
}

bool BodyOnGround::rest_holds(double t, double yaw) const {
  // The search's own conditions: where it says rest fails, it does.
  return !forced_ || rest_search_.failure(t, yaw).way == RestExitWay::None;
}

double BodyOnGround::energy(const State& z) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 om = transposed_times(r, vec_at(z, kWx)), v = vec_at(z, kVx);
  return 0.5 * body_.mass * dot(v, v) +
         0.5 * (inertia_[0] * om[0] * om[0] + inertia_[1] * om[1] * om[1] + inertia_[2] * om[2] * om[2]) +
         body_.mass * body_.g * z[kZ];
}

double BodyOnGround::tilt(const State& z) const {
  return std::acos(std::fmax(-1.0, std::fmin(1.0, rotation(quat_at(z, S::kQw))[2][2])));
}

std::array<Vec3, 2> BodyOnGround::contact_forces(double t, const Mode& m, const State& z) const {
  const Vec3 f = specific_force(t);
  if (m.contact == BodyContact::Flight) return {};
  if (m.contact == BodyContact::Rest) return {scaled(f, -body_.mass), Vec3{0, 0, 0}};
  if (m.contact == BodyContact::Slide && body_.shape == BodyShape3d::Cylinder) {
    const DiscSlide s = disc_slide_state(t, m, z);
    return {Vec3{s.friction[0], s.friction[1], s.load}, Vec3{}};
  }
  if (m.contact == BodyContact::Slide) {
    const SlideState s = slide_state(t, m, z);
    Vec3 total{};
    for (int i = 0; i < 4; ++i)
      total = plus(total, {s.motion.friction[i][0], s.motion.friction[i][1], s.motion.load[i]});
    return {total, Vec3{}};
  }
  if (m.contact == BodyContact::Roll) return {m.slips() ? rim_slipping(t, m, z).force : rolling(t, z).force, Vec3{}};
  if (m.slips()) {
    const SlipContactMotion sm = contact_slip_motion(t, m, z);
    return {sm.force[0], m.contact == BodyContact::Line ? sm.force[1] : Vec3{}};
  }
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 s = pivot_to_centroid(m), w = vec_at(z, kWx);
  if (m.contact == BodyContact::Point) return {point_pivot_motion(inertia_, body_.mass, r, s, w, f).force, Vec3{}};
  const PivotMotion pm = line_pivot_motion(inertia_, body_.mass, r, s, m.axis, w, f);
  if (m.half_length == 0) return {pm.force, Vec3{}};
  const LineLoads ll = split_line_reaction(pm.force, pm.moment, m.axis, m.half_length, opt_.mu_s);
  return {ll.plus, ll.minus};
}

Vec3 BodyOnGround::contact_point(const Mode& m, const State& z) const {
  if (m.contact == BodyContact::Roll) {
    // The rim's lowest point; with the base flat, the side it touched last.
    const Mat3 r = rotation(quat_at(z, S::kQw));
    return plus(vec_at(z, kX), r * rim_contact_point(body_.radius, body_.half_height(), r, m.point_a));
  }
  if (m.contact != BodyContact::Line && m.contact != BodyContact::Point) return {NAN, NAN, NAN};
  if (!m.slips()) return m.pivot;
  const Vec3 mid = m.contact == BodyContact::Line ? scaled(plus(m.point_a, m.point_b), 0.5) : m.point_a;
  return plus(vec_at(z, kX), rotation(quat_at(z, S::kQw)) * mid);
}

}  // namespace blockdyn
