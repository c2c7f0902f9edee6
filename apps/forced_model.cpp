// SPDX-License-Identifier: Apache-2.0
#include "forced_model.hpp"

#include <cmath>

#include "blockdyn/api/forced_model_settings.hpp"
#include "blockdyn/api/harmonic_run.hpp"
#include "cli_common.hpp"

namespace blockdyn::cli {

void add_forced_model_flags(CLI::App& s) { add_spec_options(s, forced_model_options()); }

ForcedModelChoice forced_model_choice(const CLI::App& s) { return blockdyn::forced_model_choice(settings_of(s)); }

void add_excitation_grid_flags(CLI::App& s, SurvivalOptions& o) {
  s.add_option("--excitation", o.excitation,
               "harmonic (default), half-sine, half-cosine or rect (pulses last pi/Omega)")
      ->check(CLI::IsMember({"harmonic", "half-sine", "half-cosine", "rect"}));
  s.add_option("--phase", o.phase, "phase of cos(Omega t + phase) [rad] (default 0)");
  s.add_option("--omega-min", o.omega_min, "smallest omega = Omega/p (default 1)");
  s.add_option("--omega-max", o.omega_max, "largest omega (default 20)");
  s.add_option("--omega-points", o.omega_points, "omegas, uniform (default 10)");
  s.add_option("--t-end", o.t_end, "duration of each run [s] (default 20): the transient window");
  s.add_option("--periods", o.periods, "duration of each run in forcing periods (instead of --t-end)");
  s.add_option("--threads", o.threads, "worker threads (0: all cores; default 0)");
}

ForcedModel build_forced_model(const CLI::App& s) { return forced_model_from(settings_of(s)); }

}  // namespace blockdyn::cli
