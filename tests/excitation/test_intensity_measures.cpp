// SPDX-License-Identifier: Apache-2.0
// Intensity measures and the response spectrum of a record against closed forms (a step, a
// ramp, a sinusoid on its own Fourier bin) and against brute force (fine quadrature and a
// fine Runge-Kutta integration of the oscillator) on an irregular record.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "blockdyn/excitation/intensity_measures.hpp"
#include "blockdyn/excitation/response_spectrum.hpp"
#include "blockdyn/excitation/stochastic_motion.hpp"

using namespace blockdyn;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double g = 9.81;

Accelerogram uniform(double dt, std::size_t n, double (*f)(double)) {
  std::vector<double> a(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = f(dt * double(i));
  return Accelerogram(a, dt, "test");
}

// An irregular record: random times and values, not ending at rest.
Accelerogram irregular() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> step(0.004, 0.03), val(-0.4, 0.4);
  std::vector<double> t{0.0}, a{0.0};
  while (t.size() < 300) {
    t.push_back(t.back() + step(rng));
    a.push_back(val(rng));
  }
  return Accelerogram(t, a, "irregular");
}

}  // namespace

TEST(IntensityMeasures, StepHasClosedForms) {
  const double a0 = 0.3, T = 4.0;  // a = a0 on [0, T]
  const IntensityMeasures m = intensity_measures(uniform(0.01, 401, [](double) { return 0.3; }), g);
  EXPECT_DOUBLE_EQ(m.pga, a0);
  EXPECT_NEAR(m.pgv, a0 * g * T, 1e-12 * a0 * g * T);
  EXPECT_NEAR(m.pgd, a0 * g * T * T / 2, 1e-12 * a0 * g * T * T);
  EXPECT_NEAR(m.arias, kPi * g / 2 * a0 * a0 * T, 1e-12);
  EXPECT_NEAR(m.t5, 0.05 * T, 1e-13);
  EXPECT_NEAR(m.t95, 0.95 * T, 1e-13);
  EXPECT_NEAR(m.d5_95, 0.9 * T, 1e-13);
  EXPECT_NEAR(m.t_mid, 0.45 * T, 1e-13);
}

TEST(IntensityMeasures, RampHasClosedFormsFromFewSamples) {
  // a = c t on [0, T], given by 5 samples: the Husid plot is a cubic, t_q = T q^(1/3).
  const double c = 0.1, T = 2.0;
  const IntensityMeasures m = intensity_measures(uniform(0.5, 5, [](double t) { return 0.1 * t; }), g);
  EXPECT_NEAR(m.arias, kPi * g / 2 * c * c * T * T * T / 3, 1e-14);
  EXPECT_NEAR(m.t5, T * std::cbrt(0.05), 1e-14);
  EXPECT_NEAR(m.t_mid, T * std::cbrt(0.45), 1e-14);
  EXPECT_NEAR(m.d5_95, T * (std::cbrt(0.95) - std::cbrt(0.05)), 1e-14);
  EXPECT_NEAR(m.pgv, c * g * T * T / 2, 1e-13);
  EXPECT_NEAR(m.pgd, c * g * T * T * T / 6, 1e-13);
}

TEST(IntensityMeasures, PeaksInsideASegment) {
  // a = 1 - 2 t on [0, 1] (two samples): v = g (t - t^2) peaks at t = 1/2 with g / 4, where no
  // sample is; then a = -1 on [1, 2]: v = -g (t - 1), d = g/6 - g (t-1)^2 / 2.
  const Accelerogram rec(std::vector<double>{0, 1, 2}, std::vector<double>{1, -1, -1}, "test");
  const IntensityMeasures m = intensity_measures(rec, g);
  EXPECT_NEAR(m.pgv, g, 1e-14);  // |v(2)| = g beats g/4
  const Accelerogram one(std::vector<double>{0, 1}, std::vector<double>{1, -1}, "test");
  EXPECT_NEAR(intensity_measures(one, g).pgv, g / 4, 1e-14);
  // d(2) = g/6 - g/2 = -g/3; the peak |d| inside [1, 2] is at the end.
  EXPECT_NEAR(m.pgd, g / 3, 1e-14);
  EXPECT_NEAR(m.final_velocity, -g, 1e-14);
}

