// SPDX-License-Identifier: Apache-2.0
#pragma once
// The "deformable" contact law of a contact point (spec block-assemblies.md, seed 002), piecewise
// smooth so that every switch is an event:
//   normal      F_N = k_N d + c_N d'  while the point is closed (d = -gap, the interpenetration);
//               it opens where F_N falls to 0 (the dashpot never pulls) and closes where both d
//               and k_N d + c_N d' are positive again;
//   tangential  stick: an elastic spring F_T = -k_T u on the elastic displacement u (u' = slip
//               rate) while k_T |u| <= mu_s F_N; slip in direction s: F_T = -s mu_k F_N, the spring
//               held at its cap u = s mu_k F_N / k_T, and slip goes on while the slip rate
//               s v_T - mu_k F_N' / k_T stays positive. No creep: a sticking point never slides.
// Energy: the springs store k_N d^2/2 (for d > 0) and k_T u^2/2; the dashpot and slip dissipate.
#include <cmath>
#include <cstdint>

namespace blockdyn {

enum class PointState : std::uint8_t { Open, Stick, SlipPos, SlipNeg };

inline bool is_closed(PointState s) { return s != PointState::Open; }
inline int slip_sign(PointState s) { return s == PointState::SlipPos ? 1 : s == PointState::SlipNeg ? -1 : 0; }

struct PointLaw {
  double kn = 1e7, kt = 1e7 / 3, cn = 0, mu_s = 1e9, mu_k = 1e9;
  // A 90 degree friction angle: the point never slips; its tangential spring is released when
  // the point opens.
  bool no_slip = false;
  // Hysteresis of the stick-to-slip switch (N): a sticking point slips once its spring exceeds the
  // static cone by this much. At the switch back to stick the sticking margin starts at zero with
  // zero slope (equal static and kinetic friction) and the integration error of the spring would
  // decide alone whether it slips again at once (zero-time stick/slip chatter).
  double stick_band = 0.0;
  // Hysteresis of the open-to-closed switch (N) of a point held open after zero-time chatter: it
  // closes once its force would push by this much, the rounding of k_N d at the blocks'
  // coordinates. (A point that opened where its force fell to zero, penetrating by rounding and
  // separating too slowly to leave, otherwise closes and opens again at one instant.)
  double close_band = 0.0;
  // mu_s = 0: the point never sticks; it stays in slip (no tangential force) while closed.
  bool frictionless() const { return mu_s == 0.0; }
};

inline double normal_force(const PointLaw& l, double d, double d_rate) { return l.kn * d + l.cn * d_rate; }

// Open points: >= 0 while the point stays open (negative once d > 0 and the force is pushing; by
// more than the band for a point held open).
inline double closing_margin(const PointLaw& l, double d, double d_rate, bool held = false) {
  const double f = normal_force(l, d, d_rate);
  return std::fmax(-l.kn * d, -f) + (held ? l.close_band : 0.0);
}

// Sticking points: >= 0 while the spring is inside the static cone.
inline double sticking_margin(const PointLaw& l, double fn, double u) {
  return l.no_slip ? 1.0 : l.mu_s * fn - l.kt * std::fabs(u) + l.stick_band;
}

// Slipping points in direction s: the slip rate (>= 0 while slipping goes on).
inline double slipping_rate(const PointLaw& l, int s, double v_t, double fn_rate) {
  if (l.frictionless()) return 1.0;
  return s * v_t - l.mu_k * fn_rate / l.kt;
}

}  // namespace blockdyn
