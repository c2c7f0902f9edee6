// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/winkler/flight.hpp"

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/analysis/winkler/study_run.hpp"
#include "blockdyn/model/winkler/energy.hpp"

namespace blockdyn {

namespace {

// Options for runs that only need to know when the first take-off happens.
WinklerRunOptions first_flight_options(const StudyRunOptions& o) {
  WinklerRunOptions s = lean_study_options(o);
  s.stop_at_first_flight = true;
  return s;
}

// Stops the run as soon as w' turns positive: the end of the "while w' < 0" window of ic1
// (released from rest at w0 > 0, w' = 0 at t = 0 and negative right after). w' is sampled on
// the dense output so a sign change inside a step is caught before the step's end event.
class WNegativeWindow : public WinklerSink {
 public:
  void on_segment(const WinklerBlock&, const DenseSegment<kStateDim>& seg, double t0, double t1,
                  const WinklerMode&) override {
    if (closed_ || t1 <= t0) return;
    WinklerState z;
    constexpr int kSamples = 8;
    for (int i = 1; i <= kSamples && !closed_; ++i) {
      seg.eval(t0 + (t1 - t0) * i / kSamples, z);
      if (z[kVW] > 0.0) closed_ = true;
    }
  }
  bool keep_going() const override { return !closed_; }
  bool closed() const { return closed_; }

