// SPDX-License-Identifier: Apache-2.0
// `blockdyn equilibria`, `bifurcation`, `bifurcation-curves`: static equilibria of the block on
// the Winkler foundation and their bifurcations in k (thesis 4.3.3).
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <unistd.h>

#include "blockdyn/analysis/winkler/equilibria.hpp"
#include "blockdyn/analysis/winkler/equilibrium_bifurcation.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
namespace {

using json = nlohmann::ordered_json;

constexpr double kRMin = 0.005, kKMin = 2.0, kKMax = 1e10;

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

std::string temp_path(const std::string& stem) {
  return "/tmp/blockdyn-" + stem + "-" + std::to_string(::getpid()) + ".csv";
}

// CSV written atomically, with its JSON sidecar <csv>.json.
void write_csv(const std::string& path, const std::string& text, const json& sidecar) {
  write_file_atomically(path, text);
  emit_json(sidecar, path + ".json", "sidecar");
}

void remove_temp(const std::string& path) {
  std::remove(path.c_str());
  std::remove((path + ".json").c_str());
}

// Writes the CSV text (with its sidecar) to f.csv, or to a temporary file when only f.plot is
// wanted, plots it with script and records both paths in j.
template <class Flags>
void write_csv_and_plot(const Flags& f, const std::string& stem, const std::string& text, const json& sidecar,
                        const std::string& script, json& j) {
  const std::string path = f.csv.empty() ? temp_path(stem) : f.csv;
  write_csv(path, text, sidecar);
  if (!f.plot.empty()) run_python(script, {path, f.plot});
  if (f.csv.empty()) remove_temp(path);
  if (!f.csv.empty()) j["csv"] = f.csv;
  if (!f.plot.empty()) j["plot"] = f.plot;
}

// Writes j to --json-out and, with --json, to stdout; true when it went to stdout (no table then).
template <class Flags>
bool emit_summary(const Flags& f, const json& j) {
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json) emit_json(j, "-");
  return f.json;
}

void check_threads(int t) { require_range("threads", t, 0, 1024); }

