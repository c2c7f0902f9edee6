// SPDX-License-Identifier: Apache-2.0
// Overturning spectra (issue 9): the scan-then-bisect search on a constructed overturning
// pattern (a band above a safe island), thread independence, and Housner's block under a
// rectangular pulse against the exact threshold (quadrature) and the linearised closed form.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>

#include "blockdyn/analysis/forced/overturning_spectrum.hpp"
#include "blockdyn/analysis/forced/spectrum_table.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"
#include "housner_reference.hpp"

using namespace blockdyn;
using namespace blockdyn::test;

namespace {

// Whether Housner's block overturns under a pulse of the given shape, amplitude and duration,
// followed by `t_after` seconds of free motion.
OverturnTest housner_overturns(const BlockShape& shape, PulseShape pulse, double t_after) {
  return [shape, pulse, t_after](double a, double d) {
    GroundMotion g;
    g.horizontal.pulse = pulse;
    g.horizontal.amplitude = a;
    g.horizontal.duration = d;
    RigidRunOptions ro;
    ro.t_end = d + t_after;
    ro.record_events = false;
    return simulate_housner(shape, std::nullopt, g, {}, ro).status == SimStatus::Overturned;
  };
}

}  // namespace

TEST(Spectrum, FindsTheLowestBandAndTheSafeIslandAbove) {
  // Overturns for a in [0.3 d, 0.5 d) and a >= 0.8 d: a safe island [0.5 d, 0.8 d).
  const OverturnTest t = [](double a, double d) { return (a >= 0.3 * d && a < 0.5 * d) || a >= 0.8 * d; };
  SpectrumOptions o;
  o.durations = {1.0, 2.0, 4.0};
  o.amplitude_min = 0.01;
  o.amplitude_max = 10;
  o.scan_points = 60;
  o.rel_tol = 1e-9;
  o.threads = 1;
  const auto rows = overturning_spectrum(t, o);
  ASSERT_EQ(rows.size(), 3u);
  for (const SpectrumRow& r : rows) {
    ASSERT_TRUE(r.min_overturning_amplitude);
    EXPECT_NEAR(*r.min_overturning_amplitude / (0.3 * r.duration), 1.0, 2e-9);
    ASSERT_EQ(r.safe_islands.size(), 1u) << r.duration;
    EXPECT_GE(r.safe_islands[0].from, 0.5 * r.duration);
    EXPECT_LT(r.safe_islands[0].to, 0.8 * r.duration);
  }
  // A band narrower than the scan's spacing between two survivals is missed by any scan; one
  // wider than it is found however far below the top band it lies.
  const OverturnTest none = [](double, double) { return false; };
  EXPECT_FALSE(overturning_spectrum(none, o)[0].min_overturning_amplitude);
}

namespace {
// One duration (1 s), 40 amplitudes from 0.01 g to 10 g, bisection to 1e-9, one thread.
SpectrumOptions one_duration_fine_scan() {
  SpectrumOptions o;
  o.durations = {1.0};
  o.amplitude_min = 0.01;
  o.amplitude_max = 10;
  o.scan_points = 40;
  o.rel_tol = 1e-9;
  o.threads = 1;
  return o;
}
}  // namespace

TEST(Spectrum, RunsOutsideTheModelAreNoSafeIsland) {
  // Overturns from 0.3 d; above 0.8 d the model gives up (an unsolvable contact problem): those
  // runs neither survive nor overturn, and no safe island may be claimed there.
  const OverturnTest t = [](double a, double d) {
    return a >= 0.8 * d ? kOutsideModel : a >= 0.3 * d ? kOverturns : kSurvives;
  };
  const SpectrumOptions o = one_duration_fine_scan();
  const SpectrumRow r = overturning_spectrum(t, o)[0];
  ASSERT_TRUE(r.min_overturning_amplitude);
  EXPECT_NEAR(*r.min_overturning_amplitude, 0.3, 1e-9);
  EXPECT_TRUE(r.safe_islands.empty());
  const std::vector<double> amp = scan_amplitudes(o);
  const long above = std::count_if(amp.begin(), amp.end(), [](double a) { return a >= 0.8; });
  EXPECT_EQ(r.outside_model, above);
  EXPECT_EQ(std::count(r.scan.begin(), r.scan.end(), char(kOutsideModel)), above);
}

