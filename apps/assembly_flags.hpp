// SPDX-License-Identifier: Apache-2.0
#pragma once
// The assembly family's model options (preset, contact law, friction, collapse criteria, rigid
// step), registered on `assembly` and on `simulate` (for --model assembly). The values are read by
// the library from the options given (commands/assembly_settings.cpp); the fields here only give CLI11
// the types to check and --help the defaults.
#include <CLI/CLI.hpp>

#include <string>

#include "blockdyn/model/assembly/assembly_params.hpp"

namespace blockdyn::cli {

struct AssemblyFlags {
  std::string preset, contact = "deformable", scheme = "event-driven";
  PresetOptions preset_opt;
  double phi_s = 90, phi_l = 90, tilt = 0, phi_s_kinetic = 0, phi_l_kinetic = 0;
  double k_normal = 1e7, k_tangential = 0, restitution = 0.5;
  double collapse_rotation = 1.0, min_bearing = 0.0, g = 9.81, step = 1e-4;
  bool rock_only = false;
};

// Adds the options that `app` does not have yet (a command's own --restitution, --g, ... stay).
void add_assembly_options(CLI::App& app, AssemblyFlags& f);

}  // namespace blockdyn::cli
