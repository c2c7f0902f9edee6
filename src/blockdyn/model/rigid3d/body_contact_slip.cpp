// SPDX-License-Identifier: Apache-2.0
// A box's edge or corner with points slipping on the ground (body_on_ground.hpp, contact_slip.hpp):
// the full motion of the body (six degrees of freedom) with its contact points held on the ground,
// each slipping point resisted by Coulomb friction against its own slip, a sticking one (the other
// end of an edge) held in place. Each slipping point's slip is followed against its own reference
// direction (slip_reference.hpp); where it ends, the point sticks if friction holds it (mu_s),
// else slips on the other way; a sticking point whose friction falls short starts slipping the way
// the motion takes it.
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

// A slip below this (m/s) has no direction of its own.
constexpr double kPointNoSlip = 1e-300;
// Starting directions of points that start slipping together are found in turn, the others
// held, to this agreement, at most kStartIterations times (each by slip_start_root).
constexpr double kStartAgreement = 1e-14;
constexpr int kStartIterations = 30;
// Both ends of an edge starting to slip: Newton's method on both angles from kJointStarts starts
// (the best of a kJointGrid x kJointGrid grid), kNewtonSteps steps with difference kNewtonDelta.
constexpr int kJointStarts = 6, kJointGrid = 24, kNewtonSteps = 40;
constexpr double kNewtonDelta = 1e-7;
// Friction margins (in m g) this close to zero at a point's slip onset count as reached: both
// ends of an edge loaded alike (a planar motion) start slipping together.
constexpr double kMarginTie = 1e-9;
// A point carrying less than this share of the weight is not checked for sticking (as the
// sticking contacts' rule: it is about to lift).
constexpr double kUncheckedShare = 1e-2;

Vec3 ground_part(Vec3 v) {
  v[2] = 0;
  return v;
}
double length_of(const Vec3& v) { return std::sqrt(dot(v, v)); }
Vec3 unit_or_zero(const Vec3& v) {
  const double n = length_of(v);
  return n > kPointNoSlip ? scaled(v, 1.0 / n) : Vec3{0, 0, 0};
}
unsigned bit(int i) { return 1u << unsigned(i); }
const Vec3& reference_of(const BodyOnGroundMode& m, int i) { return i == 0 ? m.slip_ref : m.slip_ref_b; }
Vec3& reference_of(BodyOnGroundMode& m, int i) { return i == 0 ? m.slip_ref : m.slip_ref_b; }

}  // namespace

BodyOnGround::ContactSlip BodyOnGround::contact_slip_of(const Mode& m, const State& z) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 v = vec_at(z, kVx), w = vec_at(z, kWx);
  const double noise = kSlipNoise * std::sqrt(body_.g * size_);
  ContactSlip c;
  ContactPoints& p = c.points;
  p.n = m.contact == BodyContact::Line ? 2 : 1;
  p.arm[0] = r * m.point_a;
  p.arm[1] = r * m.point_b;
  for (int i = 0; i < p.n; ++i) {
    c.slip[i] = ground_part(plus(v, cross(w, p.arm[i])));
    p.sticks[i] = !(m.slipping & bit(i));
    if (p.sticks[i]) continue;
    p.dir[i] = friction_direction(c.slip[i], reference_of(m, i), noise);
  }
  return c;
}

SlipContactMotion BodyOnGround::contact_slip_motion(double t, const ContactSlip& c, const State& z) const {
  return slipping_contact_motion(inertia_, body_.mass, rotation(quat_at(z, S::kQw)), c.points, vec_at(z, kWx),
                                 specific_force(t), mu_k_);
}

std::array<Vec3, 2> BodyOnGround::contact_slip_rates(double t, const ContactSlip& c, const State& z) const {
  const SlipContactMotion sm = contact_slip_motion(t, c, z);
  const Vec3 w = vec_at(z, kWx);
  std::array<Vec3, 2> a{};
  for (int i = 0; i < c.points.n; ++i) {
    const Vec3& arm = c.points.arm[i];
    a[i] = ground_part(plus(sm.accel, plus(cross(sm.domega, arm), cross(w, cross(w, arm)))));
  }
  return a;
}

