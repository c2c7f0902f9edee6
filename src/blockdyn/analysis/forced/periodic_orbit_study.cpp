// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/periodic_orbit_study.hpp"

#include <cmath>
#include <cstdio>

#include "blockdyn/analysis/forced/linear_rocking_orbits.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

json cx(const std::complex<double>& z) { return json::array({z.real(), z.imag()}); }

json orbit_json(const PeriodicOrbit& o, const RockingForcing& f) {
  json j;
  j["phase"] = o.phase;
  j["velocity"] = o.velocity;
  j["velocity_si"] = o.velocity * f.alpha() * f.p();
  j["period"] = o.period;
  j["max_abs_rotation"] = o.max_abs_rotation;
  j["max_abs_rotation_over_alpha"] = o.max_abs_rotation / f.alpha();
  j["multipliers"] = {cx(o.multipliers[0]), cx(o.multipliers[1])};
  j["multipliers_fd"] = {cx(o.multipliers_fd[0]), cx(o.multipliers_fd[1])};
  j["stable"] = o.stable;
  j["lyapunov_exponent"] = o.lyapunov_exponent;
  j["iterations"] = o.iterations;
  j["residual"] = o.residual;
  json imp = json::array();
  for (const auto& i : o.impacts)
    imp.push_back({{"t", i.t}, {"phase", i.phase}, {"rate_before", i.rate_before}, {"rate_after", i.rate_after}});
  j["impacts"] = imp;
  return j;
}

bool has_linear_theory(const OrbitType& type) { return type.symmetric && type.m == 1; }

}  // namespace

json orbit_study_header(const RockingForcing& f, const OrbitType& type, const ShootingOptions& so) {
  json j;
  j["run"] = run_info();
  j["model"] = {{"model", "housner"}, {"width", f.shape.width}, {"height", f.shape.height},
                {"g", f.shape.g},     {"restitution", f.e()},   {"alpha", f.alpha()},
                {"p", f.p()}};
  j["forcing"] =
      "a_H = K_s g sin(Omega t + phi), Omega = omega p; phase = Omega t + phi mod 2 pi at an impact onto "
      "theta > 0, velocity = theta'/(alpha p) right after it";
  j["convention"] = {
      {"cycle", {type.m, type.n}},
      {"seed_002", "(m, n): 2m impacts per n forcing periods"},
      {"seed_001", {{"n", type.n}, {"k", 2 * type.m}, {"meaning", "k impacts per period 2 pi n / omega"}}},
      {"symmetric", type.symmetric}};
  j["integrator"] = to_json(so.integrator);
  return j;
}

OrbitsAtPoint orbits_at_point(const RockingForcing& f, const OrbitType& type, const ShootingOptions& so,
                              const std::optional<std::array<double, 2>>& guess) {
  std::vector<std::array<double, 2>> guesses;
  if (guess)
    guesses.push_back(*guess);
  else
    guesses = orbit_guesses(f, type, so.integrator);
  OrbitsAtPoint r;
  r.orbits = find_periodic_orbits(f, type, guesses, so);
  const double alpha = f.alpha();
  json& j = r.summary;
  j["ks"] = f.ks;
  j["beta"] = f.ks / alpha;
  j["omega"] = f.omega;
  j["guesses"] = guesses.size();
  json oj = json::array();
  for (const auto& o : r.orbits) oj.push_back(orbit_json(o, f));
  j["orbits"] = oj;
  if (has_linear_theory(type)) {
    json lj = json::array();
    for (const auto& l : linear_symmetric_orbits(f.ks / alpha, f.omega, f.e(), type.n))
      lj.push_back({{"phase", l.phase},
                    {"velocity", l.velocity},
                    {"valid", l.valid},
                    {"multipliers", {cx(l.multipliers[0]), cx(l.multipliers[1])}}});
    j["linear_theory"] = lj;
    j["linear_fold_ks"] = alpha * linear_symmetric_fold_beta(f.omega, f.e(), type.n);
  }
  return r;
}

CellTable orbits_table(const RockingForcing& f, const std::vector<PeriodicOrbit>& orbits) {
  CellTable t;
  t.columns = {"orbit",  "phase",  "velocity", "velocity_si", "period", "max_abs_rotation",
               "mu1_re", "mu1_im", "mu2_re",   "mu2_im",      "stable", "lyapunov_exponent"};
  for (std::size_t k = 0; k < orbits.size(); ++k) {
    const auto& o = orbits[k];
    t.rows.push_back({k, o.phase, o.velocity, o.velocity * f.alpha() * f.p(), o.period, o.max_abs_rotation,
                      o.multipliers[0].real(), o.multipliers[0].imag(), o.multipliers[1].real(),
                      o.multipliers[1].imag(), int(o.stable), o.lyapunov_exponent});
  }
  return t;
}

