// SPDX-License-Identifier: Apache-2.0
// The one registration of every model family: a row each. The entries live with each family's
// runs (api/simulate_run.cpp, api/sweep_settings.cpp, api/forced_model_settings.cpp,
// api/chaos_studies.cpp) and its model (simulation/rigid_ground_model.cpp).
#include <stdexcept>

#include "blockdyn/analysis/sweep/rigid_sweep.hpp"
#include "blockdyn/api/assembly_settings.hpp"
#include "blockdyn/api/forced_model_settings.hpp"
#include "blockdyn/api/scenario_settings.hpp"
#include "blockdyn/api/simulate_run.hpp"
#include "blockdyn/api/study_command.hpp"
#include "blockdyn/api/sweep_settings.hpp"
#include "blockdyn/family/family.hpp"
#include "blockdyn/simulation/rigid_ground_model.hpp"

namespace blockdyn {

namespace {

std::vector<std::pair<std::string, std::string>> rigid_sweep_axes() { return rigid_axis_catalog(); }

}  // namespace

const std::vector<Family>& families() {
  static const std::vector<Family> rows{
      {"winkler", "block on a Winkler foundation (non-dimensional unless a physical block is given)",
       scenario_option_names, prepare_block, run_winkler, nullptr, winkler_sweep, winkler_sweep_axes, nullptr,
       winkler_lyapunov_study},
      {"housner", "1-DOF rocking on rigid ground", scenario_option_names, prepare_block, run_housner,
       &housner_on_rigid_ground(), rigid_sweep, rigid_sweep_axes, &housner_forced(), nullptr},
      {"rigid", "3-DOF on rigid ground, five mechanisms", scenario_option_names, prepare_block, run_rigid,
       &three_dof_on_rigid_ground(), rigid_sweep, rigid_sweep_axes, &rigid_forced(), nullptr},
      {"assembly", "block assemblies (preset or TOML file) with deformable or rigid contacts", assembly_option_names,
       prepare_assembly, nullptr, nullptr, nullptr, nullptr, &assembly_forced(), nullptr},
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
