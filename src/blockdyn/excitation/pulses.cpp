// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/excitation/pulses.hpp"

#include <cmath>

namespace blockdyn {

const char* to_string(PulseShape p) {
  switch (p) {
    case PulseShape::None: return "none";
    case PulseShape::Rect: return "rect";
    case PulseShape::HalfSine: return "half-sine";
    case PulseShape::HalfCosine: return "half-cosine";
    case PulseShape::OneSine: return "one-sine";
    case PulseShape::Ricker: return "ricker";
    case PulseShape::Cycloidal: return "cycloidal";
  }
  return "?";
}

const char* pulse_names() { return "rect, half-sine, half-cosine, one-sine, ricker, cycloidal"; }

std::optional<PulseShape> pulse_from_string(const std::string& n) {
  for (PulseShape p : {PulseShape::None, PulseShape::Rect, PulseShape::HalfSine, PulseShape::HalfCosine,
                       PulseShape::OneSine, PulseShape::Ricker, PulseShape::Cycloidal})
    if (n == to_string(p)) return p;
  return std::nullopt;
}

double pulse_support(PulseShape p) { return p == PulseShape::Ricker ? 3.0 : 1.0; }

double pulse_value(PulseShape p, double s, double t_p) {
  if (!(s >= 0.0) || s > pulse_support(p) * t_p) return 0.0;
  const double x = s / t_p;
  switch (p) {
    case PulseShape::None: return 0.0;
    case PulseShape::Rect: return 1.0;
    case PulseShape::HalfSine: return std::sin(M_PI * x);
    case PulseShape::HalfCosine: return std::cos(M_PI * x);
    case PulseShape::OneSine: return std::sin(2.0 * M_PI * x);
    case PulseShape::Cycloidal: return std::cos(2.0 * M_PI * x);
    case PulseShape::Ricker: {
      const double u = M_PI * (x - 1.5);
      const double u2 = u * u;
      return (1.0 - 2.0 * u2) * std::exp(-u2);
    }
  }
  return 0.0;
}

}  // namespace blockdyn
