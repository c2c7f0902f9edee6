// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/excitation/response_spectrum.hpp"

#include "blockdyn/base/angles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "blockdyn/base/range_check.hpp"

namespace blockdyn {
namespace {

// The oscillator in pseudo-acceleration units: U = w^2 u and W = U' / w stay of the size of the
// ground acceleration for every period, so that neither overflows nor underflows as T -> 0
// (w^2 would, for T = 1e-160).
struct Oscillator {
  double w, zeta, sq, wd, td;  // sq = sqrt(1 - zeta^2), wd = w sq, td = 2 pi / wd
  double inv_w, inv_sq, two_zeta_over_w;
  Oscillator(double period, double damping)
      : w(2.0 * kPi / period),
        zeta(damping),
        sq(std::sqrt(1.0 - damping * damping)),
        wd(w * sq),
        td(2.0 * kPi / (w * sq)),
        inv_w(1.0 / w),
        inv_sq(1.0 / sq),
        two_zeta_over_w(2.0 * damping / w) {}
};

// The state (U, W) at tau from (U0, W0) under a = a0 + s tau, by the Taylor series of U in tau
// (its derivatives from the equation of motion). Used where w tau < 1: there the closed form below
// subtracts terms of the size of a to leave U of the size of (w tau)^2 a (a long period).
void taylor_state(const Oscillator& o, double tau, double u0, double w0, double a0, double s, double& u, double& w) {
  if (tau == 0.0) {
    u = u0;
    w = w0;
    return;
  }
  // z_n = U^(n)(0) tau^n / n!: U = sum z_n, W = U' / w = sum n z_n / (w tau).
  const double x = o.w * tau, zx = 2.0 * o.zeta * x, xx = x * x;
  double z0 = u0, z1 = x * w0;
  const double z2 = -0.5 * (zx * z1 + xx * (z0 + a0));
  const double z3 = -(zx * z2 * 2.0 + xx * (z1 + s * tau)) / 6.0;
  double su = z0 + z1 + z2 + z3, sw = z1 + 2.0 * z2 + 3.0 * z3;
  z0 = z2;
  z1 = z3;
  for (int n = 4; n < 80; ++n) {
    const double zn = -(zx * z1 + xx * z0 / double(n - 1)) / double(n);
    su += zn;
    sw += double(n) * zn;
    z0 = z1;
    z1 = zn;
    if (std::fabs(z0) + std::fabs(z1) <= 1e-18 * (std::fabs(su) + std::fabs(sw) + 1e-300)) break;
  }
  u = su;
  w = sw / x;
}

// One segment of the input a = a0 + s tau (m/s^2): U(tau) = P0 + P1 tau + e^(-zeta w tau) (c cos
// wd tau + d sin wd tau), from (U0, W0) at tau = 0.
struct SegmentForm {
  double u0, w0, a0, s;
  double p0, p1, c, d;
  SegmentForm(const Oscillator& o, double u_0, double w_0, double a_0, double slope)
      : u0(u_0),
        w0(w_0),
        a0(a_0),
        s(slope),
        p0(-a0 + o.two_zeta_over_w * s),
        p1(-s),
        c(u0 - p0),
        d((w0 - p1 * o.inv_w + o.zeta * c) * o.inv_sq) {}
  double u(const Oscillator& o, double tau) const {
    if (o.w * tau < 1.0) {
      double uu, ww;
      taylor_state(o, tau, u0, w0, a0, s, uu, ww);
      return uu;
    }
    const double e = std::exp(-o.zeta * o.w * tau), th = o.wd * tau;
    return p0 + p1 * tau + e * (c * std::cos(th) + d * std::sin(th));
  }
  double v(const Oscillator& o, double tau) const {  // W = U' / w
    if (o.w * tau < 1.0) {
      double uu, ww;
      taylor_state(o, tau, u0, w0, a0, s, uu, ww);
      return ww;
    }
    const double e = std::exp(-o.zeta * o.w * tau), th = o.wd * tau;
    return p1 * o.inv_w + e * ((o.sq * d - o.zeta * c) * std::cos(th) - (o.zeta * d + o.sq * c) * std::sin(th));
  }
  double amplitude_sq() const { return c * c + d * d; }  // of the free vibration at tau = 0
};

// The step over a segment of length h, its transcendentals computed once per (period, h):
// e = exp(-zeta w h), C = cos(wd h), S = sin(wd h).
struct StepMap {
  double h = -1, inv_h = 0, e = 0, C = 0, S = 0;
  double curvature_sq = 0;  // ((h w)^2 / 8)^2: the curvature bound's factor, squared
  void set(const Oscillator& o, double length) {
    if (length == h) return;
    h = length;
    inv_h = 1.0 / h;
    e = std::exp(-o.zeta * o.w * h);
    C = std::cos(o.wd * h);
    S = std::sin(o.wd * h);
    const double k = 0.125 * (h * o.w) * (h * o.w);
    curvature_sq = k * k;
  }
  void advance(const Oscillator& o, const SegmentForm& f, double& u, double& w) const {
    if (o.w * h < 1.0) {
      taylor_state(o, h, f.u0, f.w0, f.a0, f.s, u, w);
      return;
    }
    u = f.p0 + f.p1 * h + e * (f.c * C + f.d * S);
    w = f.p1 * o.inv_w + e * ((o.sq * f.d - o.zeta * f.c) * C - (o.zeta * f.d + o.sq * f.c) * S);
  }
  // Whether the segment may hold a larger |U| than `peak` between its samples: false only where
  // the curvature or the envelope bound (SegmentMaximum) says it cannot, compared squared.
  bool may_exceed(const SegmentForm& f, double u0, double u1, double peak) const {
    const double a2 = f.amplitude_sq() * (1.0 + 1e-12);
    const double gap1 = peak - std::fmax(std::fabs(u0), std::fabs(u1));
    if (gap1 > 0.0 && gap1 * gap1 >= curvature_sq * a2) return false;
    const double gap2 = peak - std::fmax(std::fabs(f.p0), std::fabs(f.p0 + f.p1 * h));
    return !(gap2 > 0.0 && gap2 * gap2 >= a2);
  }
};

// The step map's coefficients on (U0, W0, a_i, a_i+1) (the samples in g): the affine map of
// StepMap::advance, read off its action on unit vectors.
struct LinearStep {
  double uu = 0, uw = 0, ua0 = 0, ua1 = 0, wu = 0, ww = 0, wa0 = 0, wa1 = 0;
  LinearStep() = default;
  LinearStep(const Oscillator& o, const StepMap& map, double g) {
    auto col = [&](double u0, double w0, double a0, double a1, double& cu, double& cw) {
      map.advance(o, SegmentForm(o, u0, w0, g * a0, g * (a1 - a0) * map.inv_h), cu, cw);
    };
    col(1, 0, 0, 0, uu, wu);
    col(0, 1, 0, 0, uw, ww);
    col(0, 0, 1, 0, ua0, wa0);
    col(0, 0, 0, 1, ua1, wa1);
  }
};

struct Peak {
  double u = 0, t = 0;  // max |U| and when
  void consider(double value, double at) {
    if (std::fabs(value) > u) {
      u = std::fabs(value);
      t = at;
    }
  }
};

// The largest |U| of one segment over [a, b], pruned by two bounds that hold for any subinterval:
// the curvature bound (|U''| <= w^2 A e^(-zeta w a), A the free vibration's amplitude, so |U| exceeds
// the larger end by at most (b - a)^2 / 8 of that) and the envelope bound (|linear part| + A e^(-zeta
// w a)). Intervals that cannot hold a new maximum cost nothing; the others are halved down to a
// sixteenth of the damped period, where U' is monotone on each side of the one zero of U'' that
// such a piece can hold (those zeros are td / 2 apart) and each sign change of U' is bisected to
// the last bit.
class SegmentMaximum {
 public:
  SegmentMaximum(const Oscillator& o, const SegmentForm& f, double t0, Peak& peak)
      : o_(o), f_(f), t0_(t0), peak_(peak), amp_(std::sqrt(f.amplitude_sq()) * (1.0 + 1e-12)) {}

