// SPDX-License-Identifier: Apache-2.0
// Studies of one orbit of the free block on the Winkler foundation: `response` (the long-term
// response type with its metrics, swings and phase portraits, thesis 4.4), `poincare` (the section
// w = 0, thesis 5.2.1) and `energy-surface` (the projections of the energy surface with the
// trajectory, thesis 5.1).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/winkler/energy_surface.hpp"
#include "blockdyn/analysis/winkler/poincare.hpp"
#include "blockdyn/analysis/winkler/response_type.hpp"
#include "blockdyn/analysis/winkler/swings.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/winkler_orbit.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/model/winkler/energy.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

std::vector<StudyOption> with_orbit(std::vector<StudyOption> own) {
  std::vector<StudyOption> o = winkler_orbit_options();
  o.insert(o.end(), own.begin(), own.end());
  return o;
}

json or_null(const std::optional<double>& v) { return v ? json(*v) : json(); }

// ---------------------------------------------------------------- response

std::vector<StudyOption> response_options() {
  const ResponseOptions d;
  const ResponseCriteria& c = d.criteria;
  auto x = [](double v) { return Settings::exact(v); };
  return with_orbit({
      {"t-end", "final time (> 0)", x(d.t_end)},
      {"late-fraction", "late window starts at this fraction of t-end, in [0, 1)", x(d.late_fraction)},
      {"quadrature-dt", "largest sample spacing of the swing averages (> 0)", x(d.quadrature_dt)},
      {"energy-axis", "energy axis of the plot: lin, or log (symmetric log: early rises of small components show)",
       "lin"},
      {"phase-dt", "phase-portrait sampling interval (>= 0)", "0.05"},
      {"steady-flight-fraction", "steady rocking if the late flight fraction is below this, in (0, 1)",
       x(c.steady_flight_fraction)},
      {"settled-energy",
       "settled if E < 0 late and the energy above rest is at most this fraction of E0 - E_rest, in (0, 1)",
       x(c.settled_energy)},
      {"settle-rotation-share", "settle down needs a late rotational share of kinetic energy below this, in (0, 1)",
       x(c.settle_rotation_share)},
      {"settle-dissipation",
       "settle down if friction dissipated at least this fraction of the available energy, in (0, 1)",
       x(c.settle_dissipation)},
      {"vertical-trend", "rock to vertical if the late rotational share <= this times the early one, in (0, 1)",
       x(c.vertical_trend)},
      {"conserved-dissipation",
       "mu > 0: rock to vertical if the late-window dissipation is below this fraction, in (0, 1)",
       x(c.conserved_dissipation)},
  });
}

json metrics_json(const ResponseMetrics& m) {
  json j;
  j["status"] = to_string(m.status);
  j["t_final"] = m.t_final;
  j["late_start"] = m.late_start;
  j["overturn_time"] = or_null(m.overturn_time);
  j["first_flight_time"] = or_null(m.first_flight_time);
  j["energy_initial"] = m.e0;
  j["energy_final"] = m.e_final;
  j["energy_rest"] = m.e_rest;
  j["work_friction"] = m.work_friction;
  j["dissipated_fraction"] = m.dissipated_fraction;
  j["late_dissipated_fraction"] = m.late_dissipated_fraction;
  j["late_energy_max"] = std::isfinite(m.late_energy_max) ? json(m.late_energy_max) : json();
  j["late_energy_fraction"] = m.late_energy_fraction;
  j["max_abs_energy_balance_error"] = m.max_abs_energy_error;
  j["ihor"] = m.upright_passages;
  j["takeoffs"] = m.takeoffs;
  j["late_takeoffs"] = m.late_takeoffs;
  j["flight_fraction"] = m.flight_fraction;
  j["late_flight_fraction"] = m.late_flight_fraction;
  j["swings"] = m.swings;
  j["late_swings"] = m.late_swings;
  j["early_swing_length"] = m.early_swing_length;
  j["late_swing_length"] = m.late_swing_length;
  j["late_swing_length_cv"] = m.late_swing_length_cv;
  j["early_average_energy"] = to_json(m.early_average);
  j["late_average_energy"] = to_json(m.late_average);
  j["early_rotation_share"] = m.early_rotation_share;
  j["late_rotation_share"] = m.late_rotation_share;
  return j;
}

