// SPDX-License-Identifier: Apache-2.0
#pragma once
// (m, n) cycles of a motion under periodic forcing (issue 9 item 4; seed 002 sec. 3.2): seed
// 002 calls a motion with 2m impacts in an orbit that repeats every n forcing periods an (m, n)
// cycle (seed 001 calls a motion with k impacts per period 2 pi n / omega an (n, k) motion: our
// (m, n) is its (n, 2m)). Like seed 002, a cycle here is a periodic behaviour over a finite time
// range: sliding windows of `window` forcing periods, one per stroboscopic sample, are each
// classified from the stroboscopic samples (theta, theta') at t0 + k T and the impact times:
// - periodic (m, n): n is the smallest period, up to max_period, for which every sample of the
//   window returns after n periods within `tolerance` of the motion's amplitude in the window
//   (|d theta| / max|theta| and |d theta'| / max|theta'|, the maxima over the whole trajectory of
//   the window, not only the samples); 2m is the number of impacts per n periods in the window;
// - no-impacts: the block had no impact in the window (rest, or vibration without rocking);
// - non-periodic: no period up to max_period returns (chaotic, quasi-periodic or a transient:
//   this test does not tell them apart).
// Windows of one label merge into segments (where windows of two labels overlap, the later
// label holds from its first window on); a periodic segment shorter than two of its orbits is
// dropped, and a time covered by no kept segment is non-periodic. A failure adds a final
// "collapse" segment at t*. A transient converging onto a cycle with a negative Floquet
// multiplier alternates about it and may read, within the tolerance, as a cycle of twice the
// period before the cycle itself.
#include <optional>
#include <string>
#include <vector>

namespace blockdyn {

struct CycleOptions {
  int window = 24;          // forcing periods per sliding window
  int max_period = 12;      // largest n tried (at most window / 2)
  double tolerance = 0.05;  // largest return distance, relative to the window's amplitude
  int transient = 0;        // forcing periods skipped at the start
};
void validate(const CycleOptions& o);
// The options for a run of `periods` stroboscopic intervals: the window shrunk to what the run
// offers (and max_period to half of it), for runs shorter than a window (the survival maps).
CycleOptions fitted(const CycleOptions& o, long periods);

// Stroboscopic samples of one block: theta and theta' at t0 + k T, k = 0 .. K-1, and the largest
// |theta|, |theta'| over each forcing period [t_k, t_k+1) (at least K-1 of them).
struct StrobeSeries {
  double t0 = 0, period = 1;
  std::vector<double> theta, omega, theta_amp, omega_amp;
};

struct CycleSegment {
  std::string type;  // periodic | no-impacts | non-periodic | collapse
  double t_start = 0, t_end = 0;
  int impacts_per_cycle = 0;   // periodic: 2m
  int n = 0;                   // periodic: forcing periods per cycle
  long impacts = 0;            // impacts in [t_start, t_end)
  double return_distance = 0;  // periodic: the largest relative return distance of its windows
  double m() const { return 0.5 * impacts_per_cycle; }
  // "(1,3)" for periodic segments, else the type.
  std::string label() const;
};

struct CycleChange {
  double t = 0;
  std::string from, to;
};

struct CycleReport {
  CycleOptions options;  // as used
  long windows = 0;      // windows classified
  std::vector<CycleSegment> segments;
  std::vector<CycleChange> changes;
  // The label with the largest total duration (periodic, no-impacts or non-periodic); empty when
  // no window fits in the run.
  std::string dominant;
};

// impact_times sorted; t_failure: the run failed then (collapse segment).
CycleReport detect_cycles(const StrobeSeries& s, const std::vector<double>& impact_times, const CycleOptions& o,
                          std::optional<double> t_failure = std::nullopt);

}  // namespace blockdyn
