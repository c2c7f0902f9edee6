// SPDX-License-Identifier: Apache-2.0
#pragma once
// Runs of block assemblies (model/assembly) and what users ask of them (spec block-assemblies.md,
// seed 002): the outcome (t_end, collapsed, invalid), the motion class (rest: no contact ever
// opened or slipped; stable: moved, no failure; collapse), the collapse mode (1: a block's
// rotation reached its limit; 2: an interface lost its bearing) and t*, per block the largest
// rotation and sliding and the final state, the energy terms and their closed balance, and the
// events. SI units.
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/integrate/integrator_options.hpp"
#include "blockdyn/model/assembly/assembly_event_kind.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/simulation/run_options.hpp"
#include "blockdyn/simulation/run_probe.hpp"
#include "blockdyn/simulation/run_result.hpp"
#include "blockdyn/simulation/sim_status.hpp"
#include "blockdyn/simulation/trajectory_table.hpp"

namespace blockdyn {

struct AssemblyEventRecord : EventRecordCore<AssemblyEventKind> {  // the kind's name: assembly_event_name()
  int block = -1;  // the block concerned (contacts: the upper block of the interface)
  int interface = -1, end = -1;
  int collapse_mode = 0;
  std::array<double, 3> pose{};  // x, y, theta of `block` after the event
};

// How the rigid contact law is integrated: event-driven (exact events: smooth phases with the
// contact forces of each mode, impacts resolved where they occur) or Moreau-Jean time-stepping
// (a fixed step; events known to within a step; for accumulations of impacts). Auto: event-driven
// up to kEventDrivenMaxBlocks blocks, time-stepping above (an arch's many joints switch so often
// that exact events cost minutes where Moreau-Jean takes seconds).
enum class AssemblyScheme { EventDriven, TimeStepping, Auto };
const char* to_string(AssemblyScheme s);

// An assembly's run: the shared options (from t = 0; tolerances 1e-8, 1e-10 by default) and the
// trajectory's interval, the event list's cap and the rigid law's scheme and step.
struct AssemblyRunOptions : RunOptions {
  AssemblyRunOptions() {
    integrator.rtol = 1e-8;
    integrator.atol = 1e-10;
  }
  double output_interval = 0.01;                 // trajectory CSV (s)
  long max_events = 1'000'000;                   // kept in the list; further events are counted only
  double step = 1e-4;                            // rigid law: Moreau-Jean time step (s)
  AssemblyScheme scheme = AssemblyScheme::Auto;  // rigid law only
  // Receives every event as it happens, whatever record_events and max_events say: a caller
  // that streams the events (the command line's JSON spool) holds O(1) memory on a run of any length.
  EventSink<AssemblyEventRecord>* events = nullptr;
};
void validate(const AssemblyRunOptions& o);
// The scheme a rigid assembly is run with: the options' (Auto resolved by the block count),
// except seed 001's 5-DOF restriction (rock_only_on_ground), which only time-stepping integrates.
AssemblyScheme effective_scheme(const Assembly& a, const AssemblyRunOptions& o);

struct AssemblyBlockSummary {
  std::string name;
  double max_abs_rotation = 0, t_max_abs_rotation = 0;
  double rotation_limit = 0;
  double max_abs_sliding = 0;  // largest slip over the interfaces it stands on (m)
  std::array<double, 6> final_state{};
};

struct AssemblyInterfaceSummary {
  int lower = -1, upper = 0;
  double max_abs_sliding = 0;  // largest |change| of the upper base centre along the lower face (m)
  double final_overlap = 0;    // length of the faces' overlap at the end (m)
  long opens = 0, slips = 0;
};

struct AssemblyEnergy {
  double kinetic = 0, gravity = 0, normal_spring = 0, tangential_spring = 0, total = 0;
};

struct AssemblyResult : RunResult {  // status: TEnd | Collapsed | Invalid
  std::string motion = "rest";       // rest | stable | collapse
  std::optional<int> collapse_mode;
  std::optional<double> t_failure;
  int failed_block = -1, failed_interface = -1;
  std::vector<AssemblyBlockSummary> blocks;
  std::vector<AssemblyInterfaceSummary> interfaces;
  AssemblyEnergy energy_initial, energy_final;
  double work_ground = 0, work_normal = 0, work_friction = 0, work_switch = 0;
  std::array<long, 16> event_counts{};  // by AssemblyEventKind
  long events_total = 0;
  std::vector<AssemblyEventRecord> events;
  std::vector<double> damping;  // calibrated damping per interface (N s/m per point)
  // impacts (rigid law): contact ends closing with an approach velocity
  // Rigid law: how the time steps' contact problems were solved (direct active-set solves, Lemke's
  // method where the active set did not settle, Gauss-Seidel as the last resort and its sweeps).
  long direct_solves = 0, lemke_solves = 0, gauss_seidel_solves = 0, gauss_seidel_sweeps = 0;
  long active_set_iterations = 0;  // the active-set guesses of all the solves
  // Rigid law, event-driven: the windows handed to time-stepping (count, total duration in s,
  // their steps) and why the first was needed.
  long time_stepping_windows = 0, time_stepping_steps = 0;
  double time_stepping_time = 0;
  std::string time_stepping_reason;
};

// One run. `trajectory` (optional) receives the trajectory table; `probe` (optional) the samples, passages of
// the rotations through 0 and contact closings/openings under each block (run_probe.hpp). Throws
// std::invalid_argument on bad input.
AssemblyResult simulate_assembly(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o,
                                 TrajectoryTable* trajectory = nullptr, RunProbe* probe = nullptr);

}  // namespace blockdyn
