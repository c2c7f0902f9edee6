// SPDX-License-Identifier: Apache-2.0
// Static equilibria of the block on the Winkler foundation and their bifurcations in k (thesis
// 4.3.3): `equilibria`, `bifurcation`, `bifurcation-curves`.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/winkler/equilibria.hpp"
#include "blockdyn/analysis/winkler/equilibrium_bifurcation.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/study_command.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

constexpr double kRMin = 0.005, kKMin = 2.0, kKMax = 1e10;

int checked_integer(const StudyOptions& o, const std::string& name, double lo, double hi) {
  const long v = o.integer(name);
  require_in_range(name, double(v), lo, hi);
  return int(v);
}

bool log_spacing(const std::string& s) {
  if (s == "log") return true;
  if (s == "lin") return false;
  throw std::invalid_argument("spacing = '" + s + "' is not one of: log, lin");
}

json equilibrium_json(const Equilibrium& e) {
  return {{"w", e.w},
          {"y", e.h + 0.5},
          {"h", e.h},
          {"stable", e.stability == Stability::Stable},
          {"stability", to_string(e.stability)},
          {"branch", to_string(e.branch)},
          {"arm_slope", e.arm_slope},
          {"corners_below", e.corners_below}};
}

json critical_json(double r, const CriticalStiffness& c) {
  json j;
  j["k_os"] = c.k_os;
  j["k_uns"] = c.k_uns;
  j["k_os_minus_k_uns"] = c.k_os - c.k_uns;
  j["k_os_small_angle"] = k_os_small_angle(r);
  j["k_os_linearized"] = k_os_linearized(r);
  j["k_uns_one_corner_closed_form"] = k_uns_one_corner(r);
  j["fold_w_one_corner"] = fold_tilt_one_corner(r);
  j["tolerance"] = "k_os, k_uns solved to 1e-13 relative (bracketing + TOMS748)";
  return j;
}

// ---------------------------------------------------------------- equilibria

std::vector<StudyOption> equilibria_options() {
  return {{"r", "aspect ratio width/height, in [0.005, 1]", "0.5"},
          {"k", "foundation stiffness, in [2, 1e10]", "1e5"},
          {"points", "landscape grid points on [0, alpha]", "401"},
          {"scan-points", "scan cells of the root search", "256"}};
}

std::string regime(double r, double k, const CriticalStiffness& c) {
  if (k > c.k_os) return "k > k_os: upright stable";
  if (k > c.k_uns) return "k_uns < k < k_os: upright unstable, stable tilted equilibrium";
  if (r == 1.0) return "k < k_uns: only w = alpha (diagonal vertical) is stable";
  return "k < k_uns: no stable equilibrium with |w| <= alpha";
}

StudyTable landscape_table(const WinklerParams& p, int points) {
  StudyTable t;
  t.columns = {"w", "y_R", "h_R", "arm", "energy", "potential", "corners_below"};
  for (const auto& q : energy_landscape(p, points))
    t.rows.push_back(
        {Cell(q.w), Cell(q.h + 0.5), Cell(q.h), Cell(q.arm), Cell(q.energy), Cell(q.potential), Cell(q.corners_below)});
  return t;
}

StudyReport equilibria_study(const Settings& given, const StudyRequest& request) {
  const StudyOptions o(given, equilibria_options());
  WinklerParams p;
  p.r = o.number("r");
  p.k = o.number("k");
  require_in_range("r", p.r, kRMin, 1.0);
  require_in_range("k", p.k, kKMin, kKMax);
  const int points = checked_integer(o, "points", 2, 1000000);
  EquilibriumSearch opt;
  opt.scan_points = checked_integer(o, "scan-points", 8, 100000);
  const auto eqs = find_equilibria(p, opt);
  const CriticalStiffness crit = critical_stiffness(p.r);

  StudyReport rep;
  json& j = rep.summary;
  j["run_info"] = run_info();
  j["params"] = {{"r", p.r}, {"k", p.k}, {"alpha", std::atan(p.r)}};
  j["equilibria"] = json::array();
  for (const auto& e : eqs) j["equilibria"].push_back(equilibrium_json(e));
  j["upright_arm_slope"] = upright_arm_slope(p);
  j["critical"] = critical_json(p.r, crit);
  j["regime"] = regime(p.r, p.k, crit);
  j["conventions"] =
      "w in [0, alpha] (mirror images -w are equilibria too); y = h + 1/2 centre height; "
      "stable: d arm/dw < 0, arm = x_R - x at Ry = 1";
  if (request.want_table) {
    rep.table = landscape_table(p, points);
    rep.sidecar = j;
    rep.sidecar["columns"] = {
        {"w", "tilt"},
        {"y_R", "centre height with Ry = 1"},
        {"h_R", "y_R - 1/2"},
        {"arm", "x_R - x at y_R (torque of the foundation reaction, units m g a)"},
        {"energy", "-int_0^w arm: work to tilt quasi-statically from upright (thesis's energy plot)"},
        {"potential", "springs + gravity V(y_R(w), w) + y_R(w), minus its value at w = 0"},
        {"corners_below", "corners below the surface at rest"}};
  }
  append_text(rep.text, "r = %g, k = %g, alpha = %.10f: %s\n", p.r, p.k, p.alpha(), regime(p.r, p.k, crit).c_str());
  append_text(rep.text, "k_os = %.10f, k_uns = %.10f\n", crit.k_os, crit.k_uns);
  append_text(rep.text, "%18s %18s %10s %10s %14s %8s\n", "w", "y", "stability", "branch", "d arm/dw", "corners");
  for (const auto& e : eqs)
    append_text(rep.text, "%18.12f %18.12f %10s %10s %14.6g %8d\n", e.w, e.h + 0.5, to_string(e.stability),
                to_string(e.branch), e.arm_slope, e.corners_below);
  rep.figure = FigureSpec{"equilibria", {}, {}};
  return rep;
}

