// SPDX-License-Identifier: Apache-2.0
// `blockdyn response`: long-term response of one block (thesis sec. 4.4): response type, metrics,
// swings (lengths, swing-averaged energies), phase portraits, plot.
#include <cmath>
#include <cstdio>
#include <memory>

#include "blockdyn/analysis/winkler/response_type.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "chaos_cli.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
namespace {

struct ResponseFlags {
  BlockParams p;
  IntegratorOptions integ;
  IcFlags ic;
  ResponseOptions opt;
  std::string csv_prefix, plot, json_out, energy_axis = "lin";
  bool json = false;
};

nlohmann::ordered_json metrics_json(const ResponseMetrics& m) {
  nlohmann::ordered_json j;
  j["status"] = to_string(m.status);
  j["t_final"] = m.t_final;
  j["late_start"] = m.late_start;
  j["overturn_time"] = m.overturn_time ? nlohmann::ordered_json(*m.overturn_time) : nlohmann::ordered_json();
  j["first_flight_time"] = m.first_flight_time ? nlohmann::ordered_json(*m.first_flight_time) : nlohmann::ordered_json();
  j["energy_initial"] = m.e0;
  j["energy_final"] = m.e_final;
  j["energy_rest"] = m.e_rest;
  j["work_friction"] = m.work_friction;
  j["dissipated_fraction"] = m.dissipated_fraction;
  j["late_dissipated_fraction"] = m.late_dissipated_fraction;
  j["late_energy_max"] =
      std::isfinite(m.late_energy_max) ? nlohmann::ordered_json(m.late_energy_max) : nlohmann::ordered_json();
  j["late_energy_fraction"] = m.late_energy_fraction;
  j["max_abs_energy_balance_error"] = m.max_abs_energy_error;
  j["ihor"] = m.ihor;
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

void write_csv(const std::string& path, const std::function<void(std::ostream&)>& fill) {
  AtomicFile f(path);
  fill(f.stream());
  f.commit();
}

void run(const CLI::App& s, ResponseFlags& f) {
  validate(f.p);
  if (f.energy_axis != "lin" && f.energy_axis != "log")
    throw UsageError("energy-axis = '" + f.energy_axis + "' is not one of: lin, log");
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  f.opt.integrator = f.integ;
  validate(f.opt);
  require_sample_count("phase-dt", f.opt.phase_dt, f.opt.t_end);
  require_sample_count("quadrature-dt", f.opt.quadrature_dt, f.opt.t_end);
  orbit_run_options(f.opt.t_end, f.integ);  // validates t_end and the tolerances
  const BlockStateVec z0 = ic_state(s, f.ic, f.p);
  const bool want_series = !f.csv_prefix.empty() || !f.plot.empty();
  if (!want_series) f.opt.phase_dt = 0.0;
  const ResponseRun run = run_response(f.p, {}, z0, f.opt);

  std::string prefix = f.csv_prefix;
  const bool temp = prefix.empty() && !f.plot.empty();
  if (temp) prefix = temp_path("response", "");
  if (!prefix.empty()) {
    write_csv(prefix + "_swings.csv", [&](std::ostream& o) { write_swings_csv(o, run.swings); });
    write_csv(prefix + "_phase.csv", [&](std::ostream& o) { write_phase_csv(o, run.phase); });
  }
  if (!f.plot.empty()) {
    char title[256];
    std::snprintf(title, sizeof title, "r=%g k=%g mu=%g %s: %s", f.p.r, f.p.k, f.p.mu, f.ic.ic.c_str(),
                  to_string(run.report.type));
    std::vector<std::string> args = {prefix + "_swings.csv", prefix + "_phase.csv", f.plot, title};
    if (f.energy_axis == "log") args.insert(args.begin(), "--log-energy");
    run_python("plot_response.py", args);
    if (temp) {
      std::remove((prefix + "_swings.csv").c_str());
      std::remove((prefix + "_phase.csv").c_str());
    }
  }

  nlohmann::ordered_json j = summary_head(f.p, f.integ, f.ic, z0);
  j["options"] = {{"t_end", f.opt.t_end},
                  {"late_fraction", f.opt.late_fraction},
                  {"quadrature_dt", f.opt.quadrature_dt},
                  {"phase_dt", f.opt.phase_dt},
                  {"steady_flight_fraction", f.opt.criteria.steady_flight_fraction},
                  {"settled_energy", f.opt.criteria.settled_energy},
                  {"settle_dissipation", f.opt.criteria.settle_dissipation},
                  {"settle_rotation_share", f.opt.criteria.settle_rotation_share},
                  {"vertical_trend", f.opt.criteria.vertical_trend},
                  {"early_swings", f.opt.criteria.early_swings},
                  {"conserved_dissipation", f.opt.criteria.conserved_dissipation}};
  j["type"] = to_string(run.report.type);
  j["reason"] = run.report.reason;
  j["metrics"] = metrics_json(run.report.metrics);
  if (!emit_summary(j, f.json, f.json_out)) {
    const ResponseMetrics& m = run.report.metrics;
    std::printf("response: %s (%s)\n", to_string(run.report.type), run.report.reason.c_str());
    std::printf("status: %s at t = %.10g, swings: %ld, take-offs: %ld (late %ld)\n", to_string(m.status), m.t_final,
                m.swings, m.takeoffs, m.late_takeoffs);
    std::printf("energy: E0 = %.10g, dissipated fraction = %.4g, balance error = %.3g\n", m.e0,
                m.dissipated_fraction, m.max_abs_energy_error);
  }
}

void add(CLI::App& app) {
  auto f = std::make_shared<ResponseFlags>();
  f->opt.phase_dt = 0.05;
  CLI::App* s = app.add_subcommand("response", "long-term response: type, swings, swing-averaged energies, phase portraits");
  add_orbit_options(*s, f->p, f->integ, f->ic);
  s->add_option("--t-end", f->opt.t_end, "final time (> 0)")->capture_default_str();
  s->add_option("--late-fraction", f->opt.late_fraction, "late window starts at this fraction of t-end, in [0, 1)")
      ->capture_default_str();
  s->add_option("--quadrature-dt", f->opt.quadrature_dt, "largest sample spacing of the swing averages (> 0)")
      ->capture_default_str();
  s->add_option("--energy-axis", f->energy_axis,
                "energy axis of the plot: lin, or log (symmetric log: early rises of small components show)")
      ->capture_default_str();
  s->add_option("--phase-dt", f->opt.phase_dt, "phase-portrait sampling interval (>= 0)")->capture_default_str();
  s->add_option("--steady-flight-fraction", f->opt.criteria.steady_flight_fraction,
                "steady rocking if the late flight fraction is below this, in (0, 1)")
      ->capture_default_str();
  s->add_option("--settled-energy", f->opt.criteria.settled_energy,
                "settled if E < 0 late and the energy above rest is at most this fraction of E0 - E_rest, in (0, 1)")
      ->capture_default_str();
  s->add_option("--settle-rotation-share", f->opt.criteria.settle_rotation_share,
                "settle down needs a late rotational share of kinetic energy below this, in (0, 1)")
      ->capture_default_str();
  s->add_option("--settle-dissipation", f->opt.criteria.settle_dissipation,
                "settle down if friction dissipated at least this fraction of the available energy, in (0, 1)")
      ->capture_default_str();
  s->add_option("--vertical-trend", f->opt.criteria.vertical_trend,
                "rock to vertical if the late rotational share <= this times the early one, in (0, 1)")
      ->capture_default_str();
  s->add_option("--conserved-dissipation", f->opt.criteria.conserved_dissipation,
                "mu > 0: rock to vertical if the late-window dissipation is below this fraction, in (0, 1)")
      ->capture_default_str();
  s->add_option("--csv-prefix", f->csv_prefix, "write PREFIX_swings.csv and PREFIX_phase.csv");
  add_summary_options(*s, f->plot, "write the phase portraits and swing-averaged energies (PNG + SVG)", f->json, f->json_out);
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(50, add);

}  // namespace
}  // namespace blockdyn::cli
