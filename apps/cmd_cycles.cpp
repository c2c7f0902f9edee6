// SPDX-License-Identifier: Apache-2.0
// `blockdyn cycles`: stroboscopic sampling at multiples of the forcing period and (m, n) cycle
// detection over sliding windows (issue 9 item 4; seed 002 Figs. 12-14) for a block on rigid
// ground or an assembly preset under a_H = beta alpha g cos(Omega t + phase).
#include <cstdio>
#include <memory>

#include "blockdyn/analysis/forced/cycle_detection.hpp"
#include "blockdyn/analysis/forced/forced_trace.hpp"
#include "blockdyn/io/json_io.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "harmonic_run.hpp"
#include "trajectory_target.hpp"

namespace blockdyn::cli {
namespace {

constexpr const char* kConvention =
    "(m, n): 2m impacts in an orbit that repeats every n forcing periods (seed 002); seed 001 calls a motion with k "
    "impacts per n forcing periods an (n, k) motion, i.e. our (m, n) is its (n, 2m)";

struct CyclesFlags {
  HarmonicRunFlags r;
  CycleOptions c;
  std::string out, trace, plot, json_out;
  bool json = false, quiet = false;
};

nlohmann::ordered_json segment_json(const CycleSegment& s, double period) {
  using json = nlohmann::ordered_json;
  const bool periodic = s.type == "periodic";
  json m = nullptr;
  if (periodic) m = s.impacts_per_cycle % 2 == 0 ? json(s.impacts_per_cycle / 2) : json(s.m());
  return {{"t_start", s.t_start},
          {"t_end", s.t_end},
          {"type", s.type},
          {"m", m},
          {"n", periodic ? json(s.n) : json(nullptr)},
          {"cycle", s.label()},
          {"impacts", s.impacts},
          {"periods", (s.t_end - s.t_start) / period},
          {"return_distance", periodic ? json(s.return_distance) : json(nullptr)}};
}

void run(const CLI::App& s, const CyclesFlags& f) {
  CycleOptions c = f.c;
  try {
    validate(c);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  require_writable("out", f.out);
  require_writable("trace", f.trace);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  const HarmonicSetup h = setup_harmonic(s, f.r);
  const bool fine = !f.trace.empty() || !f.plot.empty();
  const HarmonicRun r = run_harmonic(h, 0.0, fine ? f.r.trace_per_period : 1);
  const ForcedTrace& tr = *r.trace;
  const std::vector<Impact> imp = impacts_of(tr, h.block, h.fm.impact_rule);
  const long periods = long(tr.strobes()) - 1;
  const CycleReport rep = cycles_of(tr, h.block, h.fm.impact_rule, c, r.outcome.t_failure);

  using json = nlohmann::ordered_json;
  json j;
  describe_run(j, h, r);
  j["convention"] = kConvention;
  j["options"] = {{"window", c.window},
                  {"max_period", c.max_period},
                  {"tolerance", c.tolerance},
                  {"transient", c.transient},
                  {"strobe", "t = k T, k = 0, 1, ... (forcing phase = phase)"},
                  {"compared", "theta and theta' of the block, relative to their largest magnitudes in the window"}};
  j["strobe_samples"] = tr.strobes();
  j["impacts"] = imp.size();
  j["windows"] = rep.windows;
  if (rep.windows == 0)
    j["note"] = "the run offers " + std::to_string(periods - c.transient) +
                " periods after the transient, fewer than "
                "one window of " +
                std::to_string(c.window) + ": no cycle classified";
  json segs = json::array();
  for (const CycleSegment& sg : rep.segments) segs.push_back(segment_json(sg, h.period));
  j["segments"] = segs;
  json ch = json::array();
  for (const CycleChange& x : rep.changes) ch.push_back({{"t", x.t}, {"from", x.from}, {"to", x.to}});
  j["changes"] = ch;
  j["dominant_cycle"] = rep.dominant.empty() ? json(nullptr) : json(rep.dominant);

  // The cycle label of the segment holding t (the last segment's up to its end).
  auto label_at = [&](double t) -> std::string {
    for (const CycleSegment& sg : rep.segments)
      if (sg.type != "collapse" && t >= sg.t_start && t <= sg.t_end) return '"' + sg.label() + '"';
    return c.transient > 0 && t < c.transient * h.period ? "transient" : "";
  };
  TrajectoryTarget strobe(f.out, f.plot, "strobe");
  if (strobe.file) write_samples_csv(strobe.file->stream(), tr, true, "cycle", label_at);
  TrajectoryTarget trace(f.trace, f.plot, "trace");
  if (trace.file) {
    write_samples_csv(trace.file->stream(), tr, false);
    trace.file->commit();
    trace.file.reset();
  }
  const std::string title = run_title(h, f.r);
  try {
    strobe.figures_and_clean({{"plot_cycles.py",
                               f.plot,
                               {"--trace", trace.path, "--block", std::to_string(h.block), "--period",
                                short_num(h.period), "--title", title}}});
  } catch (...) {
    trace.figures_and_clean({});
    throw;
  }
  trace.figures_and_clean({});
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json) emit_json(j, "-");
  if (!f.json && !f.quiet) {
    std::printf("%zu strobe samples, %zu impacts, %s\n", tr.strobes(), imp.size(),
                j["status"].get<std::string>().c_str());
    for (const CycleSegment& sg : rep.segments)
      std::printf("  %10.4f .. %10.4f s  %s\n", sg.t_start, sg.t_end, sg.label().c_str());
  }
}

void add(CLI::App& app) {
  auto f = std::make_shared<CyclesFlags>();
  CLI::App* s = app.add_subcommand(
      "cycles",
      "stroboscopic samples at multiples of the forcing period and (m, n) cycles (2m impacts per n "
      "forcing periods, seed 002) over sliding windows, under a_H = beta alpha g cos(Omega t + phase)");
  add_harmonic_run_flags(*s, f->r, 100);
  s->add_option("--window", f->c.window, "forcing periods per sliding window (default 24)");
  s->add_option("--max-period", f->c.max_period, "largest n tried, at most window / 2 (default 12)");
  s->add_option("--tolerance", f->c.tolerance,
                "largest return distance of the strobe samples after n periods, relative to the window's largest "
                "|theta| and |theta'| (default 0.05)");
  s->add_option("--transient", f->c.transient, "forcing periods skipped before the first window (default 0)");
  s->add_option("--out", f->out, "write the strobe samples as CSV (k, t, states per block, cycle)");
  s->add_option("--trace", f->trace, "write the trajectory sampled --trace-per-period times per period as CSV");
  s->add_option("--plot", f->plot, "plot the strobe samples and the phase portraits of the cycles (PNG + SVG)");
  s->add_flag("--json", f->json, "print the JSON summary");
  s->add_option("--json-out", f->json_out, "write the JSON summary here");
  s->add_flag("--quiet", f->quiet, "no summary lines");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(16, add);

}  // namespace
}  // namespace blockdyn::cli