void BodyOnGround::contact_slip_rhs(double t, const Mode& m, const State& z, State& dz) const {
  const ContactSlip c = contact_slip_of(m, z);
  const SlipContactMotion sm = contact_slip_motion(t, c, z);
  set_kinematic_rates(t, z, dz);
  set_vec_at(dz, kVx, sm.accel);
  set_vec_at(dz, kWx, sm.domega);
  double power = 0;
  for (int i = 0; i < c.points.n; ++i)
    if (!c.points.sticks[i]) power += sm.force[i][0] * c.slip[i][0] + sm.force[i][1] * c.slip[i][1];
  dz[kWorkFriction] = power;
}

std::array<double, 2> BodyOnGround::stick_margins(double t, const Mode& m, const State& z) const {
  std::array<double, kNumEvents> g;
  events(t, m, z, g);
  if (!m.slips()) return {g[kEvSlipA], m.contact == BodyContact::Line ? g[kEvSlipB] : 1.0};
  std::array<double, 2> margin{1.0, 1.0};
  for (int i = 0; i < 2; ++i)
    if (!(m.slipping & bit(i)) && (i == 0 || m.contact == BodyContact::Line)) margin[i] = g[kEvSlipA + i];
  return margin;
}

void BodyOnGround::contact_slip_events(double t, const Mode& m, const State& z,
                                       std::array<double, kNumEvents>& g) const {
  const ContactSlip c = contact_slip_of(m, z);
  const SlipContactMotion sm = contact_slip_motion(t, c, z);
  const double weight = body_.mass * body_.g, vs = std::sqrt(body_.g * size_);
  const bool line = m.contact == BodyContact::Line;
  g[kEvLiftOff] = (sm.force[0][2] + (line ? sm.force[1][2] : 0.0)) / weight;
  if (line) {
    g[kEvLoadA] = sm.force[0][2] / weight;
    g[kEvLoadB] = sm.force[1][2] / weight;
  }
  for (int i = 0; i < c.points.n; ++i) {
    const Vec3& f = sm.force[i];
    if (c.points.sticks[i]) {
      g[kEvSlipA + i] = f[2] < kUncheckedShare * weight ? 1.0 : (opt_.mu_s * f[2] - std::hypot(f[0], f[1])) / weight;
    } else {
      g[kEvSlipA + i] = along(c.slip[i], reference_of(m, i), vs);
      g[kEvTurnA + i] = turn_near_stick(c.slip[i], reference_of(m, i), vs);
    }
  }
  g[kEvPainleve] = sm.consistency;
  const Vec3 up = rotation(quat_at(z, S::kQw))[2];
  for (int i = 0; i < 4; ++i)
    if (i != m.corner_a && i != m.corner_b)
      g[kEvTouch0 + i] =
          dot(up, minus(corner(i), m.point_a)) + (i == m.released && t - m.released_t < window_ ? 1e-12 * size_ : 0.0);
  g[kEvOverturn] = up[2];
}

