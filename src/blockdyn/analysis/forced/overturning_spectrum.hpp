// SPDX-License-Identifier: Apache-2.0
#pragma once
// Overturning spectra (issue 9): for each pulse duration, the smallest amplitude that overturns
// the block (or collapses the assembly). Overturning is not monotone in the amplitude (safe
// islands exist above the minimum), so a search that only bisects can miss a lower overturning
// band: every duration is first scanned over a geometric grid of amplitudes, the minimum is then
// refined by bisection between the last surviving and the first overturning scan amplitude, and
// the surviving scan amplitudes above it are reported as safe islands.
// Durations are independent: they run in parallel, each on one thread, so the result does not
// depend on the thread count.
#include <functional>
#include <optional>
#include <vector>

namespace blockdyn {

struct SpectrumOptions {
  std::vector<double> durations;  // pulse durations (s)
  double amplitude_min = 0.01;    // scanned amplitudes (g), geometric grid
  double amplitude_max = 10.0;
  int scan_points = 40;
  double rel_tol = 1e-6;  // bisection: (hi - lo) / hi
  int threads = 0;        // 0: all cores
};

struct SpectrumIsland {
  double from = 0, to = 0;  // first and last surviving scan amplitudes of a run above the minimum (g)
};

struct SpectrumRow {
  double duration = 0;
  std::optional<double> min_overturning_amplitude;  // g; nullopt: nothing in the scan overturns
  bool at_scan_floor = false;                       // the smallest scanned amplitude already overturns
  std::vector<SpectrumIsland> safe_islands;
  long runs = 0;
  // Per scan amplitude (scan_amplitudes()): kOverturns, kSurvives or kOutsideModel.
  std::vector<char> scan;
  long outside_model = 0;            // runs that left the model's validity (scan and bisection)
  long bisection_outside_model = 0;  // of which in the bisection (it then stops: 0 or 1)
  // A run below min_overturning_amplitude left the model, so the minimum may lie lower: the value
  // is an upper bound.
  bool upper_bound = false;
};

// What one run says: a run that leaves the model's validity (a state the model does not
// describe, an unsolvable contact problem) neither survives nor overturns.
inline constexpr int kSurvives = 0, kOverturns = 1, kOutsideModel = 2;
// overturns(amplitude_g, duration_s) -> kSurvives | kOverturns | kOutsideModel (a bool is read as
// survives / overturns); thread-safe (it runs one simulation).
using OverturnTest = std::function<int(double amplitude, double duration)>;

std::vector<SpectrumRow> overturning_spectrum(const OverturnTest& overturns, const SpectrumOptions& o,
                                              const std::function<void(std::size_t done)>& progress = {});

void validate(const SpectrumOptions& o);  // throws std::invalid_argument naming the field

// The scanned amplitudes (g): geometric from amplitude_min to amplitude_max.
std::vector<double> scan_amplitudes(const SpectrumOptions& o);
// One duration: scan, bisection, islands. A pure function of its arguments (the runner's rule).
SpectrumRow spectrum_row(const OverturnTest& overturns, const SpectrumOptions& o, double duration);

// The linearised closed form for a rectangular pulse (spec rigid-ground-block.md, small alpha):
// a_p / (g alpha) = 1 / (1 - exp(-p t_p)). Returns a_p in g.
double rect_pulse_overturning_linear(double alpha, double p, double t_p);

}  // namespace blockdyn
