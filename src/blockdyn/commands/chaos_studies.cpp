// SPDX-License-Identifier: Apache-2.0
// `lyapunov`: the largest Lyapunov exponent along one orbit with its convergence history: the free
// Winkler block (thesis sec. 5.2.2, two-trajectory renormalisation) or a forced block or assembly
// whose state jumps at impacts (variational equation with saltation matrices), with a
// sensitive-dependence check (two nearby orbits).
// `chaos-map`: the largest Lyapunov exponent over (beta, omega) for seed 002's harmonic excitation
// a_H = beta alpha g cos(Omega t + phase), omega = Omega / p, each point from rest through a
// transient, classified rest / superstable / periodic / neutral / chaotic / collapse
// (analysis/forced/chaos_map.hpp), for a block on rigid ground or an assembly preset.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/forced/chaos_map.hpp"
#include "blockdyn/analysis/forced/forced_lyapunov_report.hpp"
#include "blockdyn/analysis/winkler/lyapunov_block.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/forced_model_settings.hpp"
#include "blockdyn/commands/ground_settings.hpp"
#include "blockdyn/commands/harmonic_run.hpp"
#include "blockdyn/commands/winkler_orbit.hpp"
#include "blockdyn/family/family.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

std::vector<StudyOption> chaos_map_options() {
  const ChaosMapOptions d;
  std::vector<StudyOption> o = forced_model_options();
  auto x = [](double v) { return Settings::exact(v); };
  const std::vector<StudyOption> own = {
      {"excitation", "harmonic (the exponent needs a periodic motion)", "harmonic"},
      {"phase", "phase of cos(Omega t + phase) [rad]", x(d.grid.phase)},
      {"omega-min", "smallest omega = Omega/p", x(d.grid.omega_min)},
      {"omega-max", "largest omega", x(d.grid.omega_max)},
      {"omega-points", "omegas, uniform", std::to_string(d.grid.omega_points)},
      {"t-end", "duration of each run [s] (instead of `periods`)", ""},
      {"periods", "forcing periods per run, transient included", x(d.total_periods)},
      {"threads", "worker threads (0: all cores)", "0"},
      {"beta-min", "smallest beta", x(d.grid.beta_min)},
      {"beta-max", "largest beta", x(d.grid.beta_max)},
      {"beta-points", "betas, uniform", "10"},
      {"transient-periods", "forcing periods before the measurement", x(d.transient_periods)},
      {"interval-periods", "renormalisation interval in forcing periods", x(d.interval_periods)},
      {"threshold", "chaotic above, periodic below minus this exponent / p", x(d.threshold)},
      {"rtol", "relative tolerance (default 1e-10; assembly 1e-6)", ""},
      {"atol", "absolute tolerance (default 1e-12; assembly 1e-8)", ""}};
  o.insert(o.end(), own.begin(), own.end());
  return o;
}

ChaosMapOptions chaos_options_of(const StudyOptions& s) {
  ChaosMapOptions o;
  o.grid.excitation = s.text("excitation");
  o.grid.phase = s.number("phase");
  o.grid.omega_min = s.number("omega-min");
  o.grid.omega_max = s.number("omega-max");
  o.grid.omega_points = s.small_integer("omega-points");
  o.grid.beta_min = s.number("beta-min");
  o.grid.beta_max = s.number("beta-max");
  o.grid.beta_points = s.small_integer("beta-points");
  o.grid.threads = s.threads();
  if (s.given("t-end") && s.given("periods")) throw std::invalid_argument("give `t-end` or `periods`, not both");
  o.use_t_end = s.given("t-end");
  if (o.use_t_end) o.grid.t_end = s.number("t-end");
  o.total_periods = s.number("periods");
  o.transient_periods = s.number("transient-periods");
  o.interval_periods = s.number("interval-periods");
  o.threshold = s.number("threshold");
  // The family's defaults (an assembly's tangent carries stiff contact modes: ForcedFamily).
  const ForcedFamily& ff = *forced_family(s.text("model")).forced;
  o.integrator.rtol = s.given("rtol")         ? s.number("rtol")
                      : ff.chaos_map_rtol > 0 ? ff.chaos_map_rtol
                                              : o.integrator.rtol;
  o.integrator.atol = s.given("atol")         ? s.number("atol")
                      : ff.chaos_map_atol > 0 ? ff.chaos_map_atol
                                              : o.integrator.atol;
  validate(o);
  WinklerRunOptions so;
  so.integrator = o.integrator;
  validate(so);
  return o;
}