void BodyOnGround::contact_slip_complete(const Mode& m, State& z) const {
  // On the ground: an edge horizontal (turned back by its drift, and the angular velocity that
  // would tilt it removed), a sticking point where it stuck, a slipping one at height zero with
  // no vertical velocity.
  Quat q = normalized(quat_at(z, S::kQw));
  if (m.contact == BodyContact::Line) {
    const Vec3 e = unit_or_zero(rotation(q) * minus(m.point_a, m.point_b)), eh = unit_or_zero(ground_part(e));
    const Vec3 k = cross(e, eh);
    if (length_of(k) > 0)
      q = normalized(axis_angle(scaled(k, 1.0 / length_of(k)), std::atan2(length_of(k), dot(e, eh))) * q);
    const Vec3 n = {-eh[1], eh[0], 0};
    const Vec3 w = vec_at(z, kWx);
    set_vec_at(z, kWx, minus(w, scaled(n, dot(w, n))));
  }
  set_quat_at(z, kQw, q);
  const Mat3 r = rotation(q);
  const bool a_sticks = !(m.slipping & 1u), b_sticks = m.contact == BodyContact::Line && !(m.slipping & 2u);
  if (a_sticks || b_sticks) {
    const Vec3 arm = r * (a_sticks ? m.point_a : m.point_b);
    set_vec_at(z, kX, minus(m.pivot, arm));
    set_vec_at(z, kVx, cross(vec_at(z, kWx), scaled(arm, -1.0)));
    return;
  }
  const Vec3 arm = r * m.point_a;
  z[kZ] = -arm[2];
  z[kVz] = -cross(vec_at(z, kWx), arm)[2];
}

Vec3 BodyOnGround::slip_start_direction(double t, const Mode& m, const State& z, int i) const {
  // The direction point i starts slipping in: its slip accelerating along it (slip_reference.hpp).
  Mode probe = m;
  auto accel_of = [&](const Vec3& d) {
    reference_of(probe, i) = d;
    return contact_slip_rates(t, probe, z)[i];
  };
  return slip_start_root(accel_of, reference_of(m, i));
}

BodyOnGroundMode BodyOnGround::slipping_contact(double t, const Mode& base, const State& z, unsigned mask) const {
  // Newly slipping points start against the friction the contact needed of them, then take the
  // direction their slip accelerates in under the friction that direction gives (a fixed point).
  const std::array<Vec3, 2> need = contact_forces(t, base, z);
  const Mat3 r = rotation(quat_at(z, S::kQw));
  Mode m = base;
  m.slipping = static_cast<unsigned char>(mask);
  const int n = m.contact == BodyContact::Line ? 2 : 1;
  unsigned fresh = 0;
  for (int i = 0; i < n; ++i)
    if ((mask & bit(i)) && !(base.slipping & bit(i))) {
      fresh |= bit(i);
      reference_of(m, i) = unit_or_zero(ground_part(scaled(need[i], -1.0)));
    }
  for (int i = 0; i < n; ++i)
    if (!(mask & bit(i)) && (base.slipping & bit(i) || !base.slips()) && mask != 0)
      m.pivot = plus(vec_at(z, kX), r * (i == 0 ? m.point_a : m.point_b));
  // Each fresh point's direction in turn (the others held), to agreement. A point alone needs one
  // pass: its roots do not depend on the direction it started from. More passes could only move
  // it off the root nearest the friction it needed by rounding (at an onset where its slip's
  // acceleration there is still zero, a later pass may reject that root and take another).
  const int passes = fresh == 3 ? kStartIterations : 1;
  for (int k = 0; k < passes && fresh; ++k) {
    double change = 0;
    for (int i = 0; i < n; ++i) {
      if (!(fresh & bit(i))) continue;
      const Vec3 next = slip_start_direction(t, m, z, i);
      change = std::fmax(change, length_of(minus(next, reference_of(m, i))));
      reference_of(m, i) = next;
    }
    if (change < kStartAgreement) break;
  }
  if (fresh == 3) joint_start_directions(t, m, z);
  return m;
}

