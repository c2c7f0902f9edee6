// SPDX-License-Identifier: Apache-2.0
#pragma once
// Initial-condition flags shared by the response / poincare / lyapunov / energy-surface commands
// (same names and meaning as `simulate`), built through the scenario machinery.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <unistd.h>

#include "blockdyn/analysis/winkler/energy_surface.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/model/winkler/energy.hpp"
#include "blockdyn/model/winkler/initial_conditions.hpp"
#include "blockdyn/io/scenario.hpp"
#include "cli_common.hpp"

namespace blockdyn::cli {

struct IcFlags {
  std::string ic = "ic1";
  double w0 = 0, x0 = 0, y0 = 0, vx0 = 0, vy0 = 0, vw0 = 0;
  double w0_alpha = 0;              // w0 as a fraction of alpha (thesis: alpha/8, alpha/64)
  double energy = 0;                // --ic surface: the energy level ...
  std::string energy_of = "ic1";    // ... or the set whose energy is used
  int vy_sign = 1;
};

inline void add_ic_options(CLI::App& s, IcFlags& f) {
  s.add_option("--ic", f.ic,
               "initial conditions: ic1 (tilted, at rest), ic2 (upright, impulse), custom, or surface "
               "(given --w0 --y0, y' solved so that the energy is --energy / that of --energy-of)")
      ->check(CLI::IsMember({"ic1", "ic2", "custom", "surface"}))
      ->capture_default_str();
  s.add_option("--energy", f.energy, "surface: the total energy E of the initial state");
  s.add_option("--energy-of", f.energy_of, "surface: use the energy of this set (default ic1) when --energy is not given")
      ->check(CLI::IsMember({"ic1", "ic2"}))
      ->capture_default_str();
  s.add_option("--vy-sign", f.vy_sign, "surface: sign of the solved y' (+1 or -1)")
      ->check(CLI::IsMember({-1, 1}))
      ->capture_default_str();
  s.add_option("--w0", f.w0, "initial tilt w (ic1 override, default alpha/2; custom state)");
  s.add_option("--w0-alpha", f.w0_alpha, "initial tilt as a fraction of alpha = atan(r) (instead of --w0)");
  s.add_option("--x0", f.x0, "initial x (overrides the set's value)");
  s.add_option("--y0", f.y0, "initial y of the centre (overrides)");
  s.add_option("--vx0", f.vx0, "initial x' (overrides)");
  s.add_option("--vy0", f.vy0, "initial y' (overrides)");
  s.add_option("--vw0", f.vw0, "initial w' (overrides)");
}

// The initial state the flags ask for; throws std::invalid_argument on bad input.
inline BlockStateVec ic_state(const CLI::App& s, const IcFlags& f, const BlockParams& p) {
  if (s.count("--w0") && s.count("--w0-alpha")) throw UsageError("give either --w0 or --w0-alpha, not both");
  std::optional<double> w0;
  if (s.count("--w0")) w0 = f.w0;
  if (s.count("--w0-alpha")) {
    require_range("w0-alpha", f.w0_alpha, -1.0, 1.0);
    w0 = f.w0_alpha * p.alpha();
  }
  if (f.ic == "surface") {
    if (!w0 || !s.count("--y0")) throw UsageError("ic = surface needs --w0 (or --w0-alpha) and --y0");
    double E = f.energy;
    if (!s.count("--energy")) E = energy(p, f.energy_of == "ic2" ? ic2(p) : ic1(p)).total();
    return state_on_energy_surface(p, E, *w0, f.y0, f.vy_sign);
  }
  Scenario sc;
  sc.params = p;
  sc.initial.set = f.ic;
  sc.initial.w0 = w0;
  if (s.count("--x0")) sc.initial.x0 = f.x0;
  if (s.count("--y0")) sc.initial.y0 = f.y0;
  if (s.count("--vx0")) sc.initial.vx0 = f.vx0;
  if (s.count("--vy0")) sc.initial.vy0 = f.vy0;
  if (s.count("--vw0")) sc.initial.vw0 = f.vw0;
  if (sc.initial.w0) require_range("w0", *sc.initial.w0, -p.alpha(), p.alpha());
  return initial_state(sc);
}

inline nlohmann::ordered_json ic_json(const IcFlags& f, const BlockStateVec& z0, const BlockParams& p) {
  nlohmann::ordered_json j;
  j["set"] = f.ic;
  j["state"] = state_json(z0);
  j["energy"] = energy(p, z0).total();
  return j;
}

// --r --mu --k, --rtol --atol and the initial-condition flags: the orbit every command follows.
inline void add_orbit_options(CLI::App& s, BlockParams& p, IntegratorOptions& integ, IcFlags& ic) {
  add_block_options(s, p);
  add_tolerance_options(s, integ);
  add_ic_options(s, ic);
}

// --plot (help text plot_help), --json and --json-out.
inline void add_summary_options(CLI::App& s, std::string& plot, const std::string& plot_help, bool& json,
                                std::string& json_out) {
  s.add_option("--plot", plot, plot_help);
  s.add_flag("--json", json, "print the JSON summary on stdout");
  s.add_option("--json-out", json_out, "also write the JSON summary to this file");
}

// Options of a run to t_end without an event log; throws std::invalid_argument when invalid.
inline SimulationOptions orbit_run_options(double t_end, const IntegratorOptions& integ) {
  SimulationOptions so;
  so.t_end = t_end;
  so.integrator = integ;
  so.record_events = false;
  validate(so);
  return so;
}

// The opening of every summary: run info, block parameters, initial state and integrator.
inline nlohmann::ordered_json summary_head(const BlockParams& p, const IntegratorOptions& integ, const IcFlags& f,
                                           const BlockStateVec& z0) {
  nlohmann::ordered_json j;
  j["run_info"] = run_info();
  j["params"] = to_json(p);
  j["initial"] = ic_json(f, z0, p);
  j["integrator"] = to_json(integ);
  return j;
}

// Writes the summary to --json-out and, with --json, to stdout; true when it went to stdout
// (the text summary is then left out).
inline bool emit_summary(const nlohmann::ordered_json& j, bool json, const std::string& json_out) {
  if (!json_out.empty()) emit_json(j, json_out);
  if (json) emit_json(j, "-");
  return json;
}

// Temporary file path for CSVs that only feed a plot.
inline std::string temp_path(const std::string& stem, const std::string& ext) {
  return "/tmp/blockdyn-" + stem + "-" + std::to_string(::getpid()) + ext;
}

}  // namespace blockdyn::cli