 private:
  bool closed_ = false;
};

}  // namespace

FirstFlight first_flight(const WinklerParams& p, const IcChoice& ic, const StudyRunOptions& o) {
  // Not run_checked: a failed run is one point of a scan, reported through its status.
  const WinklerResult res = simulate(p, {}, ic.state(p), first_flight_options(o));
  FirstFlight f;
  f.r = p.r;
  f.k = p.k;
  f.status = res.status;
  f.flew = res.first_flight_time.has_value();
  f.time = f.flew ? *res.first_flight_time : o.t_end;
  f.t_final = res.t_final;
  f.upright_passages = f.flew ? res.upright_passages_at_first_flight : res.upright_passages;
  return f;
}

std::vector<FirstFlight> first_flight_scan(const WinklerParams& base, const IcChoice& ic, const std::vector<double>& ks,
                                           const StudyRunOptions& o, int threads) {
  return parallel_map<FirstFlight>(ks.size(), threads, [&](std::size_t i) {
    WinklerParams p = base;
    p.k = ks[i];
    return first_flight(p, ic, o);
  });
}

std::vector<FirstFlight> first_flight_map(double mu, const IcChoice& ic, const std::vector<double>& rs,
                                          const std::vector<double>& ks, const StudyRunOptions& o, int threads) {
  const std::size_t nk = ks.size();
  return parallel_map<FirstFlight>(rs.size() * nk, threads, [&](std::size_t i) {
    return first_flight(WinklerParams{rs[i / nk], mu, ks[i % nk]}, ic, o);
  });
}

double initial_energy(const WinklerParams& p, const IcChoice& ic) { return energy(p, ic.state(p)).total(); }

BoundaryResult k_min(double r, double mu, const IcChoice& ic, double k_lo, double k_hi, double per_decade) {
  const std::vector<double> grid = log_grid_per_decade(k_lo, k_hi, per_decade);
  auto e0 = [&](double k) { return initial_energy(WinklerParams{r, mu, k}, ic); };
  BoundaryResult res;
  res.lo = k_lo;
  res.hi = k_hi;
  try {
    // Downward scan: the first grid point with E0 < 0 bounds the last sign change from below.
    std::size_t i = grid.size();
    bool negative = false;
    while (i-- > 0) {
      ++res.evaluations;
      const double e = e0(grid[i]);
      res.samples.push_back({grid[i], e >= 0});
      if (e < 0) {
        negative = true;
        break;
      }
    }
    if (!negative) {
      res.status = BoundaryStatus::BelowRange;
      res.value = k_lo;
      return res;
    }
    if (i == grid.size() - 1) {
      res.status = BoundaryStatus::AboveRange;
      res.value = k_hi;
      return res;
    }
    auto f = [&](double logk) {
      ++res.evaluations;
      return e0(std::exp(logk));
    };
    std::uintmax_t iters = 200;
    const auto sol = boost::math::tools::toms748_solve(f, std::log(grid[i]), std::log(grid[i + 1]),
                                                       boost::math::tools::eps_tolerance<double>(50), iters);
    res.status = BoundaryStatus::Found;
    res.lo = std::exp(sol.first);
    res.hi = std::exp(sol.second);
    res.value = std::exp(0.5 * (sol.first + sol.second));
  } catch (const std::exception& e) {
    res.status = BoundaryStatus::Error;
    res.message = e.what();
  }
  return res;
}

const char* to_string(FirstImpact c) { return c == FirstImpact::WNegative ? "w_negative" : "ihor2"; }

FirstImpact parse_first_impact(const std::string& s) {
  if (s == "w_negative") return FirstImpact::WNegative;
  if (s == "ihor2") return FirstImpact::UprightPassagesBelow2;
  throw std::invalid_argument("high-criterion = '" + s + "' is not one of: w_negative, ihor2");
}

FlightCheck no_flight_while_upright_passages_below(const WinklerParams& p, const IcChoice& ic, long n,
                                                   const StudyRunOptions& o) {
  if (n < 1) throw std::invalid_argument("n = " + std::to_string(n) + " is out of range: must be >= 1");
  WinklerRunOptions s = first_flight_options(o);
  s.stop_at_upright_passages = n;
  const WinklerResult res = run_checked(p, ic, s);
  FlightCheck c;
  const bool flew = res.first_flight_time && res.upright_passages_at_first_flight < n;
  c.holds = !flew;
  // Settled by a flight, by reaching ihor = n, or by the end of the motion (overturn).
  c.decided = flew || res.upright_passages >= n || res.status == SimStatus::Overturned;
  return c;
}

FlightCheck flies_during_first_impact(const WinklerParams& p, const IcChoice& ic, FirstImpact crit,
                                      const StudyRunOptions& o) {
  WinklerRunOptions s = first_flight_options(o);
  FlightCheck c;
  if (crit == FirstImpact::WNegative) {
    if (!ic.is_ic1())
      throw std::invalid_argument("high-criterion = w_negative applies to ic1 only (use ihor2 for " + ic.name() + ")");
    WNegativeWindow window;
    const WinklerResult res = run_checked(p, ic, s, &window);
    // A take-off ends the run before the window closes; a closed window stops it first.
    c.holds = res.first_flight_time.has_value() && !window.closed();
    c.decided = c.holds || window.closed() || res.status == SimStatus::Overturned;
    return c;
  }
  const long n = 2;
  s.stop_at_upright_passages = n;
  const WinklerResult res = run_checked(p, ic, s);
  c.holds = res.first_flight_time && res.upright_passages_at_first_flight < n;
  c.decided = c.holds || res.upright_passages >= n || res.status == SimStatus::Overturned;
  return c;
}

namespace {

template <class Check>
Predicate counting(Check check, int& undecided) {
  return [check, &undecided](double k) {
    const FlightCheck c = check(k);
    if (!c.decided) ++undecided;
    return c.holds;
  };
}

// The boundary in k at aspect ratio r: search (sup_all_below / inf_all_above) over the grid of s,
// then the fine scan next to it.
template <class Check, class Search, class Refine>
CurvePoint curve_point(double r, const BoundarySearchOptions& s, Check check, Search search, Refine refine,
                       double k_limit) {
  CurvePoint cp;
  cp.r = r;
  const auto grid = log_grid_per_decade(s.k_lo, s.k_hi, s.per_decade);
  const Predicate pred = counting(check, cp.undecided);
  cp.result = search(pred, grid, s.bisect);
  RefineOptions ro = s.refine;
  ro.anchor = s.k_lo;
  cp.result = refine(pred, std::move(cp.result), k_limit, ro, s.bisect);
  return cp;
}

}  // namespace

CurvePoint k_critical(double r, double mu, const IcChoice& ic, long n, const StudyRunOptions& o,
                      const BoundarySearchOptions& s) {
  auto check = [&](double k) { return no_flight_while_upright_passages_below(WinklerParams{r, mu, k}, ic, n, o); };
  return curve_point(r, s, check, sup_all_below, refine_sup_all_below, s.k_lo);
}

CurvePoint k_high(double r, double mu, const IcChoice& ic, FirstImpact c, const StudyRunOptions& o,
                  const BoundarySearchOptions& s) {
  auto check = [&](double k) { return flies_during_first_impact(WinklerParams{r, mu, k}, ic, c, o); };
  return curve_point(r, s, check, inf_all_above, refine_inf_all_above, s.k_hi);
}

}  // namespace blockdyn