TEST(IntensityMeasures, IrregularRecordAgainstFineQuadrature) {
  const Accelerogram rec = irregular();
  const IntensityMeasures m = intensity_measures(rec, g);
  // Brute force: 400 substeps per segment, trapezoids for v, d and the energy.
  double v = 0, d = 0, e = 0, pgv = 0, pgd = 0;
  std::vector<std::pair<double, double>> husid;
  for (std::size_t i = 0; i + 1 < rec.size(); ++i) {
    const double t0 = rec.time(i), h = (rec.time(i + 1) - t0) / 400;
    for (int k = 0; k < 400; ++k) {
      const double ta = t0 + h * k, tb = ta + h;
      const double aa = g * rec.at(ta), ab = g * (k == 399 ? rec.values()[i + 1] : rec.at(tb));
      const double vb = v + 0.5 * h * (aa + ab);
      d += 0.5 * h * (v + vb) + h * h * (aa - ab) / 12.0;  // exact for a linear a
      v = vb;
      e += h * (aa * aa + aa * ab + ab * ab) / 3.0;
      pgv = std::max(pgv, std::fabs(v));
      pgd = std::max(pgd, std::fabs(d));
      husid.push_back({tb, e});
    }
  }
  EXPECT_NEAR(m.pgv, pgv, 1e-6 * pgv);
  EXPECT_NEAR(m.pgd, pgd, 1e-6 * pgd);
  EXPECT_NEAR(m.arias, kPi / (2 * g) * e, 1e-12 * m.arias);
  for (const double q : {0.05, 0.45, 0.95}) {
    std::size_t k = 0;
    while (husid[k].second < q * e) ++k;
    EXPECT_NEAR(husid_time(rec, q), husid[k].first, 2e-4) << q;
  }
}

TEST(IntensityMeasures, MeanPeriodOfASinusoidOnItsBin) {
  // 1024 samples at 0.01 s and 20 whole cycles: one Fourier bin, f0 = 20 / 10.24 Hz.
  const IntensityMeasures m =
      intensity_measures(uniform(0.01, 1024, [](double t) { return 0.2 * std::sin(2 * kPi * t * 20 / 10.24); }), g);
  EXPECT_NEAR(m.mean_period, 10.24 / 20, 1e-9);
}

TEST(ResponseSpectrum, StepGivesTheDynamicAmplification) {
  // A suddenly applied a0 lasting 40 periods: u peaks at t = pi / w_d with
  // (a0 g / w^2)(1 + exp(-zeta pi / sqrt(1 - zeta^2))).
  const double a0 = 0.3, T = 0.5, zeta = 0.05;
  const SpectralOrdinate s = spectral_ordinate(uniform(0.01, 2001, [](double) { return 0.3; }), T, zeta, g);
  const double amp = 1 + std::exp(-zeta * kPi / std::sqrt(1 - zeta * zeta));
  EXPECT_NEAR(s.sa, a0 * amp, 1e-12);
  EXPECT_NEAR(s.t_peak, T / 2 / std::sqrt(1 - zeta * zeta), 1e-12);
  EXPECT_NEAR(s.sd, s.sa * g / std::pow(2 * kPi / T, 2), 1e-15);
}

TEST(ResponseSpectrum, RampAndItsFreeVibration) {
  // a = c t on [0, Tr], undamped: u(Tr) = -(c g / w^2)(Tr - sin(w Tr)/w), v(Tr) =
  // -(c g / w^2)(1 - cos(w Tr)); after the record the free vibration's amplitude is the peak.
  const double c = 0.1, Tr = 2.0;
  for (const double T : {0.3, 0.77, 1.9, 5.0}) {
    const double w = 2 * kPi / T;
    const SpectralOrdinate s = spectral_ordinate(uniform(0.5, 5, [](double t) { return 0.1 * t; }), T, 0.0, g);
    const double x = Tr - std::sin(w * Tr) / w, y = (1 - std::cos(w * Tr)) / w;
    EXPECT_NEAR(s.sa, c * std::hypot(x, y), 1e-12) << T;
  }
}

