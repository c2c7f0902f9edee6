// SPDX-License-Identifier: Apache-2.0
#include "forced_model.hpp"

#include <cmath>

#include "blockdyn/api/forced_model_settings.hpp"
#include "cli_common.hpp"

namespace blockdyn::cli {

void add_forced_model_flags(CLI::App& s, ForcedModelFlags& f, const std::vector<std::string>& extra_models) {
  std::vector<std::string> models = extra_models;
  for (const char* m : {"housner", "rigid", "assembly"}) models.push_back(m);
  std::string help = "housner, rigid (a block on rigid ground) or assembly (with --preset)";
  for (const auto& m : extra_models) help += ", or " + m;
  s.add_option("--model", f.model, help)->check(CLI::IsMember(models));
  s.add_option("--width", f.width, "housner/rigid: block width [m]");
  s.add_option("--height", f.height, "housner/rigid: block height [m]");
  s.add_option("--mass", f.mass, "housner/rigid: mass [kg] (default 1)");
  s.add_option("--g", f.g, "gravity [m/s^2] (default 9.81)");
  s.add_option("--mu-s", f.mu_s, "rigid: static friction (default 0.7)");
  s.add_option("--mu-k", f.mu_k, "rigid: kinetic friction (default mu-s)");
  s.add_option("--impact", f.impact, "rigid: housner or newton")->check(CLI::IsMember({"housner", "newton"}));
  s.add_option("--restitution", f.restitution, "restitution (housner/rigid as in simulate; assembly as in assembly)");
  s.add_option("--preset", f.preset, "assembly: block, trilith or column")
      ->check(CLI::IsMember({"block", "trilith", "column"}));
  s.add_option("--contact", f.contact, "assembly: deformable or rigid")->check(CLI::IsMember({"deformable", "rigid"}));
  s.add_option("--slenderness", f.preset_opt.slenderness, "assembly: height / width (default 4)");
  s.add_option("--block-width", f.preset_opt.block_width, "assembly: width [m] (default 0.12)");
  s.add_option("--drums", f.preset_opt.drums, "assembly column: drums (default 4)");
  s.add_option("--phi-s", f.phi_s, "assembly: friction angle on the ground [deg] (default 90)");
  s.add_option("--phi-l", f.phi_l, "assembly: friction angle between blocks [deg] (default 90)");
  s.add_flag("--columns-rock-only", f.columns_rock_only,
             "assembly, rigid law: the blocks on the ground only rock (no sliding, plastic impacts): seed 001's 5-DOF "
             "trilith");
}

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

ForcedModel build_forced_model(const Settings& settings) { return forced_model_from(settings); }

ForcedModel build_forced_model(const CLI::App& s) { return forced_model_from(settings_of(s)); }

}  // namespace blockdyn::cli
