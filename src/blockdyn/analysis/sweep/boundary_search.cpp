// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/boundary_search.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace blockdyn {

const char* to_string(BoundaryStatus s) {
  switch (s) {
    case BoundaryStatus::Found: return "found";
    case BoundaryStatus::BelowRange: return "below_range";
    case BoundaryStatus::AboveRange: return "above_range";
    case BoundaryStatus::Error: return "error";
  }
  return "?";
}

std::vector<double> log_grid(double lo, double hi, int n) {
  if (!(lo > 0) || !(hi > lo) || !std::isfinite(hi) || n < 2)
    throw std::invalid_argument("log grid needs 0 < lo < hi (finite) and at least 2 points; got lo = " +
                                std::to_string(lo) + ", hi = " + std::to_string(hi) +
                                ", points = " + std::to_string(n));
  std::vector<double> g(n);
  const double a = std::log(lo), b = std::log(hi);
  for (int i = 0; i < n; ++i) g[i] = std::exp(a + (b - a) * i / (n - 1));
  g.front() = lo;  // exact ends: callers compare against them
  g.back() = hi;
  return g;
}

std::vector<double> log_grid_per_decade(double lo, double hi, double per_decade) {
  if (!(per_decade > 0) || !std::isfinite(per_decade))
    throw std::invalid_argument("points per decade must be > 0");
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

void bisect_into(Evaluator& ev, double lo, double hi, bool value_lo, const BisectionOptions& opt,
                 BoundaryResult& res) {
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

BoundaryResult bisect_log(const Predicate& pred, double lo, double hi, bool value_lo,
                          const BisectionOptions& opt) {
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

BoundaryResult sup_all_below(const Predicate& pred, const std::vector<double>& grid,
                             const BisectionOptions& opt) {
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

BoundaryResult inf_all_above(const Predicate& pred, const std::vector<double>& grid,
                             const BisectionOptions& opt) {
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

}  // namespace blockdyn
