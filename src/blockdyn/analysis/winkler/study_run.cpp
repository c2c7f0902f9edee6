// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/winkler/study_run.hpp"

#include "blockdyn/base/number_text.hpp"

#include <stdexcept>
#include <string>

namespace blockdyn {

WinklerRunOptions lean_study_options(const StudyRunOptions& o) {
  WinklerRunOptions s;
  s.t_end = o.t_end;
  s.integrator = o.integrator;
  s.track_energy = false;
  s.record_events = false;
  return s;
}

WinklerResult run_checked(const WinklerParams& p, const IcChoice& ic, const WinklerRunOptions& s, WinklerSink* sink) {
  WinklerResult res = simulate(p, {}, ic.state(p), s, sink);
  if (res.status == SimStatus::NumericalFailure)
    throw std::runtime_error("integration failed (" + std::string(to_string(res.run_status)) + ") for " + ic.name() +
                             ", r = " + number_text(p.r) + ", mu = " + number_text(p.mu) + ", k = " + number_text(p.k) +
                             " at t = " + number_text(res.t_final));
  return res;
}

}  // namespace blockdyn
