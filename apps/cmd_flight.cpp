// SPDX-License-Identifier: Apache-2.0
// Flight studies (thesis 4.2): `flight-time` (time to first flight vs k), `flight-boundary`
// (k_critical_n(r), k_high(r) and k_min(r)), `kmin` (energy lower bound), `flight-map`
// (time to first flight over (k, r)).
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "blockdyn/analysis/winkler/flight.hpp"
#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/io/json_io.hpp"
#include "bounds_common.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
namespace {

using namespace bounds;

constexpr double kRMax = 100, kMuMax = 10, kKMaxAllowed = kWinklerKMax;

json header(const std::string& command, const IcChoice& ic, double mu, const StudyRunOptions& run) {
  return {{"run_info", run_info()},
          {"command", command},
          {"ic", ic.name()},
          {"mu", mu},
          {"run_options", run_options_json(run)}};
}

void check_k_range(const std::string& lo_name, double lo, const std::string& hi_name, double hi) {
  require_range(lo_name, lo, kWinklerKMin, kKMaxAllowed);
  require_range(hi_name, hi, lo, kKMaxAllowed, false, true);
}

void check_r_range(double lo, double hi) {
  require_range("r-min", lo, kWinklerRMin, kRMax);
  require_range("r-max", hi, lo, kRMax, false, true);
}

void check_points(const std::string& name, int n, int lo = 2) { require_range(name, n, lo, 100000); }

// ------------------------------------------------------------------ flight-time

struct TimeFlags {
  BlockParams p{0.5, 0.2, 1e5};
  std::string ic = "ic1";
  double k_min = 1e3, k_max = 1e9;
  int points = 120;
  StudyRunOptions run;
  OutputFlags out;
};

void run_time(const TimeFlags& f) {
  require_range("r", f.p.r, kWinklerRMin, kRMax);
  require_range("mu", f.p.mu, 0.0, kMuMax);
  check_k_range("k-min", f.k_min, "k-max", f.k_max);
  check_points("points", f.points);
  check_run_options(f.run, f.out);
  const IcChoice ic = parse_ic(f.ic);
  const auto ks = log_grid(f.k_min, f.k_max, f.points);
  const auto runs = first_flight_scan(f.p, ic, ks, f.run, f.out.threads);

  Table t{{"k", "flew", "time", "ihor", "status", "t_final"}, {}};
  int flown = 0, failed = 0;
  double k_first = NAN, k_always = NAN;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto& x = runs[i];
    t.rows.push_back({num(x.k), x.flew ? "1" : "0", num(x.time), std::to_string(x.ihor), to_string(x.status),
                      num(x.t_final)});
    flown += x.flew;
    failed += x.status == SimStatus::NumericalFailure;
    if (x.flew && std::isnan(k_first)) k_first = x.k;
  }
  // Lowest grid k from which every larger grid k flies during the first impact (ihor < 2).
  for (std::size_t i = runs.size(); i-- > 0;) {
    if (!(runs[i].flew && runs[i].ihor < 2)) break;
    k_always = runs[i].k;
  }
  json meta = header("flight-time", ic, f.p.mu, f.run);
  meta["r"] = f.p.r;
  meta["k_range"] = {f.k_min, f.k_max};
  meta["points"] = f.points;
  meta["time_column"] = "first flight time; t_end when the block did not fly (also when it overturned first)";
  json summary = meta;
  summary["runs"] = runs.size();
  summary["flew"] = flown;
  summary["numerical_failures"] = failed;
  summary["lowest_k_with_flight"] = std::isnan(k_first) ? json(nullptr) : json(k_first);
  summary["grid_k_from_which_all_fly_while_ihor_below_2"] = std::isnan(k_always) ? json(nullptr) : json(k_always);
  finish(f.out, csv_target(f.out, "flight-time"), t, meta, "plot_flight.py", {"time"}, summary);
  if (f.out.json_out != "-")
    std::printf("%zu runs (%s, r = %g, mu = %g, t_end = %g): %d flew, %d failed; lowest k with flight: %s\n",
                runs.size(), ic.name().c_str(), f.p.r, f.p.mu, f.run.t_end, flown, failed,
                std::isnan(k_first) ? "none" : num(k_first).c_str());
}

