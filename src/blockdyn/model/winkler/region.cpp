// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/winkler/region.hpp"

#include <algorithm>
#include <cmath>

namespace blockdyn {

double one_minus_cos(double w) {
  const double s = std::sin(0.5 * w);
  return 2.0 * s * s;
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