TEST(ResponseSpectrum, IrregularRecordAgainstFineRungeKutta) {
  const Accelerogram rec = irregular();
  for (const double T : {0.05, 0.4, 2.0}) {
    const double w = 2 * kPi / T, zeta = 0.05;
    // RK4 with 2000 steps per segment, then the free vibration for a period.
    double u = 0, v = 0, peak = 0;
    auto rk = [&](double a0, double s, double h) {
      auto f = [&](double t, double uu, double vv, double& du, double& dv) {
        du = vv;
        dv = -g * (a0 + s * t) - 2 * zeta * w * vv - w * w * uu;
      };
      for (int k = 0; k < 2000; ++k) {
        const double t = h * k;
        double k1u, k1v, k2u, k2v, k3u, k3v, k4u, k4v;
        f(t, u, v, k1u, k1v);
        f(t + h / 2, u + h / 2 * k1u, v + h / 2 * k1v, k2u, k2v);
        f(t + h / 2, u + h / 2 * k2u, v + h / 2 * k2v, k3u, k3v);
        f(t + h, u + h * k3u, v + h * k3v, k4u, k4v);
        u += h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u);
        v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        peak = std::max(peak, std::fabs(u));
      }
    };
    for (std::size_t i = 0; i + 1 < rec.size(); ++i) {
      const double h = rec.time(i + 1) - rec.time(i);
      rk(rec.values()[i], (rec.values()[i + 1] - rec.values()[i]) / h, h / 2000);
    }
    rk(0, 0, T / 2000);
    const SpectralOrdinate s = spectral_ordinate(rec, T, zeta, g);
    EXPECT_NEAR(s.sd, peak, 1e-6 * peak) << T;
  }
}

TEST(ResponseSpectrum, ShortPeriodTendsToThePga) {
  const Accelerogram rec =
      uniform(0.01, 1001, [](double t) { return 0.25 * std::sin(2 * kPi * 1.3 * t) * std::exp(-0.2 * t); });
  EXPECT_NEAR(spectral_ordinate(rec, 1e-3, 0.05, g).sa / rec.peak(), 1.0, 2e-3);
  EXPECT_THROW(spectral_ordinate(rec, 0.0, 0.05, g), std::invalid_argument);
  EXPECT_THROW(spectral_ordinate(rec, 1.0, 1.0, g), std::invalid_argument);
}

TEST(StochasticMotion, ModulationMeetsTheTargetsByQuadrature) {
  // The fitted q(t) = c1 t^(c2-1) exp(-c3 t): its Husid curve, integrated independently, reaches
  // 5 %, 45 % and 95 % at t_mid and t_mid +- as D5-95 asks, and pi g / 2 int q^2 = the Arias target.
  const double arias = 0.8, d = 12, tm = 7;
  const Modulation q = fit_modulation(arias, d, tm, g);
  const double h = 1e-4;
  std::vector<double> cum{0.0};
  for (double t = 0; t < 200; t += h)
    cum.push_back(cum.back() + h * 0.5 * (std::pow(q.at(t), 2) + std::pow(q.at(t + h), 2)));
  EXPECT_NEAR(kPi * g / 2 * cum.back(), arias, 1e-8);
  auto when = [&](double f) {
    std::size_t k = 0;
    while (cum[k] < f * cum.back()) ++k;
    return h * double(k);
  };
  EXPECT_NEAR(when(0.45), tm, 2e-4);
  EXPECT_NEAR(when(0.95) - when(0.05), d, 2e-4);
  EXPECT_THROW(fit_modulation(arias, 5 * tm, tm, g), std::invalid_argument);  // beyond the gamma family
}

