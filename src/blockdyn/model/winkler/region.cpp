// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/winkler/region.hpp"

#include <algorithm>
#include <cmath>

namespace blockdyn {

Tilt make_tilt(double w) {
  double sn, c;
  ::sincos(std::fabs(w), &sn, &c);
  // 1 - cos = sin^2 / (1 + cos): no cancellation near w = 0, and cos > 0 here.
  return {w, sn, c, sn * sn / (1.0 + c), (w > 0.0) - (w < 0.0)};
}

CornerArms corner_arms(double r, const Tilt& t, int side) {
  const double sw = t.sign * t.s;  // sin w
  return {0.5 * (r * t.c - side * sw), 0.5 * (t.c + side * r * sw)};
}

CornerArms corner_arms(double r, double w, int side) { return corner_arms(r, make_tilt(w), side); }

double one_minus_cos(double w) {
  const double s = std::sin(0.5 * w);
  return 2.0 * s * s;
}

CornerHeights corner_heights(double r, double h, const Tilt& t) {
  // y = h + 1/2; corner offsets from the centre: lowest -(cos + r sin)/2, other bottom
  // (r sin - cos)/2, upper on the pivot side (cos - r sin)/2. The 1/2 is folded in exactly.
  const double rs = r * t.s;
  return {h - 0.5 * (rs - t.omc), h + 0.5 * (rs + t.omc), h + 0.5 * (2.0 - t.omc - rs)};
}

CornerHeights corner_heights(double r, double h, double w) { return corner_heights(r, h, make_tilt(w)); }

namespace {

struct Accum {
  double area = 0, moment = 0, s2 = 0;
};

// Adds the integrals of max(0, s) over the linear piece from (a, sa) to (b, sb), a <= b.
void add_segment(double a, double sa, double b, double sb, Accum& acc) {
  if (sa <= 0.0 && sb <= 0.0) return;
  if (sa < 0.0) {  // clip at the surface crossing
    a = a + (b - a) * (sa / (sa - sb));
    sa = 0.0;
  } else if (sb < 0.0) {
    b = a + (b - a) * (sa / (sa - sb));
    sb = 0.0;
  }
  const double L = b - a;
  acc.area += 0.5 * L * (sa + sb);
  acc.moment += L / 6.0 * ((2.0 * a + b) * sa + (a + 2.0 * b) * sb);
  acc.s2 += L / 3.0 * (sa * sa + sa * sb + sb * sb);
}

}  // namespace

RegionIntegrals region_integrals(double r, double h, double w) {
  return region_integrals(r, h, make_tilt(w));
}

RegionIntegrals region_integrals(double r, double h, const Tilt& t) {
  const double c = t.c, sn = t.s;
  const CornerHeights y = corner_heights(r, h, t);
  // Envelope for tilt a >= 0, abscissae about the centre: upper-left corner -> lower-left
  // (lowest) -> lower-right corner.
  const double x_ul = -0.5 * (r * c + sn), x_ll = -0.5 * (r * c - sn), x_lr = 0.5 * (r * c + sn);
  const double s_ul = -y.upper_pivot_side, s_ll = -y.lowest, s_lr = -y.other_bottom;
  Accum acc;
  add_segment(x_ul, s_ul, x_ll, s_ll, acc);
  add_segment(x_ll, s_ll, x_lr, s_lr, acc);
  RegionIntegrals out;
  out.area = acc.area;
  out.moment = (t.sign < 0) ? -acc.moment : acc.moment;
  out.s2 = acc.s2;
  out.depth_pivot_end = std::max(0.0, s_ul);
  out.depth_far_end = std::max(0.0, s_lr);
  out.corners_below = int(s_ll > 0.0) + int(s_lr > 0.0) + int(s_ul > 0.0);
  return out;
}

RegionIntegrals region_integrals_quadrature(double r, double h, double w, int n) {
  // Lower envelope of the rotated rectangle evaluated directly from its four corners.
  const double c = std::cos(w), sn = std::sin(w), y = h + 0.5;
  double cx[4], cy[4];
  const double bx[4] = {-r / 2, r / 2, r / 2, -r / 2}, by[4] = {-0.5, -0.5, 0.5, 0.5};
  double xmin = 1e300, xmax = -1e300;
  for (int i = 0; i < 4; ++i) {
    cx[i] = bx[i] * c - by[i] * sn;
    cy[i] = y + bx[i] * sn + by[i] * c;
    xmin = std::min(xmin, cx[i]);
    xmax = std::max(xmax, cx[i]);
  }
  RegionIntegrals out;
  const double dx = (xmax - xmin) / n;
  for (int j = 0; j < n; ++j) {
    const double X = xmin + (j + 0.5) * dx;
    double ylow = 1e300;
    for (int i = 0; i < 4; ++i) {  // lowest crossing of the vertical line with the four edges
      const int k = (i + 1) % 4;
      const double x0 = cx[i], x1 = cx[k];
      if ((X - x0) * (X - x1) > 0.0 || x0 == x1) continue;
      const double u = (X - x0) / (x1 - x0);
      ylow = std::min(ylow, cy[i] + u * (cy[k] - cy[i]));
    }
    const double s = std::max(0.0, -ylow);
    out.area += s * dx;
    out.moment += X * s * dx;
    out.s2 += s * s * dx;
  }
  for (int i = 0; i < 4; ++i) out.corners_below += int(cy[i] < 0.0);
  return out;
}

}  // namespace blockdyn
