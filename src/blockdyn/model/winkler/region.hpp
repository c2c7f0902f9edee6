// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Region: the part of the Winkler foundation displaced by a tilted rectangular block
// (lower envelope of the rectangle, including the air gap under a side edge next to a
// submerged corner). Exact closed forms: the spring compression s(X) is piecewise linear.
//
// Non-dimensional: block height 1, width r. The vertical coordinate is passed as
// h = y - 1/2 (height of the centre above its rigid-ground upright position) so that
// depths of order 1/k keep all their digits even for k = 1e9 and beyond.

namespace blockdyn {

struct RegionIntegrals {
  double area = 0.0;    // integral of s(X) dX
  double moment = 0.0;  // integral of (X - x) s(X) dX, about the block centre, signed with w
  double s2 = 0.0;      // integral of s(X)^2 dX
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
Tilt make_tilt(double w);

CornerArms corner_arms(double r, const Tilt& t, int side);
CornerArms corner_arms(double r, double w, int side);

// 1 - cos(w) without cancellation.
double one_minus_cos(double w);

// Height above the surface of the lowest corner, the other bottom corner and the upper corner on
// the lowest corner's side (the candidate third corner), for a block tilted by |w|.
struct CornerHeights {
  double lowest, other_bottom, upper_pivot_side;
};
CornerHeights corner_heights(double r, double h, const Tilt& t);
CornerHeights corner_heights(double r, double h, double w);

// Region integrals for a block of aspect ratio r with centre height h = y - 1/2 and tilt w.
RegionIntegrals region_integrals(double r, double h, const Tilt& t);
RegionIntegrals region_integrals(double r, double h, double w);

// Brute-force midpoint quadrature of the same integrals from the envelope s(X) (tests only).
RegionIntegrals region_integrals_quadrature(double r, double h, double w, int n);

}  // namespace blockdyn