TEST(StochasticMotion, PulseVelocityIsTheClosedForm) {
  // The acceleration integrates to v(t) = A/2 [1 + cos(2 pi tau / (gamma Tp))] cos(2 pi tau / Tp + nu).
  const PulseParams p{.pgv = 0.8, .period = 1.5, .gamma = 2.5, .nu = 0.4, .t0 = 3};
  double v = 0;
  const double h = 1e-5;
  for (double t = 0; t < 6; t += h) {
    v += 0.5 * h * g * (pulse_acceleration(p, t, g) + pulse_acceleration(p, t + h, g));
    const double tau = t + h - p.t0;
    // Zero outside the support: the envelope vanishes at its edges, so v returns to 0.
    const double exact = std::fabs(tau) > 0.5 * p.gamma * p.period
                             ? 0.0
                             : 0.5 * p.pgv * (1 + std::cos(2 * kPi * tau / (p.gamma * p.period))) *
                                   std::cos(2 * kPi * tau / p.period + p.nu);
    ASSERT_NEAR(v, exact, 1e-6) << t;
  }
}

TEST(IntensityMeasures, SineAgainstItsClosedForms) {
  // a = A sin(w t) over 3 whole periods at 1 Hz, 2000 samples per period: the interpolation
  // changes the integrals by (w dt)^2 / 12 ~ 1e-6 relative.
  const double A = 0.25, w = 2 * kPi, T = 3.0;
  const Accelerogram rec = uniform(5e-4, 6001, [](double t) { return 0.25 * std::sin(2 * kPi * t); });
  const IntensityMeasures m = intensity_measures(rec, g);
  EXPECT_NEAR(m.arias, kPi * g / 2 * A * A * T / 2, 2e-6 * m.arias);
  EXPECT_NEAR(m.pgv, 2 * A * g / w, 2e-6 * m.pgv);  // v = A g (1 - cos w t) / w
  // Husid: (t - sin(2 w t) / (2 w)) / T; its 5 %, 45 % and 95 % times by Newton.
  for (const double q : {0.05, 0.45, 0.95}) {
    double t = q * T;
    for (int i = 0; i < 50; ++i) t -= (t - std::sin(2 * w * t) / (2 * w) - q * T) / (1 - std::cos(2 * w * t));
    EXPECT_NEAR(husid_time(rec, q), t, 2e-5) << q;
  }
  // Sa of an undamped oscillator at T_n = 0.4 s: from rest, u = -(A g / (wn^2 - w^2))(sin w t -
  // (w / wn) sin wn t); after the record, the free vibration of its end state.
  const double wn = 2 * kPi / 0.4, c = -A * g / (wn * wn - w * w);
  double peak = 0;
  for (int i = 0; i <= 3'000'000; ++i) {
    const double t = T * i / 3e6;
    peak = std::max(peak, std::fabs(c * (std::sin(w * t) - w / wn * std::sin(wn * t))));
  }
  const double uT = c * (std::sin(w * T) - w / wn * std::sin(wn * T)),
               vT = c * w * (std::cos(w * T) - std::cos(wn * T));
  peak = std::max(peak, std::hypot(uT, vT / wn));
  EXPECT_NEAR(spectral_ordinate(rec, 0.4, 0.0, g).sd, peak, 1e-5 * peak);
}

TEST(StochasticMotion, FilteredNoiseIsTheDefiningSum) {
  // x_j = q(t_j) sum_i u_i h(t_j - t_i; w_i) / sqrt(sum_i h^2), h(tau; w) = w/sq e^(-zeta w tau)
  // sin(w sq tau), summed directly over every pair (the quadratic definition) for a sweeping and a
  // constant filter frequency: the generator's windowed sum and its recursion agree to rounding.
  for (const double slope : {-0.2, 0.0}) {
    RezaeianParams p;
    p.arias = 0.5;
    p.d5_95 = 3;
    p.t_mid = 4;
    p.f_mid = 3;
    p.f_slope = slope;
    p.zeta_f = 0.2;
    p.dt = 0.01;
    p.t_end = 10;
    validate(p);
    const Modulation q = fit_modulation(p.arias, p.d5_95, p.t_mid, p.g);
    const std::vector<double> x = rezaeian_filtered_noise(p, q, 9, 2);
    const std::vector<double> u = white_noise(9, 2, x.size());
    const double sq = std::sqrt(1 - p.zeta_f * p.zeta_f);
    double worst = 0, peak = 0;
    for (std::size_t j = 0; j < x.size(); ++j) {
      double sum = 0, var = 0;
      for (std::size_t i = 0; i <= j; ++i) {
        const double w = 2 * kPi * (p.f_mid + p.f_slope * (double(i) * p.dt - p.t_mid)), tau = double(j - i) * p.dt;
        const double h = w / sq * std::exp(-p.zeta_f * w * tau) * std::sin(w * sq * tau);
        sum += h * u[i];
        var += h * h;
      }
      const double direct = var > 0 ? q.at(double(j) * p.dt) * sum / std::sqrt(var) : 0.0;
      worst = std::fmax(worst, std::fabs(x[j] - direct));
      peak = std::fmax(peak, std::fabs(direct));
    }
    EXPECT_LT(worst, 1e-11 * peak) << slope;
  }
}