void add_time(CLI::App& app) {
  auto f = std::make_shared<TimeFlags>();
  CLI::App* s = app.add_subcommand("flight-time", "time (and ihor) at first flight versus k for fixed r, mu (thesis Figs 4.6-4.13)");
  s->add_option("--r", f->p.r, "aspect ratio (> 0)")->capture_default_str();
  s->add_option("--mu", f->p.mu, "friction coefficient (>= 0)")->capture_default_str();
  s->add_option("--ic", f->ic, "initial conditions: ic1, ic2, ic1:F (w0 = F alpha)")->capture_default_str();
  s->add_option("--k-min", f->k_min, "lowest k (log grid)")->capture_default_str();
  s->add_option("--k-max", f->k_max, "highest k")->capture_default_str();
  s->add_option("--points", f->points, "number of k values")->capture_default_str();
  add_run_options(*s, f->run, 30);
  add_output_options(*s, f->out);
  s->callback([f] { run_time(*f); });
}

// ------------------------------------------------------------------ flight-boundary

struct BoundaryFlags {
  std::string ic = "ic1";
  double mu = 0.2, r_min = 0.05, r_max = 1;
  int points = 12;
  std::string n_list = "2,10";
  std::string high = "";  // default depends on the ic
  BoundarySearchOptions search = [] {
    BoundarySearchOptions o;
    o.refine.per_decade = 48;  // smooth curves (docs/flight.md); 0 restores the coarse search
    return o;
  }();
  StudyRunOptions run;
  OutputFlags out;
};

// The first-impact criteria of k_high (--high-criterion; default both for ic1, else ihor2).
std::vector<FirstImpact> high_criteria(const std::string& flag, const IcChoice& ic) {
  const std::string high = flag.empty() ? (ic.is_ic1() ? "both" : "ihor2") : flag;
  if (high == "both") {
    if (!ic.is_ic1()) throw UsageError("high-criterion = both needs ic1 (w_negative applies to ic1 only)");
    return {FirstImpact::WNegative, FirstImpact::IhorBelow2};
  }
  if (high == "w_negative" || high == "ihor2") {
    const FirstImpact c = parse_first_impact(high);
    if (c == FirstImpact::WNegative && !ic.is_ic1())
      throw UsageError("high-criterion = w_negative applies to ic1 only; use ihor2 for " + ic.name());
    return {c};
  }
  if (high != "none") throw UsageError("high-criterion = '" + high + "' is not one of: w_negative, ihor2, both, none");
  return {};
}

struct BoundaryRow {
  BoundaryResult kmin;
  std::vector<CurvePoint> crit, hi;
};

void print_boundaries(const std::vector<double>& rs, const std::vector<BoundaryRow>& rows, const std::vector<long>& ns,
                      const std::vector<FirstImpact>& crits) {
  std::printf("%-10s %-14s", "r", "k_min");
  for (long n : ns) std::printf(" %-14s", ("k_crit_" + std::to_string(n)).c_str());
  for (auto c : crits) std::printf(" %-14s", (std::string("k_high_") + to_string(c)).c_str());
  std::printf("\n");
  auto show = [](const BoundaryResult& b) {
    std::printf(" %-14s", b.found() ? num(b.value).substr(0, 12).c_str() : to_string(b.status));
  };
  for (std::size_t i = 0; i < rs.size(); ++i) {
    std::printf("%-10.4g", rs[i]);
    show(rows[i].kmin);
    for (const auto& c : rows[i].crit) show(c.result);
    for (const auto& c : rows[i].hi) show(c.result);
    std::printf("\n");
  }
}

