// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Winkler family's run: the block from a state, with what users ask about (events, ihor,
// first flight, overturn, energy balance), the trajectory streamed to a sink. Built on the
// generic run_model() and observers (run.hpp, observer.hpp) that every model family shares.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/integrate/integrator_options.hpp"
#include "blockdyn/model/winkler/energy.hpp"
#include "blockdyn/model/winkler/winkler_block.hpp"
#include "blockdyn/simulation/run.hpp"
#include "blockdyn/simulation/run_clock.hpp"
#include "blockdyn/simulation/run_options.hpp"
#include "blockdyn/simulation/run_result.hpp"
#include "blockdyn/simulation/sim_status.hpp"

namespace blockdyn {

// The Winkler block's run: the shared options and its stop criteria.
struct WinklerRunOptions : RunOptions {
  bool stop_at_first_flight = false;
  long stop_at_upright_passages = 0;  // stop once ihor reaches this value (0: never)
};

struct WinklerEventRecord : EventRecordCore<WinklerEventKind> {
  WinklerMode from, to;
  WinklerState z{};
  long upright_passages = 0;  // after the event
};

constexpr int kNumEventKinds = int(WinklerEventKind::GrazingHold) + 1;

struct WinklerResult : RunResult {
  WinklerState initial_state{}, final_state{};
  WinklerMode initial_mode, final_mode;
  long upright_passages = 0;
  std::optional<double> first_flight_time;
  long upright_passages_at_first_flight = 0;
  std::optional<double> overturn_time;
  long upright_passages_at_overturn = 0;
  Energy initial_energy, final_energy;  // the balance's W: W_friction + W_nonpotential + W_ground
  std::vector<WinklerEventRecord> events;
  std::array<long, kNumEventKinds> event_counts{};

  double work_friction() const { return final_state[kWorkFriction]; }
  double work_nonpotential() const { return final_state[kWorkNonPotential]; }
  double work_ground() const { return final_state[kWorkGround]; }
};

// Receives the trajectory as it is computed (dense output pieces and events).
class WinklerSink {
 public:
  virtual ~WinklerSink() = default;
  virtual void on_start(const WinklerBlock&, double /*t*/, const WinklerMode&, const WinklerState&) {}
  virtual void on_segment(const WinklerBlock&, const DenseSegment<kStateDim>&, double /*t0*/, double /*t1*/,
                          const WinklerMode&) {}
  virtual void on_event(const WinklerBlock&, const WinklerEventRecord&) {}
  virtual bool keep_going() const { return true; }
  // Whether on_segment evaluates the dense output inside every step (see Observer::needs_dense;
  // a sink that answers false may call DenseSegment::ensure_full() on the steps that need it).
  virtual bool needs_dense() const { return true; }
};

// Throws std::invalid_argument if the parameters, options or initial state are invalid. `sink`
// watches the trajectory and the events; `events` receives each event record as it is made
// (e.g. to stream a JSON event list), whether or not the result keeps the list.
WinklerResult simulate(const WinklerParams& p, const GroundMotion& g, const WinklerState& z0,
                       const WinklerRunOptions& opt, WinklerSink* sink = nullptr,
                       EventSink<WinklerEventRecord>* events = nullptr);

}  // namespace blockdyn
