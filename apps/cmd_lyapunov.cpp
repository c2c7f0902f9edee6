// SPDX-License-Identifier: Apache-2.0
// `blockdyn lyapunov`: largest Lyapunov exponent along one orbit, with its convergence history
// (running estimate against time): the free Winkler block (thesis sec. 5.2.2, two-trajectory
// renormalisation) or, with --model housner|rigid|assembly, a forced block or assembly whose state
// jumps at impacts (variational equation with saltation matrices, analysis/forced/forced_lyapunov.hpp),
// with a sensitive-dependence check (two nearby orbits).
#include <cstdio>
#include <iomanip>
#include <memory>

#include "blockdyn/analysis/forced/forced_lyapunov_report.hpp"
#include "blockdyn/analysis/forced/forced_lyapunov.hpp"
#include "blockdyn/analysis/forced/survival_map.hpp"
#include "blockdyn/analysis/winkler/lyapunov_block.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "chaos_cli.hpp"
#include "cli_registry.hpp"
#include "forced_model.hpp"
#include "ground_flags.hpp"

namespace blockdyn::cli {
namespace {

struct LyapunovFlags {
  BlockParams p;
  IntegratorOptions integ;
  IcFlags ic;
  LyapunovOptions opt;
  std::string method = "time", csv, plot, json_out;
  bool json = false;
  // Forced models (--model housner|rigid|assembly).
  ForcedModelFlags fm;
  GroundFlags ground;
  double beta = 0, omega = 0, phase = 0, t_transient = 0, twin_d0 = 1e-9;
  std::string twin_csv;
};

void write_history(const std::string& path, const LyapunovResult& r) {
  AtomicFile f(path);
  auto& o = f.stream();
  o << "t,growth,estimate\n" << std::setprecision(17);
  for (const auto& s : r.history) o << s.t << ',' << s.growth << ',' << s.estimate << '\n';
  f.commit();
}



void run_forced(const CLI::App& s, LyapunovFlags& f) {
  refuse(s, {"--r", "--mu", "--k", "--ic", "--energy", "--energy-of", "--vy-sign", "--w0-alpha", "--d0"},
         "applies to --model winkler only (forced models: --w0 --vw0, --twin-d0)");
  if (f.method != "time") throw UsageError("--method " + f.method + ": forced models renormalise at fixed times only");
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  require_writable("csv", f.csv);
  require_writable("twin-csv", f.twin_csv);
  const ForcedModel fm = build_forced_model(s);
  if (fm.description.contains("contact") && fm.description["contact"] == "rigid")
    throw UsageError("--contact rigid: no Lyapunov exponent (Moreau-Jean time-stepping has no event-located orbit "
                     "to linearise); use --contact deformable");
  GroundMotion g;
  double T = 2 * M_PI / fm.p;  // renormalisation interval by default: a forcing period, else 2 pi / p
  const bool seed_form = given(s, "--beta") || given(s, "--omega");
  if (seed_form) {
    if (!given(s, "--beta") || !given(s, "--omega")) throw UsageError("--beta and --omega go together");
    require_range("beta", f.beta, 0, 1e3, false);
    require_range("omega", f.omega, 0, 1e4, false);
    require_range("phase", f.phase, -1e3, 1e3);
    SurvivalOptions so;
    so.phase = f.phase;
    g = survival_motion(so, f.beta, f.omega, fm.alpha, fm.p);
    T = 2 * M_PI / (f.omega * fm.p);
  } else {
    apply_ground_flags(s, f.ground, g);
    if (g.horizontal.frequency > 0 && !g.horizontal.has_pulse()) T = 1.0 / g.horizontal.frequency;
  }
  ForcedLyapunovOptions o;
  o.t_end = f.opt.t_end;
  o.t_transient = f.t_transient;
  o.interval = given(s, "--interval") ? f.opt.interval : T;
  o.integrator = f.integ;
  if (f.fm.model == "assembly" && !given(s, "--rtol")) o.integrator.rtol = 1e-8;
  if (f.fm.model == "assembly" && !given(s, "--atol")) o.integrator.atol = 1e-10;
  o.twin_d0 = f.twin_d0;
  validate(o);
  orbit_run_options(o.t_end, o.integrator);  // validates the tolerances
  RigidInitial init;
  init.w0 = f.ic.w0;
  init.vw0 = f.ic.vw0;
  if (given(s, "--x0")) init.x0 = f.ic.x0;
  if (given(s, "--y0")) init.y0 = f.ic.y0;
  if (given(s, "--vx0")) init.vx0 = f.ic.vx0;
  if (given(s, "--vy0")) init.vy0 = f.ic.vy0;
  if (f.fm.model == "assembly")
    refuse(s, {"--w0", "--vw0", "--x0", "--y0", "--vx0", "--vy0"}, "does not apply to assemblies (they start as built)");
  const ForcedLyapunovOutcome r = fm.lyapunov(g, o, init);
  const TangentLyapunovResult& tl = r.tangent;

  std::string csv = f.csv;
  const bool temp = csv.empty() && !f.plot.empty();
  if (temp) csv = temp_path("lyapunov", ".csv");
  if (!csv.empty()) {
    LyapunovResult lr;
    lr.history = tl.history;
    write_history(csv, lr);
  }
  if (!f.plot.empty()) {
    char title[256];
    std::snprintf(title, sizeof title, "%s, tangent + saltation: LE = %.4g 1/s (%.4g p)", f.fm.model.c_str(), tl.exponent,
                  tl.exponent / fm.p);
    run_python("plot_lyapunov.py", {csv, f.plot, title});
    if (temp) std::remove(csv.c_str());
  }
  if (!f.twin_csv.empty()) {
    AtomicFile tf(f.twin_csv);
    write_twin_csv(tf.stream(), r);
    tf.commit();
  }
  const nlohmann::ordered_json excitation =
      seed_form ? nlohmann::ordered_json{{"form", "a_H = beta alpha g cos(omega p t + phase)"},
                                         {"beta", f.beta},
                                         {"omega", f.omega},
                                         {"phase", f.phase}}
                : nlohmann::ordered_json(nullptr);
  const auto j = forced_lyapunov_summary(fm, g, excitation, o, r);
  if (!emit_summary(j, f.json, f.json_out)) {
    std::printf("largest Lyapunov exponent: %.6g 1/s = %.6g p (%s, tangent + saltation, t = %.6g, %ld renormalisations, %ld impacts)\n",
                tl.exponent, tl.exponent / fm.p, to_string(tl.status), tl.t_final, tl.renormalisations, r.impacts);
    std::printf("over the second half: %.6g 1/s\n", r.exponent_second_half);
    if (!r.twin.empty())
      std::printf("two orbits %.3g apart: separation %.3g at t = %.6g\n", o.twin_d0, r.twin.back().separation, r.twin.back().t);
    if (!tl.note.empty()) std::printf("note: %s\n", tl.note.c_str());
  }
}

void run(const CLI::App& s, LyapunovFlags& f) {
  if (f.fm.model != "winkler") return run_forced(s, f);
  refuse(s, {"--beta", "--omega", "--phase", "--t-transient", "--twin-d0", "--twin-csv", "--width", "--height",
             "--preset", "--restitution", "--ground-h", "--ground-h-amplitude", "--ground-h-pulse", "--ground-h-record",
             "--ground-v", "--ground-v-amplitude", "--ground-v-pulse", "--ground-v-record"},
         "applies to --model housner|rigid|assembly only (the Winkler block runs free here)");
  validate(f.p);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  require_writable("csv", f.csv);
  f.opt.integrator = f.integ;
  f.opt.method = f.method == "section" ? LyapunovMethod::Section : LyapunovMethod::Time;
  validate(f.opt);
  require_sample_count("interval", f.opt.interval, f.opt.t_end - f.opt.t_start);
  orbit_run_options(f.opt.t_end, f.integ);  // validates t_end and the tolerances
  const BlockStateVec z0 = ic_state(s, f.ic, f.p);
  const LyapunovResult r = block_lyapunov(f.p, z0, f.opt);

  std::string csv = f.csv;
  const bool temp = csv.empty() && !f.plot.empty();
  if (temp) csv = temp_path("lyapunov", ".csv");
  if (!csv.empty()) write_history(csv, r);
  if (!f.plot.empty()) {
    char title[256];
    std::snprintf(title, sizeof title, "r=%g k=%g mu=%g %s, %s method: LE = %.3f", f.p.r, f.p.k, f.p.mu,
                  f.ic.ic.c_str(), to_string(f.opt.method), r.exponent);
    run_python("plot_lyapunov.py", {csv, f.plot, title});
    if (temp) std::remove(csv.c_str());
  }
  nlohmann::ordered_json j = summary_head(f.p, f.integ, f.ic, z0);
  j["options"] = {{"method", to_string(f.opt.method)},
                  {"t_end", f.opt.t_end},
                  {"d0", f.opt.d0},
                  {"interval", f.opt.interval},
                  {"max_gap", f.opt.max_gap},
                  {"metric", "euclidean on (sqrt(k) (y - 1/2), w, x', y', w')"}};
  j["exponent"] = r.exponent;
  // Over the second half only: without the transient (settle down) that the running estimate
  // outgrows only as 1/t.
  j["exponent_second_half"] = tail_exponent(r, f.opt.t_start + 0.5 * (r.t_final - f.opt.t_start));
  j["status"] = to_string(r.status);
  j["note"] = r.note;
  j["t_final"] = r.t_final;
  j["renormalisations"] = r.renormalisations;
  j["deferrals"] = r.deferrals;
  j["resyncs"] = r.resyncs;
  // A coarse view of the convergence: the estimate at ~20 evenly spaced renormalisations.
  nlohmann::ordered_json h = nlohmann::ordered_json::array();
  const std::size_t n = r.history.size(), stride = std::max<std::size_t>(1, n / 20);
  for (std::size_t i = stride - 1; i < n; i += stride) h.push_back({{"t", r.history[i].t}, {"estimate", r.history[i].estimate}});
  j["history_coarse"] = h;
  if (!emit_summary(j, f.json, f.json_out)) {
    std::printf("largest Lyapunov exponent: %.6g (%s method, t = %.6g, %ld renormalisations, status %s)\n",
                r.exponent, to_string(f.opt.method), r.t_final, r.renormalisations, to_string(r.status));
    std::printf("over the second half: %.6g\n", tail_exponent(r, 0.5 * r.t_final));
    if (!r.note.empty()) std::printf("note: %s\n", r.note.c_str());
  }
}

void add(CLI::App& app) {
  auto f = std::make_shared<LyapunovFlags>();
  f->opt.t_end = 200;
  f->fm.model = "winkler";
  CLI::App* s = app.add_subcommand(
      "lyapunov",
      "largest Lyapunov exponent along an orbit: the free Winkler block (two-trajectory renormalisation) or a forced "
      "housner/rigid block or assembly (variational equation with saltation matrices at impacts)");
  // Lyapunov's --method (renormalisation) comes first: the integrator's is then --integrator-method.
  s->add_option("--method", f->method, "renormalise at fixed times (time) or on the w = 0 section (section)")
      ->check(CLI::IsMember({"time", "section"}))
      ->capture_default_str();
  add_orbit_options(*s, f->p, f->integ, f->ic);
  s->add_option("--t-end", f->opt.t_end, "final time (> 0)")->capture_default_str();
  s->add_option("--d0", f->opt.d0, "separation after each renormalisation, in [1e-14, 1e-2]")->capture_default_str();
  s->add_option("--interval", f->opt.interval, "time method: renormalisation interval (> 0)")->capture_default_str();
  s->add_option("--csv", f->csv, "write the convergence history (t, growth, estimate)");
  add_summary_options(*s, f->plot, "plot the running estimate against time (PNG + SVG)", f->json, f->json_out);
  add_forced_model_flags(*s, f->fm, {"winkler"});
  s->get_option("--model")->description("winkler (default: the free Winkler block, --r --mu --k), housner, rigid (a "
                                         "block on rigid ground, --width --height) or assembly (--preset)");
  add_ground_flags(*s, f->ground);
  s->add_option("--beta", f->beta, "forced: seed 002 excitation a_H = beta alpha g cos(Omega t + phase) (with --omega)");
  s->add_option("--omega", f->omega, "forced: Omega / p of the seed 002 excitation");
  s->add_option("--phase", f->phase, "forced: phase of the seed 002 excitation (rad, default 0)");
  s->add_option("--t-transient", f->t_transient, "forced: the tangent starts here (s), or at the first motion after it");
  s->add_option("--twin-d0", f->twin_d0,
                "forced: two nearby orbits this far apart in the rotation rate (units of p; 0: none; default 1e-9)");
  s->add_option("--twin-csv", f->twin_csv, "forced: write the two orbits' separation (t, separation, predicted)");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(52, add);

}  // namespace
}  // namespace blockdyn::cli
