// SPDX-License-Identifier: Apache-2.0
#pragma once
// Idealised acceleration pulses of unit amplitude, as functions of the time since the pulse
// began, s in [0, t_p] (zero outside). t_p is the pulse's "duration" parameter:
//   rect        1                                  on [0, t_p]
//   half-sine   sin(pi s / t_p)                    on [0, t_p]  (one-signed)
//   half-cosine cos(pi s / t_p)                    on [0, t_p]  (seed 002: cos(Omega t), Omega t in [0, pi])
//   one-sine    sin(2 pi s / t_p)                  on [0, t_p]  (Makris's type-A cycloidal pulse)
//   cycloidal   cos(2 pi s / t_p)                  on [0, t_p]  (Makris's type-B cycloidal pulse:
//               the ground velocity is a full sine cycle, the displacement one-sided)
//   ricker      (1 - 2 u^2) exp(-u^2), u = pi (s - 1.5 t_p) / t_p, on [0, 3 t_p]
//               (peak frequency 1/t_p, centred at 1.5 t_p; |value| < 1.1e-8 at the ends)
#include <optional>
#include <string>

namespace blockdyn {

enum class PulseShape { None, Rect, HalfSine, HalfCosine, OneSine, Ricker, Cycloidal };

const char* to_string(PulseShape p);
std::optional<PulseShape> pulse_from_string(const std::string& name);
// "rect, half-sine, ..." for error messages.
const char* pulse_names();

// Length of the pulse's support in units of t_p (3 for the Ricker wavelet, else 1).
double pulse_support(PulseShape p);
// Unit pulse value at time s since the start.
double pulse_value(PulseShape p, double s, double t_p);
// Its time derivative (zero outside the support; the right derivative at its ends).
double pulse_rate(PulseShape p, double s, double t_p);
// A bound on |d^2 pulse / ds^2| over the support (max over the shape, times 1/t_p^2).
double pulse_curvature_bound(PulseShape p, double t_p);

}  // namespace blockdyn
