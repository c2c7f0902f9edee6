// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/dynamics/lyapunov.hpp"

namespace blockdyn {

const char* to_string(LyapunovMethod m) { return m == LyapunovMethod::Time ? "time" : "section"; }

const char* to_string(LyapunovStatus s) {
  switch (s) {
    case LyapunovStatus::Completed:
      return "completed";
    case LyapunovStatus::ReferenceStopped:
      return "reference_stopped";
    case LyapunovStatus::PerturbedStopped:
      return "perturbed_stopped";
    case LyapunovStatus::Failed:
      return "failed";
  }
  return "?";
}

void validate(const LyapunovOptions& o) {
  auto bad = [](const std::string& f, const std::string& range, double v) {
    std::ostringstream os;
    os << f << " = " << v << " is out of range: must be " << range;
    throw std::invalid_argument(os.str());
  };
  if (!std::isfinite(o.t_start) || o.t_start < 0) bad("t-start", "finite and >= 0", o.t_start);
  if (!std::isfinite(o.t_end) || o.t_end <= o.t_start || o.t_end > 1e7) bad("t-end", "> t-start and <= 1e7", o.t_end);
  if (!(o.d0 >= 1e-14 && o.d0 <= 1e-2)) bad("d0", "in [1e-14, 1e-2]", o.d0);
  // Renormalisations are kept in the history: at most 1e7 of them.
  if (!std::isfinite(o.interval) || o.interval <= 0 || (o.t_end - o.t_start) / o.interval > 1e7)
    bad("interval", "> 0 and at least (t-end - t-start) / 1e7", o.interval);
  if (!std::isfinite(o.max_gap) || o.max_gap <= 0) bad("max-gap", "finite and > 0", o.max_gap);
  if (o.max_deferrals < 1) bad("max-deferrals", ">= 1", o.max_deferrals);
}

}  // namespace blockdyn