TEST(StochasticMotion, LateShortBurstsHaveFiniteSamples) {
  // A D5-95 of 1 s at t_mid = 25 s: c1 alone underflows (and t^(c2 - 1) overflows); q is finite.
  const Modulation q = fit_modulation(0.8, 1.0, 25.0, g);
  EXPECT_TRUE(std::isfinite(q.log_c1));
  EXPECT_EQ(q.c1(), 0.0);
  double arias = 0;
  for (double t = 0; t < 40; t += 1e-4) arias += 1e-4 * q.at(t) * q.at(t);
  EXPECT_NEAR(kPi * g / 2 * arias, 0.8, 1e-6);
  EXPECT_NEAR(q.husid_time(0.95) - q.husid_time(0.05), 1.0, 1e-12);
}

TEST(ResponseSpectrum, AgainstFortyDigitClosedForms) {
  // tests/reference/spectrum_reference.py: the same closed forms in 40-digit arithmetic with every
  // velocity zero bisected, on a 300-sample random record; from 0.004 s (4 oscillations per
  // sample) to 1e4 s (where U = w^2 u is 1e-5 of the ground acceleration and a closed form in
  // doubles loses 11 digits to cancellation).
  const Accelerogram rec = load_accelerogram(std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/random_300.csv", "r");
  const struct {
    double T, zeta, sa;
  } ref[] = {{0.02, 0.05, 1.3205107351455855762},      {0.3, 0.05, 0.41978527651894893906},
             {5, 0.05, 0.037457557134727773594},       {50, 0.05, 0.0028555432930054607599},
             {10000, 0.05, 0.00001431549387203141918}, {0.7, 0, 0.33128804484693789587},
             {0.004, 0.02, 0.48508836471263014291}};
  for (const auto& r : ref) {
    const double sa = spectral_ordinate(rec, r.T, r.zeta, g).sa;
    EXPECT_NEAR(sa, r.sa, 1e-12 * r.sa) << r.T;
  }
}

TEST(ResponseSpectrum, EveryPeriodHasAnAnswerAtACostIndependentOfIt) {
  // Periods far below the sampling (1e-160 s: w^2 overflows a double) tend to the pga; the search
  // inside a segment is pruned by bounds, so 1e-7 s costs what 0.02 s does (seconds would mean the
  // old scan of every oscillation).
  const Accelerogram rec =
      uniform(0.01, 1001, [](double t) { return 0.25 * std::sin(2 * kPi * 1.3 * t) * std::exp(-0.2 * t); });
  for (const double T : {1e-160, 1e-100, 1e-7}) {
    for (const double zeta : {0.0, 0.05}) {
      const SpectralOrdinate s = spectral_ordinate(rec, T, zeta, g);
      ASSERT_TRUE(std::isfinite(s.sa)) << T;
      EXPECT_NEAR(s.sa, rec.peak(), 1e-6 * rec.peak()) << T << " " << zeta;
      EXPECT_GE(s.sd, 0.0);
    }
  }
  EXPECT_NEAR(spectral_ordinate(rec, 1e-160, 0.0, g).sa, rec.peak(), 1e-14 * rec.peak());
}
