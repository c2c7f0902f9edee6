// SPDX-License-Identifier: Apache-2.0
// Flight studies of the block on the Winkler foundation (thesis 4.2): `flight-time` (time to first
// flight versus k), `flight-boundary` (k_critical_n(r), k_high(r) and k_min(r)), `kmin` (the energy
// lower bound), `flight-map` (time to first flight over (k, r)).
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/analysis/winkler/flight.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/study_command.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

constexpr double kRMax = 100, kMuMax = 10, kKMaxAllowed = kWinklerKMax;

json header(const std::string& command, const IcChoice& ic, double mu, const StudyRunOptions& run) {
  return {{"run_info", run_info()},
          {"command", command},
          {"ic", ic.name()},
          {"mu", mu},
          {"run_options", run_options_json(run)}};
}

void check_k_range(const std::string& lo_name, double lo, const std::string& hi_name, double hi) {
  require_in_range(lo_name, lo, kWinklerKMin, kKMaxAllowed);
  require_in_range(hi_name, hi, lo, kKMaxAllowed, false, true);
}

void check_r_range(double lo, double hi) {
  require_in_range("r-min", lo, kWinklerRMin, kRMax);
  require_in_range("r-max", hi, lo, kRMax, false, true);
}

int checked_points(const StudyOptions& o, const std::string& name, int lo = 2) {
  const long n = o.integer(name);
  require_in_range(name, double(n), lo, 100000);
  return int(n);
}

std::vector<double> r_grid(double lo, double hi, int points) {
  return points == 1 ? std::vector<double>{lo} : log_grid(lo, hi, points);
}

std::string null_or(double v) { return std::isnan(v) ? "none" : cell_text(v); }
json json_or_null(double v) { return std::isnan(v) ? json(nullptr) : json(v); }

const char* const kTimeColumn = "first flight time; t_end when the block did not fly (also when it overturned first)";

// ------------------------------------------------------------------ flight-time

std::vector<StudyOption> flight_time_options() {
  return with_run_options({{"r", "aspect ratio (> 0)", "0.5"},
                           {"mu", "friction coefficient (>= 0)", "0.2"},
                           {"ic", "initial conditions: ic1, ic2, ic1:F (w0 = F alpha)", "ic1"},
                           {"k-min", "lowest k (log grid)", "1000"},
                           {"k-max", "highest k", "1e9"},
                           {"points", "number of k values", "120"}},
                          "30");
}

StudyReport flight_time(const Settings& given, const StudyRequest&) {
  const StudyOptions o(given, flight_time_options());
  WinklerParams p{o.number("r"), o.number("mu"), 1e5};
  require_in_range("r", p.r, kWinklerRMin, kRMax);
  require_in_range("mu", p.mu, 0.0, kMuMax);
  const double k_min = o.number("k-min"), k_max = o.number("k-max");
  check_k_range("k-min", k_min, "k-max", k_max);
  const int points = checked_points(o, "points");
  const StudyRunOptions run = o.run_options();
  const int threads = o.threads();
  const IcChoice ic = parse_ic_choice(o.text("ic"));
  const auto runs = first_flight_scan(p, ic, log_grid(k_min, k_max, points), run, threads);

  StudyReport r;
  r.table.columns = {"k", "flew", "time", "ihor", "status", "t_final"};
  int flown = 0, failed = 0;
  double k_first = NAN, k_always = NAN;
  for (const auto& x : runs) {
    r.table.rows.push_back({Cell::shortest(x.k), Cell(x.flew ? 1 : 0), Cell::shortest(x.time), Cell(x.upright_passages),
                            to_string(x.status), Cell::shortest(x.t_final)});
    flown += x.flew;
    failed += x.status == SimStatus::NumericalFailure;
    if (x.flew && std::isnan(k_first)) k_first = x.k;
  }
  // Lowest grid k from which every larger grid k flies during the first impact (ihor < 2).
  for (std::size_t i = runs.size(); i-- > 0;) {
    if (!(runs[i].flew && runs[i].upright_passages < 2)) break;
    k_always = runs[i].k;
  }
  json meta = header("flight-time", ic, p.mu, run);
  meta["r"] = p.r;
  meta["k_range"] = {k_min, k_max};
  meta["points"] = points;
  meta["time_column"] = kTimeColumn;
  r.sidecar = meta;
  r.summary = meta;
  r.summary["runs"] = runs.size();
  r.summary["flew"] = flown;
  r.summary["numerical_failures"] = failed;
  r.summary["lowest_k_with_flight"] = json_or_null(k_first);
  r.summary["grid_k_from_which_all_fly_while_ihor_below_2"] = json_or_null(k_always);
  append_text(r.text, "%zu runs (%s, r = %g, mu = %g, t_end = %g): %d flew, %d failed; lowest k with flight: %s\n",
              runs.size(), ic.name().c_str(), p.r, p.mu, run.t_end, flown, failed, null_or(k_first).c_str());
  r.figure = FigureSpec{"flight", {"time"}, {}};
  return r;
}