// ---------------------------------------------------------------- bifurcation

std::vector<StudyOption> bifurcation_options() {
  return {{"r", "aspect ratio width/height, in [0.005, 1]", "0.5"},
          {"k-min", "diagram: smallest k, >= 2", "2"},
          {"k-max", "diagram: largest k, <= 1e10", "1e5"},
          {"points", "diagram: number of k values", "400"},
          {"zoom-points", "diagram: k values in the window around k_uns, k_os", "200"},
          {"spacing", "diagram k spacing: log or lin", "log"},
          {"threads", "worker threads (0: all cores)", "0"}};
}

void append_diagram(StudyTable& t, const char* panel, const std::vector<BifurcationSample>& d) {
  for (std::size_t i = 0; i < d.size(); ++i)
    for (const auto& e : d[i].equilibria)
      t.rows.push_back({panel, Cell(i), Cell(d[i].k), Cell(e.w), Cell(e.h + 0.5),
                        Cell(int(e.stability == Stability::Stable)), to_string(e.branch)});
}

StudyReport bifurcation_study(const Settings& given, const StudyRequest& request) {
  const StudyOptions o(given, bifurcation_options());
  const double r = o.number("r"), k_min = o.number("k-min"), k_max = o.number("k-max");
  require_in_range("r", r, kRMin, 1.0);
  require_in_range("k-min", k_min, kKMin, kKMax);
  require_in_range("k-max", k_max, k_min, kKMax, false, true);
  const int points = checked_integer(o, "points", 2, 100000);
  const int zoom_points = checked_integer(o, "zoom-points", 2, 100000);
  const int threads = o.threads();
  const std::string spacing = o.text("spacing");
  const bool logk = log_spacing(spacing);
  const CriticalStiffness c = critical_stiffness(r);

  StudyReport rep;
  json& j = rep.summary;
  j["run_info"] = run_info();
  j["r"] = r;
  j["alpha"] = std::atan(r);
  const json cj = critical_json(r, c);
  for (auto it = cj.begin(); it != cj.end(); ++it) j[it.key()] = it.value();
  if (r == 1.0) j["square_block"] = "w = alpha is an equilibrium for every k: stable for k < k_uns, unstable above";
  if (request.want_table) {
    // Magnified window around the two bifurcations, as in the thesis's left-hand panels.
    const double z_lo = std::max(kKMin, c.k_uns - 2.0), z_hi = c.k_os + 2.0;
    rep.table.columns = {"panel", "index", "k", "w", "y", "stable", "branch"};
    append_diagram(rep.table, "range", bifurcation_diagram(r, sample_range(k_min, k_max, points, logk), threads));
    append_diagram(rep.table, "zoom", bifurcation_diagram(r, sample_range(z_lo, z_hi, zoom_points, false), threads));
    rep.sidecar = j;
    rep.sidecar["range"] = {{"k_min", k_min}, {"k_max", k_max}, {"points", points}, {"spacing", spacing}};
    rep.sidecar["zoom"] = {{"k_min", z_lo}, {"k_max", z_hi}, {"points", zoom_points}, {"spacing", "lin"}};
    rep.sidecar["columns"] =
        "panel (range|zoom), index of k in its panel, k, equilibrium w, centre height y, "
        "stable (1/0), branch (upright|tilted|diagonal)";
  }
  append_text(rep.text, "r = %g, alpha = %.10f\n", r, std::atan(r));
  append_text(rep.text, "k_os  = %.10f  (linearised (3 + sqrt(9 - 3 r^2)) / r^2 = %.10f, thesis 6/r^2 - 0.5 = %.10f)\n",
              c.k_os, k_os_linearized(r), k_os_small_angle(r));
  append_text(rep.text, "k_uns = %.10f  (one-corner closed form %.10f, fold at w = %.10f)\n", c.k_uns,
              k_uns_one_corner(r), fold_tilt_one_corner(r));
  append_text(rep.text, "k_os - k_uns = %.10f\n", c.k_os - c.k_uns);
  rep.figure = FigureSpec{"bifurcation", {}, {}};
  return rep;
}

