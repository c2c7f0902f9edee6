// SPDX-License-Identifier: Apache-2.0
#pragma once
// The model options of the forced grid analyses (spectrum, survival, response-curve): a block on
// rigid ground (--model housner|rigid with --width --height ...) or an assembly preset (--model
// assembly --preset ...), registered from the library's description (forced_model_options); the
// library builds the model from the options given (forced_model_from).
#include <CLI/CLI.hpp>

#include "blockdyn/analysis/forced/forced_model.hpp"
#include "blockdyn/analysis/forced/survival_map.hpp"
#include "blockdyn/api/forced_model_settings.hpp"

namespace blockdyn::cli {

void add_forced_model_flags(CLI::App& s);
// The model's name, preset, contact law and friction angles as given.
ForcedModelChoice forced_model_choice(const CLI::App& s);
// The excitation and frequency grid of survival and response-curve: --excitation, --phase,
// --omega-min/max/points, --t-end, --periods, --threads.
void add_excitation_grid_flags(CLI::App& s, SurvivalOptions& o);
// The model the given flags describe.
ForcedModel build_forced_model(const CLI::App& s);

}  // namespace blockdyn::cli
