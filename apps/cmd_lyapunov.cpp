// SPDX-License-Identifier: Apache-2.0
// `blockdyn lyapunov`: largest Lyapunov exponent along one orbit (thesis sec. 5.2.2), with its
// convergence history (running estimate against time).
#include <cstdio>
#include <iomanip>
#include <memory>

#include "blockdyn/analysis/winkler/lyapunov_block.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "chaos_cli.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
namespace {

struct LyapunovFlags {
  BlockParams p;
  IntegratorOptions integ;
  IcFlags ic;
  LyapunovOptions opt;
  std::string method = "time", csv, plot, json_out;
  bool json = false;
};

void write_history(const std::string& path, const LyapunovResult& r) {
  AtomicFile f(path);
  auto& o = f.stream();
  o << "t,growth,estimate\n" << std::setprecision(17);
  for (const auto& s : r.history) o << s.t << ',' << s.growth << ',' << s.estimate << '\n';
  f.commit();
}

void run(const CLI::App& s, LyapunovFlags& f) {
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
  CLI::App* s = app.add_subcommand("lyapunov", "largest Lyapunov exponent along an orbit (two-trajectory renormalisation)");
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
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(52, add);

}  // namespace
}  // namespace blockdyn::cli
