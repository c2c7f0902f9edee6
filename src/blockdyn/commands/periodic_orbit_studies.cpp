// SPDX-License-Identifier: Apache-2.0
// `periodic-orbits`: the rocking periodic orbits of the Housner block under a_H = K_s g sin(Omega t +
// phi) (seed 001 sec. 4.1) by shooting on the impact map, with Floquet multipliers; continuation in
// K_s or omega; existence and stability regions over (K_s, omega). The study's three modes are in
// analysis/forced/periodic_orbit_study.hpp; this file reads the options and assembles the report.
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "blockdyn/analysis/forced/periodic_orbit_study.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/study_command.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

std::vector<StudyOption> periodic_orbit_options() {
  const OrbitRegionOptions r;
  const ContinuationOptions c;
  auto x = [](double v) { return Settings::exact(v); };
  return {{"width", "block width b [m]", ""},
          {"height", "block height h [m]", ""},
          {"g", "gravity [m/s^2]", "9.81"},
          {"restitution", "restitution e in [0, 1] (default Housner's 1 - 1.5 sin^2 alpha)", ""},
          {"ks", "forcing amplitude K_s (g)", ""},
          {"beta", "forcing amplitude as K_s / alpha (instead of `ks`)", ""},
          {"omega", "forcing frequency omega = Omega / p", "2"},
          {"cycle", "m,n: 2m impacts per n forcing periods (seed 002)", "1,1", false, true},
          {"asymmetric",
           "shoot on the full 2m-impact map (default for m or n even; else the symmetric half map is used)", "", true},
          {"guess-phase", "start Newton here: forcing phase at an impact onto theta > 0 (rad)", ""},
          {"guess-velocity", "... and theta'/(alpha p) right after it (> 0)", ""},
          {"continue", "continue every orbit found in ks or omega (both directions)", ""},
          {"continue-min", "lower end of the continuation range (K_s in g, or omega)", ""},
          {"continue-max", "upper end of the continuation range", ""},
          {"ds", "initial arclength step (in (phase, velocity, K_s/alpha or omega))", x(c.ds)},
          {"max-points", "points per branch direction", std::to_string(c.max_points)},
          {"region", "map the existence and stability of the orbits over (K_s, omega)", "", true},
          {"ks-min", "region: smallest K_s (g)", x(r.ks_min)},
          {"ks-max", "region: largest K_s (g)", x(r.ks_max)},
          {"beta-min", "region: smallest K_s / alpha (instead of `ks-min`)", ""},
          {"beta-max", "region: largest K_s / alpha (instead of `ks-max`)", ""},
          {"ks-points", "region: amplitudes", std::to_string(r.ks_points)},
          {"omega-min", "region: smallest omega", x(r.omega_min)},
          {"omega-max", "region: largest omega", x(r.omega_max)},
          {"omega-points", "region: frequencies", std::to_string(r.omega_points)},
          {"threads", "region: worker threads (0: all cores)", "0"},
          {"rtol", "integrator relative tolerance", x(r.shooting.integrator.rtol)},
          {"atol", "integrator absolute tolerance", x(r.shooting.integrator.atol)}};
}

struct OrbitSetup {
  RockingForcing rf;
  OrbitType type;
  ShootingOptions so;
  std::optional<std::array<double, 2>> guess;
  std::string title;
};

std::array<int, 2> parse_cycle(const StudyOptions& o) {
  std::vector<double> v;
  try {
    v = o.numbers("cycle");
  } catch (const std::invalid_argument&) {
    v.clear();
  }
  if (v.size() != 2 || v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]) || std::fabs(v[0]) > 1e6 ||
      std::fabs(v[1]) > 1e6)
    throw std::invalid_argument("`cycle` must be m,n (two integers)");
  return {int(v[0]), int(v[1])};
}

void read_amplitude(const StudyOptions& o, RockingForcing& rf, bool region) {
  if (o.given("ks") && o.given("beta")) throw std::invalid_argument("give `ks` or `beta`, not both");
  if (!o.given("ks") && !o.given("beta") && !region) throw std::invalid_argument("`ks` (or `beta`) is needed");
  const double alpha = rf.alpha();
  rf.ks = o.given("beta") ? o.number("beta") * alpha : o.given("ks") ? o.number("ks") : 0.1;
  require_in_range(o.given("beta") ? "beta" : "ks", o.given("beta") ? o.number("beta") : rf.ks, 0, 1e3, false);
}

