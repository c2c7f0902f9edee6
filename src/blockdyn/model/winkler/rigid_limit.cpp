// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/winkler/rigid_limit.hpp"

#include <cmath>

#include "blockdyn/model/winkler/region.hpp"

namespace blockdyn {

RigidLimitReactions RigidGroundBlock::reactions(const Mode& m, const State& z) const {
  const CornerArms arm = corner_arms(p_.r, z[kRW], 1);
  const double I = p_.inertia(), A = arm.A, B = arm.B, vw = z[kRVW];
  RigidLimitReactions out{};
  if (m.contact) {
    out.aw = -A / (I + A * A + B * B);
    out.Rx = -B * out.aw - A * vw * vw;
  } else {
    const double c = m.friction_sign * p_.mu * B - A;
    out.aw = (1.0 - B * vw * vw) * c / (I - A * c);
  }
  out.Ry = 1.0 + A * out.aw - B * vw * vw;
  if (!m.contact) out.Rx = m.friction_sign * p_.mu * out.Ry;
  out.ax = out.Rx;
  return out;
}

void RigidGroundBlock::rhs(double, const Mode& m, const State& z, State& dz) const {
  const RigidLimitReactions a = reactions(m, z);
  dz[kRX] = m.contact ? 0.0 : z[kRVX];
  dz[kRW] = z[kRVW];
  dz[kRVX] = m.contact ? 0.0 : a.ax;
  dz[kRVW] = a.aw;
}

void RigidGroundBlock::complete(const Mode& m, State& z) const {
  if (!m.contact) return;
  const CornerArms arm = corner_arms(p_.r, z[kRW], 1);
  z[kRX] = m.anchor + arm.A;
  z[kRVX] = -arm.B * z[kRVW];
}

void RigidGroundBlock::events(double, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const {
  const RigidLimitReactions a = reactions(m, z);
  g[0] = z[kRW];
  g[1] = p_.alpha() - z[kRW];
  if (m.contact)
    g[2] = friction_margin(p_.mu, a.Ry, a.Rx);
  else
    g[2] = -m.friction_sign * (z[kRVX] + corner_arms(p_.r, z[kRW], 1).B * z[kRVW]);
  g[3] = a.Ry;
}

RigidGroundBlock::Mode RigidGroundBlock::stick_or_slip(const State& z, int slip_sign) const {
  Mode c{true, 0, z[kRX] - corner_arms(p_.r, z[kRW], 1).A};
  const RigidLimitReactions a = reactions(c, z);
  if (p_.mu > 0.0 && friction_margin(p_.mu, a.Ry, a.Rx) >= 0.0) return c;
  return Mode{false, slip_sign != 0 ? slip_sign : sign_of(a.Rx), 0.0};
}

RigidGroundBlock::Mode RigidGroundBlock::initial_mode(const State& z) const { return stick_or_slip(z, 0); }

double RigidGroundBlock::rest_reaction(double w) const {
  State z{corner_arms(p_.r, w, 1).A, w, 0.0, 0.0};
  return reactions(initial_mode(z), z).Ry;
}

Transition<RigidGroundBlock::Mode> RigidGroundBlock::transition(double, const Mode& m, State& z, int event) const {
  Transition<Mode> tr{m, false, 0};
  switch (event) {
    case 0:
      tr.stop = true;
      tr.kind = kWZero;
      break;
    case 1:
      tr.stop = true;
      tr.kind = kOverturn;
      break;
    case 3:
      tr.stop = true;
      tr.kind = kLiftOff;
      break;
    case 2:
      if (m.contact) {
        tr.next = Mode{false, sign_of(reactions(m, z).Rx), 0.0};
        tr.kind = kContactToSlide;
      } else {
        tr.next = stick_or_slip(z, -m.friction_sign);
        tr.kind = tr.next.contact ? kSlideToContact : kSlideReversal;
      }
      break;
  }
  return tr;
}

}  // namespace blockdyn