json params_json(double r, double k) {
  return {{"r", r}, {"k", k}, {"alpha", std::atan(r)}};
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
struct EquilibriaFlags {
  double r = 0.5, k = 1e5;
  int points = 401, scan_points = 256;
  bool json = false;
  std::string json_out, csv, plot;
};

std::string regime(double r, double k, const CriticalStiffness& c) {
  if (k > c.k_os) return "k > k_os: upright stable";
  if (k > c.k_uns) return "k_uns < k < k_os: upright unstable, stable tilted equilibrium";
  if (r == 1.0) return "k < k_uns: only w = alpha (diagonal vertical) is stable";
  return "k < k_uns: no stable equilibrium with |w| <= alpha";
}

void run_equilibria(const EquilibriaFlags& f) {
  require_writable("plot", f.plot);
  require_writable("csv", f.csv);
  require_writable("json-out", f.json_out);
  require_range("r", f.r, kRMin, 1.0);
  require_range("k", f.k, kKMin, kKMax);
  require_range("points", f.points, 2, 1000000);
  require_range("scan-points", f.scan_points, 8, 100000);
  BlockParams p;
  p.r = f.r;
  p.k = f.k;
  EquilibriumSearch opt;
  opt.scan_points = f.scan_points;
  const auto eqs = find_equilibria(p, opt);
  const CriticalStiffness crit = critical_stiffness(f.r);

  json j;
  j["run_info"] = run_info();
  j["params"] = params_json(f.r, f.k);
  j["equilibria"] = json::array();
  for (const auto& e : eqs) j["equilibria"].push_back(equilibrium_json(e));
  j["upright_arm_slope"] = upright_arm_slope(p);
  j["critical"] = critical_json(f.r, crit);
  j["regime"] = regime(f.r, f.k, crit);
  j["conventions"] =
      "w in [0, alpha] (mirror images -w are equilibria too); y = h + 1/2 centre height; "
      "stable: d arm/dw < 0, arm = x_R - x at Ry = 1";

  if (!f.csv.empty() || !f.plot.empty()) {
    const auto land = energy_landscape(p, f.points);
    std::ostringstream os;
    os << "w,y_R,h_R,arm,energy,potential,corners_below\n";
    for (const auto& q : land)
      os << num(q.w) << ',' << num(q.h + 0.5) << ',' << num(q.h) << ',' << num(q.arm) << ',' << num(q.energy)
         << ',' << num(q.potential) << ',' << q.corners_below << '\n';
    json side = j;
    side["columns"] = {
        {"w", "tilt"},
        {"y_R", "centre height with Ry = 1"},
        {"h_R", "y_R - 1/2"},
        {"arm", "x_R - x at y_R (torque of the foundation reaction, units m g a)"},
        {"energy", "-int_0^w arm: work to tilt quasi-statically from upright (thesis's energy plot)"},
        {"potential", "springs + gravity V(y_R(w), w) + y_R(w), minus its value at w = 0"},
        {"corners_below", "corners below the surface at rest"}};
    write_csv_and_plot(f, "equilibria", os.str(), side, "plot_equilibria.py", j);
  }
  if (emit_summary(f, j)) return;
  std::printf("r = %g, k = %g, alpha = %.10f: %s\n", f.r, f.k, p.alpha(), regime(f.r, f.k, crit).c_str());
  std::printf("k_os = %.10f, k_uns = %.10f\n", crit.k_os, crit.k_uns);
  std::printf("%18s %18s %10s %10s %14s %8s\n", "w", "y", "stability", "branch", "d arm/dw", "corners");
  for (const auto& e : eqs)
    std::printf("%18.12f %18.12f %10s %10s %14.6g %8d\n", e.w, e.h + 0.5, to_string(e.stability),
                to_string(e.branch), e.arm_slope, e.corners_below);
}

void add_equilibria(CLI::App& app) {
  auto f = std::make_shared<EquilibriaFlags>();
  CLI::App* s = app.add_subcommand("equilibria", "static equilibria 0 <= w <= alpha and their stability (thesis 4.3.3)");
  s->add_option("--r", f->r, "aspect ratio width/height, in [0.005, 1]")->capture_default_str();
  s->add_option("--k", f->k, "foundation stiffness, in [2, 1e10]")->capture_default_str();
  s->add_flag("--json", f->json, "print JSON on stdout instead of a table");
  s->add_option("--json-out", f->json_out, "also write the JSON to this file");
  s->add_option("--csv", f->csv, "write w, y_R(w), arm(w), energy, potential (CSV + .json sidecar)");
  s->add_option("--plot", f->plot, "plot arm(w) and the energy landscape (PNG; SVG beside it)");
  s->add_option("--points", f->points, "landscape grid points on [0, alpha]")->capture_default_str();
  s->add_option("--scan-points", f->scan_points, "scan cells of the root search")->capture_default_str();
  s->callback([f] { run_equilibria(*f); });
}

// ---------------------------------------------------------------- bifurcation
struct BifurcationFlags {
  double r = 0.5, k_min = 2.0, k_max = 1e5;
  int points = 400, zoom_points = 200, threads = 0;
  std::string spacing = "log", json_out, csv, plot;
  bool json = false;
};

bool parse_spacing(const std::string& s) {
  if (s == "log") return true;
  if (s == "lin") return false;
  throw UsageError("spacing = '" + s + "' is not one of: log, lin");
}

void append_diagram(std::ostringstream& os, const char* panel, const std::vector<BifurcationSample>& d) {
  for (std::size_t i = 0; i < d.size(); ++i)
    for (const auto& e : d[i].equilibria)
      os << panel << ',' << i << ',' << num(d[i].k) << ',' << num(e.w) << ',' << num(e.h + 0.5) << ','
         << int(e.stability == Stability::Stable) << ',' << to_string(e.branch) << '\n';
}

void run_bifurcation(const BifurcationFlags& f) {
  require_writable("plot", f.plot);
  require_writable("csv", f.csv);
  require_writable("json-out", f.json_out);
  require_range("r", f.r, kRMin, 1.0);
  require_range("k-min", f.k_min, kKMin, kKMax);
  require_range("k-max", f.k_max, f.k_min, kKMax, false, true);
  require_range("points", f.points, 2, 100000);
  require_range("zoom-points", f.zoom_points, 2, 100000);
  check_threads(f.threads);
  const bool logk = parse_spacing(f.spacing);
  const CriticalStiffness c = critical_stiffness(f.r);

  json j;
  j["run_info"] = run_info();
  j["r"] = f.r;
  j["alpha"] = std::atan(f.r);
  const json cj = critical_json(f.r, c);
  for (auto it = cj.begin(); it != cj.end(); ++it) j[it.key()] = it.value();
  if (f.r == 1.0)
    j["square_block"] = "w = alpha is an equilibrium for every k: stable for k < k_uns, unstable above";

  if (!f.csv.empty() || !f.plot.empty()) {
    const auto ks = sample_range(f.k_min, f.k_max, f.points, logk);
    // Magnified window around the two bifurcations, as in the thesis's left-hand panels.
    const double z_lo = std::max(kKMin, c.k_uns - 2.0), z_hi = c.k_os + 2.0;
    const auto zs = sample_range(z_lo, z_hi, f.zoom_points, false);
    const auto d = bifurcation_diagram(f.r, ks, f.threads);
    const auto dz = bifurcation_diagram(f.r, zs, f.threads);
    std::ostringstream os;
    os << "panel,index,k,w,y,stable,branch\n";
    append_diagram(os, "range", d);
    append_diagram(os, "zoom", dz);
    json side = j;
    side["range"] = {{"k_min", f.k_min}, {"k_max", f.k_max}, {"points", f.points}, {"spacing", f.spacing}};
    side["zoom"] = {{"k_min", z_lo}, {"k_max", z_hi}, {"points", f.zoom_points}, {"spacing", "lin"}};
    side["columns"] = "panel (range|zoom), index of k in its panel, k, equilibrium w, centre height y, "
                      "stable (1/0), branch (upright|tilted|diagonal)";
    write_csv_and_plot(f, "bifurcation", os.str(), side, "plot_bifurcation.py", j);
  }
  if (emit_summary(f, j)) return;
  std::printf("r = %g, alpha = %.10f\n", f.r, std::atan(f.r));
  std::printf("k_os  = %.10f  (linearised (3 + sqrt(9 - 3 r^2)) / r^2 = %.10f, thesis 6/r^2 - 0.5 = %.10f)\n",
              c.k_os, k_os_linearized(f.r), k_os_small_angle(f.r));
  std::printf("k_uns = %.10f  (one-corner closed form %.10f, fold at w = %.10f)\n", c.k_uns,
              k_uns_one_corner(f.r), fold_tilt_one_corner(f.r));
  std::printf("k_os - k_uns = %.10f\n", c.k_os - c.k_uns);
}

void add_bifurcation(CLI::App& app) {
  auto f = std::make_shared<BifurcationFlags>();
  CLI::App* s = app.add_subcommand("bifurcation", "critical stiffnesses k_os, k_uns and the equilibrium diagram w vs k");
  s->add_option("--r", f->r, "aspect ratio width/height, in [0.005, 1]")->capture_default_str();
  s->add_option("--k-min", f->k_min, "diagram: smallest k, >= 2")->capture_default_str();
  s->add_option("--k-max", f->k_max, "diagram: largest k, <= 1e10")->capture_default_str();
  s->add_option("--points", f->points, "diagram: number of k values")->capture_default_str();
  s->add_option("--zoom-points", f->zoom_points, "diagram: k values in the window around k_uns, k_os")
      ->capture_default_str();
  s->add_option("--spacing", f->spacing, "diagram k spacing: log or lin")->capture_default_str();
  s->add_option("--threads", f->threads, "worker threads (0: all cores)")->capture_default_str();
  s->add_flag("--json", f->json, "print JSON on stdout");
  s->add_option("--json-out", f->json_out, "also write the JSON to this file");
  s->add_option("--csv", f->csv, "write the diagram (CSV + .json sidecar)");
  s->add_option("--plot", f->plot, "plot the diagram (PNG; SVG beside it)");
  s->callback([f] { run_bifurcation(*f); });
}

// ---------------------------------------------------------------- bifurcation-curves
struct CurvesFlags {
  double r_min = 0.05, r_max = 1.0;
  int points = 96, threads = 0;
  std::string spacing = "lin", json_out, csv, plot;
  bool json = false;
};

void run_curves(const CurvesFlags& f) {
  require_writable("plot", f.plot);
  require_writable("csv", f.csv);
  require_writable("json-out", f.json_out);
  require_range("r-min", f.r_min, kRMin, 1.0);
  require_range("r-max", f.r_max, f.r_min, 1.0, f.points == 1, true);
  require_range("points", f.points, 1, 100000);
  check_threads(f.threads);
  const auto rs = sample_range(f.r_min, f.r_max, f.points, parse_spacing(f.spacing));
  const auto cs = critical_curves(rs, f.threads);

  std::ostringstream os;
  os << "r,k_os,k_uns,k_os_minus_k_uns,k_small_angle,small_angle_minus_k_os,k_os_linearized,k_uns_one_corner\n";
  double gap_min = 1e300, gap_max = -1e300, dev_small = 0, dev_lin = 0, dev_uns = 0;
  for (const auto& c : cs) {
    const double gap = c.k_os - c.k_uns, sa = k_os_small_angle(c.r);
    gap_min = std::min(gap_min, gap);
    gap_max = std::max(gap_max, gap);
    dev_small = std::max(dev_small, std::fabs(sa - c.k_os));
    dev_lin = std::max(dev_lin, std::fabs(k_os_linearized(c.r) - c.k_os) / c.k_os);
    dev_uns = std::max(dev_uns, std::fabs(k_uns_one_corner(c.r) - c.k_uns) / c.k_uns);
    os << num(c.r) << ',' << num(c.k_os) << ',' << num(c.k_uns) << ',' << num(gap) << ',' << num(sa) << ','
       << num(sa - c.k_os) << ',' << num(k_os_linearized(c.r)) << ',' << num(k_uns_one_corner(c.r)) << '\n';
  }
  json j;
  j["run_info"] = run_info();
  j["r_min"] = f.r_min;
  j["r_max"] = f.r_max;
  j["points"] = f.points;
  j["spacing"] = f.spacing;
  j["k_os_minus_k_uns"] = {{"min", gap_min},
                           {"max", gap_max},
                           {"at_r_min", cs.front().k_os - cs.front().k_uns},
                           {"at_r_max", cs.back().k_os - cs.back().k_uns},
                           {"small_r_limit", 5.0 / 6.0}};
  j["max_abs_small_angle_minus_k_os"] = dev_small;
  j["max_rel_dev_k_os_vs_linearized"] = dev_lin;
  j["max_rel_dev_k_uns_vs_one_corner_closed_form"] = dev_uns;
  if (!f.csv.empty() || !f.plot.empty()) {
    write_csv_and_plot(f, "bifurcation-curves", os.str(), j, "plot_bifurcation_curves.py", j);
  }
  if (emit_summary(f, j)) return;
  std::printf("%10s %20s %20s %14s %14s\n", "r", "k_os", "k_uns", "k_os-k_uns", "6/r^2-.5-k_os");
  for (const auto& c : cs)
    std::printf("%10.6f %20.10f %20.10f %14.10f %14.3e\n", c.r, c.k_os, c.k_uns, c.k_os - c.k_uns,
                k_os_small_angle(c.r) - c.k_os);
}

void add_curves(CLI::App& app) {
  auto f = std::make_shared<CurvesFlags>();
  CLI::App* s = app.add_subcommand("bifurcation-curves", "k_os(r), k_uns(r) over a range of aspect ratios (thesis Fig 4.40)");
  s->add_option("--r-min", f->r_min, "smallest r, in [0.005, 1]")->capture_default_str();
  s->add_option("--r-max", f->r_max, "largest r, in (r-min, 1]")->capture_default_str();
  s->add_option("--points", f->points, "number of r values")->capture_default_str();
  s->add_option("--spacing", f->spacing, "r spacing: lin or log")->capture_default_str();
  s->add_option("--threads", f->threads, "worker threads (0: all cores)")->capture_default_str();
  s->add_flag("--json", f->json, "print the JSON summary on stdout instead of a table");
  s->add_option("--json-out", f->json_out, "also write the JSON summary to this file");
  s->add_option("--csv", f->csv, "write r, k_os, k_uns, ... (CSV + .json sidecar)");
  s->add_option("--plot", f->plot, "plot the curves (PNG; SVG beside it)");
  s->callback([f] { run_curves(*f); });
}

RegisterCommand reg_equilibria(40, add_equilibria);
RegisterCommand reg_bifurcation(41, add_bifurcation);
RegisterCommand reg_curves(42, add_curves);

}  // namespace
}  // namespace blockdyn::cli