// A model without a variational equation (the 3D body, for now) has no Lyapunov exponent.
void require_lyapunov(const ForcedModel& fm) {
  if (!fm.lyapunov)
    throw std::invalid_argument("`model` " + fm.description.value("model", std::string("?")) +
                                ": no Lyapunov exponent (its variational equation is not available yet)");
}

StudyReport chaos_map_study(const Settings& given, const StudyRequest& request) {
  const StudyOptions s(given, chaos_map_options());
  const ChaosMapOptions o = chaos_options_of(s);
  const ForcedModel fm = forced_model_of(s);
  require_lyapunov(fm);
  if (!fm.linearisable)
    throw std::invalid_argument("`contact` " + fm.description["contact"].get<std::string>() +
                                ": no Lyapunov exponent (Moreau-Jean time-stepping); use `contact` deformable");
  const auto lyap = fm.lyapunov;
  const ForcedLyapunovRun run = [lyap](const GroundMotion& g, const ForcedLyapunovOptions& fo) {
    return lyap(g, fo, RigidInitial{});
  };
  const std::size_t n = std::size_t(o.grid.beta_points) * std::size_t(o.grid.omega_points);
  std::size_t done = 0;
  request.advance(0, n);
  const auto pts = chaos_map(run, o, fm.alpha, fm.p, [&](std::size_t) { request.advance(++done, n); });

  StudyReport rep;
  json& j = rep.summary;
  j = forced_summary_head(fm);
  j["units"] = "a_H = beta alpha g cos(omega p t + phase); exponent in 1/s, exponent_nondim = exponent / p";
  j["options"] = {{"phase", o.grid.phase},
                  {"periods", o.use_t_end ? json(nullptr) : json(o.total_periods)},
                  {"t_end", o.use_t_end ? json(o.grid.t_end) : json(nullptr)},
                  {"transient_periods", o.transient_periods},
                  {"interval_periods", o.interval_periods},
                  {"threshold", o.threshold},
                  {"method", "variational equation with saltation matrices, Benettin renormalisation"},
                  {"failure", fm.overturn_rule}};
  j["integrator"] = to_json(o.integrator);
  j["counts"] = chaos_counts_json(pts);
  j["points"] = chaos_points_json(pts);
  if (request.wants("points")) {
    rep.series.push_back({"points", chaos_table(pts)});
  }
  rep.figure = FigureSpec{"chaos_map",
                          {"@csv:points", "@plot"},
                          {{"title", {forced_model_label(s) + ": largest Lyapunov exponent"}},
                           {"threshold", {std::to_string(o.threshold)}}}};
  append_text(rep.text, "%zu points:", pts.size());
  for (const std::string& m : chaos_motions()) append_text(rep.text, " %ld %s", j["counts"][m].get<long>(), m.c_str());
  rep.text += "\n";
  return rep;
}

// ---------------------------------------------------------------- lyapunov

std::vector<StudyOption> lyapunov_options() {
  const LyapunovOptions d;
  std::vector<StudyOption> o = {
      {"method", "renormalise at fixed times (time) or on the w = 0 section (section)", "time"}};
  for (const StudyOption& x : winkler_orbit_options("integrator-method")) o.push_back(x);
  for (StudyOption x : forced_model_options({"winkler"})) {
    if (x.name == "model")
      x.help =
          "winkler (default: the free Winkler block, `r` `mu` `k`), housner, rigid (a block on rigid ground, "
          "`width` `height`) or assembly (`preset`)";
    o.push_back(x);
  }
  for (const StudyOption& x : ground_options()) o.push_back(x);
  const std::vector<StudyOption> own = {
      {"t-end", "final time (> 0)", "200"},
      {"d0", "separation after each renormalisation, in [1e-14, 1e-2]", Settings::exact(d.d0)},
      {"interval", "time method: renormalisation interval (> 0)", Settings::exact(d.interval)},
      {"beta", "forced: seed 002 excitation a_H = beta alpha g cos(Omega t + phase) (with `omega`)", ""},
      {"omega", "forced: Omega / p of the seed 002 excitation", ""},
      {"phase", "forced: phase of the seed 002 excitation (rad, default 0)", ""},
      {"t-transient", "forced: the tangent starts here (s), or at the first motion after it", ""},
      {"twin-d0", "forced: two nearby orbits this far apart in the rotation rate (units of p; 0: none; default 1e-9)",
       ""}};
  o.insert(o.end(), own.begin(), own.end());
  return o;
}

