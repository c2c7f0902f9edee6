// SPDX-License-Identifier: Apache-2.0
#pragma once
// Stability against overturning (thesis 4.3.1-4.3.2): time and ihor at overturning versus k,
// the critical curves k1_stability (ic1), k2_stability and k3_stability (ic2), and the aspect
// ratios r2_s(mu), r3_s(mu) below which ic2 overturns whatever k is.
//
// Definitions (thesis), for fixed mu, r, observing the motion up to t_end (30 in the thesis):
//  - k1_stability (ic1) = sup of K such that for all k < K the block overturns while ihor < 1.
//  - k2_stability (ic2) = sup of K such that for all k < K it overturns while ihor < 2.
//  - k3_stability (ic2) = sup of K such that for all k < K outside an eps-neighbourhood of
//    k2_stability it overturns while ihor < 3. Next to k2 the block creeps towards an unstable
//    equilibrium and does not finish its swing within t_end; the neighbourhood excludes that.
//    Here it is (k2, k2 (1 + eps)] (below k2 the ihor < 2 property already implies ihor < 3).
//    If the block does not overturn while ihor < 3 at k2 (1 + eps), k3 = k2 (they coincide).
//  - r2_s(mu) (r3_s) = sup of R such that for all r < R, k2_stability(r) (k3_stability(r)) is
//    above the k range searched: "overturns regardless of k" is checked only up to k_hi (cap).
// Runs ending in a state outside the model (more than two corners submerged) count as "did not
// overturn"; they occur only at very low k.
#include <vector>

#include "blockdyn/analysis/sweep/boundary_search.hpp"
#include "blockdyn/analysis/winkler/ic_choice.hpp"
#include "blockdyn/analysis/winkler/study_options.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

struct OverturnRun {
  double r = 0, k = 0;
  bool overturned = false;
  double time = 0;            // overturning time, or the end of the run
  long upright_passages = 0;  // ihor at overturning, or at the end of the run
  SimStatus status = SimStatus::TEnd;
};

// Runs to t_end (o.t_end) or to overturning.
OverturnRun overturn_run(const WinklerParams& p, const IcChoice& ic, const StudyRunOptions& o);
std::vector<OverturnRun> overturn_scan(const WinklerParams& base, const IcChoice& ic, const std::vector<double>& ks,
                                       const StudyRunOptions& o, int threads);

// Does the block overturn (before t_end) while ihor < n? Stops as soon as ihor reaches n.
bool overturns_while_upright_passages_below(const WinklerParams& p, const IcChoice& ic, long n,
                                            const StudyRunOptions& o);

struct StabilitySearchOptions {
  double k_lo = 10, k_hi = 1e7;  // k range; k_hi is also the cap of "regardless of k"
  double per_decade = 8;         // coarse grid density in k
  double eps = 0.02;             // relative width of the excluded neighbourhood above k2
  BisectionOptions bisect;
};

CurvePoint k1_stability(double r, double mu, const IcChoice& ic1_variant, const StudyRunOptions& o,
                        const StabilitySearchOptions& s);
CurvePoint k2_stability(double r, double mu, const StudyRunOptions& o, const StabilitySearchOptions& s);

struct K3Point {
  CurvePoint point;
  bool coincides_with_k2 = false;  // k3 = k2 within eps
};
// Needs the k2 result at the same (r, mu); k3 is above range when k2 is.
K3Point k3_stability(double r, double mu, const BoundaryResult& k2, const StudyRunOptions& o,
                     const StabilitySearchOptions& s);

enum class BlowupWhich { R2, R3 };
struct BlowupPoint {
  double mu = 0;
  BoundaryResult result;  // over r
};
// r2_s(mu) or r3_s(mu): the r grid [r_lo, r_hi] (log, r_per_decade) is scanned upward and the
// first r where the block does not always overturn is refined by bisection (rel. tol `r_bisect`).
BlowupPoint blowup_ratio(double mu, BlowupWhich which, double r_lo, double r_hi, double r_per_decade,
                         const BisectionOptions& r_bisect, const StudyRunOptions& o, const StabilitySearchOptions& s);

}  // namespace blockdyn
