// SPDX-License-Identifier: Apache-2.0
#include "harmonic_run.hpp"

#include <cmath>
#include <cstdio>

#include "blockdyn/io/json_io.hpp"
#include "cli_common.hpp"

namespace blockdyn::cli {

void add_harmonic_run_flags(CLI::App& s, HarmonicRunFlags& f, double default_periods) {
  f.periods = default_periods;
  add_forced_model_flags(s, f.m);
  s.add_option("--excitation", f.excitation, "harmonic (the only one: cycles need a periodic motion)")
      ->check(CLI::IsMember({"harmonic"}));
  s.add_option("--beta", f.beta, "amplitude: a_H = beta alpha g cos(Omega t + phase) (required)");
  s.add_option("--omega", f.omega, "frequency omega = Omega / p (required)");
  s.add_option("--phase", f.phase, "phase of cos(Omega t + phase) [rad] (default 0)");
  s.add_option("--t-end", f.t_end, "duration of the run [s]");
  s.add_option("--periods", f.periods,
               "duration of the run in forcing periods (instead of --t-end; default " +
                   std::to_string(int(default_periods)) + ")");
  s.add_option("--block", f.block, "the block analysed (assemblies: 0 is the first column; default 0)");
  s.add_option("--trace-per-period", f.trace_per_period,
               "samples per forcing period of --trace and of the figures' trajectories (default 32)");
}

HarmonicSetup setup_harmonic(const CLI::App& s, const HarmonicRunFlags& f) {
  if (!given(s, "--beta")) throw UsageError("--beta is needed (a_H = beta alpha g cos(Omega t + phase)), in (0, 1000]");
  if (!given(s, "--omega")) throw UsageError("--omega is needed (omega = Omega / p), in (0, 1e4]");
  require_range("beta", f.beta, 0, 1e3, false);
  require_range("omega", f.omega, 0, 1e4, false);
  require_range("phase", f.phase, -1e3, 1e3);
  if (given(s, "--t-end") && given(s, "--periods")) throw UsageError("give --t-end or --periods, not both");
  if (given(s, "--t-end"))
    require_range("t-end", f.t_end, 0, 1e5, false);
  else
    require_range("periods", f.periods, 0, 1e6, false);
  require_range("trace-per-period", f.trace_per_period, 1, 4096);
  HarmonicSetup h;
  h.fm = build_forced_model(s);
  require_range("block", f.block, 0, double(h.fm.block_names.size()) - 1);
  h.block = f.block;
  h.beta = f.beta;
  h.omega = f.omega;
  h.phase = f.phase;
  SurvivalOptions o;
  o.excitation = "harmonic";
  o.phase = f.phase;
  h.g = survival_motion(o, f.beta, f.omega, h.fm.alpha, h.fm.p);
  h.period = 1.0 / h.g.horizontal.frequency;
  h.Omega = 2 * M_PI * h.g.horizontal.frequency;
  h.t_end = given(s, "--t-end") ? f.t_end : f.periods * h.period;
  if (!(h.t_end <= 1e5))
    throw UsageError("periods: the run would last " + std::to_string(h.t_end) + " s, at most 1e5 s");
  if (h.t_end / h.period > 1e6) throw UsageError("t-end: more than 1e6 forcing periods");
  return h;
}

HarmonicRun run_harmonic(const HarmonicSetup& h, double t0, int per_period) {
  if (h.t_end / h.period * per_period > 1e7)
    throw UsageError("trace-per-period: " + std::to_string(per_period) + " samples per period over " +
                     std::to_string(h.t_end / h.period) + " periods exceed 1e7 samples");
  HarmonicRun r;
  r.trace = std::make_unique<ForcedTrace>(t0, h.period, per_period);
  r.trace->keep_events_of(h.block);
  try {
    r.outcome = h.fm.traced(h.g, h.t_end, r.trace.get());
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return r;
}

void write_samples_csv(std::ostream& os, const ForcedTrace& tr, bool strobe_only, const std::string& extra_header,
                       const std::function<std::string(double)>& extra, double t_from) {
  os << "k,t";
  for (int b = 0; b < tr.blocks(); ++b)
    for (const char* c : {"x", "y", "theta", "vx", "vy", "omega"}) os << ',' << c << '_' << b;
  if (!extra_header.empty()) os << ',' << extra_header;
  os << '\n';
  const std::size_t n = strobe_only ? tr.strobes() : tr.samples();
  const std::size_t step = strobe_only ? std::size_t(tr.per_period()) : 1;
  char buf[64];
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i * step;
    const double t = tr.sample_t(j);
    if (t < t_from) continue;
    std::snprintf(buf, sizeof buf, "%zu,%.17g", i, t);
    os << buf;
    for (int b = 0; b < tr.blocks(); ++b)
      for (double v : tr.state(j, b)) {
        std::snprintf(buf, sizeof buf, ",%.17g", v);
        os << buf;
      }
    if (extra) os << ',' << extra(t);
    os << '\n';
  }
}

void describe_run(nlohmann::ordered_json& j, const HarmonicSetup& h, const HarmonicRun& r) {
  using json = nlohmann::ordered_json;
  j["run"] = run_info();
  j["model"] = h.fm.description;
  j["alpha"] = h.fm.alpha;
  j["p"] = h.fm.p;
  j["units"] = "a_H = beta alpha g cos(Omega t + phase), omega = Omega / p; t in s, theta in rad, theta' in rad/s";
  j["excitation"] = {{"type", "harmonic"},
                     {"beta", h.beta},
                     {"omega", h.omega},
                     {"phase", h.phase},
                     {"Omega", h.Omega},
                     {"period", h.period},
                     {"frequency", 1.0 / h.period},
                     {"amplitude_g", h.beta * h.fm.alpha}};
  j["t_end"] = h.t_end;
  j["block"] = h.block;
  j["block_name"] = h.fm.block_names[h.block];
  j["impact_definition"] = h.fm.impact_definition;
  const SurvivalOutcome& o = r.outcome;
  j["status"] = o.invalid ? "invalid" : o.collapse_mode ? "collapse" : "t_end";
  j["motion"] = o.invalid ? "invalid" : o.collapse_mode ? "collapse" : o.moved ? "stable" : "rest";
  j["collapse_mode"] = o.collapse_mode ? json(*o.collapse_mode) : json(nullptr);
  j["t_failure"] = o.t_failure ? json(*o.t_failure) : json(nullptr);
  j["t_final"] = r.trace->t_final();
  j["max_abs_rotation"] = o.max_abs_rotation;
}

std::string short_num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string run_title(const HarmonicSetup& h, const HarmonicRunFlags& f) {
  return f.m.model + (f.m.preset.empty() ? "" : " " + f.m.preset) + ", beta = " + short_num(h.beta) +
         ", omega = " + short_num(h.omega) + ", phase = " + short_num(h.phase) + ", " + h.fm.block_names[h.block];
}

}  // namespace blockdyn::cli
