// SPDX-License-Identifier: Apache-2.0
#pragma once
// Synthetic ground motions for suites of runs: the site-based stochastic model of Rezaeian & Der
// Kiureghian (2008) - white noise through a filter whose frequency and damping vary in time,
// modulated by a gamma-type function fitted to the targets (Arias intensity, D5-95, t_mid), then
// high-pass filtered by a critically damped oscillator and corrected so that the record ends at
// rest - and the near-fault velocity pulse of Mavroeidis & Papageorgiou (2003). Samples in g on
// t_i = i dt. A record is a pure function of its parameters, the seed and its index.
#include <cstdint>
#include <vector>

namespace blockdyn {

struct RezaeianParams {
  double arias = 0;             // target Arias intensity (m/s)
  double d5_95 = 0;             // target significant duration (s)
  double t_mid = 0;             // time at 45 % of the Arias intensity (s)
  double f_mid = 0;             // filter frequency at t_mid (Hz)
  double f_slope = 0;           // its rate of change (Hz/s)
  double zeta_f = 0.3;          // filter damping ratio, in (0, 1)
  double f_highpass = 0.2;      // corner of the critically damped high-pass (Hz; 0: none)
  double dt = 0.01, t_end = 0;  // sampling and duration (s)
  double g = 9.81;
};

// The modulating function q(t) = c1 t^(c2 - 1) exp(-c3 t) fitted to (arias, d5_95, t_mid): its
// Husid curve is the gamma distribution of shape 2 c2 - 1 and rate 2 c3.
struct Modulation {
  double c1 = 0, c2 = 0, c3 = 0;
  double at(double t) const;
};
// std::invalid_argument naming the target when no gamma-type function reaches it.
Modulation fit_modulation(double arias, double d5_95, double t_mid, double g);

// Checks every field (std::invalid_argument naming it: "arias", "d5-95", "f-slope", ...).
void validate(const RezaeianParams& p);

struct GeneratedRecord {
  std::vector<double> a;           // g, at t_i = i dt
  double baseline_correction = 0;  // the largest |correction| applied so that v and d end at 0 (g)
};
// Record `index` of the suite of `seed` (independent streams per record).
GeneratedRecord rezaeian_record(const RezaeianParams& p, const Modulation& q, std::uint64_t seed, std::uint64_t index);

struct PulseParams {
  double pgv = 0;     // amplitude A of the velocity pulse (m/s)
  double period = 0;  // T_p (s)
  double gamma = 2;   // oscillatory character (> 1)
  double nu = 0;      // phase (rad)
  double t0 = 0;      // time of the envelope's peak (s)
};
void validate(const PulseParams& p);
// The pulse's ground acceleration (g) at t: the derivative of
// v(t) = A/2 [1 + cos(2 pi (t - t0) / (gamma T_p))] cos(2 pi (t - t0) / T_p + nu) on its support.
double pulse_acceleration(const PulseParams& p, double t, double g);

}  // namespace blockdyn
