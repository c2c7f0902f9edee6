// SPDX-License-Identifier: Apache-2.0
#pragma once
// What happens at an assembly's event, for both contact laws: the transitions' kinds, the event
// records' and the outputs' (by name).

namespace blockdyn {

// Kinds of assembly events reported to observers.
enum AssemblyEventKind : int {
  kAssemblyContactOpens = 1,
  kAssemblyContactCloses,
  kAssemblySlipStarts,
  kAssemblyStickStarts,
  kAssemblyEndSwitch,
  kAssemblyUprightPassage,
  kAssemblyRotationCollapse,
  kAssemblyBearingCollapse,
  kAssemblyOutsideModel,
  kAssemblyInputBreakpoint,
  kAssemblyImpact,
  // The rigid law, event-driven: a window handed to time-stepping, and the return from it.
  kAssemblyToTimeStepping,
  kAssemblyToEventDriven
};
const char* assembly_event_name(int kind);

}  // namespace blockdyn
