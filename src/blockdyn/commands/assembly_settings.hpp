// SPDX-License-Identifier: Apache-2.0
#pragma once
// A block assembly's run from Settings: a preset (block, trilith, column, arch) or an assembly file, the
// contact law and its parameters, the ground motion and the run options, validated once for the
// command line (`assembly`, `simulate --model assembly`) and Python.
#include <string>
#include <vector>

#include "blockdyn/commands/settings.hpp"
#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/simulation/assembly_simulation.hpp"

namespace blockdyn {

struct AssemblySetup {
  Assembly assembly;
  GroundMotion ground;
  AssemblyRunOptions run;
};

// The presets and the geometry options of each (without dashes).
const std::vector<std::string>& preset_names();
const std::vector<std::string>& preset_geometry_option_names();
// A preset's geometry (the contact laws left at their defaults); throws std::invalid_argument
// for an unknown preset or an option that belongs to another preset.
PresetOptions preset_geometry_from(const Settings& s, const std::string& preset);

// The options assembly_from reads (without dashes); the assembly file is `file` (or `scenario`).
const std::vector<std::string>& assembly_option_names();
// Throws std::invalid_argument naming the option.
AssemblySetup assembly_from(const Settings& s);
// The assembly alone (blocks, interfaces, laws), validated for up to max_blocks blocks.
Assembly assembly_geometry_from(const Settings& s, int max_blocks);

}  // namespace blockdyn