void run_boundary(const BoundaryFlags& f) {
  require_range("mu", f.mu, 0.0, kMuMax);
  check_r_range(f.r_min, f.r_max);
  check_points("points", f.points, 1);
  check_k_range("k-lo", f.search.k_lo, "k-hi", f.search.k_hi);
  require_range("per-decade", f.search.per_decade, 0.5, 1000);
  require_range("rel-tol", f.search.bisect.rel_tol, 1e-12, 1, false, false);
  require_range("fine-per-decade", f.search.refine.per_decade, 0.0, 1000);
  require_range("fine-span", f.search.refine.span_decades, 0.0, 10, false);
  check_run_options(f.run, f.out);
  const IcChoice ic = parse_ic(f.ic);
  std::vector<long> ns;
  for (double n : parse_list("n", f.n_list)) {
    require_range("n", n, 1, 1e6);
    if (n != std::floor(n)) throw UsageError("n = " + num(n) + " must be an integer >= 1");
    ns.push_back(long(n));
  }
  const std::vector<FirstImpact> crits = high_criteria(f.high, ic);
  const auto rs = f.points == 1 ? std::vector<double>{f.r_min} : log_grid(f.r_min, f.r_max, f.points);

  const auto rows = parallel_map<BoundaryRow>(rs.size(), f.out.threads, [&](std::size_t i) {
    BoundaryRow row;
    row.kmin = k_min(rs[i], f.mu, ic);
    for (long n : ns) row.crit.push_back(k_critical(rs[i], f.mu, ic, n, f.run, f.search));
    for (auto c : crits) row.hi.push_back(k_high(rs[i], f.mu, ic, c, f.run, f.search));
    return row;
  });

  Table t;
  t.columns = {"r", "k_min"};
  for (long n : ns) t.columns.push_back("k_critical_" + std::to_string(n));
  for (auto c : crits) t.columns.push_back(std::string("k_high_") + to_string(c));
  for (long n : ns) t.columns.push_back("k_critical_" + std::to_string(n) + "_status");
  for (auto c : crits) t.columns.push_back(std::string("k_high_") + to_string(c) + "_status");
  json points = json::array();
  for (std::size_t i = 0; i < rs.size(); ++i) {
    const BoundaryRow& row = rows[i];
    std::vector<std::string> cells{num(rs[i]), num(cell(row.kmin))};
    for (const auto& c : row.crit) cells.push_back(num(cell(c.result)));
    for (const auto& c : row.hi) cells.push_back(num(cell(c.result)));
    for (const auto& c : row.crit) cells.push_back(to_string(c.result.status));
    for (const auto& c : row.hi) cells.push_back(to_string(c.result.status));
    t.rows.push_back(cells);
    json p = {{"r", rs[i]}, {"k_min", boundary_json(row.kmin)}};
    for (std::size_t j = 0; j < ns.size(); ++j) {
      json b = boundary_json(row.crit[j].result, true);
      b["undecided_runs"] = row.crit[j].undecided;
      p["k_critical_" + std::to_string(ns[j])] = b;
    }
    for (std::size_t j = 0; j < crits.size(); ++j) {
      json b = boundary_json(row.hi[j].result, true);
      b["undecided_runs"] = row.hi[j].undecided;
      p[std::string("k_high_") + to_string(crits[j])] = b;
      // The thesis's observation k_high ~ 10 k_critical.
      for (std::size_t m = 0; m < ns.size(); ++m)
        if (row.hi[j].result.found() && row.crit[m].result.found())
          p[std::string("ratio_k_high_") + to_string(crits[j]) + "_to_k_critical_" + std::to_string(ns[m])] =
              row.hi[j].result.value / row.crit[m].result.value;
    }
    points.push_back(p);
  }
  json meta = header("flight-boundary", ic, f.mu, f.run);
  meta["r_range"] = {f.r_min, f.r_max};
  meta["search"] = {{"k_range", {f.search.k_lo, f.search.k_hi}},
                    {"points_per_decade", f.search.per_decade},
                    {"bisection_rel_tol", f.search.bisect.rel_tol},
                    {"fine_points_per_decade", f.search.refine.per_decade},
                    {"fine_span_decades", f.search.refine.span_decades},
                    {"definitions",
                     "k_critical_n = sup K: no flight while ihor < n for all k < K; k_high = inf K: flight "
                     "during the first impact for all k > K; coarse log grid + bisection, then a fine grid "
                     "(anchored at k_lo) over fine_span_decades on the holding side, repeated until clean"}};
  json summary = meta;
  summary["points"] = points;
  finish(f.out, csv_target(f.out, "flight-boundary"), t, meta, "plot_flight.py", {"boundary"}, summary);
  if (f.out.json_out != "-") print_boundaries(rs, rows, ns, crits);
}