TEST(Spectrum, AMinimumWithRunsOutsideTheModelBelowItIsAnUpperBound) {
  // Overturns from 0.3; the model gives up on a narrow band in the bisection's bracket, or on one
  // scanned amplitude below the minimum: the minimum is then only an upper bound, and says so.
  const SpectrumOptions o = one_duration_fine_scan();
  const std::vector<double> amp = scan_amplitudes(o);
  const auto first_over = std::find_if(amp.begin(), amp.end(), [](double a) { return a >= 0.3; });
  const double lo = *(first_over - 1), hi = *first_over;
  // A clean threshold: exact, not a bound.
  const SpectrumRow clean = spectrum_row([](double a, double) { return a >= 0.3 ? kOverturns : kSurvives; }, o, 1.0);
  EXPECT_FALSE(clean.upper_bound);
  EXPECT_NEAR(*clean.min_overturning_amplitude, 0.3, 1e-9);
  // Outside the model just below 0.3, inside the bracket: the bisection stops there.
  const SpectrumRow in_bracket = spectrum_row(
      [](double a, double) { return a >= 0.3    ? kOverturns
                                    : a >= 0.29 ? kOutsideModel
                                                : kSurvives; }, o, 1.0);
  ASSERT_GT(0.29, lo);  // the band lies inside the scan's bracket
  EXPECT_TRUE(in_bracket.upper_bound);
  EXPECT_EQ(in_bracket.bisection_outside_model, 1);
  EXPECT_GE(*in_bracket.min_overturning_amplitude, 0.3);
  EXPECT_LE(*in_bracket.min_overturning_amplitude, hi);
  // Outside the model at one scanned amplitude far below.
  const double odd = amp[5];
  const SpectrumRow below = spectrum_row(
      [odd](double a, double) { return a == odd   ? kOutsideModel
                                       : a >= 0.3 ? kOverturns
                                                  : kSurvives; }, o, 1.0);
  EXPECT_TRUE(below.upper_bound);
  EXPECT_EQ(below.bisection_outside_model, 0);
  EXPECT_NEAR(*below.min_overturning_amplitude, 0.3, 1e-9);
  // The table's row carries it (resume, JSON).
  const std::vector<std::string> cols = spectrum_columns();
  EXPECT_EQ(cols.back(), "bisection_outside_model");
}

TEST(Spectrum, ResultsDoNotDependOnTheThreadCount) {
  const OverturnTest t = housner_overturns({0.3, 1.5, 1.0, 9.81}, PulseShape::OneSine, 5);
  SpectrumOptions o;
  o.durations = {0.25, 0.4, 0.7, 1.2};
  o.scan_points = 30;
  o.threads = 1;
  const auto a = overturning_spectrum(t, o);
  o.threads = 2;
  const auto b = overturning_spectrum(t, o);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(*a[i].min_overturning_amplitude, *b[i].min_overturning_amplitude);  // bit-identical
    EXPECT_EQ(a[i].safe_islands.size(), b[i].safe_islands.size());
  }
  // One-sine pulses have safe islands above the minimum at short durations (Zhang & Makris).
  EXPECT_FALSE(a[0].safe_islands.empty());
}

TEST(Spectrum, HousnerRectangularPulseAgainstTheExactThresholdAndTheLinearLimit) {
  for (double b_over_h : {0.2, 0.05}) {
    RigidBlockParams p;
    p.shape = {b_over_h * 1.5, 1.5, 1.0, 9.81};
    const double alpha = p.shape.alpha(), pp = p.shape.p();
    const OverturnTest t = housner_overturns(p.shape, PulseShape::Rect, 10);
    SpectrumOptions o;
    o.durations = {0.1, 0.3, 1.0};
    o.amplitude_min = 0.5 * std::tan(alpha);
    o.amplitude_max = 20;
    o.scan_points = 25;
    o.rel_tol = 1e-9;
    const auto rows = overturning_spectrum(t, o);
    for (const SpectrumRow& r : rows) {
      ASSERT_TRUE(r.min_overturning_amplitude);
      const double exact = housner_rect_pulse_threshold(alpha, pp, r.duration);
      EXPECT_NEAR(*r.min_overturning_amplitude / exact, 1.0, 1e-6) << b_over_h << ' ' << r.duration;
      // The linearised form holds to O(alpha^2): 1.5% at alpha = 0.197, 0.1% at alpha = 0.05.
      const double lin = rect_pulse_overturning_linear(alpha, pp, r.duration);
      EXPECT_NEAR(*r.min_overturning_amplitude / lin, 1.0, b_over_h > 0.1 ? 2e-2 : 1.5e-3) << r.duration;
    }
  }
}
