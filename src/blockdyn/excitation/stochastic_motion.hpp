// SPDX-License-Identifier: Apache-2.0
#pragma once
// Synthetic ground motions for suites of runs: the site-based stochastic model of Rezaeian & Der
// Kiureghian (2008) - white noise through a filter whose frequency and damping vary in time,
// modulated by a gamma-type function fitted to the targets (Arias intensity, D5-95, t_mid), then
// high-pass filtered by a critically damped oscillator and corrected so that the record ends at
// rest - and the near-fault velocity pulse of Mavroeidis & Papageorgiou (2003). Samples in g on
// t_i = i dt. A record is a pure function of its parameters, the seed and its index.
#include <cstddef>
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
// Husid curve is the gamma distribution of shape 2 c2 - 1 and rate 2 c3. Evaluated in logarithms
// (log_c1): c1 alone underflows, and t^(c2 - 1) overflows, for short, late bursts (a D5-95 of
// 1 s at t_mid = 25 s).
struct Modulation {
  double log_c1 = 0, c2 = 0, c3 = 0;
  double c1() const;  // may be inf or 0 where log_c1 is not
  double at(double t) const;
  // The time at which the expected Husid curve reaches `fraction` of the total (s).
  double husid_time(double fraction) const;
  // The expected fraction of the Arias intensity before t.
  double husid_fraction(double t) const;
};
// std::invalid_argument naming the target when no gamma-type function reaches it.
Modulation fit_modulation(double arias, double d5_95, double t_mid, double g);

// Checks every field (std::invalid_argument naming it: "arias", "d5-95", "f-slope", ...), and that
// the targets fit the record: t_mid inside it, the modulation's energy within it (at least 98 % of
// the Arias target before t_end, and the D5-95 of the record as cut within 5 % of the target),
// D5-95 over at least 20 samples.
void validate(const RezaeianParams& p);

// The cost of one record in kernel terms (samples times the filter's memory in samples; the
// memory is one term when the filter's frequency is constant, which runs as a recursion).
double rezaeian_record_cost(const RezaeianParams& p);

struct GeneratedRecord {
  std::vector<double> a;           // g, at t_i = i dt
  double baseline_correction = 0;  // the largest |correction| applied so that v and d end at 0 (g)
};
// The standard normal deviates u_0 ... u_(n-1) of record `index` of the suite of `seed`.
std::vector<double> white_noise(std::uint64_t seed, std::uint64_t index, std::size_t n);
// Its first stage: the modulated, normalised filtered white noise q(t) x(t) / sd[x(t)] at the
// samples (g), before the high-pass and the end-at-rest correction.
std::vector<double> rezaeian_filtered_noise(const RezaeianParams& p, const Modulation& q, std::uint64_t seed,
                                            std::uint64_t index);
// Record `index` of the suite of `seed` (independent streams per record).
GeneratedRecord rezaeian_record(const RezaeianParams& p, const Modulation& q, std::uint64_t seed, std::uint64_t index);

struct PulseParams {
  double pgv = 0;     // amplitude A of the velocity pulse (m/s)
  double period = 0;  // T_p (s)
  double gamma = 2;   // oscillatory character (> 1)
  double nu = 0;      // phase (rad)
  double t0 = 0;      // time of the envelope's peak (s)
};
// Checks every field, and that the pulse lies within [0, t_end] and is sampled by dt (at least
// 10 samples per period T_p).
void validate(const PulseParams& p, double dt, double t_end);
// The pulse's ground acceleration (g) at t: the derivative of
// v(t) = A/2 [1 + cos(2 pi (t - t0) / (gamma T_p))] cos(2 pi (t - t0) / T_p + nu) on its support.
double pulse_acceleration(const PulseParams& p, double t, double g);

}  // namespace blockdyn
