// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid_ground/rigid_block.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <string>

#include "blockdyn/model/rigid_ground/impact_law.hpp"

namespace blockdyn {

RigidBlock::RigidBlock(const RigidBlockParams& p, const GroundMotion& g)
    : par_(p),
      ground_(g),
      forced_(!g.is_zero()),
      m_(p.shape.mass),
      I_(p.shape.inertia_centre()),
      g_(p.shape.g),
      bh_(0.5 * p.shape.width),
      hh_(0.5 * p.shape.height),
      alpha_(p.shape.alpha()),
      p_(p.shape.p()),
      R_(p.shape.half_diagonal()),
      tan_alpha_(p.shape.width / p.shape.height) {
  // Switching tolerances, relative to the block's own scales (far above rounding, far below
  // anything physical): lengths h, speeds sqrt(g h), forces m g, accelerations g.
  const double h = p.shape.height;
  tol_gap_ = 1e-9 * h;
  tol_v_ = 1e-9 * std::sqrt(g_ * h);
  tol_f_ = 1e-9 * m_ * g_;
  tol_a_ = 1e-9 * g_;
  // A corner on the ground whose normal velocity would lift it by less than 1e-12 h (below the
  // floating-point resolution of the gap next to the centre height) is in contact.
  v_close_ = std::sqrt(2.0 * g_ * 1e-12 * h);
  if (forced_) rest_exit_ = RestExit(ground_, std::fmin(tan_alpha_, par_.interface.mu_s));
}

RigidBlock::State RigidBlock::abs_tol_scale() const {
  const double L = 2.0 * hh_, V = std::sqrt(g_ * L), W = m_ * g_ * L;
  return {L, L, 1.0, V, V, p_, W, W, W};
}

double RigidBlock::corner_gap(const State& z, int side) const { return z[kY] + corner(z[kTheta], side).y; }

double RigidBlock::kinetic_energy(const State& z) const {
  return 0.5 * m_ * (z[kVX] * z[kVX] + z[kVY] * z[kVY]) + 0.5 * I_ * z[kOmega] * z[kOmega];
}

RigidReactions RigidBlock::reactions(double t, const Mode& md, const State& z) const {
  RigidReactions f;
  const double a_h = gh(t), a_v = gv(t), w = z[kOmega];
  const double mu_k = par_.interface.mu_k;
  auto split = [&](double N, double T) {  // two corners at theta = 0: moment balance about G
    f.NA = 0.5 * (N + hh_ / bh_ * T);
    f.NB = 0.5 * (N - hh_ / bh_ * T);
    f.TA = N != 0.0 ? T * f.NA / N : 0.5 * T;
    f.TB = T - f.TA;
  };
  auto assign = [&](int side, double N, double T) {
    if (side > 0) {
      f.NA = N;
      f.TA = T;
    } else {
      f.NB = N;
      f.TB = T;
    }
  };
  switch (md.mech) {
    case Mechanism::Flight:
      f.ax = -a_h;
      f.ay = -a_v;
      break;
    case Mechanism::Rest:
      split(m_ * a_v, m_ * a_h);
      break;
    case Mechanism::Slide: {
      const double N = m_ * a_v, T = -md.slip * mu_k * N;
      split(N, T);
      f.ax = T / m_ - a_h;
      break;
    }
    case Mechanism::Rock: {
      const Vec2 r = corner(z[kTheta], md.side);
      const double Io = I_ + m_ * (r.x * r.x + r.y * r.y);
      f.alpha = m_ * (r.x * a_v - r.y * a_h) / Io;
      f.ax = f.alpha * r.y + w * w * r.x;
      f.ay = -f.alpha * r.x + w * w * r.y;
      assign(md.side, m_ * (f.ay + a_v), m_ * (f.ax + a_h));
      break;
    }
    case Mechanism::SlideRock: {
      const Vec2 r = corner(z[kTheta], md.side);
      const double q = r.x + md.slip * mu_k * r.y;
      f.D = 1.0 + m_ * r.x * q / I_;
      const double N = m_ * (w * w * r.y + a_v) / f.D;
      const double T = -md.slip * mu_k * N;
      f.alpha = N * q / I_;
      f.ax = T / m_ - a_h;
      f.ay = N / m_ - a_v;
      assign(md.side, N, T);
      break;
    }
  }
  return f;
}

double RigidBlock::next_breakpoint(double t, const Mode& md) const {
  if (!forced_) return INFINITY;
  // At rest the state is constant: the step ends where rest fails, found on the input itself.
  if (md.mech == Mechanism::Rest) return rest_exit_.checkpoint(t);
  return ground_.next_break(t);
}

// Flattened: the reactions inline here (no call and no result through memory at every stage).
[[gnu::flatten]] void RigidBlock::rhs(double t, const Mode& md, const State& z, State& dz) const {
  const RigidReactions f = reactions(t, md, z);
  dz[kX] = z[kVX];
  dz[kY] = z[kVY];
  dz[kTheta] = z[kOmega];
  dz[kVX] = f.ax;
  dz[kVY] = f.ay;
  dz[kOmega] = f.alpha;
  double friction_power = 0.0;
  if (md.mech == Mechanism::Slide) {
    friction_power = (f.TA + f.TB) * z[kVX];
  } else if (md.mech == Mechanism::SlideRock) {
    const Vec2 r = corner(z[kTheta], md.side);
    friction_power = (f.TA + f.TB) * (z[kVX] - z[kOmega] * r.y);
  }
  dz[kWorkFriction] = friction_power;
  dz[kWorkGround] = -m_ * (gh(t) * z[kVX] + (gv(t) - g_) * z[kVY]);
  dz[kWorkImpact] = 0.0;
}

void RigidBlock::complete(const Mode& md, State& z) const {
  switch (md.mech) {
    case Mechanism::Rest:
      z[kX] = md.anchor;
      z[kY] = hh_;
      z[kTheta] = z[kVX] = z[kVY] = z[kOmega] = 0.0;
      break;
    case Mechanism::Slide:
      z[kY] = hh_;
      z[kTheta] = z[kVY] = z[kOmega] = 0.0;
      break;
    case Mechanism::Rock: {
      const Vec2 r = corner(z[kTheta], md.side);
      z[kX] = md.anchor - r.x;
      z[kY] = -r.y;
      z[kVX] = z[kOmega] * r.y;
      z[kVY] = -z[kOmega] * r.x;
      break;
    }
    case Mechanism::SlideRock: {
      const Vec2 r = corner(z[kTheta], md.side);
      z[kY] = -r.y;
      z[kVY] = -z[kOmega] * r.x;
      break;
    }
    case Mechanism::Flight:
      break;
  }
}

void RigidBlock::events(double t, const Mode& md, const State& z, std::array<double, kNumEvents>& g) const {
  g.fill(1.0);
  const double W = m_ * g_, V = std::sqrt(g_ * 2.0 * hh_);
  const double mu_s = par_.interface.mu_s;
  const double th = z[kTheta];
  auto rotation_events = [&](double st) {
    g[kEvOverturn] = 0.5 * M_PI - st;
    g[kEvAlpha] = md.beyond ? st - alpha_ : alpha_ - st;
  };
  switch (md.mech) {
    case Mechanism::Rest:
    case Mechanism::Slide: {
      const RigidReactions f = reactions(t, md, z);
      g[kEvContact0] = f.NA / W;
      g[kEvContact1] = f.NB / W;
      g[kEvFriction] =
          md.mech == Mechanism::Rest ? (mu_s * (f.NA + f.NB) - std::fabs(f.TA + f.TB)) / W : md.slip * z[kVX] / V;
      break;
    }
    case Mechanism::Rock:
    case Mechanism::SlideRock: {
      const RigidReactions f = reactions(t, md, z);
      const double N = f.NA + f.NB, T = f.TA + f.TB;
      g[kEvContact0] = N / W;
      if (md.mech == Mechanism::Rock) {
        g[kEvFriction] = (mu_s * N - std::fabs(T)) / W;
      } else {
        const Vec2 r = corner(th, md.side);
        g[kEvFriction] = md.slip * (z[kVX] - z[kOmega] * r.y) / V;
        g[kEvPainleve] = f.D;
      }
      g[kEvImpact] = md.side * th;
      rotation_events(md.side * th);
      break;
    }
    case Mechanism::Flight:
      g[kEvContact0] = corner_gap(z, 1) / (2.0 * hh_);
      g[kEvContact1] = corner_gap(z, -1) / (2.0 * hh_);
      rotation_events(std::fabs(th));
      break;
  }
}

ContactProblem RigidBlock::contact_problem(double t, const State& z, int sides[2]) const {
  ContactProblem cp;
  cp.m = m_;
  cp.I = I_;
  cp.mu = par_.interface;
  cp.b = {-m_ * gh(t), -m_ * gv(t), 0.0};
  const double w = z[kOmega];
  double vt = 0.0, rx_sum = 0.0;
  for (int side : {1, -1}) {
    const Vec2 r = corner(z[kTheta], side);
    const double gap = z[kY] + r.y;
    const double vn = z[kVY] + w * r.x;
    if (gap > tol_gap_ || std::fabs(vn) > v_close_) continue;
    sides[cp.n] = side;
    cp.c[cp.n] = ContactPoint{side, r, 0.0};
    cp.cn[cp.n] = -w * w * r.y;
    vt += z[kVX] - w * r.y;
    rx_sum += r.x;
    ++cp.n;
  }
  if (cp.n > 0) {
    vt /= cp.n;
    cp.ct = -w * w * rx_sum / cp.n;
    cp.slip_sign = std::fabs(vt) > tol_v_ ? (vt > 0 ? 1 : -1) : 0;
  }
  return cp;
}

RigidMode RigidBlock::mode_of(const ContactSolution& s, const int sides[2], const State& z, const Mode& from) const {
  Mode md;
  md.beyond = std::fabs(z[kTheta]) > alpha_ || (from.beyond && std::fabs(z[kTheta]) >= alpha_);
  const int nc = s.closed_count();
  if (nc == 0) {
    md.mech = Mechanism::Flight;
    return md;
  }
  if (nc == 2) {
    md.mech = s.tang == Tangential::Stick ? Mechanism::Rest : Mechanism::Slide;
    md.slip = s.sigma();
    md.anchor = z[kX];
    return md;
  }
  const int j = s.closed[0] ? 0 : 1;
  md.side = sides[j];
  md.mech = s.tang == Tangential::Stick ? Mechanism::Rock : Mechanism::SlideRock;
  md.slip = s.sigma();
  md.anchor = z[kX] + corner(z[kTheta], md.side).x;
  return md;
}

Transition<RigidMode> RigidBlock::reselect(double t, const Mode& from, State& z, const SelectionHints& hs,
                                           int kind) const {
  int sides[2] = {0, 0};
  const ContactProblem cp = contact_problem(t, z, sides);
  SelectionHints h;
  h.no_stick = hs.no_stick;
  for (int j = 0; j < cp.n; ++j) h.must_open[j] = hs.must_open[sides[j] > 0 ? 0 : 1];
  const Selection sel = select_contacts(cp, h, tol_f_, tol_a_);
  if (sel.painleve) return Transition<Mode>{from, true, int(RigidEventKind::Painleve)};
  Transition<Mode> tr{mode_of(*sel.chosen, sides, z, from), false, kind};
  tr.next.alternatives =
      alternatives_of(select_contacts(cp, SelectionHints{}, tol_f_, tol_a_), sides, z, from, tr.next);
  // Closing a contact removes the (sub-resolution) velocity it still had: book the change of
  // kinetic energy with the impacts so that the energy balance stays closed.
  const double ke0 = kinetic_energy(z);
  complete(tr.next, z);
  z[kWorkImpact] += kinetic_energy(z) - ke0;
  return tr;
}

unsigned RigidBlock::alternatives_of(const Selection& sel, const int sides[2], const State& z, const Mode& from,
                                     const Mode& chosen) const {
  // The mechanism left is consistent only to tolerance at its own switch: it is no candidate.
  auto left = [&](const ContactSolution& c) {
    const Mode m = mode_of(c, sides, z, chosen);
    return m.mech == from.mech && m.side == from.side && m.slip == from.slip;
  };
  unsigned bits = 0;
  for (int i = 0; i < sel.consistent_count; ++i) {
    const ContactSolution& c = sel.consistent[std::size_t(i)];
    if (left(c)) continue;
    // Slip where the same contacts could stick is no alternative: static friction holds.
    bool stick_too = false;
    for (int k = 0; k < sel.consistent_count && c.tang != Tangential::Stick; ++k) {
      const ContactSolution& o = sel.consistent[std::size_t(k)];
      stick_too |= o.tang == Tangential::Stick && o.closed[0] == c.closed[0] && o.closed[1] == c.closed[1] && !left(o);
    }
    if (stick_too) continue;
    const Mechanism m = mode_of(c, sides, z, chosen).mech;
    if (m != chosen.mech) bits |= mechanism_bit(m);
  }
  return bits;
}

Transition<RigidMode> RigidBlock::leave_rest_at(double t, const Mode& md, State& z) const {
  // The same comparisons as the search (first_rest_failure), in units of g: the conditions hold
  // at every point before the checkpoint and fail at it, or it is only the end of a look-ahead.
  const double a_h = forced_ ? ground_.ah(t) : 0.0, gvn = 1.0 + (forced_ ? ground_.av(t) : 0.0);
  const bool rock = !(tan_alpha_ * gvn - std::fabs(a_h) >= 0.0);
  const bool slide = !(par_.interface.mu_s * gvn - std::fabs(a_h) >= 0.0);
  const bool lift = !(gvn > 0.0);
  if (!rock && !slide && !lift) return Transition<Mode>{md, false, int(RigidEventKind::GroundBreak)};
  SelectionHints h;
  // a_H > 0 pushes the block towards -x in the ground's frame: B (right) unloads first.
  h.must_open[0] = lift || (rock && a_h < 0.0);
  h.must_open[1] = lift || (rock && a_h > 0.0);
  h.no_stick = slide;
  return reselect(t, md, z, h, int(RigidEventKind::Mode));
}

double RigidBlock::horizon(double t, double e) const {
  return std::fmax(kAccumulationTime / p_, kAccumulationRelative * std::fabs(t) / std::fmax(1.0 - e, 1e-300));
}

Transition<RigidMode> RigidBlock::impact(double t, const Mode& from, State& z, int hit_side) const {
  if (from.mech == Mechanism::Rock || from.mech == Mechanism::SlideRock) {
    // The other corner lands at theta = 0: both corners on the ground.
    z[kTheta] = 0.0;
    z[kY] = hh_;
  }
  ImpactContact c[2];
  int n = 0;
  for (int side : {1, -1}) {
    const Vec2 r = corner(z[kTheta], side);
    if (side == hit_side || z[kY] + r.y <= tol_gap_) c[n++] = ImpactContact{side, r};
  }
  const std::array<double, 3> u0{z[kVX], z[kVY], z[kOmega]};
  auto u = apply_impact(par_, c, n, u0, tol_v_);
  if (!u) return Transition<Mode>{from, true, int(RigidEventKind::Painleve)};
  const double e = par_.e();
  if (par_.impact == ImpactLaw::Newton && e > 0.0) {
    // Bounces so small that the remaining ones end within the accumulation time, or that rise
    // less than 1e-12 h (unresolvable next to the centre height in floating point): plastic.
    double vn_max = 0.0;
    for (int j = 0; j < n; ++j) vn_max = std::fmax(vn_max, (*u)[1] + c[j].r.x * (*u)[2]);
    const double v_zeno = std::fmax(0.5 * g_ * horizon(t, e) * (1.0 - e), v_close_);
    if (vn_max > 0.0 && vn_max < v_zeno) u = apply_impact(par_, c, n, u0, tol_v_, true);
    if (!u) return Transition<Mode>{from, true, int(RigidEventKind::Painleve)};
  }
  // Accumulation of impacts: once the motion left is so slow that the remaining impacts end
  // within the accumulation time (geometric series of swings 2 v / g shrinking by e_eff), stop it.
  const double speed0 = std::hypot(u0[0], u0[1]) + R_ * std::fabs(u0[2]);
  const double speed1 = std::hypot((*u)[0], (*u)[1]) + R_ * std::fabs((*u)[2]);
  const double e_eff = speed0 > 0.0 ? std::fmin(speed1 / speed0, 1.0) : 0.0;
  if (e_eff < 1.0 && speed1 < 0.5 * g_ * horizon(t, e_eff) * (1.0 - e_eff)) *u = {0.0, 0.0, 0.0};
  const double ke0 = kinetic_energy(z);
  z[kVX] = (*u)[0];
  z[kVY] = (*u)[1];
  z[kOmega] = (*u)[2];
  z[kWorkImpact] += kinetic_energy(z) - ke0;
  return reselect(t, from, z, SelectionHints{}, int(RigidEventKind::Impact));
}

Transition<RigidMode> RigidBlock::transition(double t, const Mode& current, State& z, int event) const {
  // The alternatives belong to the switch that chose the current mode, not to the next one.
  Mode md = current;
  md.alternatives = 0;
  SelectionHints h;
  const int kind = int(RigidEventKind::Mode);
  switch (event) {
    case kBreakpoint: {
      if (md.mech == Mechanism::Rest) return leave_rest_at(t, md, z);
      // The mode stays unless the input's jump here violates one of its conditions; then it is
      // re-selected as at the event that condition would have fired.
      std::array<double, kNumEvents> g;
      events(t, md, z, g);
      if (md.mech == Mechanism::Flight || (g[kEvContact0] >= 0.0 && g[kEvContact1] >= 0.0 && g[kEvFriction] >= 0.0))
        return Transition<Mode>{md, false, int(RigidEventKind::GroundBreak)};
      if (md.mech == Mechanism::Rest || md.mech == Mechanism::Slide) {
        h.must_open[0] = g[kEvContact0] < 0.0;
        h.must_open[1] = g[kEvContact1] < 0.0;
      } else if (g[kEvContact0] < 0.0) {
        h.must_open[md.side > 0 ? 0 : 1] = true;
      }
      h.no_stick = (md.mech == Mechanism::Rest || md.mech == Mechanism::Rock) && g[kEvFriction] < 0.0;
      return reselect(t, md, z, h, kind);
    }
    case kEvContact0:
    case kEvContact1: {
      if (md.mech == Mechanism::Flight) return impact(t, md, z, event == kEvContact0 ? 1 : -1);
      if (md.mech == Mechanism::Rest || md.mech == Mechanism::Slide) {
        h.must_open[event == kEvContact0 ? 0 : 1] = true;
      } else {
        h.must_open[md.side > 0 ? 0 : 1] = true;
      }
      return reselect(t, md, z, h, kind);
    }
    case kEvFriction:
      if (md.mech == Mechanism::Rest || md.mech == Mechanism::Rock) h.no_stick = true;
      return reselect(t, md, z, h, kind);
    case kEvImpact:
      return impact(t, md, z, -md.side);
    case kEvOverturn:
      return Transition<Mode>{md, true, int(RigidEventKind::Overturn)};
    case kEvAlpha: {
      Mode next = md;
      next.beyond = !md.beyond;
      return Transition<Mode>{next, false, int(md.beyond ? RigidEventKind::WithinAlpha : RigidEventKind::BeyondAlpha)};
    }
    case kEvPainleve:
      return Transition<Mode>{md, true, int(RigidEventKind::Painleve)};
  }
  return Transition<Mode>{md, false, kind};
}

std::optional<std::string> RigidBlock::validity_problem(const State& z) const {
  for (std::size_t i = 0; i < 6; ++i)
    if (!std::isfinite(z[i])) return std::string("the state is not finite");
  if (std::fabs(z[kTheta]) >= 0.5 * M_PI)
    return "|w0| = " + number_text(std::fabs(z[kTheta])) + " rad: the block lies on its side (|w0| must be < pi/2)";
  for (int side : {1, -1}) {
    const Vec2 r = corner(z[kTheta], side);
    const double gap = z[kY] + r.y;
    if (gap < -tol_gap_)
      return std::string("corner ") + corner_name(side) + " is " + number_text(-gap, 6) +
             " m below the ground (y0 too low for this w0)";
    if (gap <= tol_gap_ && z[kVY] + z[kOmega] * r.x < -tol_v_)
      return std::string("corner ") + corner_name(side) + " touches the ground and moves into it (vy0, vw0)";
  }
  return std::nullopt;
}

std::optional<RigidMode> RigidBlock::initial_mode(double t, State& z) const {
  const Mode none;
  const Transition<Mode> tr = reselect(t, none, z, SelectionHints{}, int(RigidEventKind::Mode));
  if (tr.stop) return std::nullopt;
  return tr.next;
}

}  // namespace blockdyn
