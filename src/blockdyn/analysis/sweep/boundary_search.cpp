// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/boundary_search.hpp"

#include "blockdyn/base/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace blockdyn {

const char* to_string(BoundaryStatus s) {
  switch (s) {
    case BoundaryStatus::Found:
      return "found";
    case BoundaryStatus::BelowRange:
      return "below_range";
    case BoundaryStatus::AboveRange:
      return "above_range";
    case BoundaryStatus::Error:
      return "error";
  }
  return "?";
}

std::vector<double> log_grid(double lo, double hi, int n) {
  if (!(lo > 0) || !(hi > lo) || !std::isfinite(hi) || n < 2)
    throw std::invalid_argument("log grid needs 0 < lo < hi (finite) and at least 2 points; got lo = " +
                                number_text(lo) + ", hi = " + number_text(hi) + ", points = " + std::to_string(n));
  std::vector<double> g(n);
  const double a = std::log(lo), b = std::log(hi);
  for (int i = 0; i < n; ++i) g[i] = std::exp(a + (b - a) * i / (n - 1));
  g.front() = lo;  // exact ends: callers compare against them
  g.back() = hi;
  return g;
}

std::vector<double> log_grid_per_decade(double lo, double hi, double per_decade) {
  if (!(per_decade > 0) || !std::isfinite(per_decade)) throw std::invalid_argument("points per decade must be > 0");
  if (!(lo > 0) || !(hi > lo)) return log_grid(lo, hi, 2);  // reports the bad range
  const int n = std::max(2, int(std::ceil(std::log10(hi / lo) * per_decade)) + 1);
  return log_grid(lo, hi, n);
}

namespace {

// Evaluates the predicate and records the sample.
struct Evaluator {
  const Predicate& pred;
  BoundaryResult& res;
  bool operator()(double x) {
    const bool v = pred(x);
    ++res.evaluations;
    res.samples.push_back({x, v});
    return v;
  }
};

void bisect_into(Evaluator& ev, double lo, double hi, bool value_lo, const BisectionOptions& opt, BoundaryResult& res) {
  for (int it = 0; it < opt.max_iter && hi / lo - 1.0 > opt.rel_tol; ++it) {
    const double mid = std::sqrt(lo * hi);  // midpoint in log
    if (ev(mid) == value_lo)
      lo = mid;
    else
      hi = mid;
  }
  res.status = BoundaryStatus::Found;
  res.lo = lo;
  res.hi = hi;
  res.value = std::sqrt(lo * hi);
}

void check_grid(const std::vector<double>& grid) {
  if (grid.size() < 2) throw std::invalid_argument("boundary search needs a grid of at least 2 points");
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (!(grid[i] > 0) || !std::isfinite(grid[i]))
      throw std::invalid_argument("boundary search grid points must be finite and > 0");
    if (i > 0 && !(grid[i] > grid[i - 1]))
      throw std::invalid_argument("boundary search grid must be strictly ascending");
  }
}

// Runs `body`, turning an exception from the predicate into an Error result.
template <class F>
BoundaryResult guarded(const std::vector<double>& grid, F&& body) {
  BoundaryResult res;
  res.lo = grid.front();
  res.hi = grid.back();
  try {
    body(res);
  } catch (const std::exception& e) {
    res.status = BoundaryStatus::Error;
    res.message = e.what();
  }
  return res;
}

}  // namespace

BoundaryResult bisect_log(const Predicate& pred, double lo, double hi, bool value_lo, const BisectionOptions& opt) {
  if (!(lo > 0) || !(hi > lo)) throw std::invalid_argument("bisect_log needs 0 < lo < hi");
  return guarded({lo, hi}, [&](BoundaryResult& res) {
    Evaluator ev{pred, res};
    bisect_into(ev, lo, hi, value_lo, opt, res);
  });
}

BoundaryResult find_transition(const Predicate& pred, const std::vector<double>& grid, bool true_above,
                               const BisectionOptions& opt) {
  check_grid(grid);
  return guarded(grid, [&](BoundaryResult& res) {
    Evaluator ev{pred, res};
    const bool below = !true_above;  // value expected below the change
    if (ev(grid.front()) != below) {
      res.status = BoundaryStatus::BelowRange;
      res.value = grid.front();
      return;
    }
    if (ev(grid.back()) == below) {
      res.status = BoundaryStatus::AboveRange;
      res.value = grid.back();
      return;
    }
    // Monotone: binary search over grid indices keeps the invariant
    // pred(grid[i]) == below, pred(grid[j]) != below.
    std::size_t i = 0, j = grid.size() - 1;
    while (j - i > 1) {
      const std::size_t m = (i + j) / 2;
      if (ev(grid[m]) == below)
        i = m;
      else
        j = m;
    }
    bisect_into(ev, grid[i], grid[j], below, opt, res);
  });
}

BoundaryResult sup_all_below(const Predicate& pred, const std::vector<double>& grid, const BisectionOptions& opt) {
  check_grid(grid);
  return guarded(grid, [&](BoundaryResult& res) {
    Evaluator ev{pred, res};
    for (std::size_t i = 0; i < grid.size(); ++i) {
      if (ev(grid[i])) continue;
      if (i == 0) {
        res.status = BoundaryStatus::BelowRange;
        res.value = grid.front();
        return;
      }
      bisect_into(ev, grid[i - 1], grid[i], true, opt, res);
      return;
    }
    res.status = BoundaryStatus::AboveRange;
    res.value = grid.back();
  });
}

