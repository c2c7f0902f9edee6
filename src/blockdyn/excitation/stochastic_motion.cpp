// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/excitation/stochastic_motion.hpp"

#include "blockdyn/base/angles.hpp"

#include <boost/math/special_functions/gamma.hpp>

#include <cmath>
#include <complex>
#include <random>
#include <stdexcept>
#include <string>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/base/range_check.hpp"

namespace blockdyn {

namespace {

// (t95 - t5) / t45 of the gamma distribution of shape k: decreasing in k.
double spread_ratio(double k) {
  using boost::math::gamma_p_inv;
  return (gamma_p_inv(k, 0.95) - gamma_p_inv(k, 0.05)) / gamma_p_inv(k, 0.45);
}

// Standard normal deviates from a stream fixed by the standard (mt19937_64, seed_seq) and
// Box-Muller, so that a record depends on its seed and index only.
class NormalStream {
 public:
  NormalStream(std::uint64_t seed, std::uint64_t index)
      : rng_([&] {
          std::seed_seq s{std::uint32_t(seed), std::uint32_t(seed >> 32), std::uint32_t(index),
                          std::uint32_t(index >> 32), std::uint32_t(0x5eed)};
          return std::mt19937_64(s);
        }()) {}
  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = (double(rng_() >> 11) + 1.0) * 0x1.0p-53, u2 = double(rng_() >> 11) * 0x1.0p-53;
    const double r = std::sqrt(-2.0 * std::log(u1));
    spare_ = r * std::sin(2.0 * kPi * u2);
    has_spare_ = true;
    return r * std::cos(2.0 * kPi * u2);
  }

 private:
  std::mt19937_64 rng_;
  double spare_ = 0;
  bool has_spare_ = false;
};

// The critically damped high-pass u'' + 2 w u' + w^2 u = x over piecewise-linear x, in closed
// form per sample interval; returns u'' at the samples (the corrected acceleration).
std::vector<double> high_pass(const std::vector<double>& x, double dt, double w) {
  std::vector<double> out(x.size());
  double u = 0, v = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    out[i] = x[i] - 2.0 * w * v - w * w * u;
    if (i + 1 == x.size()) break;
    const double s = (x[i + 1] - x[i]) / dt;
    const double B = s / (w * w), A = x[i] / (w * w) - 2.0 * s / (w * w * w);
    const double C = u - A, D = v - B + w * C, e = std::exp(-w * dt);
    u = A + B * dt + (C + D * dt) * e;
    v = B + (D - w * (C + D * dt)) * e;
  }
  return out;
}

// The kernel's terms are dropped where its envelope has decayed below e^-40 (4e-18 of its size).
constexpr double kDecayCut = 40.0;

double min_filter_frequency(const RezaeianParams& p) {
  return std::fmin(p.f_mid + p.f_slope * (0.0 - p.t_mid), p.f_mid + p.f_slope * (p.t_end - p.t_mid));
}

