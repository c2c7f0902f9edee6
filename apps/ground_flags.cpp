// SPDX-License-Identifier: Apache-2.0
#include "ground_flags.hpp"

#include <memory>

#include "cli_common.hpp"

namespace blockdyn::cli {

void add_ground_flags(CLI::App& s, GroundFlags& f) {
  for (int i = 0; i < 2; ++i) {
    GroundComponentFlags& c = i == 0 ? f.h : f.v;
    const std::string n = i == 0 ? "--ground-h" : "--ground-v";
    const std::string what = i == 0 ? "horizontal" : "vertical";
    s.add_option(n, c.constant, "constant " + what + " ground acceleration (g)");
    s.add_option(n + "-amplitude", c.amplitude, what + " harmonic or pulse amplitude A (g): A g sin(2 pi F t + PHI)");
    s.add_option(n + "-frequency", c.frequency, what + " harmonic frequency F (Hz; non-dimensional winkler: per unit time)");
    s.add_option(n + "-phase", c.phase, what + " harmonic phase PHI (rad)");
    s.add_option(n + "-start", c.start, what + " ground motion start time");
    s.add_option(n + "-duration", c.duration, what + " duration: of the pulse, or of the motion (0: no end)");
    s.add_option(n + "-pulse", c.pulse,
                 what + " pulse shape: " + pulse_names() + " (with -amplitude and -duration)");
    s.add_option(n + "-record", c.record, what + " accelerogram file: PEER .AT2, or CSV 't, a' (s, g)");
    s.add_option(n + "-scale", c.scale, what + " scale factor on the record (default 1)");
  }
}

void apply_ground_flags(const CLI::App& s, const GroundFlags& f, GroundMotion& g) {
  for (int i = 0; i < 2; ++i) {
    GroundComponent& c = i == 0 ? g.horizontal : g.vertical;
    const GroundComponentFlags& k = i == 0 ? f.h : f.v;
    const std::string n = i == 0 ? "--ground-h" : "--ground-v";
    if (given(s, n)) c.constant = k.constant;
    if (given(s, n + "-amplitude")) c.amplitude = k.amplitude;
    if (given(s, n + "-frequency")) c.frequency = k.frequency;
    if (given(s, n + "-phase")) c.phase = k.phase;
    if (given(s, n + "-start")) c.t_start = k.start;
    if (given(s, n + "-duration")) c.duration = k.duration;
    if (given(s, n + "-scale")) c.scale = k.scale;
    if (given(s, n + "-pulse")) {
      const auto p = pulse_from_string(k.pulse);
      if (!p) throw UsageError(n + "-pulse = '" + k.pulse + "' is not one of: " + pulse_names());
      c.pulse = *p;
    }
    if (given(s, n + "-record"))
      c.record = std::make_shared<const Accelerogram>(load_accelerogram(k.record, n + "-record"));
    if (given(s, n + "-scale") && !c.record) throw UsageError(n + "-scale needs a record (" + n + "-record FILE)");
  }
}

}  // namespace blockdyn::cli