BoundaryResult inf_all_above(const Predicate& pred, const std::vector<double>& grid, const BisectionOptions& opt) {
  check_grid(grid);
  return guarded(grid, [&](BoundaryResult& res) {
    Evaluator ev{pred, res};
    for (std::size_t n = grid.size(), i = n; i-- > 0;) {
      if (ev(grid[i])) continue;
      if (i == n - 1) {
        res.status = BoundaryStatus::AboveRange;
        res.value = grid.back();
        return;
      }
      bisect_into(ev, grid[i], grid[i + 1], false, opt, res);
      return;
    }
    res.status = BoundaryStatus::BelowRange;
    res.value = grid.front();
  });
}

namespace {

// Fine grid points strictly inside (a, b), ascending, on the anchored grid.
std::vector<double> fine_points(double a, double b, const RefineOptions& ro) {
  std::vector<double> g;
  const double la = std::log10(a / ro.anchor) * ro.per_decade, lb = std::log10(b / ro.anchor) * ro.per_decade;
  for (double j = std::floor(la) + 1; j < lb; ++j) {
    const double x = ro.anchor * std::pow(10.0, j / ro.per_decade);
    if (x > a && x < b) g.push_back(x);
  }
  return g;
}

void check_refine(const RefineOptions& ro) {
  if (!(ro.per_decade > 0) || !std::isfinite(ro.per_decade) || !(ro.span_decades > 0) ||
      !std::isfinite(ro.span_decades) || !(ro.anchor > 0) || !std::isfinite(ro.anchor))
    throw std::invalid_argument("boundary refinement needs per_decade > 0, span_decades > 0 and anchor > 0");
}

}  // namespace

BoundaryResult refine_sup_all_below(const Predicate& pred, BoundaryResult res, double k_floor, const RefineOptions& ro,
                                    const BisectionOptions& opt) {
  if (!res.found() || ro.per_decade <= 0) return res;
  check_refine(ro);
  const double span = std::pow(10.0, ro.span_decades);
  try {
    Evaluator ev{pred, res};
    double checked = res.lo;  // every fine point in [checked, res.lo] holds, and res.lo holds
    for (;;) {
      double bottom = std::max(k_floor, res.lo / span);
      if (!(bottom < checked)) break;  // a whole window below the boundary holds
      // The scan runs upward from a point that holds; if the window's bottom fails, the
      // boundary is lower still: step down by windows until one holds.
      double top = checked;
      bool top_fails = false;
      while (!ev(bottom)) {
        if (bottom <= k_floor) {
          res.status = BoundaryStatus::BelowRange;
          res.value = res.lo = k_floor;
          return res;
        }
        top = bottom;
        top_fails = true;
        bottom = std::max(k_floor, bottom / span);
      }
      // Upward: the first failure is the lowest one on the fine grid.
      double last_hold = bottom;
      bool failed = false;
      for (double x : fine_points(bottom, top, ro)) {
        if (ev(x)) {
          last_hold = x;
          continue;
        }
        bisect_into(ev, last_hold, x, true, opt, res);
        failed = true;
        break;
      }
      if (!failed && top_fails) bisect_into(ev, last_hold, top, true, opt, res);
      checked = bottom;
    }
  } catch (const std::exception& e) {
    res.status = BoundaryStatus::Error;
    res.message = e.what();
  }
  return res;
}

BoundaryResult refine_inf_all_above(const Predicate& pred, BoundaryResult res, double k_ceiling,
                                    const RefineOptions& ro, const BisectionOptions& opt) {
  // inf { K : pred(k) for all k > K } = 1 / sup { Y : pred(1/y) for all y < Y }: mirror in log.
  if (!res.found() || ro.per_decade <= 0) return res;
  check_refine(ro);
  RefineOptions mo = ro;
  mo.anchor = 1.0 / ro.anchor;
  BoundaryResult m = res;
  m.lo = 1.0 / res.hi;
  m.hi = 1.0 / res.lo;
  m.value = 1.0 / res.value;
  m.samples.clear();
  m.evaluations = 0;
  const Predicate mirrored = [&pred](double y) { return pred(1.0 / y); };
  BoundaryResult out = refine_sup_all_below(mirrored, m, 1.0 / k_ceiling, mo, opt);
  BoundaryResult back = res;
  back.status = out.status == BoundaryStatus::BelowRange ? BoundaryStatus::AboveRange : out.status;
  back.message = out.message;
  back.evaluations += out.evaluations;
  for (const auto& smp : out.samples) back.samples.push_back({1.0 / smp.x, smp.value});
  if (out.found()) {
    back.lo = 1.0 / out.hi;
    back.hi = 1.0 / out.lo;
    back.value = std::sqrt(back.lo * back.hi);
  } else if (back.status == BoundaryStatus::AboveRange) {
    back.value = back.hi = k_ceiling;
  }
  return back;
}

}  // namespace blockdyn