// ------------------------------------------------------------------ flight-boundary

std::vector<StudyOption> flight_boundary_options() {
  return with_run_options(
      {{"ic", "initial conditions: ic1, ic2, ic1:F", "ic1"},
       {"mu", "friction coefficient (>= 0)", "0.2"},
       {"r-min", "lowest aspect ratio (log grid)", "0.05"},
       {"r-max", "highest aspect ratio", "1"},
       {"points", "number of r values", "12"},
       {"n", "k_critical_n for these n (comma-separated)", "2,10"},
       {"high-criterion",
        "k_high 'first impact' criterion: w_negative (ic1), ihor2, both (ic1), none; default both for ic1, ihor2 "
        "for ic2",
        ""},
       {"k-lo", "lowest k searched", Settings::exact(BoundarySearchOptions{}.k_lo)},
       {"k-hi", "highest k searched", Settings::exact(BoundarySearchOptions{}.k_hi)},
       {"per-decade", "coarse grid points per decade of k", Settings::exact(BoundarySearchOptions{}.per_decade)},
       {"rel-tol", "relative tolerance of the bisection in k", Settings::exact(BoundarySearchOptions{}.bisect.rel_tol)},
       // Smooth curves (docs/flight.md); 0 restores the coarse search.
       {"fine-per-decade", "fine grid points per decade scanned next to each boundary (0: coarse search only)", "48"},
       {"fine-span", "decades of k next to the boundary that the fine grid must find clean",
        Settings::exact(BoundarySearchOptions{}.refine.span_decades)}},
      "100");
}

// The first-impact criteria of k_high (--high-criterion; default both for ic1, else ihor2).
std::vector<FirstImpact> high_criteria(const std::string& flag, const IcChoice& ic) {
  const std::string high = flag.empty() ? (ic.is_ic1() ? "both" : "ihor2") : flag;
  if (high == "both") {
    if (!ic.is_ic1()) throw std::invalid_argument("high-criterion = both needs ic1 (w_negative applies to ic1 only)");
    return {FirstImpact::WNegative, FirstImpact::UprightPassagesBelow2};
  }
  if (high == "w_negative" || high == "ihor2") {
    const FirstImpact c = parse_first_impact(high);
    if (c == FirstImpact::WNegative && !ic.is_ic1())
      throw std::invalid_argument("high-criterion = w_negative applies to ic1 only; use ihor2 for " + ic.name());
    return {c};
  }
  if (high != "none")
    throw std::invalid_argument("high-criterion = '" + high + "' is not one of: w_negative, ihor2, both, none");
  return {};
}

struct BoundaryRow {
  BoundaryResult kmin;
  std::vector<CurvePoint> crit, hi;
};

struct BoundaryStudy {
  IcChoice ic;
  double mu, r_min, r_max;
  int points;
  std::vector<long> ns;
  std::vector<FirstImpact> crits;
  BoundarySearchOptions search;
  StudyRunOptions run;
  int threads;
};

BoundaryStudy boundary_study(const Settings& given) {
  const StudyOptions o(given, flight_boundary_options());
  BoundaryStudy b;
  b.mu = o.number("mu");
  b.r_min = o.number("r-min");
  b.r_max = o.number("r-max");
  require_in_range("mu", b.mu, 0.0, kMuMax);
  check_r_range(b.r_min, b.r_max);
  b.points = checked_points(o, "points", 1);
  b.search.k_lo = o.number("k-lo");
  b.search.k_hi = o.number("k-hi");
  b.search.per_decade = o.number("per-decade");
  b.search.bisect.rel_tol = o.number("rel-tol");
  b.search.refine.per_decade = o.number("fine-per-decade");
  b.search.refine.span_decades = o.number("fine-span");
  check_k_range("k-lo", b.search.k_lo, "k-hi", b.search.k_hi);
  require_in_range("per-decade", b.search.per_decade, 0.5, 1000);
  require_in_range("rel-tol", b.search.bisect.rel_tol, 1e-12, 1, false, false);
  require_in_range("fine-per-decade", b.search.refine.per_decade, 0.0, 1000);
  require_in_range("fine-span", b.search.refine.span_decades, 0.0, 10, false);
  b.run = o.run_options();
  b.threads = o.threads();
  b.ic = parse_ic_choice(o.text("ic"));
  for (double n : parse_number_list("n", o.text("n"))) {
    require_in_range("n", n, 1, 1e6);
    if (n != std::floor(n)) throw std::invalid_argument("n = " + cell_text(n) + " must be an integer >= 1");
    b.ns.push_back(long(n));
  }
  b.crits = high_criteria(o.text("high-criterion"), b.ic);
  return b;
}

