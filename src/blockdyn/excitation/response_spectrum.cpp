// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/excitation/response_spectrum.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "blockdyn/base/range_check.hpp"

namespace blockdyn {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The oscillator's response over one segment of the input a = a0 + s tau (m/s^2), from (u0, v0):
// a particular solution linear in tau plus the damped free vibration.
class Segment {
 public:
  Segment(double w, double zeta, double wd, double u0, double v0, double a0, double s)
      : zw_(zeta * w), wd_(wd), p0_(-a0 / (w * w) + 2.0 * zeta * s / (w * w * w)), p1_(-s / (w * w)) {
    c_ = u0 - p0_;
    d_ = (v0 - p1_ + zw_ * c_) / wd_;
  }
  double u(double tau) const {
    const double e = std::exp(-zw_ * tau);
    return p0_ + p1_ * tau + e * (c_ * std::cos(wd_ * tau) + d_ * std::sin(wd_ * tau));
  }
  double v(double tau) const {
    const double e = std::exp(-zw_ * tau);
    return p1_ + e * ((wd_ * d_ - zw_ * c_) * std::cos(wd_ * tau) - (zw_ * d_ + wd_ * c_) * std::sin(wd_ * tau));
  }

 private:
  double zw_, wd_, p0_, p1_, c_ = 0, d_ = 0;
};

struct Peak {
  double sd = 0, t = 0;
  void consider(double u, double t_of) {
    if (std::fabs(u) > sd) {
      sd = std::fabs(u);
      t = t_of;
    }
  }
};

// |u| over [0, h] of a segment: its end and every zero of v inside, bracketed on a grid finer
// than a sixteenth of the damped period and bisected to the last bit.
void scan(const Segment& seg, double h, double td, double t0, Peak& peak) {
  const int n = std::max(1, int(std::ceil(16.0 * h / td)));
  double ta = 0.0, va = seg.v(0.0);
  for (int k = 1; k <= n; ++k) {
    const double tb = k == n ? h : h * double(k) / double(n), vb = seg.v(tb);
    if ((va < 0.0 && vb > 0.0) || (va > 0.0 && vb < 0.0)) {
      double lo = ta, hi = tb;
      const bool rising = va < 0.0;
      while (true) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        ((seg.v(mid) < 0.0) == rising ? lo : hi) = mid;
      }
      peak.consider(seg.u(lo), t0 + lo);
    }
    ta = tb;
    va = vb;
  }
  peak.consider(seg.u(h), t0 + h);
}

}  // namespace

SpectralOrdinate spectral_ordinate(const Accelerogram& rec, double period, double damping, double g) {
  require_in_range("period", period, 0.0, 1e4, false);
  require_in_range("damping", damping, 0.0, 1.0, true, false);
  require_in_range("g", g, 0.0, 1e3, false);
  const double w = 2.0 * kPi / period, wd = w * std::sqrt(1.0 - damping * damping), td = 2.0 * kPi / wd;
  Peak peak;
  double u = 0.0, v = 0.0;
  for (std::size_t i = 0; i + 1 < rec.size(); ++i) {
    const double t0 = rec.time(i), h = rec.time(i + 1) - t0;
    const double a0 = g * rec.values()[i], s = g * (rec.values()[i + 1] - rec.values()[i]) / h;
    const Segment seg(w, damping, wd, u, v, a0, s);
    scan(seg, h, td, t0, peak);
    u = seg.u(h);
    v = seg.v(h);
  }
  // The free vibration after the record (a = 0 there): its largest |u| comes within half a
  // damped period, at the first zero of v.
  scan(Segment(w, damping, wd, u, v, 0.0, 0.0), td, td, rec.t_last(), peak);
  return {period, w * w * peak.sd / g, peak.sd, peak.t};
}

std::vector<SpectralOrdinate> response_spectrum(const Accelerogram& rec, const std::vector<double>& periods,
                                                double damping, double g) {
  std::vector<SpectralOrdinate> out;
  out.reserve(periods.size());
  for (double T : periods) out.push_back(spectral_ordinate(rec, T, damping, g));
  return out;
}

}  // namespace blockdyn
