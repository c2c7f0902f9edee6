// SPDX-License-Identifier: Apache-2.0
// The one registration of every model family: a row each. The entries live with each family's
// runs (commands/simulate_run.cpp, commands/sweep_settings.cpp, commands/forced_model_settings.cpp,
// commands/chaos_studies.cpp) and its model (simulation/rigid_ground_model.cpp).
#include <stdexcept>

#include "blockdyn/analysis/sweep/rigid_sweep.hpp"
#include "blockdyn/commands/assembly_settings.hpp"
#include "blockdyn/commands/forced_model_settings.hpp"
#include "blockdyn/commands/rigid3d_run.hpp"
#include "blockdyn/commands/scenario_settings.hpp"
#include "blockdyn/commands/settings_sweep.hpp"
#include "blockdyn/commands/simulate_run.hpp"
#include "blockdyn/commands/study_command.hpp"
#include "blockdyn/commands/sweep_settings.hpp"
#include "blockdyn/family/family.hpp"
#include "blockdyn/simulation/rigid_ground_model.hpp"

namespace blockdyn {

namespace {

std::vector<std::pair<std::string, std::string>> rigid_sweep_axes() { return rigid_axis_catalog(); }

}  // namespace

const std::vector<Family>& families() {
  // Designated: each row names the adapters it has; the others stay null.
  static const std::vector<Family> rows{
      {.name = "winkler",
       .description = "block on a Winkler foundation (non-dimensional unless a physical block is given)",
       .options = scenario_option_names,
       .prepare = prepare_block,
       .run_scenario = run_winkler,
       .sweep = winkler_sweep,
       .sweep_axes = winkler_sweep_axes,
       .free_lyapunov = winkler_lyapunov_study},
      {.name = "housner",
       .description = "1-DOF rocking on rigid ground",
       .options = scenario_option_names,
       .prepare = prepare_block,
       .run_scenario = run_housner,
       .rigid_ground = &housner_on_rigid_ground(),
       .sweep = rigid_sweep,
       .sweep_axes = rigid_sweep_axes,
       .forced = &housner_forced()},
      {.name = "rigid",
       .description = "3-DOF on rigid ground, five mechanisms",
       .options = scenario_option_names,
       .prepare = prepare_block,
       .run_scenario = run_rigid,
       .rigid_ground = &three_dof_on_rigid_ground(),
       .sweep = rigid_sweep,
       .sweep_axes = rigid_sweep_axes,
       .forced = &rigid_forced()},
      {.name = "assembly",
       .description = "block assemblies (preset or TOML file) with deformable or rigid contacts",
       .options = assembly_option_names,
       .prepare = prepare_assembly,
       .forced = &assembly_forced()},
      {.name = "rigid3d",
       .description = "3D box or cylinder on rigid ground: rocks on edges, corners and the rim, impacts, flies",
       .options = rigid3d_option_names,
       .prepare = prepare_rigid3d,
       .own_options = rigid3d_options,
       .state_columns = "x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz",
       .sweep = settings_sweep,
       .sweep_axes = rigid3d_sweep_axes,
       .result_keys = rigid3d_result_keys,
       .forced = &rigid3d_forced()},
  };
  return rows;
}

const Family* find_family(const std::string& name) {
  for (const Family& f : families())
    if (name == f.name) return &f;
  return nullptr;
}

void throw_not_a_family(const std::string& field, const std::string& name, const std::string& names) {
  throw std::invalid_argument(field + " = '" + name + "' is not one of: " + names);
}

std::string family_names() {
  return family_names([](const Family&) { return true; });
}

const Family& family_named(const std::string& field, const std::string& name) {
  return family_named(field, name, [](const Family&) { return true; });
}

}  // namespace blockdyn
