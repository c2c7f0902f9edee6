// SPDX-License-Identifier: Apache-2.0
#pragma once
// Locating a parameter value where a yes/no property of the dynamics changes (flight and
// stability boundaries). Everything works in log scale: boundaries in k span decades.
//
// Two kinds of search:
//  - find_transition: the predicate is assumed monotone in the range (false below, true above,
//    or the reverse). The first change on a log grid brackets it; bisection in log refines it.
//  - sup_all_below / inf_all_above: the thesis's definitions "sup of K such that the predicate
//    holds for all k < K" and "inf of K such that it holds for all k > K". The predicate need
//    not be monotone: a coarse log grid is scanned from the relevant end and the first failure
//    is refined by bisection between it and its neighbour on the grid.
//    Grid caveat: a failure window narrower than the grid spacing, lying before the first failure
//    the grid sees, is missed; and when the predicate flips several times inside the final
//    bracket the bisection converges to one of those flips, not necessarily the outermost one.
//    The result is exact only for predicates that change once between grid neighbours.
//  - refine_sup_all_below / refine_inf_all_above: the cure for the first caveat. After the
//    coarse search, a fine grid (anchored at a fixed k, so neighbouring searches sample the same
//    k values) is scanned over `span_decades` on the side that must hold, moving outward from
//    the far end of that window toward the boundary; a failure found there becomes the new
//    boundary (bisected as before) and the window moves with it, until one whole window holds.
//    A non-monotone predicate (flight windows below k_critical) is then resolved to the fine
//    spacing near the boundary, which is where the coarse grid misses windows.
#include <functional>
#include <string>
#include <vector>

namespace blockdyn {

// n >= 2 points from lo to hi (0 < lo < hi), equally spaced in log.
std::vector<double> log_grid(double lo, double hi, int n);
// Log grid with about `per_decade` points per decade (at least 2 points).
std::vector<double> log_grid_per_decade(double lo, double hi, double per_decade);

struct BisectionOptions {
  double rel_tol = 1e-3;  // stop when hi / lo - 1 <= rel_tol
  int max_iter = 100;
};

enum class BoundaryStatus {
  Found,       // value lies in the final bracket [lo, hi]
  BelowRange,  // the boundary is at or below the lowest point searched
  AboveRange,  // the boundary is above the highest point searched (e.g. k2_stability "infinite")
  Error,       // an evaluation threw; see message
};
const char* to_string(BoundaryStatus s);

struct BoundarySample {
  double x;
  bool value;
};

struct BoundaryResult {
  BoundaryStatus status = BoundaryStatus::Error;
  double value = 0;       // geometric mean of the final bracket (Found), else the range end
  double lo = 0, hi = 0;  // final bracket (Found), else the range searched
  int evaluations = 0;
  std::vector<BoundarySample> samples;  // every predicate evaluation, in call order
  std::string message;

  bool found() const { return status == BoundaryStatus::Found; }
};

using Predicate = std::function<bool(double)>;

// Monotone predicate on [grid.front(), grid.back()] (ascending grid): bracket the one change and
// bisect. If the predicate has the same value at every grid point visited up to the top, the
// result is BelowRange when that value is the one expected above the change (`true_above`),
// else AboveRange. `true_above` says which way the predicate is expected to change.
BoundaryResult find_transition(const Predicate& pred, const std::vector<double>& grid, bool true_above,
                               const BisectionOptions& opt = {});

// sup { K : pred(k) for all k < K }, scanning `grid` (ascending) upward.
// BelowRange: pred fails at grid.front(); AboveRange: pred holds on the whole grid.
BoundaryResult sup_all_below(const Predicate& pred, const std::vector<double>& grid, const BisectionOptions& opt = {});

// inf { K : pred(k) for all k > K }, scanning `grid` (ascending) downward from the top.
// AboveRange: pred fails at grid.back(); BelowRange: pred holds on the whole grid.
BoundaryResult inf_all_above(const Predicate& pred, const std::vector<double>& grid, const BisectionOptions& opt = {});

struct RefineOptions {
  double per_decade = 0;    // fine grid density (0: no refinement)
  double span_decades = 1;  // width of the window checked next to the boundary
  double anchor = 1;        // fine grid points are anchor * 10^(j / per_decade), j integer
};

// Refines a Found result of sup_all_below (k_floor: lowest k that may be evaluated) or of
// inf_all_above (k_ceiling: highest); other results are returned unchanged. Evaluations and
// samples are appended to those of `coarse`.
BoundaryResult refine_sup_all_below(const Predicate& pred, BoundaryResult coarse, double k_floor,
                                    const RefineOptions& ro, const BisectionOptions& opt = {});
BoundaryResult refine_inf_all_above(const Predicate& pred, BoundaryResult coarse, double k_ceiling,
                                    const RefineOptions& ro, const BisectionOptions& opt = {});

// Bisection in log between a point where pred is `value_lo` (lo) and one where it is not (hi).
// Returns the final bracket; lo < hi, both > 0.
BoundaryResult bisect_log(const Predicate& pred, double lo, double hi, bool value_lo, const BisectionOptions& opt = {});

}  // namespace blockdyn