std::string boundary_text(const std::vector<double>& rs, const std::vector<BoundaryRow>& rows,
                          const std::vector<long>& ns, const std::vector<FirstImpact>& crits) {
  std::string t;
  append_text(t, "%-10s %-14s", "r", "k_min");
  for (long n : ns) append_text(t, " %-14s", ("k_crit_" + std::to_string(n)).c_str());
  for (auto c : crits) append_text(t, " %-14s", (std::string("k_high_") + to_string(c)).c_str());
  t += "\n";
  auto show = [&t](const BoundaryResult& b) {
    append_text(t, " %-14s", b.found() ? cell_text(b.value).substr(0, 12).c_str() : to_string(b.status));
  };
  for (std::size_t i = 0; i < rs.size(); ++i) {
    append_text(t, "%-10.4g", rs[i]);
    show(rows[i].kmin);
    for (const auto& c : rows[i].crit) show(c.result);
    for (const auto& c : rows[i].hi) show(c.result);
    t += "\n";
  }
  return t;
}

json boundary_point(double r, const BoundaryRow& row, const BoundaryStudy& b) {
  json p = {{"r", r}, {"k_min", boundary_json(row.kmin)}};
  for (std::size_t j = 0; j < b.ns.size(); ++j) {
    json x = boundary_json(row.crit[j].result, true);
    x["undecided_runs"] = row.crit[j].undecided;
    p["k_critical_" + std::to_string(b.ns[j])] = x;
  }
  for (std::size_t j = 0; j < b.crits.size(); ++j) {
    json x = boundary_json(row.hi[j].result, true);
    x["undecided_runs"] = row.hi[j].undecided;
    p[std::string("k_high_") + to_string(b.crits[j])] = x;
    // The thesis's observation k_high ~ 10 k_critical.
    for (std::size_t m = 0; m < b.ns.size(); ++m)
      if (row.hi[j].result.found() && row.crit[m].result.found())
        p[std::string("ratio_k_high_") + to_string(b.crits[j]) + "_to_k_critical_" + std::to_string(b.ns[m])] =
            row.hi[j].result.value / row.crit[m].result.value;
  }
  return p;
}

StudyTable boundary_table(const std::vector<double>& rs, const std::vector<BoundaryRow>& rows, const BoundaryStudy& b) {
  StudyTable t;
  t.columns = {"r", "k_min"};
  for (long n : b.ns) t.columns.push_back("k_critical_" + std::to_string(n));
  for (auto c : b.crits) t.columns.push_back(std::string("k_high_") + to_string(c));
  for (long n : b.ns) t.columns.push_back("k_critical_" + std::to_string(n) + "_status");
  for (auto c : b.crits) t.columns.push_back(std::string("k_high_") + to_string(c) + "_status");
  for (std::size_t i = 0; i < rs.size(); ++i) {
    const BoundaryRow& row = rows[i];
    CellRow cells{Cell::shortest(rs[i]), Cell::shortest(boundary_cell(row.kmin))};
    for (const auto& c : row.crit) cells.push_back(Cell::shortest(boundary_cell(c.result)));
    for (const auto& c : row.hi) cells.push_back(Cell::shortest(boundary_cell(c.result)));
    for (const auto& c : row.crit) cells.push_back(to_string(c.result.status));
    for (const auto& c : row.hi) cells.push_back(to_string(c.result.status));
    t.rows.push_back(cells);
  }
  return t;
}

