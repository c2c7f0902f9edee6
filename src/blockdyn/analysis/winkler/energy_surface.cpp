// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/winkler/energy_surface.hpp"

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "blockdyn/model/winkler/energy.hpp"
#include "blockdyn/model/winkler/initial_conditions.hpp"
#include "blockdyn/model/winkler/region.hpp"

namespace blockdyn {

double potential(const WinklerParams& p, double h, double w) { return h + spring_energy(p, h, w); }

double heave_potential(const WinklerParams& p, double h) {
  // potential is even in w; scan [0, alpha] and refine the best grid point.
  const double a = p.alpha();
  constexpr int n = 64;
  int best = 0;
  double vbest = potential(p, h, 0.0);
  for (int i = 1; i <= n; ++i) {
    const double v = potential(p, h, a * i / n);
    if (v < vbest) {
      vbest = v;
      best = i;
    }
  }
  const double lo = a * std::max(0, best - 1) / n, hi = a * std::min(n, best + 1) / n;
  const auto m = boost::math::tools::brent_find_minima([&](double w) { return potential(p, h, w); }, lo, hi, 50);
  return std::min(vbest, m.second);
}

double heave_potential_closed_form(const WinklerParams& p, double h) { return h >= 0 ? h : h + 0.5 * p.k * h * h; }

double rock_potential(const WinklerParams& p, double w) { return potential(p, static_height(p, w, 1.0), w); }

std::vector<HeaveBoundaryPoint> heave_projection(const WinklerParams& p, double E, int n) {
  if (n < 2) throw std::invalid_argument("heave projection: n must be >= 2");
  // Range from the closed form (the numerical minimum is checked against it in the tests):
  // h + k h^2 / 2 = E below the surface, h = E above it.
  const double disc = 1.0 + 2.0 * p.k * E;
  if (disc < 0) return {};
  const double h_lo = (-1.0 - std::sqrt(disc)) / p.k;
  const double h_hi = E >= 0 ? E : (-1.0 + std::sqrt(disc)) / p.k;
  const double margin = 0.05 * (h_hi - h_lo);
  std::vector<HeaveBoundaryPoint> out(n);
  for (int i = 0; i < n; ++i) {
    const double h = h_lo - margin + (h_hi - h_lo + 2 * margin) * i / (n - 1);
    const double v = heave_potential(p, h);
    out[i] = {h + 0.5, v, v < E ? std::sqrt(2.0 * (E - v)) : 0.0};
  }
  return out;
}

std::vector<RockBoundaryPoint> rock_projection(const WinklerParams& p, double E, int n) {
  if (n < 2) throw std::invalid_argument("rock projection: n must be >= 2");
  const double a = p.alpha(), I = p.inertia();
  std::vector<RockBoundaryPoint> out(n);
  for (int i = 0; i < n; ++i) {
    const double w = -a + 2.0 * a * i / (n - 1);
    const double u = rock_potential(p, w);
    const double B = corner_arms(p.r, std::fabs(w), 1).B;
    const double room = std::max(0.0, E - u);
    out[i] = {w, u, std::sqrt(2.0 * room / I), std::sqrt(2.0 * room / (I + B * B))};
  }
  return out;
}

WinklerState state_on_energy_surface(const WinklerParams& p, double E, double w0, double y0, int vy_sign) {
  validate(p);
  if (!std::isfinite(w0) || std::fabs(w0) > p.alpha()) {
    std::ostringstream os;
    os << "w0 = " << w0 << " is out of range: must be in [-alpha, alpha] = [" << -p.alpha() << ", " << p.alpha() << "]";
    throw std::invalid_argument(os.str());
  }
  const double h0 = y0 - 0.5;
  const double v = potential(p, h0, w0);
  if (!std::isfinite(E) || !std::isfinite(y0) || E < v) {
    std::ostringstream os;
    os << "energy = " << E << " is out of range: at w0 = " << w0 << ", y0 = " << y0
       << " it must be >= the potential energy " << v;
    throw std::invalid_argument(os.str());
  }
  WinklerState z{};
  z[kW] = w0;
  z[kH] = h0;
  const double A = corner_arms(p.r, std::fabs(w0), 1).A;
  z[kX] = w0 >= 0 ? A : -A;
  z[kVY] = (vy_sign < 0 ? -1.0 : 1.0) * std::sqrt(2.0 * (E - v));
  return z;
}

}  // namespace blockdyn
