// SPDX-License-Identifier: Apache-2.0
// `blockdyn survival`: survival domains over (beta, omega) for seed 002's excitation
// a_H = beta alpha g cos(Omega t + phase), omega = Omega / p (the library's grid study,
// api/grid_studies.cpp), its points on the sweep runner (threads, MPI, journal, resume, progress).
#include <cstdio>
#include <memory>

#include "blockdyn/api/grid_studies.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "grid_run.hpp"

namespace blockdyn::cli {
namespace {

struct SurvivalFlags {
  GridRunFlags g;
  std::string out, plot, json_out, progress = "auto";
  bool json = false, quiet = false;
};

void run(const CLI::App& s, const SurvivalFlags& f) {
  const GridStudyCommand& c = grid_study_command("survival");
  const Settings given = settings_of(s, {"--out", "--plot", "--json", "--json-out", "--progress", "--quiet", "--resume",
                                         "--overwrite", "--progress-interval"});
  given.require_known(
      [&] {
        std::vector<std::string> n;
        for (const StudyOption& o : c.options) n.push_back(o.name);
        return n;
      }(),
      "survival");
  GridStudy study = c.prepare(given, "");  // usage errors before any file is made
  const GridOutput out("--out", f.out, "survival", f.g, f.json_out);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  study = c.prepare(given, out.csv());
  const GridRunResult res = run_grid(*study.table, f.g, study.threads, f.progress, f.quiet, study.plan.get());
  if (!res.root) return;
  const StudyReport r = study.finish(read_table(out.csv(), study.table->header()));
  if (!f.plot.empty()) {
    std::vector<std::string> args;
    for (const std::string& a : r.plot_args) args.push_back(a == "@plot" ? f.plot : a == "@csv:table" ? out.csv() : a);
    run_python(r.plot_script, args);
  }
  if (!f.json_out.empty()) emit_json(r.summary, f.json_out);
  if (f.json) emit_json(r.summary, "-");
  if (!f.json && !f.quiet) std::printf("%s %s\n", r.text.c_str(), grid_run_note(res).c_str());
}

void add(CLI::App& app) {
  auto f = std::make_shared<SurvivalFlags>();
  CLI::App* s = app.add_subcommand(
      "survival",
      "survival domain over (beta, omega): rest, stable or collapse per point for a_H = beta alpha g "
      "cos(Omega t + phase), omega = Omega/p (seed 002), harmonic or as a half-period pulse "
      "(threads, MPI, resumable)");
  add_spec_options(*s, grid_study_command("survival").options);
  s->add_option("--out", f->out, "the points as CSV (the runner's table: journal and sidecar .json beside it)");
  s->add_option("--plot", f->plot, "plot the survival domain (PNG + SVG) in the style of seed 002");
  add_grid_report_flags(*s, f->g, f->json, f->json_out, f->progress, f->quiet, "no summary line, no progress");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(14, add, MpiUse::Distributes);

}  // namespace
}  // namespace blockdyn::cli