ResponseOptions response_run_options(const StudyOptions& o, const WinklerOrbit& orbit) {
  ResponseOptions r;
  r.t_end = o.number("t-end");
  r.late_fraction = o.number("late-fraction");
  r.quadrature_dt = o.number("quadrature-dt");
  r.phase_dt = o.number("phase-dt");
  ResponseCriteria& c = r.criteria;
  c.steady_flight_fraction = o.number("steady-flight-fraction");
  c.settled_energy = o.number("settled-energy");
  c.settle_rotation_share = o.number("settle-rotation-share");
  c.settle_dissipation = o.number("settle-dissipation");
  c.vertical_trend = o.number("vertical-trend");
  c.conserved_dissipation = o.number("conserved-dissipation");
  r.integrator = orbit.integrator;
  validate(r);
  require_sample_count("phase-dt", r.phase_dt, r.t_end, 1e7);
  require_sample_count("quadrature-dt", r.quadrature_dt, r.t_end, 1e7);
  orbit_run_options(r.t_end, orbit.integrator);  // validates t_end and the tolerances
  return r;
}

StudyReport response_study(const Settings& given, const StudyRequest& request) {
  const StudyOptions o(given, response_options());
  const WinklerParams p{o.number("r"), o.number("mu"), o.number("k")};
  validate(p);
  const std::string axis = o.text("energy-axis");
  if (axis != "lin" && axis != "log")
    throw std::invalid_argument("energy-axis = '" + axis + "' is not one of: lin, log");
  const WinklerOrbit orbit = winkler_orbit(o);
  ResponseOptions opt = response_run_options(o, orbit);
  if (!request.want_table) opt.phase_dt = 0.0;
  const ResponseRun run = run_response(orbit.p, {}, orbit.z0, opt);

  StudyReport rep;
  if (request.want_table) {
    rep.series.push_back({"swings", swings_table(run.swings)});
    rep.series.push_back({"phase", phase_table(run.phase)});
  }
  char title[256];
  std::snprintf(title, sizeof title, "r=%g k=%g mu=%g %s: %s", p.r, p.k, p.mu, orbit.ic.c_str(),
                to_string(run.report.type));
  rep.figure = FigureSpec{"response", {"@csv:swings", "@csv:phase", "@plot", title}, {}};
  if (axis == "log") rep.figure.options.push_back({"log-energy", {}});
  json& j = rep.summary;
  j = orbit_summary_head(orbit);
  const ResponseCriteria& c = opt.criteria;
  j["options"] = {{"t_end", opt.t_end},
                  {"late_fraction", opt.late_fraction},
                  {"quadrature_dt", opt.quadrature_dt},
                  {"phase_dt", opt.phase_dt},
                  {"steady_flight_fraction", c.steady_flight_fraction},
                  {"settled_energy", c.settled_energy},
                  {"settle_dissipation", c.settle_dissipation},
                  {"settle_rotation_share", c.settle_rotation_share},
                  {"vertical_trend", c.vertical_trend},
                  {"early_swings", c.early_swings},
                  {"conserved_dissipation", c.conserved_dissipation}};
  j["type"] = to_string(run.report.type);
  j["reason"] = run.report.reason;
  j["metrics"] = metrics_json(run.report.metrics);
  const ResponseMetrics& m = run.report.metrics;
  append_text(rep.text, "response: %s (%s)\n", to_string(run.report.type), run.report.reason.c_str());
  append_text(rep.text, "status: %s at t = %.10g, swings: %ld, take-offs: %ld (late %ld)\n", to_string(m.status),
              m.t_final, m.swings, m.takeoffs, m.late_takeoffs);
  append_text(rep.text, "energy: E0 = %.10g, dissipated fraction = %.4g, balance error = %.3g\n", m.e0,
              m.dissipated_fraction, m.max_abs_energy_error);
  return rep;
}

// ---------------------------------------------------------------- poincare