void refuse_given(const StudyOptions& o, const std::vector<std::string>& names, const std::string& why) {
  for (const std::string& n : names)
    if (o.given(n)) throw std::invalid_argument(std::string("`") + n + "` " + why);
}

StudyTable history_table(const std::vector<LyapunovSample>& history) {
  StudyTable t;
  t.columns = {"t", "growth", "estimate"};
  for (const auto& s : history) t.rows.push_back({s.t, s.growth, s.estimate});
  return t;
}

// The forced motion: seed 002's form (--beta --omega) or the ground options; T the default
// renormalisation interval (a forcing period, else 2 pi / p).
struct ForcedExcitation {
  GroundMotion g;
  double T = 0;
  json description = nullptr;
};

ForcedExcitation forced_excitation(const StudyOptions& o, const ForcedModel& fm) {
  ForcedExcitation x;
  x.T = 2 * M_PI / fm.p;
  if (o.given("beta") || o.given("omega")) {
    if (!o.given("beta") || !o.given("omega")) throw std::invalid_argument("`beta` and `omega` go together");
    const double beta = o.number("beta"), omega = o.number("omega");
    const double phase = o.given("phase") ? o.number("phase") : 0.0;
    require_in_range("beta", beta, 0, 1e3, false);
    require_in_range("omega", omega, 0, 1e4, false);
    require_in_range("phase", phase, -1e3, 1e3);
    SurvivalOptions so;
    so.phase = phase;
    x.g = survival_motion(so, beta, omega, fm.alpha, fm.p);
    x.T = 2 * M_PI / (omega * fm.p);
    x.description = {
        {"form", "a_H = beta alpha g cos(omega p t + phase)"}, {"beta", beta}, {"omega", omega}, {"phase", phase}};
    return x;
  }
  apply_ground_settings(o.given_settings(), x.g);
  if (x.g.horizontal.frequency > 0 && !x.g.horizontal.has_pulse()) x.T = 1.0 / x.g.horizontal.frequency;
  return x;
}

ForcedLyapunovOptions forced_lyapunov_options(const StudyOptions& o, double T) {
  const ForcedFamily& ff = *forced_family(o.text("model")).forced;
  ForcedLyapunovOptions f;
  f.t_end = o.number("t-end");
  f.t_transient = o.given("t-transient") ? o.number("t-transient") : 0.0;
  f.interval = o.given("interval") ? o.number("interval") : T;
  f.integrator.rtol = o.given("rtol") ? o.number("rtol") : ff.lyapunov_rtol;
  f.integrator.atol = o.given("atol") ? o.number("atol") : ff.lyapunov_atol;
  const auto m = method_from_string(o.text("integrator-method"));
  if (!m)
    throw std::invalid_argument("`integrator-method` = '" + o.text("integrator-method") +
                                "' is not one of: auto, dopri5, dop853");
  f.integrator.method = *m;
  f.twin_d0 = o.given("twin-d0") ? o.number("twin-d0") : 1e-9;
  validate(f);
  orbit_run_options(f.t_end, f.integrator);  // validates the tolerances
  return f;
}

RigidInitial forced_initial(const StudyOptions& o) {
  if (!forced_family(o.text("model")).forced->initial_state)
    refuse_given(o, {"w0", "vw0", "x0", "y0", "vx0", "vy0"}, "does not apply to assemblies (they start as built)");
  RigidInitial init;
  init.w0 = o.given("w0") ? o.number("w0") : 0.0;
  init.vw0 = o.given("vw0") ? o.number("vw0") : 0.0;
  if (o.given("x0")) init.x0 = o.number("x0");
  if (o.given("y0")) init.y0 = o.number("y0");
  if (o.given("vx0")) init.vx0 = o.number("vx0");
  if (o.given("vy0")) init.vy0 = o.number("vy0");
  return init;
}