// x_j = sum_i u_i h(t_j - t_i; w_i) with the filter's impulse response h(tau; w) = w / sq e^(-zeta w
// tau) sin(w sq tau) for the frequency w_i at the pulse's time, and var_j = sum_i h^2: each pulse's
// terms run as the powers of z_i = e^((-zeta + i sq) w_i dt) (no transcendental per term), over the
// filter's memory only. A constant frequency makes it one recursion S_j = z S_(j-1) + u_j.
void filtered_noise(const RezaeianParams& p, const std::vector<double>& u, const std::vector<double>& wf,
                    std::vector<double>& sum, std::vector<double>& var) {
  const std::size_t n = u.size();
  const double sq = std::sqrt(1.0 - p.zeta_f * p.zeta_f);
  sum.assign(n, 0.0);
  var.assign(n, 0.0);
  if (p.f_slope == 0.0) {
    const double w = wf[0], amp = w / sq;
    const std::complex<double> z = std::exp(std::complex<double>(-p.zeta_f * w * p.dt, w * sq * p.dt));
    std::complex<double> s = 0.0, zk = 1.0;
    double v = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      s = z * s + u[j];
      const double h = amp * zk.imag();  // h(j dt), for the cumulative variance
      v += h * h;
      zk *= z;
      sum[j] = amp * s.imag();
      var[j] = v;
    }
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double w = wf[i], amp = w / sq;
    const std::complex<double> z = std::exp(std::complex<double>(-p.zeta_f * w * p.dt, w * sq * p.dt));
    const std::size_t memory = std::size_t(std::fmin(double(n), std::ceil(kDecayCut / (p.zeta_f * w * p.dt))));
    const std::size_t last = std::min(n - 1, i + memory);
    std::complex<double> zk = 1.0;
    for (std::size_t j = i; j <= last; ++j) {
      const double h = amp * zk.imag();
      sum[j] += h * u[i];
      var[j] += h * h;
      zk *= z;
    }
  }
}

// Final velocity and displacement (units of a times s, s^2) of the piecewise-linear samples.
void end_state(const std::vector<double>& a, double dt, double& v, double& d) {
  v = d = 0;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    d += v * dt + dt * dt * (2.0 * a[i] + a[i + 1]) / 6.0;
    v += 0.5 * dt * (a[i] + a[i + 1]);
  }
}

}  // namespace

double Modulation::c1() const { return std::exp(log_c1); }

double Modulation::at(double t) const { return t > 0.0 ? std::exp(log_c1 + (c2 - 1.0) * std::log(t) - c3 * t) : 0.0; }

double Modulation::husid_time(double fraction) const {
  return boost::math::gamma_p_inv(2.0 * c2 - 1.0, fraction) / (2.0 * c3);
}

double Modulation::husid_fraction(double t) const {
  return t > 0.0 ? boost::math::gamma_p(2.0 * c2 - 1.0, 2.0 * c3 * t) : 0.0;
}

Modulation fit_modulation(double arias, double d5_95, double t_mid, double g) {
  require_in_range("arias", arias, 0, 1e3, false);
  require_in_range("d5-95", d5_95, 0, 1e4, false);
  require_in_range("t-mid", t_mid, 0, 1e4, false);
  // The shape k = 2 c2 - 1 must exceed 1 (q(0) = 0): the spread ratio of k = 1 bounds D5-95 / t_mid.
  const double r = d5_95 / t_mid, r_max = spread_ratio(1.0 + 1e-9);
  if (!(r < r_max))
    throw std::invalid_argument("d5-95 = " + number_text(d5_95) + " s is too long for t-mid = " + number_text(t_mid) +
                                " s: a gamma-type modulation needs d5-95 / t-mid < " + number_text(r_max, 4));
  double lo = std::log(1.0 + 1e-9), hi = std::log(1e6);
  if (!(spread_ratio(std::exp(hi)) < r))
    throw std::invalid_argument("d5-95: too short for t-mid (d5-95 / t-mid below 4e-3)");
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
    const double mid = 0.5 * (lo + hi);
    (spread_ratio(std::exp(mid)) > r ? lo : hi) = mid;
  }
  const double k = std::exp(0.5 * (lo + hi)), lambda = boost::math::gamma_p_inv(k, 0.45) / t_mid;
  Modulation q;
  q.c2 = 0.5 * (k + 1.0);
  q.c3 = 0.5 * lambda;
  // Expected Arias intensity pi g / 2 int q^2 dt with int q^2 = c1^2 Gamma(k) / lambda^k.
  q.log_c1 = 0.5 * (std::log(2.0 * arias / (kPi * g)) + k * std::log(lambda) - std::lgamma(k));
  return q;
}