std::vector<StudyOption> poincare_options() {
  return with_orbit({{"t-end", "final time (> 0)", "500"},
                     {"t-min", "record crossings from this time on (drop a transient)", "0"},
                     {"direction", "crossings to keep: both, positive (w' > 0), negative", "both"}});
}

StudyReport poincare_study(const Settings& given, const StudyRequest&) {
  const StudyOptions o(given, poincare_options());
  const WinklerOrbit orbit = winkler_orbit(o);
  const double t_end = o.number("t-end"), t_min = o.number("t-min");
  const WinklerRunOptions so = orbit_run_options(t_end, orbit.integrator);
  require_in_range("t-min", t_min, 0.0, t_end);
  const std::string direction = o.text("direction");
  if (direction != "both" && direction != "positive" && direction != "negative")
    throw std::invalid_argument("`direction` = '" + direction + "' is not one of: both, positive, negative");
  const CrossingDirection dir = direction == "positive"   ? CrossingDirection::Positive
                                : direction == "negative" ? CrossingDirection::Negative
                                                          : CrossingDirection::Both;
  PoincareCollector col(orbit.p, dir, t_min);
  const WinklerResult r = simulate(orbit.p, {}, orbit.z0, so, &col);
  const auto& pts = col.points();

  StudyReport rep;
  rep.series.push_back({"crossings", poincare_table(pts)});
  char title[256];
  std::snprintf(title, sizeof title, "Poincare map w=0: r=%g k=%g mu=%g %s, t<=%g", orbit.p.r, orbit.p.k, orbit.p.mu,
                orbit.ic.c_str(), r.t_final);
  rep.figure = FigureSpec{"poincare", {"@csv:crossings", "@plot", title}, {}};
  double max_w = 0, e_lo = INFINITY, e_hi = -INFINITY;
  for (const auto& q : pts) {
    max_w = std::max(max_w, std::fabs(q.w));
    e_lo = std::min(e_lo, q.energy);
    e_hi = std::max(e_hi, q.energy);
  }
  json& j = rep.summary;
  j = orbit_summary_head(orbit);
  j["options"] = {{"t_end", t_end}, {"t_min", t_min}, {"direction", direction}};
  j["status"] = to_string(r.status);
  j["t_final"] = r.t_final;
  j["crossings"] = pts.size();
  j["ihor"] = r.upright_passages;
  j["max_abs_w_at_crossings"] = max_w;
  j["energy_at_crossings"] = {{"min", pts.empty() ? NAN : e_lo}, {"max", pts.empty() ? NAN : e_hi}};
  j["energy_initial"] = r.initial_energy.total();
  j["max_abs_energy_balance_error"] = r.max_abs_energy_error;
  append_text(rep.text, "%zu crossings of w = 0 up to t = %.6g (status %s); max |w| there %.3g\n", pts.size(),
              r.t_final, to_string(r.status), max_w);
  return rep;
}

// ---------------------------------------------------------------- energy-surface

std::vector<StudyOption> surface_options() {
  return with_orbit({{"t-end", "final time (> 0)", "200"},
                     {"phase-dt", "trajectory sampling interval (> 0)", "0.05"},
                     {"surface-energy", "energy of the drawn surface (default: the initial energy)", ""},
                     {"n", "boundary points per projection, in [2, 100000]", "401"}});
}

StudyTable projections_table(const std::vector<HeaveBoundaryPoint>& heave) {
  StudyTable t;
  t.columns = {"y", "v_min", "vy_max"};
  for (const auto& b : heave) t.rows.push_back({b.y, b.v_min, b.vy_max});
  return t;
}

StudyTable projections_table(const std::vector<RockBoundaryPoint>& rock) {
  StudyTable t;
  t.columns = {"w", "u", "vw_free", "vw_contact"};
  for (const auto& b : rock) t.rows.push_back({b.w, b.u, b.vw_free, b.vw_contact});
  return t;
}