  // `env` bounds the free vibration's envelope on [a, b]: the parent's value serves (the envelope
  // only decays), a slightly looser bound than amp e^(-zeta w a) without a transcendental per node.
  void over(double a, double b, double ua, double ub, int depth = 0, double env = -1.0) {
    if (env < 0.0) env = a == 0.0 ? amp_ : amp_ * std::exp(-o_.zeta * o_.w * a);
    const double lin = std::fmax(std::fabs(f_.p0 + f_.p1 * a), std::fabs(f_.p0 + f_.p1 * b));
    const double len = (b - a) * o_.w;
    const double bound = std::fmin(std::fmax(std::fabs(ua), std::fabs(ub)) + 0.125 * len * len * env, lin + env);
    if (!(bound > peak_.u)) return;
    const double mid = 0.5 * (a + b);
    if (b - a <= o_.td / 16.0 || !(mid > a && mid < b) || depth > 200) {
      leaf(a, b);
      return;
    }
    const double um = f_.u(o_, mid);
    peak_.consider(um, t0_ + mid);
    // The half with the larger end first: a higher peak prunes more of the other.
    if (std::fabs(ua) >= std::fabs(ub)) {
      over(a, mid, ua, um, depth + 1, env);
      over(mid, b, um, ub, depth + 1, env);
    } else {
      over(mid, b, um, ub, depth + 1, env);
      over(a, mid, ua, um, depth + 1, env);
    }
  }

