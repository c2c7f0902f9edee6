// SPDX-License-Identifier: Apache-2.0
// `blockdyn impact-map`: the forcing phase (Omega t + phase) mod 2 pi of every impact against the
// angular velocity just before it (issue 9 item 5; seed 002 Fig. 15b), and the forced Poincare
// map (the state once per forcing period at the forcing phase phi0), for a block on rigid ground
// or an assembly preset under a_H = beta alpha g cos(Omega t + phase).
#include <cmath>
#include <cstdio>
#include <memory>

#include "blockdyn/analysis/forced/impact_map.hpp"
#include "blockdyn/io/json_io.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "harmonic_run.hpp"
#include "trajectory_target.hpp"

namespace blockdyn::cli {
namespace {

struct ImpactMapFlags {
  HarmonicRunFlags r;
  double section_phase = 0;
  int transient = 0;
  std::string out, poincare, trace, plot, json_out;
  bool json = false, quiet = false;
};

void run(const CLI::App& s, const ImpactMapFlags& f) {
  require_range("section-phase", f.section_phase, -1e3, 1e3);
  require_range("transient", f.transient, 0, 1e7);
  require_writable("out", f.out);
  require_writable("poincare", f.poincare);
  require_writable("trace", f.trace);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  const HarmonicSetup h = setup_harmonic(s, f.r);
  const double t_from = f.transient * h.period;
  if (!(t_from < h.t_end))
    throw UsageError("transient: " + std::to_string(f.transient) + " periods leave nothing of a run of " +
                     std::to_string(h.t_end / h.period) + " periods");
  const double t0 = section_time(h.Omega, h.phase, f.section_phase);
  const bool fine = !f.trace.empty() || !f.plot.empty();
  const HarmonicRun r = run_harmonic(h, t0, fine ? f.r.trace_per_period : 1);
  const ForcedTrace& tr = *r.trace;
  const std::vector<ImpactMapPoint> map =
      impact_map(impacts_of(tr, h.block, h.fm.impact_rule), h.Omega, h.phase, t_from);
  std::size_t sections = 0;
  for (std::size_t k = 0; k < tr.strobes(); ++k) sections += tr.strobe_t(k) >= t_from;

  using json = nlohmann::ordered_json;
  json j;
  describe_run(j, h, r);
  j["phase_definition"] =
      "Phi = (Omega t + phase) mod 2 pi in [0, 2 pi): the forcing phase (seed 002: Omega t mod 2 pi, "
      "phase 0); omega_before / omega_after: the block's angular velocity before / after the impact";
  j["section_phase"] = f.section_phase;
  j["section_t0"] = t0;
  j["transient"] = f.transient;
  j["impacts"] = map.size();
  j["poincare_samples"] = sections;
  double wmin = INFINITY, wmax = -INFINITY;
  for (const ImpactMapPoint& p : map) {
    wmin = std::fmin(wmin, p.omega_before);
    wmax = std::fmax(wmax, p.omega_before);
  }
  j["omega_before_range"] = map.empty() ? json(nullptr) : json::array({wmin, wmax});

  TrajectoryTarget impacts(f.out, f.plot, "impacts");
  if (impacts.file) {
    std::ostream& os = impacts.file->stream();
    os << "i,t,phase,omega_before,omega_after\n";
    char buf[160];
    for (std::size_t i = 0; i < map.size(); ++i) {
      std::snprintf(buf, sizeof buf, "%zu,%.17g,%.17g,%.17g,%.17g\n", i, map[i].t, map[i].phase, map[i].omega_before,
                    map[i].omega_after);
      os << buf;
    }
  }
  TrajectoryTarget section(f.poincare, f.plot, "poincare");
  if (section.file) {
    write_samples_csv(section.file->stream(), tr, true, "", {}, t_from);
    section.file->commit();
    section.file.reset();
  }
  TrajectoryTarget trace(f.trace, f.plot, "trace");
  if (trace.file) {
    write_samples_csv(trace.file->stream(), tr, false, "", {}, t_from);
    trace.file->commit();
    trace.file.reset();
  }
  auto clean = [&] {
    section.figures_and_clean({});
    trace.figures_and_clean({});
  };
  try {
    impacts.figures_and_clean({{"plot_impact_map.py",
                                f.plot,
                                {"--poincare", section.path, "--trace", trace.path, "--block", std::to_string(h.block),
                                 "--section-phase", short_num(f.section_phase), "--period", short_num(h.period),
                                 "--title", run_title(h, f.r)}}});
  } catch (...) {
    clean();
    throw;
  }
  clean();
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json) emit_json(j, "-");
  if (!f.json && !f.quiet)
    std::printf("%zu impacts, %zu Poincare samples (phase %g), %s\n", map.size(), sections, f.section_phase,
                j["status"].get<std::string>().c_str());
}

void add(CLI::App& app) {
  auto f = std::make_shared<ImpactMapFlags>();
  CLI::App* s = app.add_subcommand(
      "impact-map",
      "impact map (forcing phase (Omega t + phase) mod 2 pi versus the angular velocity before each "
      "impact, seed 002 Fig. 15b) and forced Poincare map at a forcing phase, under a_H = beta alpha g "
      "cos(Omega t + phase)");
  add_harmonic_run_flags(*s, f->r, 200);
  s->add_option("--section-phase", f->section_phase,
                "forcing phase phi0 of the Poincare section: the state where Omega t + phase = phi0 mod 2 pi [rad] "
                "(default 0)");
  s->add_option("--transient", f->transient, "forcing periods left out of the maps (default 0)");
  s->add_option("--out", f->out, "write the impacts as CSV (i, t, phase, omega_before, omega_after)");
  s->add_option("--poincare", f->poincare, "write the Poincare section as CSV (k, t, states per block)");
  s->add_option("--trace", f->trace, "write the trajectory sampled --trace-per-period times per period as CSV");
  s->add_option("--plot", f->plot, "plot the trajectory, the impact map and the Poincare section (PNG + SVG)");
  s->add_flag("--json", f->json, "print the JSON summary");
  s->add_option("--json-out", f->json_out, "write the JSON summary here");
  s->add_flag("--quiet", f->quiet, "no summary line");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(17, add);

}  // namespace
}  // namespace blockdyn::cli
