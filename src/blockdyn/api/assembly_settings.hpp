// SPDX-License-Identifier: Apache-2.0
#pragma once
// A block assembly's run from Settings: a preset (block, trilith, column) or an assembly file, the
// contact law and its parameters, the ground motion and the run options, validated once for the
// command line (`assembly`, `simulate --model assembly`) and Python.
#include <string>
#include <vector>

#include "blockdyn/api/settings.hpp"
#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/simulation/assembly_simulation.hpp"

namespace blockdyn {

struct AssemblySetup {
  Assembly assembly;
  GroundMotion ground;
  AssemblyRunOptions run;
};

// The options assembly_from reads (without dashes); the assembly file is `file` (or `scenario`).
const std::vector<std::string>& assembly_option_names();
// Throws std::invalid_argument naming the option.
AssemblySetup assembly_from(const Settings& s);

}  // namespace blockdyn
