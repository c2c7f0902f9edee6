// SPDX-License-Identifier: Apache-2.0
#pragma once
// Flight studies of the thesis's section 4.2: time to first flight versus k, the energy lower
// bound k_min(r), and the critical curves k_critical_n(r) and k_high(r).
//
// Definitions (thesis, 4.2.2), for fixed mu, r and initial conditions:
//  - k_critical_n(r) = sup of K such that for all k < K the block does not fly while ihor < n.
//  - k_high(r) = inf of K such that for all k > K the block flies "before or during the first
//    impact": "while w' < 0" (ic1 only: the block falls from its tilt with w' < 0 and the first
//    impact is usually over before w' turns positive) or "while ihor < 2".
// Runs that reach t_end without deciding the question (no flight, and neither ihor = n nor the
// end of the first impact reached) count as "did not fly" and are reported as undecided.
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/analysis/sweep/boundary_search.hpp"
#include "blockdyn/analysis/winkler/ic_choice.hpp"
#include "blockdyn/analysis/winkler/study_options.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

// One run stopped at the first take-off.
struct FirstFlight {
  double r = 0, k = 0;
  bool flew = false;
  // First take-off time; without flight t_end (the thesis's convention for "no flight", also
  // when the block overturned first: the motion is over and it never flew).
  double time = 0;
  double t_final = 0;                  // when the run ended
  long upright_passages = 0;           // ihor at first flight, or at the end of the run
  SimStatus status = SimStatus::TEnd;  // EarlyStop when stopped at the flight
};

FirstFlight first_flight(const WinklerParams& p, const IcChoice& ic, const StudyRunOptions& o);

// first_flight at every k (mu, r from `base`), in parallel, results in the order of `ks`.
std::vector<FirstFlight> first_flight_scan(const WinklerParams& base, const IcChoice& ic, const std::vector<double>& ks,
                                           const StudyRunOptions& o, int threads);

// Time-to-flight map over (k, r) (thesis Fig. 4.20); row-major: index = ir * ks.size() + ik.
std::vector<FirstFlight> first_flight_map(double mu, const IcChoice& ic, const std::vector<double>& rs,
                                          const std::vector<double>& ks, const StudyRunOptions& o, int threads);

// Total initial energy of the initial-condition set (E = 0 is the least energy in flight).
double initial_energy(const WinklerParams& p, const IcChoice& ic);

// k_min(r) = inf of K such that E0(k) >= 0 for all k > K (thesis 4.2.1), found by scanning a log
// grid in k downward for the first E0 < 0 and solving E0 = 0 (TOMS 748 in log k) above it.
// Found: value is the root, [lo, hi] its bracket.
BoundaryResult k_min(double r, double mu, const IcChoice& ic, double k_lo = 1e-2, double k_hi = 1e12,
                     double per_decade = 4);

enum class FirstImpact { WNegative, UprightPassagesBelow2 };
const char* to_string(FirstImpact c);
FirstImpact parse_first_impact(const std::string& s);  // "w_negative" | "ihor2"

// Outcome of one flight predicate run.
struct FlightCheck {
  bool holds = false;
  bool decided = true;  // false: t_end reached before the question was settled
};

// Does the block stay on the foundation while ihor < n? (stops at first flight or at ihor = n)
FlightCheck no_flight_while_upright_passages_below(const WinklerParams& p, const IcChoice& ic, long n,
                                                   const StudyRunOptions& o);
// Does the block fly before or during the first impact (criterion c)?
FlightCheck flies_during_first_impact(const WinklerParams& p, const IcChoice& ic, FirstImpact c,
                                      const StudyRunOptions& o);

struct BoundarySearchOptions {
  double k_lo = 1e1, k_hi = 1e10;  // k range scanned
  double per_decade = 6;           // coarse grid density
  BisectionOptions bisect;
  // Fine scan next to the boundary (boundary_search.hpp). The flight predicates flip in narrow
  // k windows below k_critical (above k_high); a coarse grid misses some of them at one r and
  // not at the next, which made the curves jagged. Anchored at k_lo, so every r samples the
  // same k values.
  RefineOptions refine;
};

CurvePoint k_critical(double r, double mu, const IcChoice& ic, long n, const StudyRunOptions& o,
                      const BoundarySearchOptions& s);
CurvePoint k_high(double r, double mu, const IcChoice& ic, FirstImpact c, const StudyRunOptions& o,
                  const BoundarySearchOptions& s);

}  // namespace blockdyn