void BodyOnGround::joint_start_directions(double t, Mode& m, const State& z) const {
  // Both ends of an edge starting to slip: their directions (phi_a, phi_b) solve d_i x a_i = 0
  // together with a_i . d_i > 0. The ends in turn may not settle there; Newton's method on both
  // angles does, from the turn's result and from the best points of a coarse grid.
  Mode probe = m;
  auto residual = [&](const double phi[2], double f[2], double c[2], double scale[2]) {
    for (int i = 0; i < 2; ++i) reference_of(probe, i) = {std::cos(phi[i]), std::sin(phi[i]), 0};
    const std::array<Vec3, 2> a = contact_slip_rates(t, probe, z);
    for (int i = 0; i < 2; ++i) {
      const Vec3& d = reference_of(probe, i);
      f[i] = d[0] * a[i][1] - d[1] * a[i][0];
      c[i] = dot(a[i], d);
      scale[i] = length_of(a[i]);
    }
  };
  auto solved = [&](const double f[2], const double c[2], const double scale[2]) {
    return c[0] > 0 && c[1] > 0 && std::fabs(f[0]) <= kRootSine * scale[0] && std::fabs(f[1]) <= kRootSine * scale[1];
  };
  double f[2], c[2], scale[2];
  double phi[2] = {std::atan2(m.slip_ref[1], m.slip_ref[0]), std::atan2(m.slip_ref_b[1], m.slip_ref_b[0])};
  residual(phi, f, c, scale);
  if (solved(f, c, scale)) return;
  // Starts: the turn's result, then the grid's points of smallest residual.
  std::array<std::array<double, 3>, kJointStarts> starts{};
  for (auto& st : starts) st = {INFINITY, 0, 0};
  starts[0] = {0, phi[0], phi[1]};
  for (int ia = 0; ia < kJointGrid; ++ia)
    for (int ib = 0; ib < kJointGrid; ++ib) {
      const double p[2] = {2 * M_PI * ia / kJointGrid, 2 * M_PI * ib / kJointGrid};
      residual(p, f, c, scale);
      if (!(c[0] > 0 && c[1] > 0)) continue;
      const double size = std::fabs(f[0]) / scale[0] + std::fabs(f[1]) / scale[1];
      for (int k = 1; k < kJointStarts; ++k)
        if (size < starts[k][0]) {
          for (int q = kJointStarts - 1; q > k; --q) starts[q] = starts[q - 1];
          starts[k] = {size, p[0], p[1]};
          break;
        }
    }
  for (const auto& st : starts) {
    if (!std::isfinite(st[0])) continue;
    double p[2] = {st[1], st[2]};
    for (int it = 0; it < kNewtonSteps; ++it) {
      residual(p, f, c, scale);
      if (solved(f, c, scale)) {
        for (int i = 0; i < 2; ++i) reference_of(m, i) = {std::cos(p[i]), std::sin(p[i]), 0};
        return;
      }
      double jac[2][2], fh[2], ch[2], sh[2];
      for (int j = 0; j < 2; ++j) {
        double q[2] = {p[0], p[1]};
        q[j] += kNewtonDelta;
        residual(q, fh, ch, sh);
        for (int i = 0; i < 2; ++i) jac[i][j] = (fh[i] - f[i]) / kNewtonDelta;
      }
      const double det = jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0];
      if (!(std::fabs(det) > 0)) break;
      p[0] -= (f[0] * jac[1][1] - f[1] * jac[0][1]) / det;
      p[1] -= (f[1] * jac[0][0] - f[0] * jac[1][0]) / det;
    }
  }
}

bool BodyOnGround::consistent_contact(double t, const Mode& m, const State& z, int lifted) const {
  // Loads not pulling, sticking points within their friction, points starting to slip
  // accelerating the way they slip, the slip's loads solvable, a lifted corner rising.
  std::array<double, kNumEvents> g;
  events(t, m, z, g);
  if (g[kEvLiftOff] < -kLoadTie) return false;
  if (m.contact == BodyContact::Line && (g[kEvLoadA] < -kLoadTie || g[kEvLoadB] < -kLoadTie)) return false;
  const std::array<double, 2> margin = stick_margins(t, m, z);
  if (margin[0] < -kLoadTie || margin[1] < -kLoadTie) return false;
  if (m.slips()) {
    if (!(g[kEvPainleve] > 0)) return false;
    const ContactSlip c = contact_slip_of(m, z);
    const std::array<Vec3, 2> a = contact_slip_rates(t, c, z);
    const double noise = kSlipNoise * std::sqrt(body_.g * size_);
    // A point starting to slip accelerates along its direction (a root of d x a(d)), not against it.
    for (int i = 0; i < c.points.n; ++i) {
      if (c.points.sticks[i] || length_of(c.slip[i]) >= noise) continue;
      const Vec3& d = reference_of(m, i);
      if (dot(a[i], d) < -kLoadTie * body_.g) return false;
      if (std::fabs(d[0] * a[i][1] - d[1] * a[i][0]) > kRootSine * length_of(a[i]) + kLoadTie * body_.g) return false;
    }
  }
  if (lifted >= 0) {
    State dz{};
    rhs(t, m, z, dz);
    const Mat3 r = rotation(quat_at(z, S::kQw));
    if (point_acceleration(z, dz, r * corner(lifted))[2] < -kLoadTie * body_.g) return false;
  }
  return true;
}

