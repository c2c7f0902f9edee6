#pragma once
// Initial-condition flags shared by the response / poincare / lyapunov / energy-surface commands
// (same names and meaning as `simulate`), built through the scenario machinery.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <unistd.h>

#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/scenario.hpp"
#include "cli_common.hpp"

namespace blockdyn::cli {

struct IcFlags {
  std::string ic = "ic1";
  double w0 = 0, x0 = 0, y0 = 0, vx0 = 0, vy0 = 0, vw0 = 0;
};

inline void add_ic_options(CLI::App& s, IcFlags& f) {
  s.add_option("--ic", f.ic, "initial conditions: ic1 (tilted, at rest), ic2 (upright, impulse), custom")
      ->check(CLI::IsMember({"ic1", "ic2", "custom"}))
      ->capture_default_str();
  s.add_option("--w0", f.w0, "initial tilt w (ic1 override, default alpha/2; custom state)");
  s.add_option("--x0", f.x0, "initial x (overrides the set's value)");
  s.add_option("--y0", f.y0, "initial y of the centre (overrides)");
  s.add_option("--vx0", f.vx0, "initial x' (overrides)");
  s.add_option("--vy0", f.vy0, "initial y' (overrides)");
  s.add_option("--vw0", f.vw0, "initial w' (overrides)");
}

// The initial state the flags ask for; throws std::invalid_argument on bad input.
inline BlockStateVec ic_state(const CLI::App& s, const IcFlags& f, const BlockParams& p) {
  Scenario sc;
  sc.params = p;
  sc.initial.set = f.ic;
  if (s.count("--w0")) sc.initial.w0 = f.w0;
  if (s.count("--x0")) sc.initial.x0 = f.x0;
  if (s.count("--y0")) sc.initial.y0 = f.y0;
  if (s.count("--vx0")) sc.initial.vx0 = f.vx0;
  if (s.count("--vy0")) sc.initial.vy0 = f.vy0;
  if (s.count("--vw0")) sc.initial.vw0 = f.vw0;
  if (sc.initial.w0) require_range("w0", *sc.initial.w0, -p.alpha(), p.alpha());
  return initial_state(sc);
}

inline nlohmann::ordered_json ic_json(const IcFlags& f, const BlockStateVec& z0) {
  nlohmann::ordered_json j;
  j["set"] = f.ic;
  j["state"] = state_json(z0);
  return j;
}

// Temporary file path for CSVs that only feed a plot.
inline std::string temp_path(const std::string& stem, const std::string& ext) {
  return "/tmp/blockdyn-" + stem + "-" + std::to_string(::getpid()) + ext;
}

}  // namespace blockdyn::cli