StudyReport flight_boundary(const Settings& given, const StudyRequest&) {
  const BoundaryStudy b = boundary_study(given);
  const auto rs = r_grid(b.r_min, b.r_max, b.points);
  const auto rows = parallel_map<BoundaryRow>(rs.size(), b.threads, [&](std::size_t i) {
    BoundaryRow row;
    row.kmin = k_min(rs[i], b.mu, b.ic);
    for (long n : b.ns) row.crit.push_back(k_critical(rs[i], b.mu, b.ic, n, b.run, b.search));
    for (auto c : b.crits) row.hi.push_back(k_high(rs[i], b.mu, b.ic, c, b.run, b.search));
    return row;
  });
  StudyReport r;
  r.table = boundary_table(rs, rows, b);
  json points = json::array();
  for (std::size_t i = 0; i < rs.size(); ++i) points.push_back(boundary_point(rs[i], rows[i], b));
  json meta = header("flight-boundary", b.ic, b.mu, b.run);
  meta["r_range"] = {b.r_min, b.r_max};
  meta["search"] = {{"k_range", {b.search.k_lo, b.search.k_hi}},
                    {"points_per_decade", b.search.per_decade},
                    {"bisection_rel_tol", b.search.bisect.rel_tol},
                    {"fine_points_per_decade", b.search.refine.per_decade},
                    {"fine_span_decades", b.search.refine.span_decades},
                    {"definitions",
                     "k_critical_n = sup K: no flight while ihor < n for all k < K; k_high = inf K: flight "
                     "during the first impact for all k > K; coarse log grid + bisection, then a fine grid "
                     "(anchored at k_lo) over fine_span_decades on the holding side, repeated until clean"}};
  r.sidecar = meta;
  r.summary = meta;
  r.summary["points"] = points;
  r.text = boundary_text(rs, rows, b.ns, b.crits);
  r.figure = FigureSpec{"flight", {"boundary"}, {}};
  return r;
}

// ------------------------------------------------------------------ kmin

std::vector<StudyOption> kmin_options() {
  return {{"ic", "comma-separated sets: ic1, ic2, ic1:F (w0 = F alpha)", "ic1,ic1:0.25,ic1:0.125,ic2"},
          {"mu", "friction coefficient (>= 0)", "0.2"},
          {"r-min", "lowest aspect ratio (log grid)", "0.02"},
          {"r-max", "highest aspect ratio", "1"},
          {"points", "number of r values", "60"},
          {"k-lo", "lowest k searched for the root", "1"},
          {"k-hi", "highest k searched", "1e12"},
          threads_option()};
}

StudyReport kmin_study(const Settings& given, const StudyRequest&) {
  const StudyOptions o(given, kmin_options());
  const double mu = o.number("mu"), r_min = o.number("r-min"), r_max = o.number("r-max");
  const double k_lo = o.number("k-lo"), k_hi = o.number("k-hi");
  require_in_range("mu", mu, 0.0, kMuMax);
  check_r_range(r_min, r_max);
  const int points = checked_points(o, "points", 1);
  check_k_range("k-lo", k_lo, "k-hi", k_hi);
  const int threads = o.threads();
  const std::string ic_list = o.text("ic");
  std::vector<IcChoice> ics;
  std::stringstream ss(ic_list);
  for (std::string item; std::getline(ss, item, ',');) ics.push_back(parse_ic_choice(item));
  if (ics.empty()) throw std::invalid_argument("ic must list at least one initial-condition set");
  const auto rs = r_grid(r_min, r_max, points);
  const auto res = parallel_map<std::vector<BoundaryResult>>(rs.size(), threads, [&](std::size_t i) {
    std::vector<BoundaryResult> v;
    for (const auto& ic : ics) v.push_back(k_min(rs[i], mu, ic, k_lo, k_hi));
    return v;
  });
  StudyReport r;
  r.table.columns = {"r"};
  for (const auto& ic : ics) r.table.columns.push_back("k_min_" + ic.name());
  json curves = json::object();
  for (const auto& ic : ics) curves[ic.name()] = json::array();
  for (std::size_t i = 0; i < rs.size(); ++i) {
    CellRow row{Cell::shortest(rs[i])};
    for (std::size_t j = 0; j < ics.size(); ++j) {
      row.push_back(Cell::shortest(boundary_cell(res[i][j])));
      json b = boundary_json(res[i][j]);
      b["r"] = rs[i];
      curves[ics[j].name()].push_back(b);
    }
    r.table.rows.push_back(row);
  }
  json meta = {{"run_info", run_info()},
               {"command", "kmin"},
               {"mu", mu},
               {"ics", ic_list},
               {"r_range", {r_min, r_max}},
               {"k_search_range", {k_lo, k_hi}},
               {"definition",
                "k_min(r) = inf K: E0(k) >= 0 for all k > K (E = 0: least energy in flight); "
                "E0 = 0 solved by TOMS 748 in log k"}};
  r.sidecar = meta;
  r.summary = meta;
  r.summary["curves"] = curves;
  for (const auto& c : r.table.columns) append_text(r.text, "%-20s", c.c_str());
  r.text += "\n";
  for (const auto& row : r.table.rows) {
    for (const Cell& c : row) append_text(r.text, "%-20.8g", c.number());
    r.text += "\n";
  }
  r.figure = FigureSpec{"flight", {"kmin"}, {}};
  return r;
}

