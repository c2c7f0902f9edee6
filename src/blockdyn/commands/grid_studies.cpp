// SPDX-License-Identifier: Apache-2.0
// The grid studies' registry and runner: each study in its own file (spectrum_study.cpp,
// survival_study.cpp, response_curve_study.cpp, rocking_spectrum.cpp, fragility.cpp).
#include "blockdyn/commands/grid_studies.hpp"
#include "blockdyn/commands/grid_study_common.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "blockdyn/analysis/forced/spectrum_table.hpp"
#include "blockdyn/analysis/forced/survival_table.hpp"
#include "blockdyn/analysis/sweep/refinement_plan.hpp"
#include "blockdyn/analysis/sweep/sweep_axis.hpp"
#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/forced_model_settings.hpp"
#include "blockdyn/commands/fragility.hpp"
#include "blockdyn/commands/harmonic_run.hpp"
#include "blockdyn/commands/rocking_spectrum.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

std::vector<StudyOption> excitation_grid_options() {
  const SurvivalOptions d;
  auto x = [](double v) { return Settings::exact(v); };
  return {{"excitation", "harmonic (default), half-sine, half-cosine or rect (pulses last pi/Omega)", d.excitation},
          {"phase", "phase of cos(Omega t + phase) [rad]", x(d.phase)},
          {"omega-min", "smallest omega = Omega/p", x(d.omega_min)},
          {"omega-max", "largest omega", x(d.omega_max)},
          {"omega-points", "omegas, uniform", std::to_string(d.omega_points)},
          {"t-end", "duration of each run [s]: the transient window", x(d.t_end)},
          {"periods", "duration of each run in forcing periods (instead of `t-end`)", ""},
          {"threads", "worker threads (0: all cores)", "0"}};
}

SurvivalOptions excitation_grid_of(const StudyOptions& o) {
  SurvivalOptions s;
  s.excitation = o.text("excitation");
  s.phase = o.number("phase");
  s.omega_min = o.number("omega-min");
  s.omega_max = o.number("omega-max");
  s.omega_points = o.small_integer("omega-points");
  s.t_end = o.number("t-end");
  if (o.given("periods")) s.periods = o.number("periods");
  s.threads = o.threads();
  return s;
}

std::string title_of(const ForcedModelChoice& m, const std::string& excitation) {
  std::string title = m.label() + ", " + excitation;
  if (m.friction_angles())
    title += ", " + m.contact + " law, phi_s = " + short_num(m.phi_s) + ", phi_l = " + short_num(m.phi_l);
  return title;
}

const std::vector<GridStudyCommand>& grid_study_commands() {
  static const std::vector<GridStudyCommand> all = {spectrum_command(), survival_command(), response_curve_command(),
                                                    rocking_spectrum_command(), fragility_command()};
  return all;
}

const GridStudyCommand& grid_study_command(const std::string& name) {
  for (const GridStudyCommand& c : grid_study_commands())
    if (c.name == name) return c;
  throw std::invalid_argument("grid study '" + name +
                              "' is not one of: spectrum, survival, response-curve, rocking-spectrum, fragility");
}

StudyReport run_grid_study(const std::string& name, const Settings& s,
                           const std::function<void(std::size_t, std::size_t)>& progress) {
  const GridStudyCommand& c = grid_study_command(name);
  s.require_known(c.options, {}, name);
  const GridStudy g = c.prepare(s, "(memory)");
  const Table t = compute_table(*g.table, g.threads, g.plan.get(), progress);
  StudyReport rep = g.finish(t);
  rep.table.columns = t.columns;
  for (const TableRow& r : t.rows) rep.table.rows.push_back(r.cells);
  rep.text += "\n";
  return rep;
}

}  // namespace blockdyn
