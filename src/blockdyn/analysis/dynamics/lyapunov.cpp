// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/dynamics/lyapunov.hpp"

namespace blockdyn {

const char* to_string(LyapunovMethod m) { return m == LyapunovMethod::Time ? "time" : "section"; }

const char* to_string(LyapunovStatus s) {
  switch (s) {
    case LyapunovStatus::Completed: return "completed";
    case LyapunovStatus::ReferenceStopped: return "reference_stopped";
    case LyapunovStatus::PerturbedStopped: return "perturbed_stopped";
    case LyapunovStatus::Failed: return "failed";
  }
  return "?";
}

void validate(const LyapunovOptions& o) {
  auto bad = [](const std::string& f, const std::string& range, double v) {
    throw std::invalid_argument(f + " = " + std::to_string(v) + " is out of range: must be " + range);
  };
  if (!std::isfinite(o.t_start) || o.t_start < 0) bad("t-start", "finite and >= 0", o.t_start);
  if (!std::isfinite(o.t_end) || o.t_end <= o.t_start) bad("t-end", "finite and > t-start", o.t_end);
  if (!(o.d0 >= 1e-14 && o.d0 <= 1e-2)) bad("d0", "in [1e-14, 1e-2]", o.d0);
  if (!std::isfinite(o.interval) || o.interval <= 0) bad("interval", "finite and > 0", o.interval);
  if (!std::isfinite(o.max_gap) || o.max_gap <= 0) bad("max-gap", "finite and > 0", o.max_gap);
  if (o.max_deferrals < 1) bad("max-deferrals", ">= 1", o.max_deferrals);
}

}  // namespace blockdyn