void validate(const RezaeianParams& p) {
  require_in_range("dt", p.dt, 1e-4, 1.0);
  require_in_range("t-end", p.t_end, 10 * p.dt, 1e4);
  if (p.t_end / p.dt > 2e6) throw std::invalid_argument("t-end / dt: at most 2e6 samples per record");
  require_in_range("f-mid", p.f_mid, 0, 0.25 / p.dt, false);
  require_in_range("f-slope", p.f_slope, -1e3, 1e3);
  require_in_range("zeta-f", p.zeta_f, 0, 1, false, false);
  require_in_range("f-highpass", p.f_highpass, 0, 10);
  require_in_range("g", p.g, 0, 1e3, false);
  for (const double t : {0.0, p.t_end})
    if (!(p.f_mid + p.f_slope * (t - p.t_mid) > 0.0))
      throw std::invalid_argument("f-slope = " + number_text(p.f_slope) +
                                  " Hz/s makes the filter frequency f-mid + f-slope (t - " +
                                  "t-mid) reach 0 within [0, t-end]: give a smaller |f-slope|");
  if (!(p.t_mid < p.t_end))
    throw std::invalid_argument("t-mid = " + number_text(p.t_mid) +
                                " s lies outside the record [0, t-end = " + number_text(p.t_end) + " s]");
  if (!(p.d5_95 >= 20.0 * p.dt))
    throw std::invalid_argument("d5-95 = " + number_text(p.d5_95) + " s spans fewer than 20 samples of dt = " +
                                number_text(p.dt) + " s: give a longer `d5-95` or a smaller `dt`");
  const Modulation q = fit_modulation(p.arias, p.d5_95, p.t_mid, p.g);
  // The record cut at t_end keeps the fraction F of the modulation's energy: its expected D5-95
  // runs between the quantiles 0.05 F and 0.95 F.
  const double kept = q.husid_fraction(p.t_end);
  const double d_cut = q.husid_time(0.95 * kept) - q.husid_time(0.05 * kept);
  if (!(kept >= 0.98) || !(std::fabs(d_cut - p.d5_95) <= 0.05 * p.d5_95))
    throw std::invalid_argument(
        "t-end = " + number_text(p.t_end) + " s cuts the modulation of d5-95 = " + number_text(p.d5_95) +
        " s, t-mid = " + number_text(p.t_mid) + " s: the record would hold " + number_text(100.0 * kept, 4) +
        " % of the Arias target and a D5-95 of " + number_text(d_cut, 4) +
        " s (at least 98 %, and within 5 %, needed); its 99.5 % point lies at " + number_text(q.husid_time(0.995), 4) +
        " s: give a longer `t-end` or move `t-mid` and `d5-95` earlier");
}

double rezaeian_record_cost(const RezaeianParams& p) {
  const double n = std::floor(p.t_end / p.dt + 1e-9) + 1.0;
  if (p.f_slope == 0.0) return n;
  return n * std::fmin(n, std::ceil(kDecayCut / (p.zeta_f * 2.0 * kPi * min_filter_frequency(p) * p.dt)) + 1.0);
}

std::vector<double> white_noise(std::uint64_t seed, std::uint64_t index, std::size_t n) {
  NormalStream normal(seed, index);
  std::vector<double> u(n);
  for (double& x : u) x = normal.next();
  return u;
}

std::vector<double> rezaeian_filtered_noise(const RezaeianParams& p, const Modulation& q, std::uint64_t seed,
                                            std::uint64_t index) {
  const std::size_t n = std::size_t(std::floor(p.t_end / p.dt + 1e-9)) + 1;
  const std::vector<double> u = white_noise(seed, index, n);
  std::vector<double> x(n, 0.0), wf(n), sum, var;
  for (std::size_t i = 0; i < n; ++i) wf[i] = 2.0 * kPi * (p.f_mid + p.f_slope * (double(i) * p.dt - p.t_mid));
  filtered_noise(p, u, wf, sum, var);
  for (std::size_t j = 0; j < n; ++j)
    if (var[j] > 0.0) x[j] = q.at(double(j) * p.dt) * sum[j] / std::sqrt(var[j]);
  return x;
}

