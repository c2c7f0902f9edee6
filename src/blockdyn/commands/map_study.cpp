// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/map_study.hpp"

#include "blockdyn/simulation/run_options.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/analysis/winkler/flight.hpp"
#include "blockdyn/analysis/winkler/ic_choice.hpp"
#include "blockdyn/analysis/winkler/stability.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/model/winkler/winkler_params.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

namespace {

struct MapBoundaryRow {
  double inv_r = 0, r = 0;
  CurvePoint stability, high, critical;
  std::optional<K3Point> k3;  // ic2 only: overturning before the third passage (docs/stability.md)
};

// Stability boundary (k1 for ic1, k2 for ic2), k_high and k_critical_n at one aspect ratio.
MapBoundaryRow boundary_row(double inv_r, double mu, const IcChoice& ic, long n, const StudyRunOptions& run,
                            double k_lo, double k_hi, double fine_per_decade) {
  MapBoundaryRow b;
  b.inv_r = inv_r;
  b.r = 1.0 / inv_r;
  StabilitySearchOptions ss;
  ss.k_lo = k_lo;
  ss.k_hi = k_hi;
  ss.per_decade = 4;
  ss.bisect.rel_tol = 1e-2;
  b.stability = ic.is_ic1() ? k1_stability(b.r, mu, ic, run, ss) : k2_stability(b.r, mu, run, ss);
  // ic2: k2 is where overturning on the first swing ends; the slender blocks above it can still
  // overturn on the second, up to k3 (the thesis's Fig 6.2 discussion).
  if (!ic.is_ic1()) b.k3 = k3_stability(b.r, mu, b.stability.result, run, ss);
  BoundarySearchOptions fs;
  fs.k_lo = k_lo;
  fs.k_hi = k_hi;
  fs.per_decade = 4;
  fs.bisect.rel_tol = 1e-2;
  fs.refine.per_decade = fine_per_decade;
  const FirstImpact fi = ic.is_ic1() ? FirstImpact::WNegative : FirstImpact::UprightPassagesBelow2;
  b.high = k_high(b.r, mu, ic, fi, run, fs);
  b.critical = k_critical(b.r, mu, ic, n, run, fs);
  return b;
}

// The map's grid as a sweep definition, after checking every option.
SweepSpec map_spec(const Settings& s) {
  s.require_known(map_options(), {"output"}, "map");
  const double mu = s.number("mu", 0.2), t_end = s.number("t-end", 30);
  require_in_range("mu", mu, 0.0, kWinklerMuMax);
  require_in_range("t-end", t_end, 0.0, kMaxTime, false);
  const long boundary_points = s.integer("boundary-points", 10), critical_n = s.integer("critical-n", 10);
  if (boundary_points < 0 || boundary_points > 1000)
    throw std::invalid_argument("boundary-points = " + std::to_string(boundary_points) +
                                " is out of range: must be in [0, 1000]");
  require_in_range("fine-per-decade", s.number("fine-per-decade", 48), 0.0, 1000);
  if (critical_n < 2)
    throw std::invalid_argument("critical-n = " + std::to_string(critical_n) + " is out of range: must be >= 2");
  const IcChoice ic = parse_ic_choice(s.text("ic", "ic1"));
  SweepSpec spec;
  spec.k = parse_axis("k", s.text("k", "1e1:1e8:40"), AxisSpacing::Log);
  spec.r = parse_axis("inv_r", s.text("inv-r", "1:20:30"), AxisSpacing::Linear);
  spec.mu = axis_list("mu", {mu});
  spec.initial.sets = {ic.is_ic1() ? "ic1" : "ic2"};
  if (ic.is_ic1()) spec.initial.w0_over_alpha = ic.w0_fraction;
  spec.options.t_end = t_end;
  apply_integrator_settings(s, spec.options.integrator);
  spec.options.integrator.max_steps = s.integer("max-steps", 20'000'000);
  spec.metrics = {"response_type"};
  if (s.flag("sensitivity")) spec.metrics.push_back("sensitive_dependence");
  spec.output = s.text("output", "map.csv");
  if (spec.output.empty()) throw std::invalid_argument("output: the CSV path is empty");
  validate(spec);
  return spec;
}

}  // namespace