OrbitSetup orbit_setup(const StudyOptions& o) {
  if (!o.given("width") || !o.given("height")) throw std::invalid_argument("`width` and `height` are needed");
  OrbitSetup st;
  RockingForcing& rf = st.rf;
  const double width = o.number("width"), height = o.number("height");
  rf.shape = BlockShape{width, height, 1.0, o.number("g")};
  validate(rf.shape);
  if (o.given("restitution")) {
    rf.restitution = o.number("restitution");
    require_in_range("restitution", rf.restitution, 0, 1);
  }
  const bool region = o.flag("region");
  read_amplitude(o, rf, region);
  rf.omega = o.number("omega");
  require_in_range("omega", rf.omega, 0, 1e4, false);
  const std::array<int, 2> mn = parse_cycle(o);
  st.type = OrbitType{mn[0], mn[1], !o.flag("asymmetric") && mn[0] % 2 == 1 && mn[1] % 2 == 1};
  require_in_range("cycle m", mn[0], 1, 50);
  require_in_range("cycle n", mn[1], 1, 50);
  st.so.integrator.rtol = o.number("rtol");
  st.so.integrator.atol = o.number("atol");
  require_in_range("rtol", st.so.integrator.rtol, 0, 1e-3, false);
  require_in_range("atol", st.so.integrator.atol, 0, 1e-3, false);
  const bool guess_given = o.given("guess-phase") || o.given("guess-velocity");
  if (guess_given && !(o.given("guess-phase") && o.given("guess-velocity")))
    throw std::invalid_argument("`guess-phase` and `guess-velocity` go together");
  if (guess_given) {
    require_in_range("guess-velocity", o.number("guess-velocity"), 0, 1e3, false);
    st.guess = std::array<double, 2>{o.number("guess-phase"), o.number("guess-velocity")};
  }
  if (region && o.given("continue")) throw std::invalid_argument("give `region` or `continue`, not both");
  const OrbitType& type = st.type;
  st.title = "housner b/h=" + std::to_string(width / height).substr(0, 5) +
             " e=" + std::to_string(rf.e()).substr(0, 5) + " (" + std::to_string(type.m) + "," +
             std::to_string(type.n) + ")" + (type.symmetric ? " symmetric" : "");
  return st;
}

std::string linear_overlay(const OrbitSetup& st, bool with_point) {
  std::ostringstream extra;
  extra << st.rf.alpha() << ',' << st.rf.e() << ',' << st.type.n << ','
        << (st.type.symmetric && st.type.m == 1 ? 1 : 0);
  if (with_point) extra << ',' << st.rf.ks << ',' << st.rf.omega;
  return extra.str();
}

void merge(json& j, const json& part) {
  for (auto it = part.begin(); it != part.end(); ++it) j[it.key()] = it.value();
}

StudyReport region_report(const StudyOptions& o, const OrbitSetup& st, const StudyRequest& request) {
  OrbitRegionOptions ro;
  ro.ks_min = o.number("ks-min");
  ro.ks_max = o.number("ks-max");
  if (o.given("beta-min") || o.given("beta-max")) {
    if (o.given("ks-min") || o.given("ks-max"))
      throw std::invalid_argument("give `ks-min`/max or `beta-min`/max, not both");
    ro.ks_min = (o.given("beta-min") ? o.number("beta-min") : 0.0) * st.rf.alpha();
    ro.ks_max = (o.given("beta-max") ? o.number("beta-max") : 0.0) * st.rf.alpha();
  }
  ro.ks_points = o.small_integer("ks-points");
  ro.omega_min = o.number("omega-min");
  ro.omega_max = o.number("omega-max");
  ro.omega_points = o.small_integer("omega-points");
  ro.shooting = st.so;
  ro.threads = o.threads();
  validate(ro);
  const std::size_t n = std::size_t(ro.ks_points) * std::size_t(ro.omega_points);
  request.advance(0, n);
  const OrbitRegion r = orbit_region(st.rf, st.type, ro, [&](std::size_t d) { request.advance(d, n); });
  StudyReport rep;
  rep.summary = orbit_study_header(st.rf, st.type, st.so);
  rep.summary["mode"] = "region";
  merge(rep.summary, r.summary);
  if (request.wants("table")) rep.series.push_back({"table", region_table(st.rf, r.points)});
  rep.figure = FigureSpec{"periodic_orbits",
                          {"@csv:table", "@plot"},
                          {{"kind", {"region"}}, {"title", {st.title}}, {"linear", {linear_overlay(st, false)}}}};
  append_text(rep.text, "%zu points: %ld with orbits, %ld with a stable orbit\n", r.points.size(), r.with_orbits,
              r.with_stable_orbits);
  return rep;
}

StudyReport orbits_report(const OrbitSetup& st, const OrbitsAtPoint& at, const StudyRequest& request) {
  StudyReport rep;
  rep.summary = orbit_study_header(st.rf, st.type, st.so);
  merge(rep.summary, at.summary);
  rep.summary["mode"] = "orbits";
  const auto& orbits = at.orbits;
  if (request.asked("table")) rep.series.push_back({"table", orbits_table(st.rf, orbits)});
  if (request.figure) rep.series.push_back({"trajectories", orbit_trajectories_table(st.rf, orbits, st.so.integrator)});
  char title[256];
  std::snprintf(title, sizeof title, "%s, K_s=%.4g g, omega=%.4g", st.title.c_str(), st.rf.ks, st.rf.omega);
  rep.figure =
      FigureSpec{"periodic_orbits", {"@csv:trajectories", "@plot"}, {{"kind", {"orbits"}}, {"title", {title}}}};
  const double alpha = st.rf.alpha();
  append_text(rep.text, "%zu orbit(s) of type (%d,%d)%s at K_s = %g g (beta = %g), omega = %g:\n", orbits.size(),
              st.type.m, st.type.n, st.type.symmetric ? " symmetric" : "", st.rf.ks, st.rf.ks / alpha, st.rf.omega);
  for (const auto& x : orbits)
    append_text(rep.text, "  phase %.6f  velocity %.6f  |mu| %.4g %.4g  %s  max|theta|/alpha %.4g\n", x.phase,
                x.velocity, std::abs(x.multipliers[0]), std::abs(x.multipliers[1]), x.stable ? "stable" : "unstable",
                x.max_abs_rotation / alpha);
  return rep;
}

