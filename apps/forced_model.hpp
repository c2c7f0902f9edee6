// SPDX-License-Identifier: Apache-2.0
#pragma once
// The model flags shared by the forced analyses (spectrum, survival, ...): a block on rigid ground
// (--model housner|rigid with --width --height ...) or an assembly preset (--model assembly
// --preset ...). The library builds the model from the flags given (forced_model_from).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/analysis/forced/forced_model.hpp"
#include "blockdyn/api/settings.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"

namespace blockdyn::cli {

struct ForcedModelFlags {
  std::string model = "housner", preset, contact = "deformable", impact = "housner";
  double width = 0, height = 0, mass = 1, g = 9.81, mu_s = 0.7, mu_k = -1, restitution = -1;
  PresetOptions preset_opt;
  double phi_s = 90, phi_l = 90;
  bool columns_rock_only = false;  // seed 001's 5-DOF trilith (rigid law)
};

using blockdyn::ForcedModel;

// extra_models: further values --model accepts (handled by the command itself).
void add_forced_model_flags(CLI::App& s, ForcedModelFlags& f, const std::vector<std::string>& extra_models = {});
// The excitation and frequency grid of survival and response-curve: --excitation, --phase,
// --omega-min/max/points, --t-end, --periods, --threads.
void add_excitation_grid_flags(CLI::App& s, SurvivalOptions& o);
// The model the given flags describe (api/forced_model_settings.hpp); `settings` (optional) are the
// flags already gathered and possibly changed (a response curve's friction axes).
ForcedModel build_forced_model(const CLI::App& s);
ForcedModel build_forced_model(const Settings& settings);

}  // namespace blockdyn::cli
