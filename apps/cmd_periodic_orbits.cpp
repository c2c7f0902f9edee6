// SPDX-License-Identifier: Apache-2.0
// `blockdyn periodic-orbits`: rocking periodic orbits of the Housner block under
// a_H = K_s g sin(Omega t + phi) (seed 001 sec. 4.1), by shooting on the impact map, with their
// Floquet multipliers; continued in K_s or omega (--continue), or mapped over the (K_s, omega)
// plane (--region). Convention: seed 002's (m, n) = 2m impacts per n forcing periods (seed 001's
// (n, k) with k = 2m).
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include "blockdyn/analysis/forced/housner_periodic_orbits.hpp"
#include "blockdyn/analysis/forced/linear_rocking_orbits.hpp"
#include "blockdyn/analysis/forced/orbit_continuation.hpp"
#include "blockdyn/analysis/forced/orbit_region_map.hpp"
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

json cx(const std::complex<double>& z) { return json::array({z.real(), z.imag()}); }
json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json orbit_json(const PeriodicOrbit& o, const RockingForcing& f) {
  json j;
  j["phase"] = o.phase;
  j["velocity"] = o.velocity;
  j["velocity_si"] = o.velocity * f.alpha() * f.p();
  j["period"] = o.period;
  j["max_abs_rotation"] = o.max_abs_rotation;
  j["max_abs_rotation_over_alpha"] = o.max_abs_rotation / f.alpha();
  j["multipliers"] = {cx(o.multipliers[0]), cx(o.multipliers[1])};
  j["multipliers_fd"] = {cx(o.multipliers_fd[0]), cx(o.multipliers_fd[1])};
  j["stable"] = o.stable;
  j["lyapunov_exponent"] = o.lyapunov_exponent;
  j["iterations"] = o.iterations;
  j["residual"] = o.residual;
  json imp = json::array();
  for (const auto& i : o.impacts)
    imp.push_back({{"t", i.t}, {"phase", i.phase}, {"rate_before", i.rate_before}, {"rate_after", i.rate_after}});
  j["impacts"] = imp;
  return j;
}