StudyReport forced_lyapunov_study(const StudyOptions& o, const StudyRequest& request) {
  refuse_given(o, {"r", "mu", "k", "ic", "energy", "energy-of", "vy-sign", "w0-alpha", "d0"},
               "applies to `model` winkler only (forced models: `w0` `vw0`, `twin-d0`)");
  if (o.text("method") != "time")
    throw std::invalid_argument("`method` " + o.text("method") + ": forced models renormalise at fixed times only");
  const ForcedModel fm = forced_model_of(o);
  require_lyapunov(fm);
  if (!fm.linearisable)
    throw std::invalid_argument("`contact` " + fm.description["contact"].get<std::string>() +
                                ": no Lyapunov exponent (Moreau-Jean time-stepping has no event-located orbit to "
                                "linearise); use `contact` deformable");
  const ForcedExcitation x = forced_excitation(o, fm);
  const ForcedLyapunovOptions f = forced_lyapunov_options(o, x.T);
  const ForcedLyapunovOutcome r = fm.lyapunov(x.g, f, forced_initial(o));
  const TangentLyapunovResult& tl = r.tangent;

  StudyReport rep;
  rep.summary = forced_lyapunov_summary(fm, x.g, x.description, f, r);
  if (request.wants("history")) rep.series.push_back({"history", history_table(tl.history)});
  if (request.wants("twin")) {
    rep.series.push_back({"twin", twin_table(r)});
  }
  char title[256];
  std::snprintf(title, sizeof title, "%s, tangent + saltation: LE = %.4g 1/s (%.4g p)", o.text("model").c_str(),
                tl.exponent, tl.exponent / fm.p);
  rep.figure = FigureSpec{"lyapunov", {"@csv:history", "@plot", title}, {}};
  append_text(rep.text,
              "largest Lyapunov exponent: %.6g 1/s = %.6g p (%s, tangent + saltation, t = %.6g, %ld renormalisations, "
              "%ld impacts)\n",
              tl.exponent, tl.exponent / fm.p, to_string(tl.status), tl.t_final, tl.renormalisations, r.impacts);
  append_text(rep.text, "over the second half: %.6g 1/s\n", r.exponent_second_half);
  if (!r.twin.empty())
    append_text(rep.text, "two orbits %.3g apart: separation %.3g at t = %.6g\n", f.twin_d0, r.twin.back().separation,
                r.twin.back().t);
  if (!tl.note.empty()) append_text(rep.text, "note: %s\n", tl.note.c_str());
  return rep;
}

}  // namespace

