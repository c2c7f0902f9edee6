// SPDX-License-Identifier: Apache-2.0
#pragma once
// The model flags shared by the forced analyses (spectrum, survival): a block on rigid ground
// (--model housner|rigid with --width --height ...) or an assembly preset (--model assembly
// --preset ...), and one run of it under a ground motion, reduced to what the analyses classify.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"

namespace blockdyn::cli {

struct ForcedModelFlags {
  std::string model = "housner", preset, contact = "deformable", impact = "housner";
  double width = 0, height = 0, mass = 1, g = 9.81, mu_s = 0.7, mu_k = -1, restitution = -1;
  PresetOptions preset_opt;
  double phi_s = 90, phi_l = 90;
};

struct ForcedOutcome {
  bool moved = false;                 // left rest at some time (a contact opened, closed or slipped)
  std::optional<int> collapse_mode;   // 1 (rotation) or 2 (bearing); blocks: 1 when overturned
  std::optional<double> t_failure;    // s
  double max_abs_rotation = 0;        // rad (assemblies: the largest over the blocks)
  double max_sliding = 0;             // m: assemblies, the largest slip between blocks (0 otherwise)
  bool invalid = false;               // the run left the model's validity
};

struct ForcedModel {
  double alpha = 0, p = 0;  // of the (first) block: slenderness angle and frequency parameter
  double width = 0;         // of the (first) block (m): the scale of sliding
  nlohmann::ordered_json description;
  std::string overturn_rule;
  // Thread-safe: one simulation from rest to t_end (s) under g.
  std::function<ForcedOutcome(const GroundMotion& g, double t_end)> run;
};

void add_forced_model_flags(CLI::App& s, ForcedModelFlags& f);
ForcedModel build_forced_model(const CLI::App& s, const ForcedModelFlags& f);

}  // namespace blockdyn::cli