std::string branches_text(const json& bj, int count, std::size_t orbits) {
  std::string t;
  append_text(t, "%d branch(es) from %zu orbit(s):\n", count, orbits);
  for (const auto& b : bj) {
    append_text(t, "  branch %d (direction %+d): %zu points, end: %s\n", b["branch"].get<int>(),
                b["direction"].get<int>(), b["points"].size(), b["end"].get<std::string>().c_str());
    for (const auto& p : b["points"])
      if (!p["event"].get<std::string>().empty())
        append_text(t, "    %s at K_s = %.6g g (beta %.6g), omega = %.6g, velocity %.6g\n",
                    p["event"].get<std::string>().c_str(), p["ks"].get<double>(), p["beta"].get<double>(),
                    p["omega"].get<double>(), p["velocity"].get<double>());
  }
  return t;
}

ContinuationOptions continuation_options(const StudyOptions& o, const OrbitSetup& st) {
  ContinuationOptions co;
  co.parameter = o.text("continue");
  if (co.parameter != "ks" && co.parameter != "omega")
    throw std::invalid_argument("`continue` = '" + co.parameter + "' is not one of: ks, omega");
  if (!o.given("continue-min") || !o.given("continue-max"))
    throw std::invalid_argument("`continue` needs `continue-min` and `continue-max` (K_s in g, or omega)");
  co.min = o.number("continue-min");
  co.max = o.number("continue-max");
  co.ds = o.number("ds");
  co.ds_max = std::fmax(co.ds, co.ds_max);
  co.ds_min = std::fmin(co.ds_min, co.ds);
  co.max_points = o.small_integer("max-points");
  co.shooting = st.so;
  validate(co);
  return co;
}

StudyReport continuation_report(const StudyOptions& o, const OrbitSetup& st, const OrbitsAtPoint& at,
                                const StudyRequest& request) {
  const ContinuationOptions co = continuation_options(o, st);
  if (at.orbits.empty())
    throw std::runtime_error("no orbit found at the start point to continue (give `guess-phase`/`guess-velocity`)");
  const OrbitBranches b = continue_orbits(st.rf, st.type, at.orbits, co);
  StudyReport rep;
  rep.summary = orbit_study_header(st.rf, st.type, st.so);
  merge(rep.summary, at.summary);
  rep.summary["mode"] = "continue";
  merge(rep.summary, b.summary);
  if (request.wants("table")) rep.series.push_back({"table", branches_table(st.rf, b.rows)});
  rep.figure = FigureSpec{"periodic_orbits",
                          {"@csv:table", "@plot"},
                          {{"kind", {"branches"}},
                           {"parameter", {co.parameter}},
                           {"title", {st.title}},
                           {"linear", {linear_overlay(st, true)}}}};
  rep.text = branches_text(b.summary["branches"], b.count, at.orbits.size());
  return rep;
}

StudyReport periodic_orbits_study(const Settings& given, const StudyRequest& request) {
  const StudyOptions o(given, periodic_orbit_options());
  const OrbitSetup st = orbit_setup(o);
  if (o.flag("region")) return region_report(o, st, request);
  if (o.given("continue")) continuation_options(o, st);  // its usage errors before the shooting
  const OrbitsAtPoint at = orbits_at_point(st.rf, st.type, st.so, st.guess);
  if (!o.given("continue")) return orbits_report(st, at, request);
  return continuation_report(o, st, at, request);
}

}  // namespace

void add_periodic_orbit_studies(std::vector<StudyCommand>& to) {
  StudyCommand c{"periodic-orbits",
                 "rocking periodic orbits of the Housner block under a_H = K_s g sin(Omega t + phi) (seed 001 sec. "
                 "4.1) by shooting on the impact map, with Floquet multipliers; continuation in K_s or omega; "
                 "existence and stability regions over (K_s, omega). Cycle (m, n): 2m impacts per n forcing periods "
                 "(seed 002)",
                 17,
                 StudyOutputs::Series,
                 periodic_orbit_options(),
                 periodic_orbits_study};
  c.series_outputs = {{"table", "out", "CSV: the orbits, the branch points or the region grid"}};
  c.quiet_flag = true;
  c.progress_flag = true;
  to.push_back(c);
}

}  // namespace blockdyn
