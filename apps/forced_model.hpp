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
#include <vector>

#include "blockdyn/analysis/forced/forced_trace.hpp"
#include "blockdyn/analysis/forced/forced_lyapunov.hpp"
#include "blockdyn/analysis/forced/survival_map.hpp"
#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"

namespace blockdyn::cli {

struct ForcedModelFlags {
  std::string model = "housner", preset, contact = "deformable", impact = "housner";
  double width = 0, height = 0, mass = 1, g = 9.81, mu_s = 0.7, mu_k = -1, restitution = -1;
  PresetOptions preset_opt;
  double phi_s = 90, phi_l = 90;
  bool columns_rock_only = false;  // seed 001's 5-DOF trilith (rigid law)
};


struct ForcedModel {
  double alpha = 0, p = 0;  // of the (first) block: slenderness angle and frequency parameter
  double width = 0;         // of the (first) block (m): the scale of sliding
  nlohmann::ordered_json description;
  nlohmann::ordered_json tolerances;  // of every run (recorded in the table's sidecar)
  std::string overturn_rule;
  // Thread-safe: one simulation from rest to t_end (s) under g, reduced to what the forced
  // analyses classify (blocks: collapse mode 1 when overturned). Under harmonic motion the
  // outcome's cycle is the dominant (m, n) cycle of block 0 (cycle_detection.hpp).
  SurvivalRun run;
  // The same run reporting to a probe (may be null): the cycle and impact-map analyses.
  std::function<SurvivalOutcome(const GroundMotion& g, double t_end, RunProbe* probe)> traced;
  ImpactRule impact_rule = ImpactRule::VelocityJump;  // what an impact is for this model (forced_trace.hpp)
  std::vector<std::string> block_names;               // one per block (1 for housner/rigid)
  std::string impact_definition;                       // the same in words, for the outputs
  // Thread-safe: the largest Lyapunov exponent of one run under g (the initial state is used by
  // the rigid-ground models; assemblies start as built).
  std::function<ForcedLyapunovOutcome(const GroundMotion& g, const ForcedLyapunovOptions& o, const RigidInitial& init)>
      lyapunov;
};

// extra_models: further values --model accepts (handled by the command itself).
void add_forced_model_flags(CLI::App& s, ForcedModelFlags& f, const std::vector<std::string>& extra_models = {});
// The excitation and frequency grid of survival and response-curve: --excitation, --phase,
// --omega-min/max/points, --t-end, --periods, --threads.
void add_excitation_grid_flags(CLI::App& s, SurvivalOptions& o);
ForcedModel build_forced_model(const CLI::App& s, const ForcedModelFlags& f);

}  // namespace blockdyn::cli