// ------------------------------------------------------------------ flight-map

std::vector<StudyOption> flight_map_options() {
  return with_run_options({{"ic", "initial conditions: ic1, ic2, ic1:F", "ic1"},
                           {"mu", "friction coefficient (>= 0)", "0.2"},
                           {"r-min", "lowest aspect ratio (log grid)", "0.05"},
                           {"r-max", "highest aspect ratio", "1"},
                           {"r-points", "number of r values", "24"},
                           {"k-min", "lowest k (log grid)", "100"},
                           {"k-max", "highest k", "1e10"},
                           {"k-points", "number of k values", "48"}},
                          "30");
}

StudyReport flight_map(const Settings& given, const StudyRequest&) {
  const StudyOptions o(given, flight_map_options());
  const double mu = o.number("mu"), r_min = o.number("r-min"), r_max = o.number("r-max");
  const double k_min = o.number("k-min"), k_max = o.number("k-max");
  require_in_range("mu", mu, 0.0, kMuMax);
  check_r_range(r_min, r_max);
  check_k_range("k-min", k_min, "k-max", k_max);
  const int r_points = checked_points(o, "r-points"), k_points = checked_points(o, "k-points");
  const StudyRunOptions run = o.run_options();
  const int threads = o.threads();
  const IcChoice ic = parse_ic_choice(o.text("ic"));
  const auto cells =
      first_flight_map(mu, ic, log_grid(r_min, r_max, r_points), log_grid(k_min, k_max, k_points), run, threads);
  StudyReport r;
  r.table.columns = {"r", "k", "flew", "time", "ihor", "status", "t_final"};
  int flown = 0, failed = 0;
  for (const auto& c : cells) {
    r.table.rows.push_back({Cell::shortest(c.r), Cell::shortest(c.k), Cell(c.flew ? 1 : 0), Cell::shortest(c.time),
                            Cell(c.upright_passages), to_string(c.status), Cell::shortest(c.t_final)});
    flown += c.flew;
    failed += c.status == SimStatus::NumericalFailure;
  }
  json meta = header("flight-map", ic, mu, run);
  meta["r_grid"] = {{"min", r_min}, {"max", r_max}, {"points", r_points}, {"spacing", "log"}};
  meta["k_grid"] = {{"min", k_min}, {"max", k_max}, {"points", k_points}, {"spacing", "log"}};
  meta["time_column"] = kTimeColumn;
  r.sidecar = meta;
  r.summary = meta;
  r.summary["cells"] = cells.size();
  r.summary["flew"] = flown;
  r.summary["numerical_failures"] = failed;
  append_text(r.text, "%zu cells (%s, mu = %g, t_end = %g): %d flew, %d failed\n", cells.size(), ic.name().c_str(), mu,
              run.t_end, flown, failed);
  r.figure = FigureSpec{"flight", {"map"}, {}};
  return r;
}

}  // namespace

void add_flight_studies(std::vector<StudyCommand>& to) {
  to.push_back({"flight-time", "time (and ihor) at first flight versus k for fixed r, mu (thesis Figs 4.6-4.13)", 30,
                StudyOutputs::Table, flight_time_options(), flight_time});
  to.push_back({"flight-boundary", "critical flight curves k_critical_n(r), k_high(r) with k_min(r) (Figs 4.14-4.19)",
                31, StudyOutputs::Table, flight_boundary_options(), flight_boundary});
  to.push_back({"kmin", "energy lower bound k_min(r) of the flight region (E0 = 0, Fig 4.5)", 32, StudyOutputs::Table,
                kmin_options(), kmin_study});
  to.push_back({"flight-map", "time to first flight over the (k, r) plane (Fig 4.20)", 33, StudyOutputs::Table,
                flight_map_options(), flight_map});
}

}  // namespace blockdyn
