// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/excitation/ground_motion.hpp"

#include <cmath>
#include <string>

#include "blockdyn/base/checks.hpp"
#include "blockdyn/base/number_text.hpp"

namespace blockdyn {

double GroundComponent::next_break(double t) const {
  double b = std::numeric_limits<double>::infinity();
  if (is_zero()) return b;
  if (t < t_start) return t_start;
  const double stop = t_stop();
  if (t < stop) b = stop;
  if (record && t < stop) {
    const double s = (t - t_start) * record_time_unit;
    double next = record->next_sample_after(s);
    // The sample time converted back must lie strictly after t (rounding).
    while (std::isfinite(next) && !(t_start + next / record_time_unit > t)) next = record->next_sample_after(next);
    if (std::isfinite(next)) b = std::fmin(b, t_start + next / record_time_unit);
  }
  return b;
}

double GroundComponent::rate(double t) const {
  if (t < t_start || t >= t_stop()) return 0.0;
  const double s = t - t_start;
  double r = 0.0;
  if (amplitude != 0.0) {
    if (has_pulse()) {
      r += amplitude * pulse_rate(pulse, s, duration);
    } else {
      const double w = 2.0 * M_PI * frequency;
      r += amplitude * w * std::cos(w * s + phase);
    }
  }
  if (record) r += scale * record_time_unit * record->slope(s * record_time_unit);
  return r;
}

double GroundComponent::curvature_bound() const {
  if (amplitude == 0.0) return 0.0;
  if (has_pulse()) return std::fabs(amplitude) * pulse_curvature_bound(pulse, duration);
  const double w = 2.0 * M_PI * frequency;
  return std::fabs(amplitude) * w * w;
}

void validate(const GroundMotion& g) {
  validate(g.horizontal, "ground.horizontal");
  validate(g.vertical, "ground.vertical");
}

void validate(const GroundComponent& k, const std::string& n) {
  const double amax = kMaxGroundAcceleration;
  const std::string acc = "finite, |value| <= " + std::to_string(int(amax)) + " g";
  require(std::isfinite(k.constant) && std::fabs(k.constant) <= amax, n + ".constant", acc, k.constant);
  require(std::isfinite(k.amplitude) && std::fabs(k.amplitude) <= amax, n + ".amplitude", acc, k.amplitude);
  require(std::isfinite(k.frequency) && k.frequency >= 0.0 && k.frequency <= kMaxGroundFrequency, n + ".frequency",
          "in [0, 1e4] (Hz, or cycles per time unit)", k.frequency);
  require(std::isfinite(k.phase) && std::fabs(k.phase) <= 1e6, n + ".phase", "finite (rad)", k.phase);
  require(std::isfinite(k.t_start) && k.t_start >= 0.0, n + ".t_start", "finite and >= 0", k.t_start);
  require(std::isfinite(k.duration) && k.duration >= 0.0, n + ".duration", "finite and >= 0", k.duration);
  require(std::isfinite(k.scale) && std::fabs(k.scale) <= amax, n + ".scale", "finite, |scale| <= 1000", k.scale);
  if (k.has_pulse()) {
    require(k.duration > 0.0, n + ".duration", "> 0 for a pulse (the pulse duration)", k.duration);
    require(k.frequency == 0.0, n + ".frequency", "0 with a pulse (a pulse is set by its duration)", k.frequency);
    require(k.phase == 0.0, n + ".phase", "0 with a pulse", k.phase);
  }
  if (!k.has_pulse() && k.amplitude != 0.0)
    require(k.frequency > 0.0, n + ".frequency", "> 0 for a harmonic amplitude (or give a pulse)", k.frequency);
}

GroundMotion in_time_unit(const GroundMotion& g, double tu) {
  GroundMotion out = g;
  for (GroundComponent* c : {&out.horizontal, &out.vertical}) {
    c->t_start /= tu;
    c->duration /= tu;
    c->frequency *= tu;
    c->record_time_unit *= tu;
  }
  return out;
}

namespace {

std::string describe_component(const GroundComponent& c, const char* hz, const char* sec) {
  std::string parts;
  auto add = [&](const std::string& p) { parts += (parts.empty() ? "" : " + ") + p; };
  if (c.constant != 0.0) add(number_text(c.constant, 3) + " g constant");
  if (c.amplitude != 0.0) {
    if (c.has_pulse())
      add(number_text(c.amplitude, 3) + " g " + to_string(c.pulse) + " pulse of " + number_text(c.duration, 3) + " " +
          sec);
    else
      add(number_text(c.amplitude, 3) + " g harmonic at " + number_text(c.frequency, 3) + " " + hz);
  }
  if (c.record) {
    const std::string& src = c.record->source();
    const std::size_t slash = src.find_last_of('/');
    std::string r = "record " + (slash == std::string::npos ? src : src.substr(slash + 1));
    if (c.scale != 1.0) r += " x " + number_text(c.scale, 3);
    add(r + " (pga " + number_text(std::fabs(c.scale) * c.record->peak(), 3) + " g)");
  }
  return parts;
}

}  // namespace

std::string describe(const GroundMotion& g, const char* frequency_unit, const char* time_unit) {
  const std::string h = describe_component(g.horizontal, frequency_unit, time_unit);
  const std::string v = describe_component(g.vertical, frequency_unit, time_unit);
  if (h.empty() && v.empty()) return "free motion";
  if (v.empty()) return h;
  if (h.empty()) return "vertical " + v;
  return h + ", vertical " + v;
}

}  // namespace blockdyn
