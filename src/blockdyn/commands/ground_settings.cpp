// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/ground_settings.hpp"

#include <stdexcept>
#include <string>

namespace blockdyn {

namespace {

void add_component_options(std::vector<StudyOption>& o, const std::string& n, const std::string& what) {
  o.push_back({n, "constant " + what + " ground acceleration (g)"});
  o.push_back({n + "-amplitude", what + " harmonic or pulse amplitude A (g): A g sin(2 pi F t + PHI)"});
  o.push_back({n + "-frequency", what + " harmonic frequency F (Hz; non-dimensional winkler: per unit time)"});
  o.push_back({n + "-phase", what + " harmonic phase PHI (rad)"});
  o.push_back({n + "-start", what + " ground motion start time"});
  o.push_back({n + "-duration", what + " duration: of the pulse, or of the motion (0: no end)"});
  o.push_back({n + "-pulse", what + " pulse shape: " + pulse_names() + " (with -amplitude and -duration)"});
  o.push_back({n + "-record", what + " accelerogram file: PEER .AT2, or CSV 't, a' (s, g)"});
  o.push_back({n + "-scale", what + " scale factor on the record (default 1)"});
}

// The fields of one component whose options (n, n-amplitude, ...) were given.
void apply_component_settings(const Settings& s, const std::string& n, GroundComponent& c) {
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
    if (!p) throw std::invalid_argument(std::string("`") + n + "-pulse` = '" + v + "' is not one of: " + pulse_names());
    c.pulse = *p;
  }
  if (auto r = s.record(n + "-record"))
    c.record = std::move(r);
  else if (s.has(n + "-record"))
    c.record = std::make_shared<const Accelerogram>(
        load_accelerogram(s.text(n + "-record"), std::string("`") + n + "-record`"));
  if (s.has(n + "-scale") && !c.record)
    throw std::invalid_argument(std::string("`") + n + "-scale` needs a record (`" + n + "-record` FILE)");
}

}  // namespace

const std::vector<StudyOption>& ground_options() {
  static const std::vector<StudyOption> options = [] {
    std::vector<StudyOption> o;
    add_component_options(o, "ground-h", "horizontal");
    add_component_options(o, "ground-v", "vertical");
    return o;
  }();
  return options;
}

const std::vector<StudyOption>& ground_3d_options() {
  static const std::vector<StudyOption> options = [] {
    std::vector<StudyOption> o;
    add_component_options(o, "ground-h2", "rigid3d: second horizontal (at the azimuth + 90 deg)");
    o.push_back({"ground-azimuth", "rigid3d: direction of the ground-h component, degrees from x towards y", "0"});
    return o;
  }();
  return options;
}

const std::vector<std::string>& ground_option_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const StudyOption& o : ground_options()) n.push_back(o.name);
    return n;
  }();
  return names;
}

void apply_ground_settings(const Settings& s, GroundMotion& g) {
  apply_component_settings(s, "ground-h", g.horizontal);
  apply_component_settings(s, "ground-v", g.vertical);
}

void apply_ground_settings(const Settings& s, GroundMotion3d& g) {
  apply_component_settings(s, "ground-h", g.h);
  apply_component_settings(s, "ground-h2", g.h2);
  apply_component_settings(s, "ground-v", g.v);
  g.azimuth = s.number("ground-azimuth", g.azimuth);
}

}  // namespace blockdyn