StudyReport surface_study(const Settings& given, const StudyRequest& request) {
  const StudyOptions o(given, surface_options());
  const WinklerOrbit orbit = winkler_orbit(o);
  const WinklerParams& p = orbit.p;
  const double t_end = o.number("t-end"), phase_dt = o.number("phase-dt");
  const WinklerRunOptions so = orbit_run_options(t_end, orbit.integrator);
  require_in_range("phase-dt", phase_dt, 0.0, t_end, false, true);
  require_sample_count("phase-dt", phase_dt, t_end, 1e7);
  const long n = o.integer("n");
  require_in_range("n", double(n), 2, 100000);
  const double E = o.given("surface-energy") ? o.number("surface-energy") : energy(p, orbit.z0).total();
  require_in_range("surface-energy", E, -0.5 / p.k, 1e6);

  SwingOptions sw;
  sw.phase_dt = phase_dt;
  sw.quadrature_dt = t_end;  // only the phase samples are wanted
  sw.min_samples_per_step = 1;
  SwingAccumulator acc(p, sw);
  const WinklerResult r = simulate(p, {}, orbit.z0, so, &acc);
  // How far the sampled trajectory gets outside the projections (should be <= rounding + the
  // integration error for mu = 0, and negative margins when friction dissipates).
  double heave_excess = -INFINITY, rock_excess = -INFINITY;
  for (const PhaseSample& q : acc.phase()) {
    heave_excess = std::max(heave_excess, 0.5 * q.s.vy * q.s.vy + heave_potential(p, q.s.y - 0.5) - E);
    rock_excess = std::max(rock_excess, 0.5 * p.inertia() * q.s.vw * q.s.vw + rock_potential(p, q.s.w) - E);
  }
  StudyReport rep;
  if (request.want_table) {
    rep.series.push_back({"heave", projections_table(heave_projection(p, E, int(n)))});
    rep.series.push_back({"rock", projections_table(rock_projection(p, E, int(n)))});
    rep.series.push_back({"phase", phase_table(acc.phase())});
  }
  char title[256];
  std::snprintf(title, sizeof title, "r=%g k=%g mu=%g %s, E=%.6g, w0=%.4g y0=%.6g y0'=%.6g", p.r, p.k, p.mu,
                orbit.ic.c_str(), E, orbit.z0[kW], orbit.z0[kH] + 0.5, orbit.z0[kVY]);
  rep.figure = FigureSpec{"energy_surface", {"@csv:heave", "@csv:rock", "@csv:phase", "@plot", title}, {}};
  json& j = rep.summary;
  j = orbit_summary_head(orbit);
  j["options"] = {{"t_end", t_end}, {"phase_dt", phase_dt}, {"n", n}};
  j["surface_energy"] = E;
  j["status"] = to_string(r.status);
  j["t_final"] = r.t_final;
  j["samples"] = acc.phase().size();
  j["max_heave_excess"] = heave_excess;
  j["max_rock_excess"] = rock_excess;
  j["max_abs_energy_balance_error"] = r.max_abs_energy_error;
  append_text(rep.text, "E = %.12g; initial y' = %.12g; trajectory to t = %.6g (%s)\n", E, orbit.z0[kVY], r.t_final,
              to_string(r.status));
  append_text(rep.text, "largest excess over the projections: (y, y') %.3g, (w, w') %.3g\n", heave_excess, rock_excess);
  return rep;
}

}  // namespace

void add_orbit_studies(std::vector<StudyCommand>& to) {
  StudyCommand response{"response",
                        "long-term response: type, swings, swing-averaged energies, phase portraits",
                        50,
                        StudyOutputs::Series,
                        response_options(),
                        response_study};
  response.csv_flag = "csv-prefix";
  to.push_back(response);
  to.push_back({"poincare", "Poincare section w = 0: crossing states (y, y', w', x, x') and plots", 51,
                StudyOutputs::Series, poincare_options(), poincare_study});
  StudyCommand surface{"energy-surface",
                       "energy-surface projections on (y, y') and (w, w') with the trajectory; ICs on a given energy",
                       53,
                       StudyOutputs::Series,
                       surface_options(),
                       surface_study};
  surface.csv_flag = "csv-prefix";
  to.push_back(surface);
}

}  // namespace blockdyn
