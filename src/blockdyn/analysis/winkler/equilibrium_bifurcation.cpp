// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/winkler/equilibrium_bifurcation.hpp"

#include "blockdyn/base/number_text.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

#include "blockdyn/analysis/sweep/parallel_map.hpp"

namespace blockdyn {

namespace {

constexpr double kMinK = 2.0;  // below it a resting block may have three corners submerged

WinklerParams params(double r, double k) {
  WinklerParams p;
  p.r = r;
  p.k = k;
  p.mu = 0.0;  // friction plays no part in static equilibria
  return p;
}

template <class F>
double solve_in_k(F f, double lo, double hi, double flo, double fhi) {
  std::uintmax_t it = 200;
  auto stop = [](double a, double b) { return std::fabs(b - a) <= 1e-13 * std::max(1.0, std::fabs(a)); };
  auto r = boost::math::tools::toms748_solve(f, lo, hi, flo, fhi, stop, it);
  return 0.5 * (r.first + r.second);
}

}  // namespace

double k_os_linearized(double r) { return (3.0 + std::sqrt(9.0 - 3.0 * r * r)) / (r * r); }

double k_os_small_angle(double r) { return 6.0 / (r * r) - 0.5; }

double fold_tilt_one_corner(double r) { return r >= 1.0 ? std::atan(1.0) : std::atan(std::tanh(std::atanh(r) / 3.0)); }

double k_uns_one_corner(double r) {
  const double t = std::tan(fold_tilt_one_corner(r));
  if (r >= 1.0) return 32.0 / 9.0;  // t = 1: (1 - t^2)^2 / (1 - t)^2 = (1 + t)^2 = 4
  const double u = 1.0 - t * t, v = r - t;
  return 8.0 * r * u * u / (9.0 * v * v * t);
}

double find_k_os(double r) {
  validate_equilibrium_params(params(r, kMinK));
  // The upright slope decreases in k for k > sqrt(3)/r (its r^2 k / 12 + 1/(4k) part grows), which
  // holds on k >= 2 for r <= 1; it is positive at k = 2. Double until it turns negative.
  auto f = [r](double k) { return upright_arm_slope(params(r, k)); };
  double lo = kMinK, flo = f(lo), hi = 2.0 * lo, fhi = f(hi);
  if (!(flo > 0.0)) throw std::domain_error("upright already stable at k = 2: no k_os");
  while (fhi > 0.0) {
    lo = hi;
    flo = fhi;
    hi *= 2.0;
    if (hi > 1e12) throw std::domain_error("no k_os below 1e12");
    fhi = f(hi);
  }
  if (fhi == 0.0) return hi;
  return solve_in_k(f, lo, hi, flo, fhi);
}

double reduced_arm_minimum(const WinklerParams& p, int scan_points) {
  const ReducedArm g(p);
  const int n = scan_points;
  double best = std::min(g.at0, g.at_alpha);
  std::vector<double> w(n + 1), v(n + 1);
  for (int i = 0; i <= n; ++i) {
    w[i] = (i == n) ? g.alpha : g.alpha * i / n;
    v[i] = g(w[i]);
    best = std::min(best, v[i]);
  }
  // Refine every interior local minimum of the scan (the global one could hide between nodes).
  for (int i = 1; i < n; ++i) {
    if (!(v[i] <= v[i - 1] && v[i] <= v[i + 1])) continue;
    const auto m = boost::math::tools::brent_find_minima(g, w[i - 1], w[i + 1], 50);
    best = std::min(best, m.second);
  }
  return best;
}

double find_k_uns(double r) {
  const double k_os = find_k_os(r);
  if (r == 1.0) {
    // Square block: w = alpha is always an equilibrium; the stable tilted branch merges with it
    // where its stability changes.
    auto f = [r](double k) { return diagonal_arm_slope(params(r, k)); };
    const double flo = f(kMinK), fhi = f(k_os);
    if (!(flo < 0.0 && fhi > 0.0)) throw std::domain_error("no stability change of w = alpha for r = 1");
    return solve_in_k(f, kMinK, k_os, flo, fhi);
  }
  auto m = [r](double k) { return reduced_arm_minimum(params(r, k)); };
  double hi = k_os, mhi = m(hi);
  if (!(mhi < 0.0)) throw std::domain_error("no stable tilted branch below k_os for r = " + number_text(r));
  // Walk down from k_os to the first k with no tilted equilibrium left.
  for (double step = 0.25;; step *= 2.0) {
    const double lo = std::max(kMinK, k_os - step);
    const double mlo = m(lo);
    if (mlo > 0.0) return solve_in_k(m, lo, hi, mlo, mhi);
    if (mlo == 0.0) return lo;
    if (lo == kMinK) throw std::domain_error("a stable equilibrium persists down to k = 2 for r = " + number_text(r));
    hi = lo;
    mhi = mlo;
  }
}

CriticalStiffness critical_stiffness(double r) {
  CriticalStiffness c;
  c.r = r;
  c.k_os = find_k_os(r);
  c.k_uns = find_k_uns(r);
  return c;
}

std::vector<CriticalStiffness> critical_curves(const std::vector<double>& rs, int threads) {
  return parallel_map<CriticalStiffness>(rs.size(), threads, [&](std::size_t i) { return critical_stiffness(rs[i]); });
}

std::vector<BifurcationSample> bifurcation_diagram(double r, const std::vector<double>& ks, int threads) {
  return parallel_map<BifurcationSample>(ks.size(), threads, [&](std::size_t i) {
    return BifurcationSample{ks[i], find_equilibria(params(r, ks[i]))};
  });
}

std::vector<double> sample_range(double a, double b, int n, bool logarithmic) {
  if (n < 1) throw std::invalid_argument("points = " + std::to_string(n) + " is out of range: must be >= 1");
  std::vector<double> out(n);
  for (int i = 0; i < n; ++i) {
    const double t = n == 1 ? 0.0 : double(i) / (n - 1);
    out[i] = (i == n - 1 && n > 1) ? b : (logarithmic ? a * std::pow(b / a, t) : a + (b - a) * t);
  }
  return out;
}

}  // namespace blockdyn
