// SPDX-License-Identifier: Apache-2.0
#pragma once
// `blockdyn limit-analysis (--preset ... | FILE.toml)`: the static collapse multiplier of an
// assembly (analysis/masonry/limit_analysis.hpp) from options by name: the preset's geometry
// options or `file`, `phi-s`, `phi-l`, `g`, `direction`, `min-thickness` (the arch preset), and
// `tolerance` (of the minimum thickness).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/commands/option_spec.hpp"
#include "blockdyn/commands/settings.hpp"

namespace blockdyn {

const std::vector<StudyOption>& limit_analysis_options();
// The JSON document (schema blockdyn.limit-analysis/1); std::invalid_argument naming the option.
nlohmann::ordered_json limit_analysis_run(const Settings& s);
// The same for a person.
std::string limit_analysis_text(const nlohmann::ordered_json& j);

}  // namespace blockdyn
