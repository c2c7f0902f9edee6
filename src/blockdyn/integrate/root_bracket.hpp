// SPDX-License-Identifier: Apache-2.0
#pragma once
// Bracketing root solver for event location on a step's dense output.
// TOMS 748 (Alefeld, Potra & Shi) from Boost.Math, iterated until the bracket is a few ulps wide.
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

namespace blockdyn {

// Root of g on [a, b] given g(a) >= 0 > g(b). Returns the left end of the final bracket
// (the last time at which g was not yet negative) so that the event state is never past it.
template <class G>
double locate_root(G&& g, double a, double b, double ga, double gb) {
  if (ga <= 0.0) return a;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  auto tol = [](double lo, double hi) {
    return std::fabs(hi - lo) <= 4.0 * eps * std::fmax(std::fabs(lo), std::fabs(hi)) + 1e-300;
  };
  std::uintmax_t iters = 200;
  auto r = boost::math::tools::toms748_solve(g, a, b, ga, gb, tol, iters);
  return r.first;
}

}  // namespace blockdyn
