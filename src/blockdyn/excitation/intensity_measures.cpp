// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/excitation/intensity_measures.hpp"

#include "blockdyn/base/angles.hpp"

#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

namespace blockdyn {
namespace {

// The record's energy int a^2 dt over [0, tau] of a segment a = a0 + s tau (units of g^2 s).
double energy_in(double a0, double s, double tau) { return tau * (a0 * a0 + a0 * s * tau + s * s * tau * tau / 3.0); }

// The largest |q| of q(tau) = q0 + q1 tau + q2 tau^2 over [0, h] (a parabola: ends and vertex).
double parabola_peak(double q0, double q1, double q2, double h) {
  double m = std::max(std::fabs(q0), std::fabs(q0 + q1 * h + q2 * h * h));
  if (q2 != 0.0) {
    const double tau = -q1 / (2.0 * q2);
    if (tau > 0.0 && tau < h) m = std::max(m, std::fabs(q0 + q1 * tau + q2 * tau * tau));
  }
  return m;
}

// The roots in (0, h) of c0 + c1 tau + c2 tau^2 (cancellation-free formula).
int quadratic_roots(double c0, double c1, double c2, double h, double out[2]) {
  int n = 0;
  auto keep = [&](double r) {
    if (r > 0.0 && r < h) out[n++] = r;
  };
  if (c2 == 0.0) {
    if (c1 != 0.0) keep(-c0 / c1);
    return n;
  }
  const double disc = c1 * c1 - 4.0 * c2 * c0;
  if (disc < 0.0) return 0;
  const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
  if (q != 0.0) {
    keep(q / c2);
    keep(c0 / q);
  } else {
    keep(0.0);
  }
  return n;
}

// In-place radix-2 FFT (size a power of two).
void fft(std::vector<std::complex<double>>& x) {
  const std::size_t n = x.size();
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(x[i], x[j]);
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const double ang = -2.0 * kPi / double(len);
    for (std::size_t i = 0; i < n; i += len)
      for (std::size_t k = 0; k < len / 2; ++k) {
        const std::complex<double> w = std::polar(1.0, ang * double(k));
        const std::complex<double> u = x[i + k], v = x[i + k + len / 2] * w;
        x[i + k] = u + v;
        x[i + k + len / 2] = u - v;
      }
  }
}

// Rathje, Abrahamson & Bray (1998): the Fourier amplitudes' mean period over 0.25-20 Hz. The
// record is sampled on a uniform grid at its smallest spacing (exact for a uniform record: its
// own samples) and padded with zeros to a power of two.
double mean_period(const Accelerogram& rec) {
  double dt = rec.dt();
  if (!rec.uniform()) {
    dt = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < rec.size(); ++i) dt = std::min(dt, rec.time(i + 1) - rec.time(i));
  }
  const double span = rec.t_last() - rec.t_first();
  const std::size_t samples = std::size_t(std::floor(span / dt + 1e-9)) + 1;
  if (samples > (std::size_t(1) << 26)) return std::nan("");  // a resampled record too long to transform
  std::size_t n = 1;
  while (n < samples) n <<= 1;
  std::vector<std::complex<double>> x(n);
  for (std::size_t i = 0; i < samples; ++i)
    x[i] = rec.uniform() ? rec.values()[i] : rec.at(rec.t_first() + dt * double(i));
  fft(x);
  double num = 0, den = 0;
  for (std::size_t k = 1; k <= n / 2; ++k) {
    const double f = double(k) / (double(n) * dt);
    if (f < 0.25 || f > 20.0) continue;
    const double c2 = std::norm(x[k]);
    num += c2 / f;
    den += c2;
  }
  return den > 0 ? num / den : std::nan("");
}

}  // namespace

double husid_time(const Accelerogram& rec, double fraction) {
  if (!(fraction >= 0.0 && fraction <= 1.0)) throw std::invalid_argument("fraction must be in [0, 1]");
  double total = 0;
  for (std::size_t i = 0; i + 1 < rec.size(); ++i) {
    const double h = rec.time(i + 1) - rec.time(i), a0 = rec.values()[i];
    total += energy_in(a0, (rec.values()[i + 1] - a0) / h, h);
  }
  if (!(total > 0.0)) return std::nan("");
  const double level = fraction * total;
  double e = 0;
  for (std::size_t i = 0; i + 1 < rec.size(); ++i) {
    const double h = rec.time(i + 1) - rec.time(i), a0 = rec.values()[i], s = (rec.values()[i + 1] - a0) / h;
    const double seg = energy_in(a0, s, h);
    if (e + seg < level && i + 2 < rec.size()) {
      e += seg;
      continue;
    }
    // The cumulative energy is nondecreasing in the segment (its rate is a^2): bisect on the
    // cubic to the last bit of tau.
    double lo = 0.0, hi = h;
    while (true) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (e + energy_in(a0, s, mid) < level ? lo : hi) = mid;
    }
    return rec.time(i) + hi;
  }
  return rec.t_last();
}

IntensityMeasures intensity_measures(const Accelerogram& rec, double g) {
  if (!(std::isfinite(g) && g > 0.0)) throw std::invalid_argument("g must be finite and > 0");
  IntensityMeasures m;
  m.pga = rec.peak();
  m.duration = rec.t_last() - rec.t_first();
  double v = 0, d = 0, energy = 0;
  for (std::size_t i = 0; i + 1 < rec.size(); ++i) {
    const double h = rec.time(i + 1) - rec.time(i);
    const double a0 = g * rec.values()[i], s = g * (rec.values()[i + 1] - rec.values()[i]) / h;
    m.pgv = std::max(m.pgv, parabola_peak(v, a0, 0.5 * s, h));
    // |d| peaks at the segment's ends or where v = 0 inside it.
    auto d_at = [&](double tau) { return d + tau * (v + tau * (0.5 * a0 + tau * s / 6.0)); };
    m.pgd = std::max(m.pgd, std::fabs(d_at(h)));
    double roots[2];
    for (int k = 0, n = quadratic_roots(v, a0, 0.5 * s, h, roots); k < n; ++k)
      m.pgd = std::max(m.pgd, std::fabs(d_at(roots[k])));
    energy += energy_in(rec.values()[i], (rec.values()[i + 1] - rec.values()[i]) / h, h);
    d = d_at(h);
    v += h * (a0 + 0.5 * s * h);
  }
  m.final_velocity = v;
  m.final_displacement = d;
  m.arias = kPi * g / 2.0 * energy;  // pi / (2 g) int (g a)^2 dt
  m.t5 = husid_time(rec, 0.05);
  m.t95 = husid_time(rec, 0.95);
  m.d5_95 = m.t95 - m.t5;
  m.t_mid = husid_time(rec, 0.45);
  m.mean_period = mean_period(rec);
  return m;
}

}  // namespace blockdyn