// ---------------------------------------------------------------- bifurcation-curves

std::vector<StudyOption> curves_options() {
  return {{"r-min", "smallest r, in [0.005, 1]", "0.05"},
          {"r-max", "largest r, in (r-min, 1]", "1"},
          {"points", "number of r values", "96"},
          {"spacing", "r spacing: lin or log", "lin"},
          {"threads", "worker threads (0: all cores)", "0"}};
}

StudyReport curves_study(const Settings& given, const StudyRequest&) {
  const StudyOptions o(given, curves_options());
  const double r_min = o.number("r-min"), r_max = o.number("r-max");
  const long points = o.integer("points");
  require_in_range("r-min", r_min, kRMin, 1.0);
  require_in_range("r-max", r_max, r_min, 1.0, points == 1, true);
  require_in_range("points", double(points), 1, 100000);
  const int threads = o.threads();
  const std::string spacing = o.text("spacing");
  const auto cs = critical_curves(sample_range(r_min, r_max, int(points), log_spacing(spacing)), threads);

  StudyReport rep;
  rep.table.columns = {"r",
                       "k_os",
                       "k_uns",
                       "k_os_minus_k_uns",
                       "k_small_angle",
                       "small_angle_minus_k_os",
                       "k_os_linearized",
                       "k_uns_one_corner"};
  double gap_min = 1e300, gap_max = -1e300, dev_small = 0, dev_lin = 0, dev_uns = 0;
  for (const auto& c : cs) {
    const double gap = c.k_os - c.k_uns, sa = k_os_small_angle(c.r);
    gap_min = std::min(gap_min, gap);
    gap_max = std::max(gap_max, gap);
    dev_small = std::max(dev_small, std::fabs(sa - c.k_os));
    dev_lin = std::max(dev_lin, std::fabs(k_os_linearized(c.r) - c.k_os) / c.k_os);
    dev_uns = std::max(dev_uns, std::fabs(k_uns_one_corner(c.r) - c.k_uns) / c.k_uns);
    rep.table.rows.push_back({Cell(c.r), Cell(c.k_os), Cell(c.k_uns), Cell(gap), Cell(sa), Cell(sa - c.k_os),
                              Cell(k_os_linearized(c.r)), Cell(k_uns_one_corner(c.r))});
    append_text(rep.text, "%10.6f %20.10f %20.10f %14.10f %14.3e\n", c.r, c.k_os, c.k_uns, c.k_os - c.k_uns,
                sa - c.k_os);
  }
  char head[128];
  std::snprintf(head, sizeof head, "%10s %20s %20s %14s %14s\n", "r", "k_os", "k_uns", "k_os-k_uns", "6/r^2-.5-k_os");
  rep.text = head + rep.text;
  json& j = rep.summary;
  j["run_info"] = run_info();
  j["r_min"] = r_min;
  j["r_max"] = r_max;
  j["points"] = points;
  j["spacing"] = spacing;
  j["k_os_minus_k_uns"] = {{"min", gap_min},
                           {"max", gap_max},
                           {"at_r_min", cs.front().k_os - cs.front().k_uns},
                           {"at_r_max", cs.back().k_os - cs.back().k_uns},
                           {"small_r_limit", 5.0 / 6.0}};
  j["max_abs_small_angle_minus_k_os"] = dev_small;
  j["max_rel_dev_k_os_vs_linearized"] = dev_lin;
  j["max_rel_dev_k_uns_vs_one_corner_closed_form"] = dev_uns;
  rep.sidecar = j;
  rep.figure = FigureSpec{"bifurcation_curves", {}, {}};
  return rep;
}

}  // namespace

void add_equilibrium_studies(std::vector<StudyCommand>& to) {
  to.push_back({"equilibria", "static equilibria 0 <= w <= alpha and their stability (thesis 4.3.3)", 40,
                StudyOutputs::SummaryFirst, equilibria_options(), equilibria_study});
  to.push_back({"bifurcation", "critical stiffnesses k_os, k_uns and the equilibrium diagram w vs k", 41,
                StudyOutputs::SummaryFirst, bifurcation_options(), bifurcation_study});
  to.push_back({"bifurcation-curves", "k_os(r), k_uns(r) over a range of aspect ratios (thesis Fig 4.40)", 42,
                StudyOutputs::SummaryFirst, curves_options(), curves_study});
}

}  // namespace blockdyn