void add_boundary(CLI::App& app) {
  auto f = std::make_shared<BoundaryFlags>();
  f->run.t_end = 100;
  CLI::App* s = app.add_subcommand("flight-boundary",
                                   "critical flight curves k_critical_n(r), k_high(r) with k_min(r) (Figs 4.14-4.19)");
  s->add_option("--ic", f->ic, "initial conditions: ic1, ic2, ic1:F")->capture_default_str();
  s->add_option("--mu", f->mu, "friction coefficient (>= 0)")->capture_default_str();
  s->add_option("--r-min", f->r_min, "lowest aspect ratio (log grid)")->capture_default_str();
  s->add_option("--r-max", f->r_max, "highest aspect ratio")->capture_default_str();
  s->add_option("--points", f->points, "number of r values")->capture_default_str();
  s->add_option("--n", f->n_list, "k_critical_n for these n (comma-separated)")->capture_default_str();
  s->add_option("--high-criterion", f->high,
                "k_high 'first impact' criterion: w_negative (ic1), ihor2, both (ic1), none; default both "
                "for ic1, ihor2 for ic2");
  s->add_option("--k-lo", f->search.k_lo, "lowest k searched")->capture_default_str();
  s->add_option("--k-hi", f->search.k_hi, "highest k searched")->capture_default_str();
  s->add_option("--per-decade", f->search.per_decade, "coarse grid points per decade of k")->capture_default_str();
  s->add_option("--rel-tol", f->search.bisect.rel_tol, "relative tolerance of the bisection in k")->capture_default_str();
  s->add_option("--fine-per-decade", f->search.refine.per_decade,
                "fine grid points per decade scanned next to each boundary (0: coarse search only)")
      ->capture_default_str();
  s->add_option("--fine-span", f->search.refine.span_decades,
                "decades of k next to the boundary that the fine grid must find clean")
      ->capture_default_str();
  add_run_options(*s, f->run, 100);
  add_output_options(*s, f->out);
  s->callback([f] { run_boundary(*f); });
}

// ------------------------------------------------------------------ kmin

struct KMinFlags {
  std::string ics = "ic1,ic1:0.25,ic1:0.125,ic2";
  double mu = 0.2, r_min = 0.02, r_max = 1, k_lo = 1, k_hi = 1e12;
  int points = 60;
  OutputFlags out;
};

void run_kmin(const KMinFlags& f) {
  require_range("mu", f.mu, 0.0, kMuMax);
  check_r_range(f.r_min, f.r_max);
  check_points("points", f.points, 1);
  check_k_range("k-lo", f.k_lo, "k-hi", f.k_hi);
  require_range("threads", f.out.threads, 0, 1024);
  StudyRunOptions none;
  check_run_options(none, f.out);
  std::vector<IcChoice> ics;
  std::stringstream ss(f.ics);
  for (std::string item; std::getline(ss, item, ',');) ics.push_back(parse_ic(item));
  if (ics.empty()) throw UsageError("ic must list at least one initial-condition set");
  const auto rs = f.points == 1 ? std::vector<double>{f.r_min} : log_grid(f.r_min, f.r_max, f.points);
  const auto res = parallel_map<std::vector<BoundaryResult>>(rs.size(), f.out.threads, [&](std::size_t i) {
    std::vector<BoundaryResult> v;
    for (const auto& ic : ics) v.push_back(k_min(rs[i], f.mu, ic, f.k_lo, f.k_hi));
    return v;
  });
  Table t;
  t.columns = {"r"};
  for (const auto& ic : ics) t.columns.push_back("k_min_" + ic.name());
  json curves = json::object();
  for (std::size_t j = 0; j < ics.size(); ++j) curves[ics[j].name()] = json::array();
  for (std::size_t i = 0; i < rs.size(); ++i) {
    std::vector<std::string> row{num(rs[i])};
    for (std::size_t j = 0; j < ics.size(); ++j) {
      row.push_back(num(cell(res[i][j])));
      json b = boundary_json(res[i][j]);
      b["r"] = rs[i];
      curves[ics[j].name()].push_back(b);
    }
    t.rows.push_back(row);
  }
  json meta = {{"run_info", run_info()},
               {"command", "kmin"},
               {"mu", f.mu},
               {"ics", f.ics},
               {"r_range", {f.r_min, f.r_max}},
               {"k_search_range", {f.k_lo, f.k_hi}},
               {"definition", "k_min(r) = inf K: E0(k) >= 0 for all k > K (E = 0: least energy in flight); "
                              "E0 = 0 solved by TOMS 748 in log k"}};
  json summary = meta;
  summary["curves"] = curves;
  finish(f.out, csv_target(f.out, "kmin"), t, meta, "plot_flight.py", {"kmin"}, summary);
  if (f.out.json_out != "-") {
    for (const auto& c : t.columns) std::printf("%-20s", c.c_str());
    std::printf("\n");
    for (const auto& row : t.rows) {
      for (const auto& c : row) std::printf("%-20.8g", std::strtod(c.c_str(), nullptr));
      std::printf("\n");
    }
  }
}