bool BodyOnGround::other_corners_rise(double t, const Mode& m, const State& z, double touch) const {
  State dz{};
  rhs(t, m, z, dz);
  const Mat3 r = rotation(quat_at(z, S::kQw));
  for (int i = 0; i < 4; ++i) {
    if (i == m.corner_a || i == m.corner_b) continue;
    const Vec3 arm = r * corner(i);
    if (z[kZ] + arm[2] > touch * size_) continue;
    if (point_acceleration(z, dz, arm)[2] < -kLoadTie * body_.g) return false;
  }
  return true;
}

Tr BodyOnGround::stick_or_slip(double t, const Mode& stick, const State& z, int kind, bool may_stick) const {
  if (body_.shape != BodyShape3d::Box) {
    const bool rim = stick.contact == BodyContact::Roll || (stick.contact == BodyContact::Line && !stick.slips());
    return rim ? rim_contact_holds_or_slips(t, stick, z, kind, may_stick) : Tr{stick, false, kind};
  }
  if (stick.contact != BodyContact::Line && stick.contact != BodyContact::Point) return {stick, false, kind};
  const int slip_kind = kind == int(Body3dEventKind::Mode) ? int(Body3dEventKind::Slip) : kind;
  if (may_stick && consistent_contact(t, stick, z, -1)) return {stick, false, kind};
  // The candidates, in order: the points friction cannot hold slipping (with any loaded alike,
  // to the tie), each point alone, all of them; then, for an edge, each corner alone (the other
  // lifting), sticking or slipping. Points already slipping keep slipping. The first consistent
  // one is the motion; none: Painleve.
  const int n = stick.contact == BodyContact::Line ? 2 : 1;
  const unsigned all = n == 2 ? 3u : 1u, keep = stick.slipping;
  const std::array<double, 2> margin = stick_margins(t, stick, z);
  unsigned failing = keep;
  for (int i = 0; i < n; ++i)
    if (margin[i] < kMarginTie) failing |= bit(i);
  const unsigned masks[] = {failing, keep | 1u, keep | 2u, all};
  for (unsigned mask : masks) {
    mask &= all;
    if (mask == keep) continue;
    const Mode m = slipping_contact(t, stick, z, mask);
    if (consistent_contact(t, m, z, -1)) return {m, false, slip_kind};
  }
  if (n == 2) {
    const Mat3 r = rotation(quat_at(z, S::kQw));
    const Vec3 x = vec_at(z, kX);
    for (int j = 0; j < 2; ++j) {
      const int lifted = j == 0 ? stick.corner_b : stick.corner_a;
      Mode p = point_mode(r, x, j == 0 ? stick.point_a : stick.point_b, j == 0 ? stick.corner_a : stick.corner_b);
      p.released = lifted;
      p.released_t = t;
      if (keep & bit(j)) {
        p.slipping = 1;
        p.slip_ref = reference_of(stick, j);
        if (consistent_contact(t, p, z, lifted)) return {p, false, int(Body3dEventKind::Mode)};
        continue;
      }
      if (consistent_contact(t, p, z, lifted)) return {p, false, int(Body3dEventKind::Mode)};
      const Mode ps = slipping_contact(t, p, z, 1u);
      if (consistent_contact(t, ps, z, lifted)) return {ps, false, slip_kind};
    }
  }
  return {stick, true, int(Body3dEventKind::Painleve)};
}

