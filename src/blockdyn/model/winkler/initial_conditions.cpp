// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/winkler/initial_conditions.hpp"

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "blockdyn/model/winkler/region.hpp"
#include "blockdyn/model/winkler/rigid_limit.hpp"

namespace blockdyn {

double static_height(const WinklerParams& p, double w, double Ry) {
  const double a = std::fabs(w);
  const CornerHeights at_surface = corner_heights(p.r, 0.0, a);  // heights when h = 0
  // One submerged corner: area d^2 / (2 sin cos) = r Ry / k  (closed form of the thesis).
  const double d = std::sqrt(2.0 * p.r * std::sin(a) * std::cos(a) * Ry / p.k);
  const double h1 = -at_surface.lowest - d;
  if (a > 0.0 && corner_heights(p.r, h1, a).other_bottom >= 0.0 && corner_heights(p.r, h1, a).upper_pivot_side >= 0.0)
    return h1;
  // Two corners: Ry(h) decreases monotonically in h; bracket and solve.
  auto f = [&](double h) { return p.k / p.r * region_integrals(p.r, h, a).area - Ry; };
  double hi = -at_surface.lowest;  // lowest corner at the surface: Ry = 0
  // 1/k may be below the spacing of doubles at hi: start the bracket at least a few ulps down,
  // and widen it a bounded number of times.
  double lo = hi - std::fmax(1.0 / p.k, 4.0 * (std::nextafter(std::fabs(hi), INFINITY) - std::fabs(hi)) + 1e-300);
  for (int i = 0; f(lo) < 0.0; ++i) {
    lo = hi - 2.0 * (hi - lo);
    if (hi - lo > 10.0 || i > 200) throw std::invalid_argument("cannot find a resting height for this tilt");
  }
  std::uintmax_t it = 200;
  auto tol = boost::math::tools::eps_tolerance<double>(52);
  auto r = boost::math::tools::toms748_solve(f, lo, hi, tol, it);
  return 0.5 * (r.first + r.second);
}

WinklerState ic1(const WinklerParams& p, std::optional<double> w0_opt) {
  const double w0 = w0_opt.value_or(0.5 * p.alpha());
  if (!std::isfinite(w0) || std::fabs(w0) > p.alpha() || w0 == 0.0) {
    std::ostringstream os;
    os << "w0 = " << w0 << " is out of range: ic1 needs 0 < |w0| <= alpha = atan(r) = " << p.alpha();
    throw std::invalid_argument(os.str());
  }
  const double a = std::fabs(w0);
  const RigidGroundBlock rigid(p);
  const double Ry0 = rigid.rest_reaction(a);
  WinklerState z{};
  z[kW] = w0;
  z[kH] = static_height(p, a, Ry0);
  const double A = corner_arms(p.r, a, 1).A;
  z[kX] = (w0 > 0.0) ? A : -A;
  return z;
}

WinklerState ic2(const WinklerParams& p) {
  WinklerState z{};
  z[kH] = -1.0 / p.k;
  z[kX] = p.r / 2.0;
  z[kVX] = 0.06;
  z[kVY] = 0.0001;
  z[kVW] = 6.0 * z[kVX] / (1.0 + p.r * p.r);
  return z;
}

}  // namespace blockdyn