void add_kmin(CLI::App& app) {
  auto f = std::make_shared<KMinFlags>();
  CLI::App* s = app.add_subcommand("kmin", "energy lower bound k_min(r) of the flight region (E0 = 0, Fig 4.5)");
  s->add_option("--ic", f->ics, "comma-separated sets: ic1, ic2, ic1:F (w0 = F alpha)")->capture_default_str();
  s->add_option("--mu", f->mu, "friction coefficient (>= 0)")->capture_default_str();
  s->add_option("--r-min", f->r_min, "lowest aspect ratio (log grid)")->capture_default_str();
  s->add_option("--r-max", f->r_max, "highest aspect ratio")->capture_default_str();
  s->add_option("--points", f->points, "number of r values")->capture_default_str();
  s->add_option("--k-lo", f->k_lo, "lowest k searched for the root")->capture_default_str();
  s->add_option("--k-hi", f->k_hi, "highest k searched")->capture_default_str();
  add_output_options(*s, f->out);
  s->callback([f] { run_kmin(*f); });
}

// ------------------------------------------------------------------ flight-map

struct MapFlags {
  std::string ic = "ic1";
  double mu = 0.2, r_min = 0.05, r_max = 1, k_min = 1e2, k_max = 1e10;
  int r_points = 24, k_points = 48;
  StudyRunOptions run;
  OutputFlags out;
};

void run_map(const MapFlags& f) {
  require_range("mu", f.mu, 0.0, kMuMax);
  check_r_range(f.r_min, f.r_max);
  check_k_range("k-min", f.k_min, "k-max", f.k_max);
  check_points("r-points", f.r_points);
  check_points("k-points", f.k_points);
  check_run_options(f.run, f.out);
  const IcChoice ic = parse_ic(f.ic);
  const auto rs = log_grid(f.r_min, f.r_max, f.r_points);
  const auto ks = log_grid(f.k_min, f.k_max, f.k_points);
  const auto cells = first_flight_map(f.mu, ic, rs, ks, f.run, f.out.threads);
  Table t{{"r", "k", "flew", "time", "ihor", "status", "t_final"}, {}};
  int flown = 0, failed = 0;
  for (const auto& c : cells) {
    t.rows.push_back({num(c.r), num(c.k), c.flew ? "1" : "0", num(c.time), std::to_string(c.ihor),
                      to_string(c.status), num(c.t_final)});
    flown += c.flew;
    failed += c.status == SimStatus::NumericalFailure;
  }
  json meta = header("flight-map", ic, f.mu, f.run);
  meta["r_grid"] = {{"min", f.r_min}, {"max", f.r_max}, {"points", f.r_points}, {"spacing", "log"}};
  meta["k_grid"] = {{"min", f.k_min}, {"max", f.k_max}, {"points", f.k_points}, {"spacing", "log"}};
  meta["time_column"] = "first flight time; t_end when the block did not fly (also when it overturned first)";
  json summary = meta;
  summary["cells"] = cells.size();
  summary["flew"] = flown;
  summary["numerical_failures"] = failed;
  finish(f.out, csv_target(f.out, "flight-map"), t, meta, "plot_flight.py", {"map"}, summary);
  if (f.out.json_out != "-")
    std::printf("%zu cells (%s, mu = %g, t_end = %g): %d flew, %d failed\n", cells.size(), ic.name().c_str(), f.mu,
                f.run.t_end, flown, failed);
}

void add_map(CLI::App& app) {
  auto f = std::make_shared<MapFlags>();
  CLI::App* s = app.add_subcommand("flight-map", "time to first flight over the (k, r) plane (Fig 4.20)");
  s->add_option("--ic", f->ic, "initial conditions: ic1, ic2, ic1:F")->capture_default_str();
  s->add_option("--mu", f->mu, "friction coefficient (>= 0)")->capture_default_str();
  s->add_option("--r-min", f->r_min, "lowest aspect ratio (log grid)")->capture_default_str();
  s->add_option("--r-max", f->r_max, "highest aspect ratio")->capture_default_str();
  s->add_option("--r-points", f->r_points, "number of r values")->capture_default_str();
  s->add_option("--k-min", f->k_min, "lowest k (log grid)")->capture_default_str();
  s->add_option("--k-max", f->k_max, "highest k")->capture_default_str();
  s->add_option("--k-points", f->k_points, "number of k values")->capture_default_str();
  add_run_options(*s, f->run, 30);
  add_output_options(*s, f->out);
  s->callback([f] { run_map(*f); });
}

RegisterCommand reg_time(30, add_time);
RegisterCommand reg_boundary(31, add_boundary);
RegisterCommand reg_kmin(32, add_kmin);
RegisterCommand reg_map(33, add_map);

}  // namespace
}  // namespace blockdyn::cli