Tr BodyOnGround::contact_slip_change(double t, const Mode& m, State& z, int event) const {
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 x = vec_at(z, kX);
  const double vs = std::sqrt(body_.g * size_);
  if (const auto tr = moving_contact_ends(m, event)) return *tr;
  switch (event) {
    case kEvLoadA:
    case kEvLoadB: {
      // One end of the edge lifts: the body goes on on the other corner, slipping or sticking.
      const int keep = event == kEvLoadA ? 1 : 0;
      Mode next = point_mode(r, x, keep == 1 ? m.point_b : m.point_a, keep == 1 ? m.corner_b : m.corner_a);
      next.released = keep == 1 ? m.corner_a : m.corner_b;
      next.released_t = t;
      if (m.slipping & bit(keep)) {
        next.slipping = 1;
        next.slip_ref = reference_of(m, keep);
      } else {
        set_contact_velocity(next, z);
      }
      if (pulls_away(t, next, z)) return {Mode{BodyContact::Flight}, false, int(Body3dEventKind::LiftOff)};
      return next.slips() ? Tr{next, false, int(Body3dEventKind::Mode)}
                          : stick_or_slip(t, next, z, int(Body3dEventKind::Mode));
    }
    case kEvSlipA:
    case kEvSlipB:
    case kEvTurnA:
    case kEvTurnB:
      break;
    default:
      return impact(t, m, z, event);
  }
  const int i = (event == kEvSlipA || event == kEvTurnA) ? 0 : 1;
  if (!(m.slipping & bit(i))) return stick_or_slip(t, m, z, int(Body3dEventKind::Slip), false);  // starts slipping
  const Vec3 s = contact_slip_of(m, z).slip[i];
  if ((event == kEvTurnA || event == kEvTurnB) && length_of(s) > kStickSlip * vs) {
    Mode next = m;
    reference_of(next, i) = scaled(s, 1.0 / length_of(s));
    return {next, false, int(Body3dEventKind::SlipTurn)};
  }
  // Point i's slip ends: it stops where it is (what is left of its slip, the event's rounding,
  // is lost to friction), and sticks if friction holds it.
  const double ke = energy(z);
  unsigned rest = m.slipping & ~bit(i);
  // An edge slipping alike at both ends reaches its stick at both at one instant: the other end
  // sticks with it (taken one end first, the other would slip about it, where no load is consistent).
  const int o = 1 - i;
  if (m.contact == BodyContact::Line && (rest & bit(o)) && length_of(contact_slip_of(m, z).slip[o]) <= kStickSlip * vs)
    rest = 0;
  Mode stick;
  if (rest == 0) {
    stick = m.contact == BodyContact::Line ? line_mode(r, x, m.point_a, m.point_b, m.corner_a, m.corner_b)
                                           : point_mode(r, x, m.point_a, m.corner_a);
    stick.released = m.released;
    stick.released_t = m.released_t;
    if (stick.contact == BodyContact::Line) set_vec_at(z, kWx, scaled(stick.axis, dot(stick.axis, vec_at(z, kWx))));
    set_contact_velocity(stick, z);
  } else {
    stick = m;
    stick.slipping = static_cast<unsigned char>(rest);
    stick.pivot = plus(x, r * (i == 0 ? m.point_a : m.point_b));
    set_vec_at(z, kVx, minus(vec_at(z, kVx), s));
  }
  z[kWorkFriction] += energy(z) - ke;
  Tr tr = stick_or_slip(t, stick, z, int(Body3dEventKind::Stick));
  if (!tr.stop && (tr.next.slipping & bit(i))) tr.kind = int(Body3dEventKind::Slip);
  return tr;
}

}  // namespace blockdyn
