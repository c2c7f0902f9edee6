#pragma once
// Horizontal and vertical ground acceleration in units of g. In the frame moving with the
// ground they act on the block as pseudo-forces: x'' = Rx - a_h(t), y'' = Ry - 1 - a_v(t).
#include <cmath>

namespace blockdyn {

// One component: a_const + amplitude * sin(2 pi frequency (t - t_start) + phase) on
// [t_start, t_start + duration) (duration <= 0: forever), zero outside.
struct GroundComponent {
  double constant = 0.0;
  double amplitude = 0.0;
  double frequency = 0.0;  // cycles per unit non-dimensional time
  double phase = 0.0;      // radians
  double t_start = 0.0;
  double duration = 0.0;

  bool is_zero() const { return constant == 0.0 && amplitude == 0.0; }
  double at(double t) const {
    if (t < t_start || (duration > 0.0 && t >= t_start + duration)) return 0.0;
    double a = constant;
    if (amplitude != 0.0)
      a += amplitude * std::sin(2.0 * M_PI * frequency * (t - t_start) + phase);
    return a;
  }
};

struct GroundMotion {
  GroundComponent horizontal, vertical;
  bool is_zero() const { return horizontal.is_zero() && vertical.is_zero(); }
};

void validate(const GroundMotion& g);

}  // namespace blockdyn