const std::vector<StudyOption>& map_options() {
  static const std::vector<StudyOption> options = [] {
    const IntegratorOptions d;
    return std::vector<StudyOption>{
        {"k", "k axis: min:max:points[:log|:lin] or a list", "1e1:1e8:40"},
        {"inv-r", "1/r axis (height/width): min:max:points or a list", "1:20:30"},
        {"mu", "friction coefficient (>= 0)", "0.2"},
        {"ic", "initial conditions: ic1, ic1:F (w0 = F alpha) or ic2", "ic1"},
        {"t-end", "observation time of each run", "30"},
        {"rtol", rtol_help(), Settings::exact(d.rtol)},
        {"atol", atol_help(), Settings::exact(d.atol)},
        {"method", "Runge-Kutta pair: dopri5, dop853 or auto (dop853 when rtol < 1e-6; default)", "auto"},
        {"max-steps", "step cap per run (reported as numerical_failure)", "20000000"},
        {"boundary-points", "1/r values for the boundary curves (0: none)", "10"},
        {"fine-per-decade", "fine grid next to k_high and k_critical (points per decade; 0: coarse search only)", "48"},
        {"critical-n", "n of k_critical_n (no flight while ihor < n)", "10"},
        {"sensitivity", "also run every point from y'(0) + 1e-8 and mark sensitive dependence (twice the cost)", "",
         true},
        {"plot", "write the map figure (PNG; SVG beside it)"}};
  }();
  return options;
}

MapStudy map_study(const Settings& s) {
  MapStudy m;
  const SweepSpec spec = map_spec(s);
  m.table = std::make_shared<SweepEvaluator>(spec);
  m.plot = s.text("plot");
  m.title = "mu = " + cell_text(spec.mu.values.front()) + ", " + parse_ic_choice(s.text("ic", "ic1")).name();
  return m;
}

MapBoundaries map_boundaries(const Settings& s, int threads) {
  const SweepSpec spec = map_spec(s);
  const IcChoice ic = parse_ic_choice(s.text("ic", "ic1"));
  const double mu = spec.mu.values.front(), fine_per_decade = s.number("fine-per-decade", 48);
  const long critical_n = s.integer("critical-n", 10);
  // Boundary curves on a coarser set of 1/r values spanning the grid.
  const double ir_lo = spec.r.values.front(), ir_hi = spec.r.values.back();
  const double k_lo = std::fmin(spec.k.values.front(), spec.k.values.back());
  const double k_hi = std::fmax(spec.k.values.front(), spec.k.values.back());
  StudyRunOptions run;
  run.t_end = spec.options.t_end;
  run.integrator = spec.options.integrator;
  const long nb = s.integer("boundary-points", 10);
  const std::vector<MapBoundaryRow> rows = parallel_map<MapBoundaryRow>(std::size_t(nb), threads, [&](std::size_t i) {
    const double ir = nb == 1 ? ir_lo : ir_lo + (ir_hi - ir_lo) * double(i) / double(nb - 1);
    return boundary_row(ir, mu, ic, critical_n, run, k_lo, k_hi, fine_per_decade);
  });
  MapBoundaries out;
  StudyTable& t = out.table;
  t.columns = {"inv_r",         "r",          "k_stability",       "stability_status", "k_high",
               "k_high_status", "k_critical", "k_critical_status", "k3_stability",     "k3_status"};
  for (const auto& b : rows)
    t.rows.push_back({Cell::shortest(b.inv_r), Cell::shortest(b.r), Cell::shortest(boundary_cell(b.stability.result)),
                      to_string(b.stability.result.status), Cell::shortest(boundary_cell(b.high.result)),
                      to_string(b.high.result.status), Cell::shortest(boundary_cell(b.critical.result)),
                      to_string(b.critical.result.status),
                      b.k3 ? Cell::shortest(boundary_cell(b.k3->point.result)) : Cell::shortest(NAN),
                      b.k3 ? to_string(b.k3->point.result.status) : "not_applicable"});
  out.meta = {{"run", run_info()},
              {"what", "boundaries of the response map"},
              {"mu", mu},
              {"ic", ic.name()},
              {"stability_curve", ic.is_ic1() ? "k1_stability" : "k2_stability"},
              {"k3_curve", ic.is_ic1() ? "none (ic2 only)" : "k3_stability"},
              {"k_high_criterion", ic.is_ic1() ? "w_negative" : "ihor2"},
              {"k_critical_n", critical_n},
              {"fine_points_per_decade", fine_per_decade},
              {"k_range", {k_lo, k_hi}},
              {"run_options", run_options_json(run)}};
  return out;
}

std::string map_boundaries_path(const std::string& csv) {
  const std::string stem =
      (csv.size() > 4 && csv.substr(csv.size() - 4) == ".csv") ? csv.substr(0, csv.size() - 4) : csv;
  return stem + "_boundaries.csv";
}

}  // namespace blockdyn
