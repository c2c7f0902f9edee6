// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid_ground/housner_block.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace blockdyn {

double housner_coefficient(const BlockShape& shape, std::optional<double> restitution) {
  if (restitution) {
    if (!(std::isfinite(*restitution) && *restitution >= 0.0 && *restitution <= 1.0))
      throw std::invalid_argument("restitution = " + number_text(*restitution) + " is out of range: must be in [0, 1]");
    return *restitution;
  }
  const double e = shape.housner_restitution();
  if (!(e >= 0.0))
    throw std::invalid_argument(
        "restitution: Housner's 1 - 1.5 sin^2(alpha) = " + number_text(e, 6) +
        " is negative for this block (b/h = " + number_text(shape.width / shape.height, 6) +
        " > sqrt(2)): it would bounce back onto the same corner; give `restitution` in [0, 1], or use `model` rigid "
        "(impacts by the impact law, `impact`)");
  return e;
}

HousnerBlock::HousnerBlock(const BlockShape& shape, double restitution, const GroundMotion& g)
    : shape_(shape),
      e_(restitution),
      ground_(g),
      forced_(!g.is_zero()),
      alpha_(shape.alpha()),
      R_(shape.half_diagonal()),
      p_(shape.p()),
      io_(shape.inertia_corner()),
      ta_(std::tan(shape.alpha())),
      wscale_(shape.mass * shape.g * shape.half_diagonal()) {
  if (forced_) rest_exit_ = RestExit(ground_, ta_);
}

double HousnerBlock::angular_acceleration(double t, const Mode& m, const State& z) const {
  if (m.mech == Mechanism::Rest) return 0.0;
  const double phi = m.side * alpha_ - z[kTheta];
  return -p_ * p_ * ((1.0 + av(t)) * std::sin(phi) - ah(t) * std::cos(phi));
}

void HousnerBlock::rhs(double t, const Mode& m, const State& z, State& dz) const {
  if (m.mech == Mechanism::Rest) {
    dz = {0.0, 0.0, 0.0, 0.0};
    return;
  }
  const double phi = m.side * alpha_ - z[kTheta];
  const double sp = std::sin(phi), cp = std::cos(phi);
  const double a_h = ah(t), a_v = av(t);
  dz[kTheta] = z[kOmega];
  dz[kOmega] = -p_ * p_ * ((1.0 + a_v) * sp - a_h * cp);
  // Power of the inertial forces -m a_H, -m a_V on the centre's velocity omega x (G - pivot).
  dz[kWorkGround] = wscale_ * z[kOmega] * (a_h * cp - a_v * sp);
  dz[kWorkImpact] = 0.0;
}

double HousnerBlock::next_breakpoint(double t, const Mode& m) const {
  if (!forced_) return INFINITY;
  // At rest the state is constant: the step ends where rest fails (at the breakpoint the
  // transition re-selects the mode), found on the input itself, never by the event scan of a step
  // over which nothing else changes and that may grow over a whole window of failure.
  if (m.mech == Mechanism::Rest) return rest_exit_.checkpoint(t);
  return ground_.next_break(t);
}

bool HousnerBlock::rest_holds(double t) const {
  const double gv = 1.0 + av(t);
  return gv > 0.0 && std::fabs(ah(t)) <= gv * ta_;
}

void HousnerBlock::events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const {
  if (m.mech == Mechanism::Rest) {
    g[kEvImpact] = g[kEvOverturn] = g[kEvAlpha] = 1.0;
    const double gv = 1.0 + av(t);
    g[kEvUplift] = gv * ta_ - std::fabs(ah(t));
    g[kEvLiftOff] = gv;
    return;
  }
  const double st = m.side * z[kTheta];
  g[kEvImpact] = st;
  g[kEvOverturn] = 0.5 * M_PI - st;
  g[kEvAlpha] = m.beyond ? st - alpha_ : alpha_ - st;
  g[kEvUplift] = g[kEvLiftOff] = 1.0;
}

double HousnerBlock::potential_energy(const Mode& m, const State& z) const {
  if (m.mech == Mechanism::Rest) return 0.0;
  return shape_.mass * shape_.g * (R_ * std::cos(m.side * alpha_ - z[kTheta]) - 0.5 * shape_.height);
}

double HousnerBlock::normal_reaction(double t, const Mode& m, const State& z) const {
  if (m.mech == Mechanism::Rest) return 1.0 + av(t);
  const double phi = m.side * alpha_ - z[kTheta];
  const double acc = angular_acceleration(t, m, z);
  return 1.0 + av(t) + R_ / shape_.g * (std::sin(phi) * acc - std::cos(phi) * z[kOmega] * z[kOmega]);
}

std::array<double, 6> HousnerBlock::pose(const Mode& m, const State& z) const {
  if (m.mech == Mechanism::Rest) return {0.0, 0.5 * shape_.height, 0.0, 0.0, 0.0, 0.0};
  // Centre relative to the pivot: R (sin phi, cos phi), phi = s alpha - theta; pivot at -s b/2.
  const double phi = m.side * alpha_ - z[kTheta];
  const double sp = std::sin(phi), cp = std::cos(phi), w = z[kOmega];
  return {-m.side * 0.5 * shape_.width + R_ * sp, R_ * cp, z[kTheta], -R_ * cp * w, R_ * sp * w, w};
}

