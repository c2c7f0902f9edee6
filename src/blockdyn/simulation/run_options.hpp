// SPDX-License-Identifier: Apache-2.0
#pragma once
// The options of one run, shared by every model family, with one validation. A family's options
// extend them (WinklerRunOptions: the Winkler block's stop criteria; AssemblyRunOptions: the
// trajectory's interval, the rigid law's scheme and step).
#include "blockdyn/integrate/integrator_options.hpp"

namespace blockdyn {

// Bounded: a run of 1e7 time units is already days of computation at the default tolerances.
inline constexpr double kMaxTime = 1e7;
// The tolerances a run accepts: below 1e-14 no pair can meet the tolerance in double precision;
// above 1e-2 the events and energies lose their meaning.
inline constexpr double kMinRtol = 1e-14, kMaxRtol = 1e-2, kMinAtol = 1e-16, kMaxAtol = 1e-2;

// The tolerances' help, from the same bounds as the check.
inline const char* rtol_help() { return "relative tolerance of the integrator, in [1e-14, 1e-2]"; }
inline const char* atol_help() { return "absolute tolerance (scaled by 1/k for y), in [1e-16, 1e-2]"; }
static_assert(kMinRtol == 1e-14 && kMaxRtol == 1e-2 && kMinAtol == 1e-16 && kMaxAtol == 1e-2,
              "the help strings above state these bounds");

struct RunOptions {
  double t_start = 0.0;
  double t_end = 10.0;
  IntegratorOptions integrator;
  bool record_events = true;  // keep the list of events (counts are always kept)
  bool track_energy = true;   // the energy balance at every step end
};

// t-start in [0, 1e7], t-end in (t-start, 1e7], rtol in [1e-14, 1e-2], atol in [1e-16, 1e-2],
// h-max > 0, max-steps in [1, 1e12], event-samples in [1, 64]; std::invalid_argument naming the
// option and its range.
void validate(const RunOptions& o);

}  // namespace blockdyn
