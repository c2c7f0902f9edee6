// SPDX-License-Identifier: Apache-2.0
// `blockdyn periodic-orbits`: rocking periodic orbits of the Housner block under
// a_H = K_s g sin(Omega t + phi) (seed 001 sec. 4.1), by shooting on the impact map, with their
// Floquet multipliers; continued in K_s or omega (--continue), or mapped over the (K_s, omega)
// plane (--region). Convention: seed 002's (m, n) = 2m impacts per n forcing periods (seed 001's
// (n, k) with k = 2m).
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

#include "blockdyn/analysis/forced/periodic_orbit_study.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/progress.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "trajectory_target.hpp"

namespace blockdyn::cli {
namespace {

using json = nlohmann::ordered_json;

struct OrbitFlags {
  double width = 0, height = 0, g = 9.81, restitution = -1;
  double ks = 0, beta = 0, omega = 2;
  std::vector<int> cycle{1, 1};
  bool asymmetric = false;
  double guess_phase = 0, guess_velocity = 0;
  std::string cont;  // ks | omega
  double cont_min = 0, cont_max = 0, ds = 0.02;
  int max_points = 400;
  bool region = false;
  OrbitRegionOptions reg;
  double beta_min = 0, beta_max = 0;
  IntegratorOptions integ{1e-12, 1e-14};
  std::string out, plot, json_out, progress = "auto";
  bool json_flag = false, quiet = false;
};

// Appends the members of `part` to `j`, in order.
void merge(json& j, const json& part) {
  for (auto it = part.begin(); it != part.end(); ++it) j[it.key()] = it.value();
}

void emit(const json& j, const OrbitFlags& f) {
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json_flag) emit_json(j, "-");
}

struct Study {
  RockingForcing rf;
  OrbitType type;
  ShootingOptions so;
  std::optional<std::array<double, 2>> guess;
  std::string title;
};

Study parse_study(const CLI::App& s, const OrbitFlags& f) {
  if (!given(s, "--width") || !given(s, "--height")) throw UsageError("--width and --height are needed");
  Study st;
  RockingForcing& rf = st.rf;
  rf.shape = BlockShape{f.width, f.height, 1.0, f.g};
  rf.restitution = f.restitution;
  try {
    validate(rf.shape);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (given(s, "--restitution")) require_range("restitution", f.restitution, 0, 1);
  const double alpha = rf.alpha();
  if (given(s, "--ks") && given(s, "--beta")) throw UsageError("give --ks or --beta, not both");
  rf.ks = given(s, "--beta") ? f.beta * alpha : f.ks;
  if (!given(s, "--ks") && !given(s, "--beta") && !f.region) throw UsageError("--ks (or --beta) is needed");
  if (f.region && !given(s, "--ks") && !given(s, "--beta")) rf.ks = 0.1;
  require_range(given(s, "--beta") ? "beta" : "ks", given(s, "--beta") ? f.beta : rf.ks, 0, 1e3, false);
  require_range("omega", f.omega, 0, 1e4, false);
  rf.omega = f.omega;
  if (f.cycle.size() != 2) throw UsageError("--cycle must be m,n (two integers)");
  st.type = OrbitType{f.cycle[0], f.cycle[1], !f.asymmetric && f.cycle[0] % 2 == 1 && f.cycle[1] % 2 == 1};
  require_range("cycle m", f.cycle[0], 1, 50);
  require_range("cycle n", f.cycle[1], 1, 50);
  require_range("rtol", f.integ.rtol, 0, 1e-3, false);
  require_range("atol", f.integ.atol, 0, 1e-3, false);
  const bool guess_given = given(s, "--guess-phase") || given(s, "--guess-velocity");
  if (guess_given && !(given(s, "--guess-phase") && given(s, "--guess-velocity")))
    throw UsageError("--guess-phase and --guess-velocity go together");
  if (guess_given) {
    require_range("guess-velocity", f.guess_velocity, 0, 1e3, false);
    st.guess = std::array<double, 2>{f.guess_phase, f.guess_velocity};
  }
  if (f.region && !f.cont.empty()) throw UsageError("give --region or --continue, not both");
  require_writable("out", f.out);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  st.so.integrator = f.integ;
  const OrbitType& type = st.type;
  st.title = "housner b/h=" + std::to_string(f.width / f.height).substr(0, 5) + " e=" + std::to_string(rf.e()).substr(0, 5) +
             " (" + std::to_string(type.m) + "," + std::to_string(type.n) + ")" + (type.symmetric ? " symmetric" : "");
  return st;
}

// The figures' closed-form overlay: alpha, e, n, whether the linear fold applies (and the point).
std::string linear_overlay(const Study& st, bool with_point) {
  std::ostringstream extra;
  extra << st.rf.alpha() << ',' << st.rf.e() << ',' << st.type.n << ',' << (st.type.symmetric && st.type.m == 1 ? 1 : 0);
  if (with_point) extra << ',' << st.rf.ks << ',' << st.rf.omega;
  return extra.str();
}

void run_region(const CLI::App& s, const OrbitFlags& f, const Study& st, json j) {
  OrbitRegionOptions ro = f.reg;
  if (given(s, "--beta-min") || given(s, "--beta-max")) {
    if (given(s, "--ks-min") || given(s, "--ks-max")) throw UsageError("give --ks-min/max or --beta-min/max, not both");
    ro.ks_min = f.beta_min * st.rf.alpha();
    ro.ks_max = f.beta_max * st.rf.alpha();
  }
  ro.shooting = st.so;
  require_range("threads", ro.threads, 0, 1024);
  try {
    validate(ro);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const std::size_t n = std::size_t(ro.ks_points) * ro.omega_points;
  Progress bar("periodic-orbits", n, 0, f.quiet ? ProgressMode::None : parse_progress_mode(f.progress));
  std::size_t shown = 0;
  const OrbitRegion r = orbit_region(st.rf, st.type, ro, [&](std::size_t d) {
    for (; shown < d; ++shown) bar.advance();
  });
  bar.finish();
  j["mode"] = "region";
  merge(j, r.summary);
  TrajectoryTarget table(f.out, f.plot);
  if (table.file) write_region_csv(table.file->stream(), st.rf, r.points);
  table.figures_and_clean({{"plot_periodic_orbits.py",
                            f.plot,
                            {"--kind", "region", "--title", st.title, "--linear", linear_overlay(st, false)}}});
  emit(j, f);
  if (!f.json_flag && !f.quiet)
    std::printf("%zu points: %ld with orbits, %ld with a stable orbit\n", r.points.size(), r.with_orbits,
                r.with_stable_orbits);
}

void plot_orbits(const OrbitFlags& f, const Study& st, const std::vector<PeriodicOrbit>& orbits) {
  // The orbits' trajectories over one period, for the figure.
  const std::string tmp = "/tmp/blockdyn-orbits-" + std::to_string(::getpid()) + ".csv";
  RemoveOnSignal cleanup(tmp);
  {
    AtomicFile tf(tmp);
    write_orbit_trajectories_csv(tf.stream(), st.rf, orbits);
    tf.commit();
  }
  char title[256];
  std::snprintf(title, sizeof title, "%s, K_s=%.4g g, omega=%.4g", st.title.c_str(), st.rf.ks, st.rf.omega);
  try {
    run_python("plot_periodic_orbits.py", {tmp, f.plot, "--kind", "orbits", "--title", title});
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  std::remove(tmp.c_str());
}

void run_orbits(const OrbitFlags& f, const Study& st, const std::vector<PeriodicOrbit>& orbits, json j) {
  j["mode"] = "orbits";
  TrajectoryTarget table(f.out, "");
  if (table.file) {
    write_orbits_csv(table.file->stream(), st.rf, orbits);
    table.figures_and_clean({});
  }
  if (!f.plot.empty()) plot_orbits(f, st, orbits);
  emit(j, f);
  if (!f.json_flag && !f.quiet) {
    const double alpha = st.rf.alpha();
    std::printf("%zu orbit(s) of type (%d,%d)%s at K_s = %g g (beta = %g), omega = %g:\n", orbits.size(), st.type.m,
                st.type.n, st.type.symmetric ? " symmetric" : "", st.rf.ks, st.rf.ks / alpha, st.rf.omega);
    for (const auto& o : orbits)
      std::printf("  phase %.6f  velocity %.6f  |mu| %.4g %.4g  %s  max|theta|/alpha %.4g\n", o.phase, o.velocity,
                  std::abs(o.multipliers[0]), std::abs(o.multipliers[1]), o.stable ? "stable" : "unstable",
                  o.max_abs_rotation / alpha);
  }
}

void print_branches(const json& bj, int count, std::size_t orbits) {
  std::printf("%d branch(es) from %zu orbit(s):\n", count, orbits);
  for (const auto& b : bj) {
    std::printf("  branch %d (direction %+d): %zu points, end: %s\n", b["branch"].get<int>(), b["direction"].get<int>(),
                b["points"].size(), b["end"].get<std::string>().c_str());
    for (const auto& p : b["points"])
      if (!p["event"].get<std::string>().empty())
        std::printf("    %s at K_s = %.6g g (beta %.6g), omega = %.6g, velocity %.6g\n",
                    p["event"].get<std::string>().c_str(), p["ks"].get<double>(), p["beta"].get<double>(),
                    p["omega"].get<double>(), p["velocity"].get<double>());
  }
}

void run_continuation(const CLI::App& s, const OrbitFlags& f, const Study& st, const std::vector<PeriodicOrbit>& orbits,
                      json j) {
  ContinuationOptions co;
  co.parameter = f.cont;
  co.min = f.cont_min;
  co.max = f.cont_max;
  if (!given(s, "--continue-min") || !given(s, "--continue-max"))
    throw UsageError("--continue needs --continue-min and --continue-max (K_s in g, or omega)");
  co.ds = f.ds;
  co.ds_max = std::fmax(co.ds, co.ds_max);
  co.ds_min = std::fmin(co.ds_min, co.ds);
  co.max_points = f.max_points;
  co.shooting = st.so;
  try {
    validate(co);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (orbits.empty())
    throw std::runtime_error("no orbit found at the start point to continue (give --guess-phase/--guess-velocity)");
  j["mode"] = "continue";
  const OrbitBranches b = continue_orbits(st.rf, st.type, orbits, co);
  merge(j, b.summary);
  TrajectoryTarget table(f.out, f.plot);
  if (table.file) write_branches_csv(table.file->stream(), st.rf, b.rows);
  table.figures_and_clean({{"plot_periodic_orbits.py",
                            f.plot,
                            {"--kind", "branches", "--parameter", co.parameter, "--title", st.title, "--linear",
                             linear_overlay(st, true)}}});
  emit(j, f);
  if (!f.json_flag && !f.quiet) print_branches(b.summary["branches"], b.count, orbits.size());
}

void run(const CLI::App& s, const OrbitFlags& f) {
  const Study st = parse_study(s, f);
  json j = orbit_study_header(st.rf, st.type, st.so);
  if (f.region) return run_region(s, f, st, std::move(j));
  // Orbits at the point (from the guess, or from the closed form / runs from rest).
  const OrbitsAtPoint at = orbits_at_point(st.rf, st.type, st.so, st.guess);
  merge(j, at.summary);
  if (f.cont.empty()) return run_orbits(f, st, at.orbits, std::move(j));
  run_continuation(s, f, st, at.orbits, std::move(j));
}

void add(CLI::App& app) {
  auto f = std::make_shared<OrbitFlags>();
  CLI::App* s = app.add_subcommand(
      "periodic-orbits",
      "rocking periodic orbits of the Housner block under a_H = K_s g sin(Omega t + phi) (seed 001 sec. 4.1) by "
      "shooting on the impact map, with Floquet multipliers; continuation in K_s or omega; existence and stability "
      "regions over (K_s, omega). Cycle (m, n): 2m impacts per n forcing periods (seed 002)");
  s->add_option("--width", f->width, "block width b [m]");
  s->add_option("--height", f->height, "block height h [m]");
  s->add_option("--g", f->g, "gravity [m/s^2] (default 9.81)");
  s->add_option("--restitution", f->restitution, "restitution e in [0, 1] (default Housner's 1 - 1.5 sin^2 alpha)");
  s->add_option("--ks", f->ks, "forcing amplitude K_s (g)");
  s->add_option("--beta", f->beta, "forcing amplitude as K_s / alpha (instead of --ks)");
  s->add_option("--omega", f->omega, "forcing frequency omega = Omega / p (default 2)");
  s->add_option("--cycle", f->cycle, "m,n: 2m impacts per n forcing periods (seed 002; default 1,1)")
      ->delimiter(',')
      ->expected(2);
  s->add_flag("--asymmetric", f->asymmetric,
              "shoot on the full 2m-impact map (default for m or n even; else the symmetric half map is used)");
  s->add_option("--guess-phase", f->guess_phase, "start Newton here: forcing phase at an impact onto theta > 0 (rad)");
  s->add_option("--guess-velocity", f->guess_velocity, "... and theta'/(alpha p) right after it (> 0)");
  s->add_option("--continue", f->cont, "continue every orbit found in ks or omega (both directions)")
      ->check(CLI::IsMember({"ks", "omega"}));
  s->add_option("--continue-min", f->cont_min, "lower end of the continuation range (K_s in g, or omega)");
  s->add_option("--continue-max", f->cont_max, "upper end of the continuation range");
  s->add_option("--ds", f->ds, "initial arclength step (default 0.02, in (phase, velocity, K_s/alpha or omega))");
  s->add_option("--max-points", f->max_points, "points per branch direction (default 400)");
  s->add_flag("--region", f->region, "map the existence and stability of the orbits over (K_s, omega)");
  s->add_option("--ks-min", f->reg.ks_min, "region: smallest K_s (g, default 0.01)");
  s->add_option("--ks-max", f->reg.ks_max, "region: largest K_s (g, default 0.5)");
  s->add_option("--beta-min", f->beta_min, "region: smallest K_s / alpha (instead of --ks-min)");
  s->add_option("--beta-max", f->beta_max, "region: largest K_s / alpha (instead of --ks-max)");
  s->add_option("--ks-points", f->reg.ks_points, "region: amplitudes (default 20)");
  s->add_option("--omega-min", f->reg.omega_min, "region: smallest omega (default 1)");
  s->add_option("--omega-max", f->reg.omega_max, "region: largest omega (default 10)");
  s->add_option("--omega-points", f->reg.omega_points, "region: frequencies (default 20)");
  s->add_option("--threads", f->reg.threads, "region: worker threads (0: all cores)");
  s->add_option("--rtol", f->integ.rtol, "integrator relative tolerance (default 1e-12)");
  s->add_option("--atol", f->integ.atol, "integrator absolute tolerance (default 1e-14)");
  s->add_option("--out", f->out, "CSV: the orbits, the branch points or the region grid");
  s->add_option("--plot", f->plot, "figure (PNG + SVG): the orbits, the branches or the region map");
  s->add_flag("--json", f->json_flag, "print the JSON summary");
  s->add_option("--json-out", f->json_out, "write the JSON summary here");
  s->add_option("--progress", f->progress, "auto, bar, plain or none")
      ->check(CLI::IsMember({"auto", "bar", "plain", "none"}));
  s->add_flag("--quiet", f->quiet, "no summary lines, no progress");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(17, add);

}  // namespace
}  // namespace blockdyn::cli