 private:
  void leaf(double a, double b) {
    double cut = b;
    if (const double z = curvature_zero(a, b); z > a && z < b) cut = z;
    zero_of_velocity(a, cut);
    if (cut < b) zero_of_velocity(cut, b);
  }

  // The zero of U'' = e^(-zeta w tau) Re[lambda^2 C e^(i wd tau)] in (a, b), if any (b - a < td / 2).
  double curvature_zero(double a, double b) const {
    const double lr = -o_.zeta * o_.w, li = o_.wd;
    const double l2r = lr * lr - li * li, l2i = 2.0 * lr * li;                // lambda^2
    const double kr = l2r * f_.c + l2i * f_.d, ki = l2i * f_.c - l2r * f_.d;  // lambda^2 (c - i d)
    if (kr == 0.0 && ki == 0.0) return -1.0;
    // Re[K e^(i th)] = |K| cos(th + arg K): zero at th = pi/2 - arg K + k pi.
    const double th0 = 0.5 * kPi - std::atan2(ki, kr);
    const double k = std::ceil((o_.wd * a - th0) / kPi);
    return (th0 + k * kPi) / o_.wd;
  }

  // A sign change of U' over [a, b] (U' monotone there) is bisected and its |U| considered.
  void zero_of_velocity(double a, double b) {
    const double va = f_.v(o_, a), vb = f_.v(o_, b);
    if (!((va < 0.0 && vb > 0.0) || (va > 0.0 && vb < 0.0))) return;
    const bool rising = va < 0.0;
    double lo = a, hi = b;
    for (;;) {
      const double mid = 0.5 * (lo + hi);
      if (!(mid > lo && mid < hi)) break;
      ((f_.v(o_, mid) < 0.0) == rising ? lo : hi) = mid;
    }
    peak_.consider(f_.u(o_, lo), t0_ + lo);
    peak_.consider(f_.u(o_, hi), t0_ + hi);
  }

  const Oscillator& o_;
  const SegmentForm& f_;
  double t0_;
  Peak& peak_;
  double amp_;
};

}  // namespace

SpectralOrdinate spectral_ordinate(const Accelerogram& rec, double period, double damping, double g) {
  require_in_range("period", period, 0.0, 1e4, false);
  require_in_range("damping", damping, 0.0, 1.0, true, false);
  require_in_range("g", g, 0.0, 1e3, false);
  const Oscillator o(period, damping);
  const std::vector<double>& a = rec.values();
  const std::size_t n = a.size();
  // Pass 1: the state at every sample by the exact step map (no transcendental per sample on a
  // uniform record), and the largest |U| at the samples.
  thread_local std::vector<double> us, ws;  // kept between calls: no allocation per period
  us.resize(n);
  ws.resize(n);
  us[0] = ws[0] = 0.0;
  StepMap map;
  for (std::size_t i = 0; i + 1 < n;) {
    map.set(o, rec.time(i + 1) - rec.time(i));
    const LinearStep m(o, map, g);
    // The segments of the same length run through one map (all of them on a uniform record).
    const std::size_t end = rec.uniform() ? n - 1 : i + 1;
    for (; i < end; ++i) {
      const double u0 = us[i], w0 = ws[i], a0 = a[i], a1 = a[i + 1];
      us[i + 1] = m.uu * u0 + m.uw * w0 + m.ua0 * a0 + m.ua1 * a1;
      ws[i + 1] = m.wu * u0 + m.ww * w0 + m.wa0 * a0 + m.wa1 * a1;
    }
  }
  Peak peak;
  for (std::size_t i = 1; i < n; ++i) peak.consider(us[i], rec.time(i));
  // Pass 2: only segments whose bounds exceed that peak are searched between their samples.
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double t0 = rec.time(i);
    map.set(o, rec.time(i + 1) - t0);
    const SegmentForm f(o, us[i], ws[i], g * a[i], g * (a[i + 1] - a[i]) * map.inv_h);
    if (map.may_exceed(f, us[i], us[i + 1], peak.u)) SegmentMaximum(o, f, t0, peak).over(0.0, map.h, us[i], us[i + 1]);
  }
  // The free vibration after the record (a = 0 there): its largest |U| comes within half a damped
  // period, at the first zero of U'.
  const SegmentForm tail(o, us[n - 1], ws[n - 1], 0.0, 0.0);
  SegmentMaximum(o, tail, rec.t_last(), peak).over(0.0, o.td, us[n - 1], tail.u(o, o.td));
  return {period, peak.u / g, peak.u / (o.w * o.w), peak.t};
}

std::vector<SpectralOrdinate> response_spectrum(const Accelerogram& rec, const std::vector<double>& periods,
                                                double damping, double g) {
  std::vector<SpectralOrdinate> out;
  out.reserve(periods.size());
  for (double T : periods) out.push_back(spectral_ordinate(rec, T, damping, g));
  return out;
}

}  // namespace blockdyn