CellTable orbit_trajectories_table(const RockingForcing& f, const std::vector<PeriodicOrbit>& orbits,
                                   const IntegratorOptions& integ) {
  CellTable t;
  t.columns = {"orbit", "stable", "t", "theta", "rate"};
  for (std::size_t k = 0; k < orbits.size(); ++k) {
    const OrbitSamples sm = orbit_trajectory(f, orbits[k], integ);
    for (std::size_t i = 0; i < sm.t.size(); ++i)
      t.rows.push_back({k, int(orbits[k].stable), sm.t[i], sm.theta[i], sm.rate[i]});
  }
  return t;
}

OrbitBranches continue_orbits(const RockingForcing& f, const OrbitType& type, const std::vector<PeriodicOrbit>& orbits,
                              ContinuationOptions co) {
  OrbitBranches r;
  const double alpha = f.alpha();
  r.summary["continuation"] = {{"parameter", co.parameter},
                               {"min", co.min},
                               {"max", co.max},
                               {"ds", co.ds},
                               {"max_points", co.max_points},
                               {"multipliers", "eigenvalues of the shooting Jacobian"}};
  json bj = json::array();
  for (const auto& o : orbits) {
    for (int dir : {-1, 1}) {
      co.direction = dir;
      const Branch b = continue_orbit(f, type, o.phase, o.velocity, co);
      json pts = json::array();
      for (const auto& p : b.points) {
        pts.push_back({{"ks", p.ks},
                       {"beta", p.ks / alpha},
                       {"omega", p.omega},
                       {"phase", p.phase},
                       {"velocity", p.velocity},
                       {"multipliers", {cx(p.multipliers[0]), cx(p.multipliers[1])}},
                       {"stable", p.stable},
                       {"event", p.event}});
        r.rows.push_back({r.count, p});
      }
      bj.push_back({{"branch", r.count},
                    {"from_orbit", &o - orbits.data()},
                    {"direction", dir},
                    {"end", b.end},
                    {"points", pts}});
      ++r.count;
    }
  }
  r.summary["branches"] = bj;
  return r;
}

CellTable branches_table(const RockingForcing& f, const std::vector<BranchRow>& rows) {
  CellTable t;
  t.columns = {"branch",  "ks",     "beta",   "omega",  "phase",  "velocity", "mu1_abs",
               "mu2_abs", "mu1_re", "mu1_im", "mu2_re", "mu2_im", "stable",   "event"};
  for (const BranchRow& r : rows) {
    const BranchPoint& p = r.point;
    t.rows.push_back({r.branch, p.ks, p.ks / f.alpha(), p.omega, p.phase, p.velocity, std::abs(p.multipliers[0]),
                      std::abs(p.multipliers[1]), p.multipliers[0].real(), p.multipliers[0].imag(),
                      p.multipliers[1].real(), p.multipliers[1].imag(), int(p.stable), p.event});
  }
  return t;
}

OrbitRegion orbit_region(const RockingForcing& f, const OrbitType& type, const OrbitRegionOptions& ro,
                         const std::function<void(std::size_t)>& progress) {
  OrbitRegion r;
  r.points = orbit_region_map(f, type, ro, progress);
  const double alpha = f.alpha();
  json arr = json::array();
  for (const auto& p : r.points) {
    arr.push_back({{"ks", p.ks},
                   {"beta", p.ks / alpha},
                   {"omega", p.omega},
                   {"orbits", p.orbits},
                   {"stable", p.stable},
                   {"phase", finite_or_null(p.phase)},
                   {"velocity", finite_or_null(p.velocity)},
                   {"max_multiplier", finite_or_null(p.max_multiplier)},
                   {"linear_orbits", p.linear_orbits < 0 ? json(nullptr) : json(p.linear_orbits)},
                   {"linear_stable", p.linear_stable < 0 ? json(nullptr) : json(p.linear_stable)}});
    r.with_orbits += p.orbits > 0;
    r.with_stable_orbits += p.stable > 0;
  }
  r.summary["points"] = arr;
  r.summary["counts"] = {
      {"points", r.points.size()}, {"with_orbits", r.with_orbits}, {"with_stable_orbits", r.with_stable_orbits}};
  if (has_linear_theory(type)) {
    json fold = json::array();
    for (int k = 0; k <= 200; ++k) {
      const double w = ro.omega_min + (ro.omega_max - ro.omega_min) * k / 200.0;
      fold.push_back({{"omega", w}, {"ks", alpha * linear_symmetric_fold_beta(w, f.e(), type.n)}});
    }
    r.summary["linear_fold"] = fold;
  }
  return r;
}

CellTable region_table(const RockingForcing& f, const std::vector<OrbitRegionPoint>& points) {
  CellTable t;
  t.columns = {"ks",    "beta",     "omega",          "orbits",        "stable",
               "phase", "velocity", "max_multiplier", "linear_orbits", "linear_stable"};
  for (const auto& p : points)
    t.rows.push_back({p.ks, p.ks / f.alpha(), p.omega, p.orbits, p.stable, p.phase, p.velocity, p.max_multiplier,
                      p.linear_orbits, p.linear_stable});
  return t;
}

}  // namespace blockdyn
