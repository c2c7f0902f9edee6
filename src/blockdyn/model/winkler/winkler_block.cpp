// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/winkler/winkler_block.hpp"

#include "blockdyn/base/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "blockdyn/model/winkler/stick_reaction.hpp"

namespace blockdyn {

const char* to_string(WinklerEventKind k) {
  switch (k) {
    case WinklerEventKind::ContactToSlide:
      return "contact_to_slide";
    case WinklerEventKind::SlideToContact:
      return "slide_to_contact";
    case WinklerEventKind::SlideReversal:
      return "slide_reversal";
    case WinklerEventKind::Takeoff:
      return "takeoff";
    case WinklerEventKind::Landing:
      return "landing";
    case WinklerEventKind::WZero:
      return "w_zero";
    case WinklerEventKind::Overturn:
      return "overturn";
    case WinklerEventKind::Invalid:
      return "invalid";
    case WinklerEventKind::GroundBreak:
      return "ground_break";
    case WinklerEventKind::GrazingHold:
      return "grazing_hold";
  }
  return "?";
}

WinklerBlock::WinklerBlock(const WinklerParams& p, const GroundMotion& g)
    : p_(p), ground_(g), forced_(!g.is_zero()), inertia_(p.inertia()), alpha_(p.alpha()), stiffness_(p) {}

BlockForces WinklerBlock::forces(double t, const Mode& m, const State& z) const {
  return forces(t, m, z, make_tilt(z[kW]));
}

BlockForces WinklerBlock::forces(double t, const Mode& m, const State& z, const Tilt& tilt) const {
  // Every branch returns all the fields at once: a default-constructed result assigned field by
  // field was zero-filled first, with a `rep stos` that cost about a tenth of this function.
  // Fields: Rx, Ry, torque, torque_nonpot, ax, ay, aw, v_corner, margin, vx, corners_below.
  const double a_h = ah(t), a_v = av(t);
  const CornerArms arm = corner_arms(p_.r, tilt, m.side);
  if (m.regime == Regime::Flight)
    return BlockForces{0.0, 0.0, 0.0, 0.0, -a_h, -1.0 - a_v, 0.0, z[kVX] + arm.B * z[kVW], 0.0, 0.0, 0};
  const FoundationForce ff = foundation_force(stiffness_, p_.r, z[kH], tilt);
  // The lowest corner's side, not the sign of w: the two agree except at w = 0 (an upright start,
  // or a w_zero event whose state is left of the root by rounding), where the non-potential
  // torque jumps and the side says which way the block goes on. With sign(w) there, the first
  // stage of the next step took the wrong branch, an error the step's estimate did not see
  // (5e-11 in the energy balance at rtol 1e-11).
  const double torque_nonpot = ff.torque_nonpot(m.side);
  const double ay = ff.Ry - 1.0 - a_v;
  if (m.regime == Regime::Contact) {
    const StickReaction st = stick_reaction(inertia_, arm, m.side, ff.torque, z[kVW], a_h);
    return BlockForces{st.Rx,
                       ff.Ry,
                       ff.torque,
                       torque_nonpot,
                       st.Rx - a_h,
                       ay,
                       st.ww,
                       0.0,
                       friction_margin(p_.mu, ff.Ry, st.Rx),
                       -arm.B * z[kVW],
                       ff.corners_below};
  }
  const double Rx = m.friction_sign * p_.mu * ff.Ry;
  return BlockForces{Rx,
                     ff.Ry,
                     ff.torque,
                     torque_nonpot,
                     Rx - a_h,
                     ay,
                     (ff.torque + arm.B * Rx) / inertia_,
                     z[kVX] + arm.B * z[kVW],
                     0.0,
                     0.0,
                     ff.corners_below};
}

[[gnu::flatten]] Energy WinklerBlock::energy_rates(double t, const Mode& m, const State& z) const {
  const BlockForces f = forces(t, m, z);
  // dV/dy = -Ry; dV/dw = torque_nonpot - torque (foundation_force.hpp).
  return Energy{z[kVX] * f.ax, z[kVY] * f.ay, inertia_ * z[kVW] * f.aw, z[kVY],
                -f.Ry * z[kVY] + (f.torque_nonpot - f.torque) * z[kVW]};
}

// Flattened: the forces inline here (the stages' calls and the result passed through memory were
// a fifth of a response map's time).
[[gnu::flatten]] void WinklerBlock::rhs(double t, const Mode& m, const State& z, State& dz) const {
  const BlockForces f = forces(t, m, z);
  const bool contact = m.regime == Regime::Contact;
  // In contact x and x' follow from w (complete()); only 4 mechanical states are integrated.
  const double vx = contact ? f.vx : z[kVX];
  dz[kX] = contact ? 0.0 : z[kVX];
  dz[kH] = z[kVY];
  dz[kW] = z[kVW];
  dz[kVX] = contact ? 0.0 : f.ax;
  dz[kVY] = f.ay;
  dz[kVW] = f.aw;
  dz[kWorkFriction] = contact ? 0.0 : f.Rx * f.v_corner;
  dz[kWorkNonPotential] = f.torque_nonpot * z[kVW];
  dz[kWorkGround] = forced_ ? -(ah(t) * vx + av(t) * z[kVY]) : 0.0;
}

void WinklerBlock::complete(const Mode& m, State& z) const {
  if (m.regime != Regime::Contact) return;
  complete(m, z, make_tilt(z[kW]));
}

void WinklerBlock::complete(const Mode& m, State& z, const Tilt& tilt) const {
  if (m.regime != Regime::Contact) return;
  const CornerArms arm = corner_arms(p_.r, tilt, m.side);
  z[kX] = m.anchor + m.side * arm.A;
  z[kVX] = -arm.B * z[kVW];
}

[[gnu::flatten]] void WinklerBlock::complete_and_events(double t, const Mode& m, State& z,
                                                        std::array<double, kNumEvents>& g) const {
  const Tilt tilt = make_tilt(z[kW]);  // complete() changes x and x', not w
  complete(m, z, tilt);
  events(t, m, z, tilt, g);
}

void WinklerBlock::events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const {
  events(t, m, z, make_tilt(z[kW]), g);
}

void WinklerBlock::events(double t, const Mode& m, const State& z, const Tilt& tilt,
                          std::array<double, kNumEvents>& g) const {
  const CornerHeights ch = corner_heights(p_.r, z[kH], tilt);
  g[kEvOverturn] = alpha_ - m.side * z[kW];
  g[kEvInvalid] = std::max(ch.other_bottom, ch.upper_pivot_side);  // third-lowest corner
  g[kEvSurface] = (m.regime == Regime::Flight) ? ch.lowest : -ch.lowest;
  g[kEvWZero] = m.side * z[kW];
  if (m.regime == Regime::Contact) {
    g[kEvFriction] = forces(t, m, z, tilt).margin;
  } else if (m.regime == Regime::Slide && p_.mu > 0.0) {
    g[kEvFriction] = -m.friction_sign * (z[kVX] + corner_arms(p_.r, tilt, m.side).B * z[kVW]);
  } else {
    g[kEvFriction] = 1.0;
  }
}

[[gnu::flatten]] void WinklerBlock::event_rates(double t, const Mode& m, const State& z, const State& dz,
                                                std::array<double, kNumEvents>& g,
                                                std::array<double, kNumEvents>& gdot) const {
  const Tilt tilt = make_tilt(z[kW]);
  const CornerHeights ch = corner_heights(p_.r, z[kH], tilt);
  const double vw = dz[kW];
  const CornerHeights rate = corner_height_rates(p_.r, tilt, dz[kH], vw);
  g[kEvOverturn] = alpha_ - m.side * z[kW];
  gdot[kEvOverturn] = -m.side * vw;
  const bool other = ch.other_bottom >= ch.upper_pivot_side;
  g[kEvInvalid] = other ? ch.other_bottom : ch.upper_pivot_side;
  gdot[kEvInvalid] = other ? rate.other_bottom : rate.upper_pivot_side;
  const double surface_sign = (m.regime == Regime::Flight) ? 1.0 : -1.0;
  g[kEvSurface] = surface_sign * ch.lowest;
  gdot[kEvSurface] = surface_sign * rate.lowest;
  g[kEvWZero] = m.side * z[kW];
  gdot[kEvWZero] = m.side * vw;
  if (m.regime == Regime::Contact) {
    g[kEvFriction] = forces(t, m, z, tilt).margin;
    gdot[kEvFriction] = std::numeric_limits<double>::quiet_NaN();
  } else if (m.regime == Regime::Slide && p_.mu > 0.0) {
    // v_P = x' + B w', B = (cos w + side r sin w) / 2.
    const double sw = tilt.sign * tilt.s;
    const double B = 0.5 * (tilt.c + m.side * p_.r * sw);
    const double B_rate = 0.5 * (m.side * p_.r * tilt.c - sw) * vw;
    g[kEvFriction] = -m.friction_sign * (z[kVX] + B * z[kVW]);
    gdot[kEvFriction] = -m.friction_sign * (dz[kVX] + B * dz[kVW] + B_rate * z[kVW]);
  } else {
    g[kEvFriction] = 1.0;
    gdot[kEvFriction] = 0.0;
  }
}

WinklerBlock::Mode WinklerBlock::stick_or_slip(double t, const State& z, int side, int slip_sign) const {
  Mode c{Regime::Contact, side, 0, 0.0};
  const CornerArms arm = corner_arms(p_.r, z[kW], side);
  c.anchor = z[kX] - side * arm.A;
  const BlockForces f = forces(t, c, z);
  if (f.margin >= 0.0) return c;
  const int s = slip_sign != 0 ? slip_sign : sign_of(f.Rx);
  return Mode{Regime::Slide, side, s, 0.0};
}

WinklerBlock::Mode WinklerBlock::submerged_mode(double t, const State& z, int side) const {
  if (p_.mu == 0.0) return Mode{Regime::Slide, side, 0, 0.0};
  const double vp = z[kVX] + corner_arms(p_.r, z[kW], side).B * z[kVW];
  if (vp != 0.0) return Mode{Regime::Slide, side, -sign_of(vp), 0.0};
  return stick_or_slip(t, z, side, 0);
}

WinklerBlock::Mode WinklerBlock::initial_mode(double t, const State& z) const {
  int side = sign_of(z[kW]);
  if (side == 0) side = sign_of(z[kVW]);
  const bool airborne = corner_heights(p_.r, z[kH], z[kW]).lowest > 0.0;
  if (side == 0) {  // upright and not rotating: the side the block starts to tip to
    Mode probe = airborne ? Mode{Regime::Flight, 1, 0, 0.0} : submerged_mode(t, z, 1);
    State dz;
    State zc = z;
    complete(probe, zc);
    rhs(t, probe, zc, dz);
    side = sign_of(dz[kVW]);
    if (side == 0) side = 1;
  }
  if (airborne) return Mode{Regime::Flight, side, 0, 0.0};
  return submerged_mode(t, z, side);
}

Transition<WinklerBlock::Mode> WinklerBlock::transition(double t, const Mode& m, State& z, int event) const {
  Transition<Mode> tr;
  tr.next = m;
  switch (event) {
    case kEvOverturn:
      tr.stop = true;
      tr.kind = int(WinklerEventKind::Overturn);
      break;
    case kEvInvalid:
      tr.stop = true;
      tr.kind = int(WinklerEventKind::Invalid);
      break;
    case kEvSurface:
      if (m.regime == Regime::Flight) {
        tr.kind = int(WinklerEventKind::Landing);
        tr.next = submerged_mode(t, z, m.side);
      } else {
        tr.kind = int(WinklerEventKind::Takeoff);
        tr.next = Mode{Regime::Flight, m.side, 0, 0.0};
      }
      break;
    case kEvWZero:
      tr.kind = int(WinklerEventKind::WZero);
      tr.next.side = -m.side;
      if (m.regime == Regime::Contact) tr.next = stick_or_slip(t, z, -m.side, 0);
      break;
    case kEvFriction:
      if (m.regime == Regime::Contact) {
        tr.kind = int(WinklerEventKind::ContactToSlide);
        tr.next = Mode{Regime::Slide, m.side, sign_of(forces(t, m, z).Rx), 0.0};
      } else {
        tr.next = stick_or_slip(t, z, m.side, -m.friction_sign);
        tr.kind =
            int(tr.next.regime == Regime::Contact ? WinklerEventKind::SlideToContact : WinklerEventKind::SlideReversal);
      }
      break;
    case kBreakpoint:
      tr.kind = int(WinklerEventKind::GroundBreak);
      if (m.regime == Regime::Contact) tr.next = stick_or_slip(t, z, m.side, 0);
      break;
  }
  return tr;
}

std::optional<Transition<WinklerBlock::Mode>> WinklerBlock::resolve_chatter(double t, const Mode& m,
                                                                            const State& z) const {
  if (m.regime == Regime::Flight) return std::nullopt;
  // Grazing: v_P and the friction margin vanish together. Hold the corner, unless the contact
  // margin is falling (Ry -> 0 just before a take-off): then holding fails again at once, and the
  // corner must slip in the direction the stick reaction pushes (the only consistent mode).
  Mode c{Regime::Contact, m.side, 0, z[kX] - m.side * corner_arms(p_.r, z[kW], m.side).A};
  State zc = z;
  complete(c, zc);
  const BlockForces f0 = forces(t, c, zc);
  if (p_.mu > 0.0) {
    State dz;
    rhs(t, c, zc, dz);
    const double dt = 1e-6 * step_hint(c);
    State z1 = zc;
    for (std::size_t i = 0; i < kDim; ++i) z1[i] += dt * dz[i];
    complete(c, z1);
    const double margin1 = forces(t + dt, c, z1).margin;
    if (margin1 < 0.0 && margin1 < f0.margin && f0.Rx != 0.0) {
      const Mode s{Regime::Slide, m.side, sign_of(f0.Rx), 0.0};
      return Transition<Mode>{s, false, int(WinklerEventKind::ContactToSlide)};
    }
  }
  return Transition<Mode>{c, false, int(WinklerEventKind::GrazingHold)};
}

double WinklerBlock::step_hint(const Mode& m) const {
  if (m.regime == Regime::Flight) return 0.05;
  return 0.5 / std::sqrt(std::max(1.0, p_.k));
}

double WinklerBlock::restart_step(double, const Mode& m, const State& z, const State& dz, double h) const {
  if (m.regime != Regime::Flight || forced_) return h;
  const CornerHeights rate = corner_height_rates(p_.r, make_tilt(z[kW]), dz[kH], dz[kW]);
  // The lowest corner rises at its rate and falls back under gravity (y'' = -1) in about twice
  // that; a step a little longer holds the landing, which the scan then finds.
  const double flight = 2.0 * rate.lowest;
  if (!(flight > 0.0)) return h;
  return std::fmax(h, std::fmin(kFlightStepMargin * flight, step_hint(m)));
}

namespace {
// The first tau > 0 with x + v tau + a tau^2 / 2 = 0 (infinity if none).
double first_zero(double x, double v, double a) {
  if (std::fabs(a) * std::fabs(x) < 1e-12 * v * v) return (v != 0.0 && -x / v > 0.0) ? -x / v : INFINITY;
  const double disc = v * v - 2.0 * a * x;
  if (!(disc >= 0.0)) return INFINITY;
  const double q = -(v + std::copysign(std::sqrt(disc), v));  // the two roots: q / a and 2 x / q
  double best = INFINITY;
  for (const double r : {q / a, q != 0.0 ? 2.0 * x / q : INFINITY})
    if (r > 0.0 && r < best) best = r;
  return best;
}
}  // namespace

double WinklerBlock::kink_ahead(double, const Mode& m, const State& z, const State& dz) const {
  if (m.regime == Regime::Flight) return INFINITY;
  // Corner heights along the motion to second order (h' = y', h'' = y'', w', w'' from dz).
  const Tilt tilt = make_tilt(z[kW]);
  const CornerHeights ch = corner_heights(p_.r, z[kH], tilt);
  const CornerHeights rate = corner_height_rates(p_.r, tilt, dz[kH], dz[kW]);
  const CornerHeights acc = corner_height_accelerations(p_.r, tilt, dz[kVY], dz[kW], dz[kVW]);
  const double far = first_zero(ch.other_bottom, rate.other_bottom, acc.other_bottom);
  // The take-off: the lowest corner rising through the surface.
  const double lift = ch.lowest < 0.0 ? first_zero(ch.lowest, rate.lowest, acc.lowest) : INFINITY;
  // A kink closer than this is where the step starts (both corners meeting the surface together,
  // or the last one stepped onto): not one to step to, but the other may still be ahead.
  const double near = 1e-6 * step_hint(m);
  return std::fmin(far > near ? far : INFINITY, lift > near ? lift : INFINITY);
}

WinklerBlock::State WinklerBlock::abs_tol_scale() const {
  State s;
  s.fill(1.0);
  // Depths are of order 1/k and the heave velocity of order 1/sqrt(k): scale their absolute
  // tolerances so that the foundation force keeps its relative accuracy at any stiffness.
  s[kH] = std::min(1.0, 1.0 / p_.k);
  s[kVY] = std::min(1.0, 1.0 / std::sqrt(p_.k));
  return s;
}

std::optional<std::string> WinklerBlock::validity_problem(const State& z) const {
  for (std::size_t i = 0; i < 6; ++i)
    if (!std::isfinite(z[i])) return std::string("state contains a non-finite value");
  if (std::fabs(z[kW]) > alpha_)
    return "|w| = " + number_text(std::fabs(z[kW]), 6) +
           " exceeds the overturning angle alpha = atan(r) = " + number_text(alpha_, 6);
  const CornerHeights ch = corner_heights(p_.r, z[kH], z[kW]);
  if (std::max(ch.other_bottom, ch.upper_pivot_side) < 0.0)
    return std::string("more than two corners are below the foundation surface (the model allows at most two)");
  return std::nullopt;
}

}  // namespace blockdyn
