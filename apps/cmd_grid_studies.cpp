// SPDX-License-Identifier: Apache-2.0
// Every library grid study (blockdyn/commands/grid_studies.hpp: spectrum, survival) as a subcommand:
// its options from the study's description, its points on the sweep runner (threads, MPI ranks,
// journal and --resume, progress), then its report from the finished table: JSON, figures, text.
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <map>
#include <memory>

#include "blockdyn/commands/grid_studies.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "figure_script.hpp"
#include "grid_run.hpp"

namespace blockdyn::cli {
// Each command's own names (add, Flags, ...) in its own namespace: the files build as one unity.
namespace cmd_grid_studies {
namespace {

struct GridStudyFlags {
  GridRunFlags g;
  std::string csv, json_out, progress = "auto";
  std::map<std::string, std::string> figures;  // output option -> path
  bool json = false, quiet = false;
};

std::vector<std::string> output_flags(const GridStudyCommand& c) {
  std::vector<std::string> n{"--" + c.csv_flag, "--json",   "--json-out",  "--progress",
                             "--quiet",         "--resume", "--overwrite", "--progress-interval"};
  for (const StudyOption& fig : c.figures) n.push_back("--" + fig.name);
  return n;
}

void run_figure(const std::string& script, const std::vector<std::string>& args, const std::string& csv,
                const std::string& out) {
  std::vector<std::string> a;
  for (const std::string& x : args) a.push_back(x == "@plot" ? out : x == "@csv:table" ? csv : x);
  run_python(script, a);
}

// The CSV the figure scripts read: the table itself when it is a regular file, else (a FIFO, a
// device) a scratch copy from memory, removed afterwards.
class FigureTable {
 public:
  FigureTable(const std::string& csv, const Table& t) : path_(csv) {
    struct stat st {};
    if (::stat(csv.c_str(), &st) == 0 && S_ISREG(st.st_mode)) return;
    path_ = "/tmp/blockdyn-figure-table-" + std::to_string(::getpid()) + ".csv";
    guard_ = std::make_unique<RemoveOnSignal>(path_);
    write_file_atomically(path_, csv_text(t));
    scratch_ = true;
  }
  ~FigureTable() {
    if (scratch_) std::remove(path_.c_str());
  }
  FigureTable(const FigureTable&) = delete;
  FigureTable& operator=(const FigureTable&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  bool scratch_ = false;
  std::unique_ptr<RemoveOnSignal> guard_;
};

void run(const GridStudyCommand& c, const CLI::App& s, const GridStudyFlags& f) {
  const Settings given = settings_of(s, output_flags(c));
  std::vector<std::string> known;
  for (const StudyOption& o : c.options) known.push_back(o.name);
  given.require_known(known, c.name);
  c.prepare(given, "");  // usage errors before any file is made
  const GridOutput out("--" + c.csv_flag, f.csv, c.name, f.g, f.json_out);
  for (const auto& [flag, path] : f.figures) require_writable(flag, path);
  require_writable("json-out", f.json_out);
  const GridStudy study = c.prepare(given, out.csv());
  const GridRunResult res = run_grid(*study.table, f.g, study.threads, f.progress, f.quiet, study.plan.get());
  if (!res.root) return;  // the other ranks computed their share of the points
  const StudyReport r = study.finish(res.outcome.table);
  const std::string& plot = f.figures.at("plot");
  bool figures = !plot.empty();
  for (const auto& more : r.more_figures)
    if (const auto it = f.figures.find(more.first); it != f.figures.end() && !it->second.empty()) figures = true;
  if (figures) {
    const FigureTable table(out.csv(), res.outcome.table);
    if (!plot.empty()) run_figure(plot_script(r.figure), figure_arguments(r.figure), table.path(), plot);
    for (const auto& [flag, figure] : r.more_figures)
      if (const auto it = f.figures.find(flag); it != f.figures.end() && !it->second.empty())
        run_figure(plot_script(figure), figure_arguments(figure), table.path(), it->second);
  }
  if (!f.json_out.empty()) emit_json(r.summary, f.json_out);
  if (f.json) emit_json(r.summary, "-");
  if (!f.json && !f.quiet) std::printf("%s %s\n", r.text.c_str(), grid_run_note(res).c_str());
}

void add(CLI::App& app, const GridStudyCommand& c) {
  auto f = std::make_shared<GridStudyFlags>();
  CLI::App* s = app.add_subcommand(c.name, cli_text(c.description));
  add_spec_options(*s, c.options);
  s->add_option("--" + c.csv_flag, f->csv, cli_text(c.csv_help));
  for (const StudyOption& fig : c.figures) s->add_option("--" + fig.name, f->figures[fig.name], cli_text(fig.help));
  add_grid_report_flags(*s, f->g, f->json, f->json_out, f->progress, f->quiet, cli_text(c.quiet_help));
  s->callback([&c, s, f] { run(c, *s, *f); });
}

const bool registered = [] {
  for (const GridStudyCommand& c : grid_study_commands())
    command_registry().push_back({c.order, [&c](CLI::App& app) { add(app, c); }, MpiUse::Distributes});
  return true;
}();

}  // namespace
}  // namespace cmd_grid_studies
}  // namespace blockdyn::cli
