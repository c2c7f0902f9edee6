// SPDX-License-Identifier: Apache-2.0
#pragma once
// The model of every forced analysis (spectrum, survival, response curve, cycles, impact maps,
// Lyapunov exponents, chaos maps): a block on rigid ground (housner, 3-DOF) or an assembly, and
// one run of it under a ground motion reduced to what the analyses classify.
#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

#include "blockdyn/analysis/forced/forced_lyapunov.hpp"
#include "blockdyn/analysis/forced/forced_trace.hpp"
#include "blockdyn/analysis/forced/survival_map.hpp"
#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/excitation/ground_motion_3d.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/model/rigid_ground/rigid_params.hpp"

namespace blockdyn {

struct ForcedModel {
  // Of the (first) block: slenderness angle and frequency parameter; width (m), the scale of
  // sliding. Polygonal assemblies: atan(lambda) of the static limit analysis, and the assembly's
  // bounding box.
  double alpha = 0, p = 0;
  double width = 0;
  nlohmann::ordered_json description;
  nlohmann::ordered_json tolerances;  // of every run (recorded in the table's sidecar)
  std::string overturn_rule;
  // Thread-safe: one simulation from rest to t_end (s) under g, reduced to what the forced
  // analyses classify (blocks: collapse mode 1 when overturned). Under harmonic motion the
  // outcome's cycle is the dominant (m, n) cycle of block 0 (cycle_detection.hpp).
  SurvivalRun run;
  // A 3D body's run under ground motion in three components (its `azimuth` the direction of h
  // from the body's e1); null for the planar families.
  std::function<SurvivalOutcome(const GroundMotion3d& g, double t_end)> run3;
  // The same run reporting to a probe (may be null): the cycle and impact-map analyses.
  std::function<SurvivalOutcome(const GroundMotion& g, double t_end, RunProbe* probe)> traced;
  ImpactRule impact_rule = ImpactRule::VelocityJump;  // what an impact is for this model (forced_trace.hpp)
  std::vector<std::string> block_names;               // one per block (1 for housner/rigid)
  std::string impact_definition;                      // the same in words, for the outputs
  // Thread-safe: the largest Lyapunov exponent of one run under g (the initial state is used by
  // the rigid-ground models; assemblies start as built).
  std::function<ForcedLyapunovOutcome(const GroundMotion& g, const ForcedLyapunovOptions& o, const RigidInitial& init)>
      lyapunov;
  // Its orbits have a variational equation (false: an assembly run by time-stepping).
  bool linearisable = true;
};

struct RigidGroundModel;
// A block on rigid ground: Housner's 1-DOF block or the 3-DOF block. Throws std::invalid_argument
// for invalid parameters (a Housner block with b/h > sqrt(2) and no restitution).
ForcedModel forced_block_model(const RigidBlockParams& p, const RigidGroundModel& m);
// An assembly (validated); `description` is recorded as the model's in the outputs.
ForcedModel forced_assembly_model(const Assembly& a, nlohmann::ordered_json description);

}  // namespace blockdyn
