// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/winkler/stability.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/analysis/winkler/study_run.hpp"

namespace blockdyn {

namespace {

void check_search(const StabilitySearchOptions& s) {
  if (!(s.eps > 0) || !(s.eps < 1))
    throw std::invalid_argument("eps = " + number_text(s.eps) + " is out of range: must be in (0, 1)");
}

}  // namespace

OverturnRun overturn_run(const WinklerParams& p, const IcChoice& ic, const StudyRunOptions& o) {
  // Not run_checked: a failed run is one point of a scan, reported through its status.
  const WinklerResult res = simulate(p, {}, ic.state(p), lean_study_options(o));
  OverturnRun out;
  out.r = p.r;
  out.k = p.k;
  out.status = res.status;
  out.overturned = res.overturn_time.has_value();
  out.time = out.overturned ? *res.overturn_time : res.t_final;
  out.upright_passages = out.overturned ? res.upright_passages_at_overturn : res.upright_passages;
  return out;
}

std::vector<OverturnRun> overturn_scan(const WinklerParams& base, const IcChoice& ic, const std::vector<double>& ks,
                                       const StudyRunOptions& o, int threads) {
  return parallel_map<OverturnRun>(ks.size(), threads, [&](std::size_t i) {
    WinklerParams p = base;
    p.k = ks[i];
    return overturn_run(p, ic, o);
  });
}

bool overturns_while_upright_passages_below(const WinklerParams& p, const IcChoice& ic, long n,
                                            const StudyRunOptions& o) {
  if (n < 1) throw std::invalid_argument("n = " + std::to_string(n) + " is out of range: must be >= 1");
  WinklerRunOptions s = lean_study_options(o);
  s.stop_at_upright_passages = n;  // once ihor = n the answer is no: stop there
  const WinklerResult res = run_checked(p, ic, s);
  return res.overturn_time.has_value() && res.upright_passages_at_overturn < n;
}

CurvePoint k1_stability(double r, double mu, const IcChoice& ic, const StudyRunOptions& o,
                        const StabilitySearchOptions& s) {
  if (!ic.is_ic1()) throw std::invalid_argument("k1_stability is defined for ic1 (or an ic1 variant)");
  CurvePoint cp;
  cp.r = r;
  auto pred = [&](double k) { return overturns_while_upright_passages_below(WinklerParams{r, mu, k}, ic, 1, o); };
  cp.result = sup_all_below(pred, log_grid_per_decade(s.k_lo, s.k_hi, s.per_decade), s.bisect);
  return cp;
}

CurvePoint k2_stability(double r, double mu, const StudyRunOptions& o, const StabilitySearchOptions& s) {
  CurvePoint cp;
  cp.r = r;
  const IcChoice ic{IcChoice::Set::Ic2};
  auto pred = [&](double k) { return overturns_while_upright_passages_below(WinklerParams{r, mu, k}, ic, 2, o); };
  cp.result = sup_all_below(pred, log_grid_per_decade(s.k_lo, s.k_hi, s.per_decade), s.bisect);
  return cp;
}

K3Point k3_stability(double r, double mu, const BoundaryResult& k2, const StudyRunOptions& o,
                     const StabilitySearchOptions& s) {
  check_search(s);
  K3Point out;
  out.point.r = r;
  BoundaryResult& res = out.point.result;
  if (k2.status == BoundaryStatus::Error || k2.status == BoundaryStatus::AboveRange) {
    res = k2;  // k3 >= k2: undefined with k2, or also beyond the range
    res.samples.clear();
    res.evaluations = 0;
    return out;
  }
  const IcChoice ic{IcChoice::Set::Ic2};
  auto pred = [&](double k) { return overturns_while_upright_passages_below(WinklerParams{r, mu, k}, ic, 3, o); };
  // The scan starts at the edge of the excluded neighbourhood; for k2 below range, at k_lo.
  const double start = k2.status == BoundaryStatus::Found ? k2.hi * (1.0 + s.eps) : s.k_lo;
  if (start >= s.k_hi) {
    res.status = BoundaryStatus::AboveRange;
    res.lo = res.hi = res.value = s.k_hi;
    return out;
  }
  res = sup_all_below(pred, log_grid_per_decade(start, s.k_hi, s.per_decade), s.bisect);
  if (k2.status == BoundaryStatus::Found && res.status == BoundaryStatus::BelowRange) {
    // Fails right at the edge of the neighbourhood: k3 = k2 to within eps.
    out.coincides_with_k2 = true;
    res.status = BoundaryStatus::Found;
    res.lo = k2.lo;
    res.hi = k2.hi;
    res.value = k2.value;
  }
  return out;
}

BlowupPoint blowup_ratio(double mu, BlowupWhich which, double r_lo, double r_hi, double r_per_decade,
                         const BisectionOptions& r_bisect, const StudyRunOptions& o, const StabilitySearchOptions& s) {
  check_search(s);
  const IcChoice ic{IcChoice::Set::Ic2};
  const long n = which == BlowupWhich::R2 ? 2 : 3;
  // "Overturns while ihor < n regardless of k" (up to the cap k_hi). The cap is the likeliest
  // place to fail (stability grows with k), so it is tried first; the full search follows.
  auto always_overturns = [&](double r) {
    if (!overturns_while_upright_passages_below(WinklerParams{r, mu, s.k_hi}, ic, n, o)) return false;
    const CurvePoint k2 = k2_stability(r, mu, o, s);
    if (k2.result.status == BoundaryStatus::Error) throw std::runtime_error(k2.result.message);
    if (which == BlowupWhich::R2) return k2.result.status == BoundaryStatus::AboveRange;
    const K3Point k3 = k3_stability(r, mu, k2.result, o, s);
    if (k3.point.result.status == BoundaryStatus::Error) throw std::runtime_error(k3.point.result.message);
    return k3.point.result.status == BoundaryStatus::AboveRange;
  };
  BlowupPoint out;
  out.mu = mu;
  out.result = sup_all_below(always_overturns, log_grid_per_decade(r_lo, r_hi, r_per_decade), r_bisect);
  return out;
}

}  // namespace blockdyn