void run(const CLI::App& s, const OrbitFlags& f) {
  if (!given(s, "--width") || !given(s, "--height")) throw UsageError("--width and --height are needed");
  RockingForcing rf;
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
  OrbitType type{f.cycle[0], f.cycle[1], !f.asymmetric && f.cycle[0] % 2 == 1 && f.cycle[1] % 2 == 1};
  require_range("cycle m", f.cycle[0], 1, 50);
  require_range("cycle n", f.cycle[1], 1, 50);
  require_range("rtol", f.integ.rtol, 0, 1e-3, false);
  require_range("atol", f.integ.atol, 0, 1e-3, false);
  const bool guess_given = given(s, "--guess-phase") || given(s, "--guess-velocity");
  if (guess_given && !(given(s, "--guess-phase") && given(s, "--guess-velocity")))
    throw UsageError("--guess-phase and --guess-velocity go together");
  if (guess_given) require_range("guess-velocity", f.guess_velocity, 0, 1e3, false);
  if (f.region && !f.cont.empty()) throw UsageError("give --region or --continue, not both");
  require_writable("out", f.out);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  ShootingOptions so;
  so.integrator = f.integ;

  json j;
  j["run"] = run_info();
  j["model"] = {{"model", "housner"},    {"width", f.width}, {"height", f.height}, {"g", f.g},
                {"restitution", rf.e()}, {"alpha", alpha},   {"p", rf.p()}};
  j["forcing"] =
      "a_H = K_s g sin(Omega t + phi), Omega = omega p; phase = Omega t + phi mod 2 pi at an impact onto "
      "theta > 0, velocity = theta'/(alpha p) right after it";
  j["convention"] = {
      {"cycle", {type.m, type.n}},
      {"seed_002", "(m, n): 2m impacts per n forcing periods"},
      {"seed_001", {{"n", type.n}, {"k", 2 * type.m}, {"meaning", "k impacts per period 2 pi n / omega"}}},
      {"symmetric", type.symmetric}};
  j["integrator"] = to_json(f.integ);
  const std::string title_base = "housner b/h=" + std::to_string(f.width / f.height).substr(0, 5) +
                                 " e=" + std::to_string(rf.e()).substr(0, 5) + " (" + std::to_string(type.m) + "," +
                                 std::to_string(type.n) + ")" + (type.symmetric ? " symmetric" : "");

  if (f.region) {
    OrbitRegionOptions ro = f.reg;
    if (given(s, "--beta-min") || given(s, "--beta-max")) {
      if (given(s, "--ks-min") || given(s, "--ks-max"))
        throw UsageError("give --ks-min/max or --beta-min/max, not both");
      ro.ks_min = f.beta_min * alpha;
      ro.ks_max = f.beta_max * alpha;
    }
    ro.shooting = so;
    require_range("threads", ro.threads, 0, 1024);
    try {
      validate(ro);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    const std::size_t n = std::size_t(ro.ks_points) * ro.omega_points;
    Progress bar("periodic-orbits", n, 0, f.quiet ? ProgressMode::None : parse_progress_mode(f.progress));
    std::size_t shown = 0;
    const auto pts = orbit_region_map(rf, type, ro, [&](std::size_t d) {
      for (; shown < d; ++shown) bar.advance();
    });
    bar.finish();
    json arr = json::array();
    long exist = 0, stable = 0;
    for (const auto& p : pts) {
      arr.push_back({{"ks", p.ks},
                     {"beta", p.ks / alpha},
                     {"omega", p.omega},
                     {"orbits", p.orbits},
                     {"stable", p.stable},
                     {"phase", num(p.phase)},
                     {"velocity", num(p.velocity)},
                     {"max_multiplier", num(p.max_multiplier)},
                     {"linear_orbits", p.linear_orbits < 0 ? json(nullptr) : json(p.linear_orbits)},
                     {"linear_stable", p.linear_stable < 0 ? json(nullptr) : json(p.linear_stable)}});
      exist += p.orbits > 0;
      stable += p.stable > 0;
    }
    j["mode"] = "region";
    j["points"] = arr;
    j["counts"] = {{"points", pts.size()}, {"with_orbits", exist}, {"with_stable_orbits", stable}};
    if (type.symmetric && type.m == 1) {
      json fold = json::array();
      for (int k = 0; k <= 200; ++k) {
        const double w = ro.omega_min + (ro.omega_max - ro.omega_min) * k / 200.0;
        fold.push_back({{"omega", w}, {"ks", alpha * linear_symmetric_fold_beta(w, rf.e(), type.n)}});
      }
      j["linear_fold"] = fold;
    }
    TrajectoryTarget table(f.out, f.plot);
    if (table.file) {
      std::ostream& os = table.file->stream();
      os << "ks,beta,omega,orbits,stable,phase,velocity,max_multiplier,linear_orbits,linear_stable\n";
      char buf[512];
      for (const auto& p : pts) {
        std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g,%d,%d,%.17g,%.17g,%.17g,%d,%d\n", p.ks, p.ks / alpha, p.omega,
                      p.orbits, p.stable, p.phase, p.velocity, p.max_multiplier, p.linear_orbits, p.linear_stable);
        os << buf;
      }
    }
    std::ostringstream extra;
    extra << alpha << ',' << rf.e() << ',' << type.n << ',' << (type.symmetric && type.m == 1 ? 1 : 0);
    table.figures_and_clean(
        {{"plot_periodic_orbits.py", f.plot, {"--kind", "region", "--title", title_base, "--linear", extra.str()}}});
    if (!f.json_out.empty()) emit_json(j, f.json_out);
    if (f.json_flag) emit_json(j, "-");
    if (!f.json_flag && !f.quiet)
      std::printf("%zu points: %ld with orbits, %ld with a stable orbit\n", pts.size(), exist, stable);
    return;
  }

  // Orbits at the point (from the guess, or from the closed form / runs from rest).
  std::vector<std::array<double, 2>> guesses;
  if (guess_given)
    guesses.push_back({f.guess_phase, f.guess_velocity});
  else
    guesses = orbit_guesses(rf, type);
  const auto orbits = find_periodic_orbits(rf, type, guesses, so);
  j["ks"] = rf.ks;
  j["beta"] = rf.ks / alpha;
  j["omega"] = rf.omega;
  j["guesses"] = guesses.size();
  json oj = json::array();
  for (const auto& o : orbits) oj.push_back(orbit_json(o, rf));
  j["orbits"] = oj;
  if (type.symmetric && type.m == 1) {
    json lj = json::array();
    for (const auto& l : linear_symmetric_orbits(rf.ks / alpha, rf.omega, rf.e(), type.n))
      lj.push_back({{"phase", l.phase},
                    {"velocity", l.velocity},
                    {"valid", l.valid},
                    {"multipliers", {cx(l.multipliers[0]), cx(l.multipliers[1])}}});
    j["linear_theory"] = lj;
    j["linear_fold_ks"] = alpha * linear_symmetric_fold_beta(rf.omega, rf.e(), type.n);
  }

  if (f.cont.empty()) {
    j["mode"] = "orbits";
    TrajectoryTarget table(f.out, "");
    if (table.file) {
      std::ostream& os = table.file->stream();
      os << "orbit,phase,velocity,velocity_si,period,max_abs_rotation,mu1_re,mu1_im,mu2_re,mu2_im,stable,lyapunov_"
            "exponent\n";
      char buf[512];
      for (std::size_t k = 0; k < orbits.size(); ++k) {
        const auto& o = orbits[k];
        std::snprintf(buf, sizeof buf, "%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%.17g\n", k,
                      o.phase, o.velocity, o.velocity * alpha * rf.p(), o.period, o.max_abs_rotation,
                      o.multipliers[0].real(), o.multipliers[0].imag(), o.multipliers[1].real(),
                      o.multipliers[1].imag(), int(o.stable), o.lyapunov_exponent);
        os << buf;
      }
      table.figures_and_clean({});
    }
    if (!f.plot.empty()) {
      // The orbits' trajectories over one period, for the figure.
      const std::string tmp = "/tmp/blockdyn-orbits-" + std::to_string(::getpid()) + ".csv";
      RemoveOnSignal cleanup(tmp);
      {
        AtomicFile tf(tmp);
        auto& os = tf.stream();
        os << "orbit,stable,t,theta,rate\n";
        char buf[256];
        for (std::size_t k = 0; k < orbits.size(); ++k) {
          const OrbitSamples sm = orbit_trajectory(rf, orbits[k]);
          for (std::size_t i = 0; i < sm.t.size(); ++i) {
            std::snprintf(buf, sizeof buf, "%zu,%d,%.17g,%.17g,%.17g\n", k, int(orbits[k].stable), sm.t[i], sm.theta[i],
                          sm.rate[i]);
            os << buf;
          }
        }
        tf.commit();
      }
      char title[256];
      std::snprintf(title, sizeof title, "%s, K_s=%.4g g, omega=%.4g", title_base.c_str(), rf.ks, rf.omega);
      try {
        run_python("plot_periodic_orbits.py", {tmp, f.plot, "--kind", "orbits", "--title", title});
      } catch (...) {
        std::remove(tmp.c_str());
        throw;
      }
      std::remove(tmp.c_str());
    }
    if (!f.json_out.empty()) emit_json(j, f.json_out);
    if (f.json_flag) emit_json(j, "-");
    if (!f.json_flag && !f.quiet) {
      std::printf("%zu orbit(s) of type (%d,%d)%s at K_s = %g g (beta = %g), omega = %g:\n", orbits.size(), type.m,
                  type.n, type.symmetric ? " symmetric" : "", rf.ks, rf.ks / alpha, rf.omega);
      for (const auto& o : orbits)
        std::printf("  phase %.6f  velocity %.6f  |mu| %.4g %.4g  %s  max|theta|/alpha %.4g\n", o.phase, o.velocity,
                    std::abs(o.multipliers[0]), std::abs(o.multipliers[1]), o.stable ? "stable" : "unstable",
                    o.max_abs_rotation / alpha);
    }
    return;
  }

  // Continuation of every orbit found, both ways.
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
  co.shooting = so;
  try {
    validate(co);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (orbits.empty())
    throw std::runtime_error("no orbit found at the start point to continue (give --guess-phase/--guess-velocity)");
  j["mode"] = "continue";
  j["continuation"] = {{"parameter", co.parameter},
                       {"min", co.min},
                       {"max", co.max},
                       {"ds", co.ds},
                       {"max_points", co.max_points},
                       {"multipliers", "eigenvalues of the shooting Jacobian"}};
  json bj = json::array();
  struct Row {
    int branch;
    BranchPoint p;
  };
  std::vector<Row> rows;
  int bi = 0;
  for (const auto& o : orbits) {
    for (int dir : {-1, 1}) {
      co.direction = dir;
      const Branch b = continue_orbit(rf, type, o.phase, o.velocity, co);
      json pts = json::array();
      for (const auto& p : b.points) {
        pts.push_back({{"ks", p.ks},
                       {"beta", p.ks / alpha},
                       {"omega", p.omega},
                       {"phase", p.phase},
                       {"velocity", p.velocity},
                       {"multipliers", {cx(p.multipliers[0]), cx(p.multipliers[1])}},
                       {"stable", p.stable},
                       {"event", p.event}});
        rows.push_back({bi, p});
      }
      bj.push_back(
          {{"branch", bi}, {"from_orbit", &o - orbits.data()}, {"direction", dir}, {"end", b.end}, {"points", pts}});
      ++bi;
    }
  }
  j["branches"] = bj;
  TrajectoryTarget table(f.out, f.plot);
  if (table.file) {
    std::ostream& os = table.file->stream();
    os << "branch,ks,beta,omega,phase,velocity,mu1_abs,mu2_abs,mu1_re,mu1_im,mu2_re,mu2_im,stable,event\n";
    char buf[512];
    for (const Row& r : rows) {
      const BranchPoint& p = r.p;
      std::snprintf(buf, sizeof buf, "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%s\n",
                    r.branch, p.ks, p.ks / alpha, p.omega, p.phase, p.velocity, std::abs(p.multipliers[0]),
                    std::abs(p.multipliers[1]), p.multipliers[0].real(), p.multipliers[0].imag(),
                    p.multipliers[1].real(), p.multipliers[1].imag(), int(p.stable), p.event.c_str());
      os << buf;
    }
  }
  std::ostringstream extra;
  extra << alpha << ',' << rf.e() << ',' << type.n << ',' << (type.symmetric && type.m == 1 ? 1 : 0) << ',' << rf.ks
        << ',' << rf.omega;
  table.figures_and_clean(
      {{"plot_periodic_orbits.py",
        f.plot,
        {"--kind", "branches", "--parameter", co.parameter, "--title", title_base, "--linear", extra.str()}}});
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json_flag) emit_json(j, "-");
  if (!f.json_flag && !f.quiet) {
    std::printf("%d branch(es) from %zu orbit(s):\n", bi, orbits.size());
    for (const auto& b : bj) {
      std::printf("  branch %d (direction %+d): %zu points, end: %s\n", b["branch"].get<int>(),
                  b["direction"].get<int>(), b["points"].size(), b["end"].get<std::string>().c_str());
      for (const auto& p : b["points"])
        if (!p["event"].get<std::string>().empty())
          std::printf("    %s at K_s = %.6g g (beta %.6g), omega = %.6g, velocity %.6g\n",
                      p["event"].get<std::string>().c_str(), p["ks"].get<double>(), p["beta"].get<double>(),
                      p["omega"].get<double>(), p["velocity"].get<double>());
    }
  }
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
