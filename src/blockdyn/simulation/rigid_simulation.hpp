// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid-ground family's runs (Housner's 1-DOF block and the 3-DOF block) and what users ask
// of them: outcome (t_end, overturned, invalid), the mechanism at the end, the largest rotation,
// impacts, mechanism changes, passages beyond alpha, the energy terms and their closed balance.
// SI units: seconds, metres, radians, joules.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/model/rigid_ground/housner_block.hpp"
#include "blockdyn/model/rigid_ground/rigid_block.hpp"
#include "blockdyn/simulation/observer.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

// Initial rotation and rate; for the 3-DOF block also the centre and its velocity. Without y0 the
// block stands on its lowest base corner; without vx0/vy0 it rotates about that corner.
struct RigidInitial {
  double w0 = 0.0, vw0 = 0.0;
  std::optional<double> x0, y0, vx0, vy0;
};

// The rigid block's run: the shared options as they are.
using RigidRunOptions = RunOptions;

struct RigidEventRecord : EventRecordCore<RigidEventKind> {
  Mechanism from = Mechanism::Rest, to = Mechanism::Rest;
  int corner = 0;                      // impact: +1 A (left), -1 B (right)
  int pivot = 0, slip = 0;             // the new mode's corner in contact (rock, slide-rock) and slip sign
  double vw_before = 0, vw_after = 0;  // impact: theta' before and after
  std::array<double, 6> state{};       // x, y, w, vx, vy, vw after the event
  unsigned mechanisms = 0;             // ambiguous_onset: the consistent mechanisms (mechanism_bit)
};

inline constexpr int kNumRigidEventKinds = int(RigidEventKind::AmbiguousOnset) + 1;

// Receives each event record as it is made (e.g. to stream a JSON event list), whether or not
// the result keeps the list (RigidRunOptions::record_events).
using RigidEventSink = EventSink<RigidEventRecord>;

struct RigidResult : RunResult {
  std::string model;  // housner | rigid
  double t_start = 0;
  Mechanism initial_mode = Mechanism::Rest, final_mode = Mechanism::Rest;
  std::array<double, 6> initial_state{}, final_state{};
  double max_abs_rotation = 0, t_max_abs_rotation = 0;
  std::optional<double> overturn_time, first_motion_time, first_uplift_time, first_beyond_alpha_time;
  long mode_changes = 0;
  std::array<long, kNumRigidEventKinds> event_counts{};
  std::vector<RigidEventRecord> events;
  double energy_initial = 0, kinetic_final = 0, potential_final = 0;
  double work_friction = 0, work_ground = 0, work_impact = 0;
};

// Throws std::invalid_argument for invalid parameters, options or initial states.
RigidResult simulate_housner(const BlockShape& shape, std::optional<double> restitution, const GroundMotion& g,
                             const RigidInitial& init, const RigidRunOptions& opt,
                             Observer<HousnerBlock>* extra = nullptr, RigidEventSink* events = nullptr);
RigidResult simulate_rigid(const RigidBlockParams& p, const GroundMotion& g, const RigidInitial& init,
                           const RigidRunOptions& opt, Observer<RigidBlock>* extra = nullptr,
                           RigidEventSink* events = nullptr);

// The initial state vectors (validated against the model; throw std::invalid_argument).
HousnerBlock::State housner_initial_state(const HousnerBlock& m, const RigidInitial& init);
RigidBlock::State rigid_initial_state(const RigidBlock& m, const RigidInitial& init);

}  // namespace blockdyn
