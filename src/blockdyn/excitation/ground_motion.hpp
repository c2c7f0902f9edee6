// SPDX-License-Identifier: Apache-2.0
#pragma once
// Horizontal and vertical ground acceleration, in units of g, for every model family. In the
// frame moving with the ground they act on a body as inertial forces -m a_H, -m a_V.
//
// A component is the sum of
//   constant                          (g)
//   harmonic  amplitude sin(2 pi frequency (t - t_start) + phase)
//   or pulse  amplitude * unit pulse (excitation/pulses.hpp) of duration t_p = duration
//   record    scale * accelerogram(t - t_start)   (excitation/accelerogram.hpp)
// acting on the window [t_start, t_start + duration) (duration 0: no end; a pulse's window is
// its support) and zero outside. Times and frequencies are in the model's time unit (seconds
// and Hz for physical models); records are sampled in seconds and converted with
// record_time_unit. The kinks and jumps of the input (window ends, pulse ends, record samples)
// are breakpoints: next_break() lets the integrator stop there instead of stepping across.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "blockdyn/excitation/accelerogram.hpp"
#include "blockdyn/excitation/pulses.hpp"

namespace blockdyn {

struct GroundComponent {
  double constant = 0.0;
  double amplitude = 0.0;  // harmonic or pulse amplitude (g)
  double frequency = 0.0;  // harmonic frequency (cycles per time unit: Hz for physical models)
  double phase = 0.0;      // harmonic phase (rad)
  double t_start = 0.0;
  double duration = 0.0;  // window length (0: forever); for a pulse its duration t_p (> 0)
  PulseShape pulse = PulseShape::None;
  std::shared_ptr<const Accelerogram> record;
  double scale = 1.0;             // factor on the record
  double record_time_unit = 1.0;  // seconds per model time unit

  bool is_zero() const { return constant == 0.0 && amplitude == 0.0 && !record; }
  bool has_pulse() const { return pulse != PulseShape::None; }
  // End of the window (infinity when the component never ends).
  double t_stop() const {
    if (has_pulse()) return t_start + pulse_support(pulse) * duration;
    return duration > 0.0 ? t_start + duration : std::numeric_limits<double>::infinity();
  }

  double at(double t) const {
    if (t < t_start || t >= t_stop()) return 0.0;
    double a = constant;
    const double s = t - t_start;
    if (amplitude != 0.0) {
      if (has_pulse())
        a += amplitude * pulse_value(pulse, s, duration);
      else
        a += amplitude * std::sin(2.0 * M_PI * frequency * s + phase);
    }
    if (record) a += scale * record->at(s * record_time_unit);
    return a;
  }

  // Time derivative of at() (the right derivative at a breakpoint).
  double rate(double t) const;
  // A bound on |d^2 at / dt^2| between breakpoints (records are linear there).
  double curvature_bound() const;

  // The first breakpoint strictly after t (infinity if none).
  double next_break(double t) const;
  // Linear between consecutive breakpoints (constant and record terms only): then any function
  // a - |b| of the input with a, b linear in it is concave between breakpoints, and its minimum
  // over such an interval lies at an end.
  bool piecewise_linear() const { return amplitude == 0.0; }
  // Its shortest smooth time scale (a harmonic's period, a pulse's duration; infinity if none).
  double time_scale() const {
    if (amplitude == 0.0) return std::numeric_limits<double>::infinity();
    return has_pulse() ? duration : 1.0 / frequency;
  }
};

struct GroundMotion {
  GroundComponent horizontal, vertical;
  bool is_zero() const { return horizontal.is_zero() && vertical.is_zero(); }
  double next_break(double t) const { return std::fmin(horizontal.next_break(t), vertical.next_break(t)); }
  bool piecewise_linear() const { return horizontal.piecewise_linear() && vertical.piecewise_linear(); }
  double ah(double t) const { return horizontal.at(t); }
  double av(double t) const { return vertical.at(t); }
};

// A short description for figure titles: "record X.AT2 x 1.8 (pga 0.361 g)", "0.35 g one-sine
// pulse of 1 s", "0.3 g harmonic at 2 Hz", "free motion" (frequency unit as given, "Hz" or "/t").
std::string describe(const GroundMotion& g, const char* frequency_unit = "Hz", const char* time_unit = "s");

// Checks every field (names them as ground.horizontal.<field> or ground.vertical.<field>).
void validate(const GroundMotion& g);
// One component's fields, named <name>.<field>.
void validate(const GroundComponent& c, const std::string& name);

// The same motion with times given in seconds re-expressed in a model time unit of
// `seconds_per_unit` seconds (t_start, duration divided, frequency multiplied by it).
GroundMotion in_time_unit(const GroundMotion& g, double seconds_per_unit);

// Largest |a| the inputs allow (g) and the largest harmonic frequency (cycles per time unit).
inline constexpr double kMaxGroundAcceleration = 1e3;
inline constexpr double kMaxGroundFrequency = 1e4;

}  // namespace blockdyn