StudyReport winkler_lyapunov_study(const StudyOptions& o, const StudyRequest& request) {
  std::vector<std::string> forced_only = {"beta", "omega", "phase", "t-transient", "twin-d0"};
  for (const StudyOption& x : forced_model_options())
    if (x.name != "model") forced_only.push_back(x.name);
  for (const char* g : {"ground-h", "ground-h-amplitude", "ground-h-pulse", "ground-h-record", "ground-v",
                        "ground-v-amplitude", "ground-v-pulse", "ground-v-record"})
    forced_only.push_back(g);
  refuse_given(o, forced_only, "applies to `model` housner|rigid|assembly only (the Winkler block runs free here)");
  if (request.asked("twin"))
    throw std::invalid_argument(
        "`twin-csv` applies to `model` housner|rigid|assembly only (the Winkler block runs free here)");
  const WinklerParams p{o.number("r"), o.number("mu"), o.number("k")};
  validate(p);
  LyapunovOptions opt;
  opt.t_end = o.number("t-end");
  opt.d0 = o.number("d0");
  opt.interval = o.number("interval");
  const std::string method = o.text("method");
  if (method != "time" && method != "section")
    throw std::invalid_argument("`method` = '" + method + "' is not one of: time, section");
  opt.method = method == "section" ? LyapunovMethod::Section : LyapunovMethod::Time;
  const WinklerOrbit orbit = winkler_orbit(o, "integrator-method");
  opt.integrator = orbit.integrator;
  validate(opt);
  require_sample_count("interval", opt.interval, opt.t_end - opt.t_start, 1e7);
  orbit_run_options(opt.t_end, orbit.integrator);  // validates t_end and the tolerances
  const LyapunovResult r = block_lyapunov(orbit.p, orbit.z0, opt);

  StudyReport rep;
  if (request.wants("history")) rep.series.push_back({"history", history_table(r.history)});
  char title[256];
  std::snprintf(title, sizeof title, "r=%g k=%g mu=%g %s, %s method: LE = %.3f", p.r, p.k, p.mu, orbit.ic.c_str(),
                to_string(opt.method), r.exponent);
  rep.figure = FigureSpec{"lyapunov", {"@csv:history", "@plot", title}, {}};
  json& j = rep.summary;
  j = orbit_summary_head(orbit);
  j["options"] = {{"method", to_string(opt.method)},
                  {"t_end", opt.t_end},
                  {"d0", opt.d0},
                  {"interval", opt.interval},
                  {"max_gap", opt.max_gap},
                  {"metric", "euclidean on (sqrt(k) (y - 1/2), w, x', y', w')"}};
  j["exponent"] = r.exponent;
  // Over the second half only: without the transient (settle down) that the running estimate
  // outgrows only as 1/t.
  j["exponent_second_half"] = tail_exponent(r, opt.t_start + 0.5 * (r.t_final - opt.t_start));
  j["status"] = to_string(r.status);
  j["note"] = r.note;
  j["t_final"] = r.t_final;
  j["renormalisations"] = r.renormalisations;
  j["deferrals"] = r.deferrals;
  j["resyncs"] = r.resyncs;
  // A coarse view of the convergence: the estimate at ~20 evenly spaced renormalisations.
  json h = json::array();
  const std::size_t n = r.history.size(), stride = std::max<std::size_t>(1, n / 20);
  for (std::size_t i = stride - 1; i < n; i += stride)
    h.push_back({{"t", r.history[i].t}, {"estimate", r.history[i].estimate}});
  j["history_coarse"] = h;
  append_text(rep.text, "largest Lyapunov exponent: %.6g (%s method, t = %.6g, %ld renormalisations, status %s)\n",
              r.exponent, to_string(opt.method), r.t_final, r.renormalisations, to_string(r.status));
  append_text(rep.text, "over the second half: %.6g\n", tail_exponent(r, 0.5 * r.t_final));
  if (!r.note.empty()) append_text(rep.text, "note: %s\n", r.note.c_str());
  return rep;
}

namespace {

StudyReport lyapunov_study(const Settings& given, const StudyRequest& request) {
  const StudyOptions o(given, lyapunov_options());
  const Family& f =
      family_named("`model`", o.text("model"), [](const Family& x) { return x.free_lyapunov || x.forced; });
  return f.free_lyapunov ? f.free_lyapunov(o, request) : forced_lyapunov_study(o, request);
}

}  // namespace

void add_chaos_studies(std::vector<StudyCommand>& to) {
  StudyCommand lyapunov{"lyapunov",
                        "largest Lyapunov exponent along an orbit: the free Winkler block (two-trajectory "
                        "renormalisation) or a forced housner/rigid block or assembly (variational equation with "
                        "saltation matrices at impacts)",
                        52,
                        StudyOutputs::Series,
                        lyapunov_options(),
                        lyapunov_study};
  lyapunov.series_outputs = {
      {"history", "csv", "write the convergence history (t, growth, estimate)"},
      {"twin", "twin-csv", "forced: write the two orbits' separation (t, separation, predicted)"}};
  to.push_back(lyapunov);
  StudyCommand map{"chaos-map",
                   "largest Lyapunov exponent over (beta, omega) for a_H = beta alpha g cos(Omega t + phase), "
                   "omega = Omega/p (seed 002): rest, superstable, periodic, neutral, chaotic or collapse per point",
                   16,
                   StudyOutputs::Series,
                   chaos_map_options(),
                   chaos_map_study};
  map.series_outputs = {{"points", "out", "write the points as CSV"}};
  map.quiet_flag = true;
  map.progress_flag = true;
  to.push_back(map);
}

}  // namespace blockdyn
