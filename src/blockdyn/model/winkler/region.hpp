// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Region: the part of the Winkler foundation displaced by a tilted rectangular block
// (lower envelope of the rectangle, including the air gap under a side edge next to a
// submerged corner). Exact closed forms: the spring compression s(X) is piecewise linear.
//
// Non-dimensional: block height 1, width r. The vertical coordinate is passed as
// h = y - 1/2 (height of the centre above its rigid-ground upright position) so that
// depths of order 1/k keep all their digits even for k = 1e9 and beyond.

#include <algorithm>
#include <cmath>

#include "blockdyn/model/common/quarter_turn_sincos.hpp"

namespace blockdyn {

struct RegionIntegrals {
  double area = 0.0;             // integral of s(X) dX
  double moment = 0.0;           // integral of (X - x) s(X) dX, about the block centre, signed with w
  double s2 = 0.0;               // integral of s(X)^2 dX
  double depth_pivot_end = 0.0;  // compression at the Region's end on the lowest corner's edge
  double depth_far_end = 0.0;    // compression at the Region's end on the bottom-edge side
  int corners_below = 0;         // corners strictly below the surface
};

// Kinematics of the corner on side s (s = +1: lower-left corner, the lowest one for w > 0;
// s = -1: lower-right corner, the lowest one for w < 0). Relative to the centre the corner
// sits at (-s A_s(w), -B_s(w)); its horizontal velocity is x' + B_s(w) w'.
struct CornerArms {
  double A;  // (r cos w - s sin w) / 2
  double B;  // (cos w + s r sin w) / 2
};

// The trigonometry of a tilt, computed once per state (one sincos) and shared by all the
// geometry below. Valid for |w| < pi/2 (the model stops at |w| = alpha < pi/2).
struct Tilt {
  double w;    // signed tilt
  double s;    // sin|w|
  double c;    // cos w
  double omc;  // 1 - cos w, without cancellation
  int sign;    // sign of w (0 at w = 0)
};
// The geometry below is evaluated at every right-hand side: defined here so that it inlines
// into the model's force computation.
inline Tilt make_tilt(double w) {
  double sn, c;
  sincos_quarter_turn(std::fabs(w), sn, c);
  // 1 - cos = sin^2 / (1 + cos): no cancellation near w = 0, and cos > 0 here.
  return {w, sn, c, sn * sn / (1.0 + c), (w > 0.0) - (w < 0.0)};
}

inline CornerArms corner_arms(double r, const Tilt& t, int side) {
  const double sw = t.sign * t.s;  // sin w
  return {0.5 * (r * t.c - side * sw), 0.5 * (t.c + side * r * sw)};
}

inline CornerArms corner_arms(double r, double w, int side) { return corner_arms(r, make_tilt(w), side); }

// 1 - cos(w) without cancellation.
double one_minus_cos(double w);

// Height above the surface of the lowest corner, the other bottom corner and the upper corner on
// the lowest corner's side (the candidate third corner), for a block tilted by |w|.
struct CornerHeights {
  double lowest, other_bottom, upper_pivot_side;
};
inline CornerHeights corner_heights(double r, double h, const Tilt& t) {
  // y = h + 1/2; corner offsets from the centre: lowest -(cos + r sin)/2, other bottom
  // (r sin - cos)/2, upper on the pivot side (cos - r sin)/2. The 1/2 is folded in exactly.
  const double rs = r * t.s;
  return {h - 0.5 * (rs - t.omc), h + 0.5 * (rs + t.omc), h + 0.5 * (2.0 - t.omc - rs)};
}

inline CornerHeights corner_heights(double r, double h, double w) { return corner_heights(r, h, make_tilt(w)); }

// The same heights' time derivatives, given h' and w'. At w = 0 the lowest corner is the one |w|
// makes lowest as it grows.
inline CornerHeights corner_height_rates(double r, const Tilt& t, double h_rate, double w_rate) {
  const double abs_rate = t.sign != 0 ? t.sign * w_rate : std::fabs(w_rate);
  const double rs_rate = r * t.c * abs_rate;  // d(r sin|w|)/dt
  const double omc_rate = t.s * abs_rate;     // d(1 - cos w)/dt
  return {h_rate - 0.5 * (rs_rate - omc_rate), h_rate + 0.5 * (rs_rate + omc_rate),
          h_rate - 0.5 * (omc_rate + rs_rate)};
}

// Their second derivatives, given h'', w' and w''. With u = |w| (u' = sign w', at w = 0 the sign
// of w'): d2(r sin u) = r (cos u u'' - sin u u'^2), d2(1 - cos u) = sin u u'' + cos u u'^2.
inline CornerHeights corner_height_accelerations(double r, const Tilt& t, double h_acc, double w_rate, double w_acc) {
  const int sg = t.sign != 0 ? t.sign : (w_rate >= 0.0 ? 1 : -1);
  const double u1 = sg * w_rate, u2 = sg * w_acc;
  const double rs_acc = r * (t.c * u2 - t.s * u1 * u1);
  const double omc_acc = t.s * u2 + t.c * u1 * u1;
  return {h_acc - 0.5 * (rs_acc - omc_acc), h_acc + 0.5 * (rs_acc + omc_acc), h_acc - 0.5 * (omc_acc + rs_acc)};
}

namespace region_detail {

struct Accum {
  double area = 0, moment = 0, s2 = 0;
};

// Adds the integrals of max(0, s) over the linear piece from (a, sa) to (b, sb), a <= b.
inline void add_segment(double a, double sa, double b, double sb, Accum& acc) {
  if (sa <= 0.0 && sb <= 0.0) return;
  if (sa < 0.0) {  // clip at the surface crossing
    a = a + (b - a) * (sa / (sa - sb));
    sa = 0.0;
  } else if (sb < 0.0) {
    b = a + (b - a) * (sa / (sa - sb));
    sb = 0.0;
  }
  // Multiplied by 1/6 and 1/3 rather than divided: two divisions fewer on every right-hand side.
  constexpr double kSixth = 1.0 / 6.0, kThird = 1.0 / 3.0;
  const double L = b - a;
  acc.area += 0.5 * L * (sa + sb);
  acc.moment += kSixth * L * ((2.0 * a + b) * sa + (a + 2.0 * b) * sb);
  acc.s2 += kThird * L * (sa * sa + sa * sb + sb * sb);
}

}  // namespace region_detail

// Region integrals for a block of aspect ratio r with centre height h = y - 1/2 and tilt w.
inline RegionIntegrals region_integrals(double r, double h, const Tilt& t) {
  const double c = t.c, sn = t.s;
  const CornerHeights y = corner_heights(r, h, t);
  // Envelope for tilt a >= 0, abscissae about the centre: upper-left corner -> lower-left
  // (lowest) -> lower-right corner.
  const double x_ul = -0.5 * (r * c + sn), x_ll = -0.5 * (r * c - sn), x_lr = 0.5 * (r * c + sn);
  const double s_ul = -y.upper_pivot_side, s_ll = -y.lowest, s_lr = -y.other_bottom;
  region_detail::Accum acc;
  region_detail::add_segment(x_ul, s_ul, x_ll, s_ll, acc);
  region_detail::add_segment(x_ll, s_ll, x_lr, s_lr, acc);
  RegionIntegrals out;
  out.area = acc.area;
  out.moment = (t.sign < 0) ? -acc.moment : acc.moment;
  out.s2 = acc.s2;
  out.depth_pivot_end = std::max(0.0, s_ul);
  out.depth_far_end = std::max(0.0, s_lr);
  out.corners_below = int(s_ll > 0.0) + int(s_lr > 0.0) + int(s_ul > 0.0);
  return out;
}

inline RegionIntegrals region_integrals(double r, double h, double w) { return region_integrals(r, h, make_tilt(w)); }

// Brute-force midpoint quadrature of the same integrals from the envelope s(X) (tests only).
RegionIntegrals region_integrals_quadrature(double r, double h, double w, int n);

}  // namespace blockdyn