GeneratedRecord rezaeian_record(const RezaeianParams& p, const Modulation& q, std::uint64_t seed, std::uint64_t index) {
  const std::vector<double> x = rezaeian_filtered_noise(p, q, seed, index);
  const std::size_t n = x.size();
  GeneratedRecord r;
  r.a = p.f_highpass > 0.0 ? high_pass(x, p.dt, 2.0 * kPi * p.f_highpass) : x;
  // Ends at rest exactly: a correction alpha q + beta t q (shapes of the motion itself) cancels
  // the final velocity and displacement the high-pass leaves (small: it has nearly done so). The
  // shapes are scaled to a peak of 1, so that the solve neither underflows nor overflows whatever
  // the Arias target.
  std::vector<double> w1(n), w2(n);
  const double q_peak = q.at(std::fmin(p.t_end, (q.c2 - 1.0) / q.c3));
  for (std::size_t i = 0; i < n; ++i) {
    w1[i] = q_peak > 0.0 ? q.at(double(i) * p.dt) / q_peak : 0.0;
    w2[i] = w1[i] * double(i) * p.dt / p.t_end;
  }
  double v0, d0, v1, d1, v2, d2;
  end_state(r.a, p.dt, v0, d0);
  end_state(w1, p.dt, v1, d1);
  end_state(w2, p.dt, v2, d2);
  const double det = v1 * d2 - v2 * d1;
  if (det != 0.0) {
    const double alpha = (-v0 * d2 + v2 * d0) / det, beta = (-v1 * d0 + v0 * d1) / det;
    for (std::size_t i = 0; i < n; ++i) {
      const double c = alpha * w1[i] + beta * w2[i];
      r.a[i] += c;
      r.baseline_correction = std::max(r.baseline_correction, std::fabs(c));
    }
  }
  return r;
}

void validate(const PulseParams& p, double dt, double t_end) {
  require_in_range("pulse-pgv", p.pgv, 0, 1e2, false);
  require_in_range("pulse-period", p.period, 0, 1e3, false);
  require_in_range("gamma", p.gamma, 1, 1e2, false);
  require_in_range("nu", p.nu, -2 * kPi, 2 * kPi);
  require_in_range("pulse-t0", p.t0, 0, 1e4);
  if (!(p.period >= 10.0 * dt))
    throw std::invalid_argument("pulse-period = " + number_text(p.period) +
                                " s is sampled by fewer than 10 samples of dt = " + number_text(dt) +
                                " s: give a longer `pulse-period` or a smaller `dt`");
  const double half = 0.5 * p.gamma * p.period;
  if (!(p.t0 - half >= -1e-12 * half))
    throw std::invalid_argument(
        "pulse-t0 = " + number_text(p.t0) + " s starts the pulse at " + number_text(p.t0 - half) +
        " s, before the record: give pulse-t0 >= gamma pulse-period / 2 = " + number_text(half) + " s");
  if (!(p.t0 + half <= t_end * (1.0 + 1e-12)))
    throw std::invalid_argument("t-end = " + number_text(t_end) + " s: shorter than the pulse (it ends at " +
                                number_text(p.t0 + half) + " s)");
}

double pulse_acceleration(const PulseParams& p, double t, double g) {
  const double tau = t - p.t0;
  if (std::fabs(tau) > 0.5 * p.gamma * p.period) return 0.0;
  const double we = 2.0 * kPi / (p.gamma * p.period), wp = 2.0 * kPi / p.period;
  const double dv = -0.5 * p.pgv *
                    (we * std::sin(we * tau) * std::cos(wp * tau + p.nu) +
                     (1.0 + std::cos(we * tau)) * wp * std::sin(wp * tau + p.nu));
  return dv / g;
}

}  // namespace blockdyn
