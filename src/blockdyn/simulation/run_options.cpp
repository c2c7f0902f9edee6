// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/run_options.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace blockdyn {

void validate(const RunOptions& o) {
  auto bad = [](const std::string& f, const std::string& range, double v) {
    throw std::invalid_argument(f + " = " + number_text(v) + " is out of range: must be " + range);
  };
  if (!std::isfinite(o.t_start) || o.t_start < 0 || o.t_start > kMaxTime) bad("t-start", "in [0, 1e7]", o.t_start);
  if (!std::isfinite(o.t_end) || o.t_end <= o.t_start || o.t_end > kMaxTime)
    bad("t-end", "> t-start and <= 1e7", o.t_end);
  const IntegratorOptions& i = o.integrator;
  if (!(i.rtol >= kMinRtol && i.rtol <= kMaxRtol)) bad("rtol", "in [1e-14, 1e-2]", i.rtol);
  if (!(i.atol >= kMinAtol && i.atol <= kMaxAtol)) bad("atol", "in [1e-16, 1e-2]", i.atol);
  if (!(i.h_max > 0)) bad("h-max", "> 0", i.h_max);
  if (i.max_steps <= 0 || i.max_steps > 1'000'000'000'000) bad("max-steps", "in [1, 1e12]", double(i.max_steps));
  if (i.event_samples < 1 || i.event_samples > 64) bad("event-samples", "in [1, 64]", i.event_samples);
}

}  // namespace blockdyn