std::array<double, 4> HousnerBlock::contact_forces(double t, const Mode& m, const State& z) const {
  const double W = shape_.mass * shape_.g;
  if (m.mech == Mechanism::Rest) {
    // Both corners: moment balance about the centre splits the load.
    const double N = W * (1.0 + av(t)), T = W * ah(t), k = shape_.height / shape_.width;
    const double NA = 0.5 * (N + k * T), NB = 0.5 * (N - k * T);
    const double TA = N != 0.0 ? T * NA / N : 0.5 * T;
    return {NA, TA, NB, T - TA};
  }
  const double phi = m.side * alpha_ - z[kTheta];
  const double acc = angular_acceleration(t, m, z), w = z[kOmega];
  const double N = W * normal_reaction(t, m, z);
  const double ax = -R_ * (std::sin(phi) * w * w + std::cos(phi) * acc);
  const double T = shape_.mass * ax + W * ah(t);
  return m.side > 0 ? std::array<double, 4>{N, T, 0.0, 0.0} : std::array<double, 4>{0.0, 0.0, N, T};
}

HousnerMode HousnerBlock::initial_mode(double t, const State& z) const {
  if (z[kTheta] != 0.0) return {Mechanism::Rock, z[kTheta] > 0 ? 1 : -1, std::fabs(z[kTheta]) > alpha_};
  if (z[kOmega] != 0.0) return {Mechanism::Rock, z[kOmega] > 0 ? 1 : -1, false};
  if (rest_holds(t)) return {Mechanism::Rest, 1, false};
  return {Mechanism::Rock, ah(t) >= 0 ? 1 : -1, false};
}

std::optional<std::string> HousnerBlock::validity_problem(const State& z) const {
  if (!std::isfinite(z[kTheta]) || !std::isfinite(z[kOmega])) return std::string("the state is not finite");
  if (std::fabs(z[kTheta]) >= 0.5 * M_PI)
    return "|w0| = " + number_text(std::fabs(z[kTheta])) + " rad: the block lies on its side (|w0| must be < pi/2)";
  return std::nullopt;
}

Transition<HousnerMode> HousnerBlock::after_impact(double t, const Mode& m, State& z) const {
  Transition<Mode> tr{m, false, int(RigidEventKind::Impact)};
  const double v_minus = z[kOmega];
  double v = e_ * v_minus;
  const int side = -m.side;  // the impacting corner becomes the pivot
  z[kTheta] = 0.0;
  // Deceleration of a swing on the new side at theta = 0, and the time the remaining impacts
  // take (geometric series of swings 2|v|/c shrinking by e each).
  const double a_h = ah(t), a_v = av(t);
  const double c = p_ * p_ * ((1.0 + a_v) * std::sin(alpha_) - side * a_h * std::cos(alpha_));
  const double remaining = 2.0 * std::fabs(v) / (c * (1.0 - e_));
  const double horizon = std::fmax(kAccumulationTime / p_, kAccumulationRelative * std::fabs(t) / (1.0 - e_));
  const bool settles = v == 0.0 || (c > 0.0 && e_ < 1.0 && remaining < horizon);
  if (settles) {
    v = 0.0;
    tr.next = rest_holds(t) ? Mode{Mechanism::Rest, side, false} : Mode{Mechanism::Rock, a_h >= 0 ? 1 : -1, false};
  } else {
    tr.next = Mode{Mechanism::Rock, side, false};
  }
  z[kWorkImpact] += 0.5 * io_ * (v * v - v_minus * v_minus);
  z[kOmega] = v;
  return tr;
}

Transition<HousnerMode> HousnerBlock::transition(double t, const Mode& m, State& z, int event) const {
  Transition<Mode> tr{m, false, int(RigidEventKind::Mode)};
  switch (event) {
    case kBreakpoint:
      tr.kind = int(RigidEventKind::GroundBreak);
      if (m.mech == Mechanism::Rest && !rest_holds(t)) {
        if (1.0 + av(t) <= 0.0) {
          tr.stop = true;
          tr.kind = int(RigidEventKind::Invalid);
        } else {
          tr.next = Mode{Mechanism::Rock, ah(t) >= 0 ? 1 : -1, false};
          tr.kind = int(RigidEventKind::Mode);
        }
      }
      break;
    case kEvImpact:
      return after_impact(t, m, z);
    case kEvOverturn:
      tr.stop = true;
      tr.kind = int(RigidEventKind::Overturn);
      break;
    case kEvAlpha:
      tr.next.beyond = !m.beyond;
      tr.kind = int(m.beyond ? RigidEventKind::WithinAlpha : RigidEventKind::BeyondAlpha);
      break;
    case kEvUplift:
      tr.next = Mode{Mechanism::Rock, ah(t) >= 0 ? 1 : -1, false};
      z[kOmega] = 0.0;
      break;
    case kEvLiftOff:
      tr.stop = true;
      tr.kind = int(RigidEventKind::Invalid);
      break;
  }
  return tr;
}

}  // namespace blockdyn
