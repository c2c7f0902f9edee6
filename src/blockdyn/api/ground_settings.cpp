// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/api/ground_settings.hpp"

#include <stdexcept>
#include <string>

namespace blockdyn {

const std::vector<std::string>& ground_option_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const char* c : {"ground-h", "ground-v"})
      for (const char* k :
           {"", "-amplitude", "-frequency", "-phase", "-start", "-duration", "-pulse", "-record", "-scale"})
        n.push_back(std::string(c) + k);
    return n;
  }();
  return names;
}

void apply_ground_settings(const Settings& s, GroundMotion& g) {
  for (int i = 0; i < 2; ++i) {
    GroundComponent& c = i == 0 ? g.horizontal : g.vertical;
    const std::string n = i == 0 ? "ground-h" : "ground-v";
    c.constant = s.number(n, c.constant);
    c.amplitude = s.number(n + "-amplitude", c.amplitude);
    c.frequency = s.number(n + "-frequency", c.frequency);
    c.phase = s.number(n + "-phase", c.phase);
    c.t_start = s.number(n + "-start", c.t_start);
    c.duration = s.number(n + "-duration", c.duration);
    c.scale = s.number(n + "-scale", c.scale);
    if (s.has(n + "-pulse")) {
      const std::string v = s.text(n + "-pulse");
      const auto p = pulse_from_string(v);
      if (!p) throw std::invalid_argument("--" + n + "-pulse = '" + v + "' is not one of: " + pulse_names());
      c.pulse = *p;
    }
    if (auto r = s.record(n + "-record"))
      c.record = std::move(r);
    else if (s.has(n + "-record"))
      c.record = std::make_shared<const Accelerogram>(load_accelerogram(s.text(n + "-record"), "--" + n + "-record"));
    if (s.has(n + "-scale") && !c.record)
      throw std::invalid_argument("--" + n + "-scale needs a record (--" + n + "-record FILE)");
  }
}

}  // namespace blockdyn
