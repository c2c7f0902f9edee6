// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/winkler/equilibria.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "blockdyn/model/winkler/energy.hpp"
#include "blockdyn/model/winkler/region.hpp"

namespace blockdyn {

namespace {

void require(const char* field, double v, double lo, double hi, const char* why) {
  if (!(std::isfinite(v) && v >= lo && v <= hi)) {
    std::ostringstream os;
    os << field << " = " << v << " is out of range: must be in [" << lo << ", " << hi << "] (" << why << ")";
    throw std::invalid_argument(os.str());
  }
}

// Polynomial extrapolation to 0 of f(d0), f(d0/2), f(d0/4), ... (Neville, n levels): the
// one-sided limits of arm(w)/w and of the secant slope at alpha are smooth in the offset.
template <class F>
double extrapolate_to_zero(F f, double d0, int n) {
  std::vector<double> T(n), d(n);
  for (int j = 0; j < n; ++j) {
    d[j] = d0 / double(1 << j);
    T[j] = f(d[j]);
  }
  for (int m = 1; m < n; ++m)
    for (int j = n - 1; j >= m; --j) T[j] = (d[j - m] * T[j] - d[j] * T[j - 1]) / (d[j - m] - d[j]);
  return T[n - 1];
}

double refine_root(const ReducedArm& g, double a, double b, double ga, double gb, double tol) {
  std::uintmax_t it = 200;
  auto stop = [tol](double x, double y) { return std::fabs(y - x) <= tol; };
  auto r = boost::math::tools::toms748_solve(g, a, b, ga, gb, stop, it);
  return 0.5 * (r.first + r.second);
}

}  // namespace

void validate_equilibrium_params(const WinklerParams& p) {
  require("r", p.r, 0.005, 1.0, "the thesis's equilibrium analysis covers blocks with r <= 1");
  require("k", p.k, 2.0, 1e10, "k >= 2 keeps at most two corners submerged at rest");
}

double resting_height(const WinklerParams& p, double w) {
  const double a = std::fabs(w);
  // Parametrise by the depth d of the lowest corner: h = top - d, Ry(d) increases strictly.
  const double top = -corner_heights(p.r, 0.0, a).lowest;
  const double kr = p.k / p.r;
  auto f = [&](double d) { return kr * region_integrals(p.r, top - d, a).area - 1.0; };
  // Start from the one-corner closed form (area d^2 / (2 sin cos)) or the upright depth 1/k.
  double hi = std::max(1.0 / p.k, std::sqrt(2.0 * p.r * std::sin(a) * std::cos(a) / p.k));
  double fhi = f(hi);
  double lo = 0.0, flo = -1.0;
  while (fhi < 0.0) {
    lo = hi;
    flo = fhi;
    hi *= 2.0;
    if (hi > 4.0) throw std::domain_error("no resting height: the block sinks completely");
    fhi = f(hi);
  }
  if (fhi == 0.0) return top - hi;
  std::uintmax_t it = 200;
  auto r = boost::math::tools::toms748_solve(f, lo, hi, flo, fhi, boost::math::tools::eps_tolerance<double>(52), it);
  return top - 0.5 * (r.first + r.second);
}

ArmSample arm_sample(const WinklerParams& p, double w) {
  ArmSample s;
  s.w = w;
  s.h = resting_height(p, w);
  const RegionIntegrals g = region_integrals(p.r, s.h, w);
  s.arm = g.moment / g.area;
  s.corners_below = g.corners_below;
  return s;
}

double upright_arm_slope(const WinklerParams& p) {
  // arm(w)/w is smooth on the two-corner range 0 < w < ~2/(r k) (the far corner emerges when
  // r w / 2 reaches the upright depth 1/k); sample well inside it and extrapolate.
  const double w_c = std::min(p.alpha(), 2.0 / (p.r * p.k));
  return extrapolate_to_zero([&](double d) { return equilibrium_arm(p, d) / d; }, 0.05 * w_c, 5);
}

double upright_arm_slope_linearized(double r, double k) { return 0.5 - r * r * k / 12.0 - 0.25 / k; }

double diagonal_arm_slope(const WinklerParams& p) {
  const double al = p.alpha();
  const double a0 = equilibrium_arm(p, al);
  return extrapolate_to_zero([&](double d) { return (a0 - equilibrium_arm(p, al - d)) / d; }, 0.01 * al, 5);
}

ReducedArm::ReducedArm(const WinklerParams& p_)
    : p(p_),
      alpha(p_.alpha()),
      square(p_.r == 1.0),
      upright_slope(upright_arm_slope(p_)),
      diagonal_slope(square ? diagonal_arm_slope(p_) : 0.0) {
  at0 = square ? upright_slope / alpha : upright_slope;
  at_alpha = square ? -diagonal_slope / alpha : equilibrium_arm(p, alpha) / alpha;
}

double ReducedArm::operator()(double w) const {
  if (w <= 0.0) return at0;
  if (w >= alpha) return at_alpha;
  const double a = equilibrium_arm(p, w);
  return square ? a / (w * (alpha - w)) : a / w;
}

const char* to_string(Stability s) {
  switch (s) {
    case Stability::Stable:
      return "stable";
    case Stability::Unstable:
      return "unstable";
    default:
      return "neutral";
  }
}

const char* to_string(EquilibriumBranch b) {
  switch (b) {
    case EquilibriumBranch::Upright:
      return "upright";
    case EquilibriumBranch::Diagonal:
      return "diagonal";
    default:
      return "tilted";
  }
}

namespace {

Stability from_slope(double s) {
  return s < 0.0 ? Stability::Stable : (s > 0.0 ? Stability::Unstable : Stability::Neutral);
}

Equilibrium make_equilibrium(const WinklerParams& p, double w, double slope, EquilibriumBranch b) {
  Equilibrium e;
  e.w = w;
  const ArmSample s = arm_sample(p, w);
  e.h = s.h;
  e.corners_below = s.corners_below;
  e.arm_slope = slope;
  e.stability = from_slope(slope);
  e.branch = b;
  return e;
}

}  // namespace

std::vector<Equilibrium> find_equilibria(const WinklerParams& p, const EquilibriumSearch& opt) {
  validate_equilibrium_params(p);
  if (opt.scan_points < 8) throw std::invalid_argument("scan_points must be >= 8");
  const double al = p.alpha();
  const bool square = (p.r == 1.0);
  const ReducedArm g(p);
  const double s0 = g.upright_slope, s_alpha = g.diagonal_slope;

  std::vector<Equilibrium> out;
  out.push_back(make_equilibrium(p, 0.0, s0, EquilibriumBranch::Upright));

  // Tilted equilibria: uniform scan of the reduced arm, then bracket and refine. A root pair
  // closer than a scan cell shows up as a local extremum of the wrong sign: minimise there.
  const int n = opt.scan_points;
  std::vector<double> w(n + 1), v(n + 1);
  for (int i = 0; i <= n; ++i) {
    w[i] = (i == n) ? al : al * i / n;
    v[i] = g(w[i]);
  }
  auto slope_at = [&](double x) {
    const double d = std::min({1e-6 * al, x, al - x});
    return (equilibrium_arm(p, x + d) - equilibrium_arm(p, x - d)) / (2.0 * d);
  };
  // g decreasing through a root <=> arm decreasing <=> stable.
  auto add_root = [&](double a, double b, double ga, double gb) {
    const double x = refine_root(g, a, b, ga, gb, opt.w_tol);
    Equilibrium e = make_equilibrium(p, x, slope_at(x), EquilibriumBranch::Tilted);
    e.stability = ga > 0.0 ? Stability::Stable : Stability::Unstable;
    out.push_back(e);
  };
  for (int i = 0; i < n; ++i) {
    if (i > 0 && v[i] == 0.0) {
      Equilibrium e = make_equilibrium(p, w[i], slope_at(w[i]), EquilibriumBranch::Tilted);
      out.push_back(e);
    } else if (v[i] * v[i + 1] < 0.0) {
      add_root(w[i], w[i + 1], v[i], v[i + 1]);
    }
  }
  for (int i = 1; i < n; ++i) {
    const double sg = v[i] > 0.0 ? 1.0 : -1.0;
    if (v[i] == 0.0 || sg * v[i - 1] <= 0.0 || sg * v[i + 1] <= 0.0) continue;
    if (!(sg * v[i] < sg * v[i - 1] && sg * v[i] <= sg * v[i + 1])) continue;
    auto m = boost::math::tools::brent_find_minima([&](double x) { return sg * g(x); }, w[i - 1], w[i + 1], 40);
    if (m.second >= 0.0) continue;
    add_root(w[i - 1], m.first, v[i - 1], sg * m.second);
    add_root(m.first, w[i + 1], sg * m.second, v[i + 1]);
  }
  if (square) {
    out.push_back(make_equilibrium(p, al, s_alpha, EquilibriumBranch::Diagonal));
  } else if (v[n] == 0.0) {
    out.push_back(make_equilibrium(p, al, slope_at(al - 1e-6 * al), EquilibriumBranch::Diagonal));
  }
  std::sort(out.begin(), out.end(), [](const Equilibrium& a, const Equilibrium& b) { return a.w < b.w; });
  return out;
}

std::vector<LandscapePoint> energy_landscape(const WinklerParams& p, int points) {
  validate_equilibrium_params(p);
  if (points < 2 || points > 1000000)
    throw std::invalid_argument("points = " + std::to_string(points) + " is out of range: must be in [2, 1000000]");
  const double al = p.alpha();
  const double h0 = resting_height(p, 0.0);
  const double p0 = spring_energy(p, h0, 0.0) + h0;
  auto arm = [&](double x) { return equilibrium_arm(p, x); };
  std::vector<LandscapePoint> out(points);
  double energy = 0.0;
  for (int i = 0; i < points; ++i) {
    const double wi = (i == points - 1) ? al : al * i / (points - 1);
    if (i > 0)
      // The tolerance is met by the embedded Gauss estimate, so the Kronrod value returned is far
      // more accurate; only cells with a corner crossing (a kink in arm) get subdivided.
      energy -= boost::math::quadrature::gauss_kronrod<double, 15>::integrate(arm, out[i - 1].w, wi, 10, 1e-9);
    const ArmSample s = arm_sample(p, wi);
    LandscapePoint& q = out[i];
    q.w = wi;
    q.h = s.h;
    q.arm = s.arm;
    q.energy = energy;
    q.potential = spring_energy(p, s.h, wi) + s.h - p0;
    q.corners_below = s.corners_below;
  }
  return out;
}

}  // namespace blockdyn
