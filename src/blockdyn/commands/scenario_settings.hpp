// SPDX-License-Identifier: Apache-2.0
#pragma once
// One block's run (winkler, housner, rigid) from Settings: an optional TOML scenario (`scenario`)
// with the options given on top of it, every family's options checked against the family chosen.
#include <string>
#include <vector>

#include "blockdyn/commands/settings.hpp"
#include "blockdyn/io/scenario.hpp"

namespace blockdyn {

// The options scenario_from reads (without dashes).
const std::vector<std::string>& scenario_option_names();
// Throws std::invalid_argument naming the option for a value out of range, an option of another
// family, or a block described twice.
Scenario scenario_from(const Settings& s);

}  // namespace blockdyn
