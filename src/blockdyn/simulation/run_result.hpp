// SPDX-License-Identifier: Apache-2.0
#pragma once
// What every run reports, whatever its family: the result core each family's result extends
// (WinklerResult, RigidResult, AssemblyResult, Body3dResult), the event record core each
// family's typed event record extends, and the one shape in which a run hands its event records
// to a caller as they happen (an EventSink of the family's record: a JSON event list streamed to
// a file, a Python callback).
#include <string>
#include <utility>

#include "blockdyn/integrate/dense_segment.hpp"
#include "blockdyn/integrate/integrator_options.hpp"
#include "blockdyn/simulation/run_clock.hpp"
#include "blockdyn/simulation/sim_status.hpp"

namespace blockdyn {

struct RunResult {
  SimStatus status = SimStatus::TEnd;            // the one status vocabulary (sim_status.hpp)
  RunStatus run_status = RunStatus::ReachedEnd;  // why the stepping ended
  std::string note;                              // why a run stopped early (Painleve, outside the model, ...)
  double t_final = 0;
  // The closed energy balance |E - E0 - W| (W: the works of the ground, friction, impacts) and
  // the largest |E - E0|, over every step end and both sides of every event.
  double max_abs_energy_error = 0, max_abs_energy_change = 0;
  long impacts = 0;
  StepperStats stats;  // accepted and rejected steps, right-hand sides
  RunTiming timing;    // of the integration alone
};

// A family's event record: when, and its typed kind (the family's enum; its name only in the
// family's JSON writer), followed by what the family records of it.
template <class Kind>
struct EventRecordCore {
  double t = 0;
  Kind kind{};
};

template <class Record>
class EventSink {
 public:
  virtual ~EventSink() = default;
  virtual void on_event(const Record&) = 0;
};

// An EventSink that hands each record to a function.
template <class Record, class F>
class EventCallback final : public EventSink<Record> {
 public:
  explicit EventCallback(F f) : f_(std::move(f)) {}
  void on_event(const Record& r) override { f_(r); }

 private:
  F f_;
};

}  // namespace blockdyn
