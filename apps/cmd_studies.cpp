// SPDX-License-Identifier: Apache-2.0
// Every library study (blockdyn/commands/study_command.hpp) as a subcommand: its options from the
// study's description, its outputs written here (CSV with sidecar, figure, JSON, text).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "blockdyn/commands/study_command.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/progress.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "figure_script.hpp"
#include "study_table_output.hpp"

namespace blockdyn::cli {
namespace {

struct StudyOutputFlags {
  std::string csv, plot, json_out, progress = "auto";
  bool json_stdout = false, quiet = false;          // --json (SummaryFirst, Series), --quiet
  std::map<std::string, std::string> series_paths;  // Series with series_outputs: name -> --flag value
};

// Where a series goes: the user's file, or a temporary one when only the figure needs it.
struct SeriesTarget {
  std::string path;
  bool temporary = false;
};

SeriesTarget series_target(const StudyCommand& c, const StudyOutputFlags& f, const std::string& name) {
  const std::string temp =
      "/tmp/blockdyn-" + (c.series_outputs.empty() ? c.name : name) + "-" + std::to_string(::getpid());
  std::string given;
  if (c.csv_flag == "csv-prefix")
    return f.csv.empty() ? SeriesTarget{temp + "_" + name + ".csv", true} : SeriesTarget{f.csv + "_" + name + ".csv"};
  if (!c.series_outputs.empty()) {
    const auto it = f.series_paths.find(name);
    given = it == f.series_paths.end() ? "" : it->second;
  } else {
    given = f.csv;
  }
  return given.empty() ? SeriesTarget{temp + ".csv", true} : SeriesTarget{given};
}

// Series: each table to its file, then the figure from the script's argument template ("@plot",
// "@csv:<name>"); files that only fed the figure are removed (also on failure or a signal).
void write_series_and_figure(const StudyCommand& c, const StudyOutputFlags& f, const StudyReport& r) {
  std::vector<std::unique_ptr<RemoveOnSignal>> guards;
  std::vector<std::string> temporaries;
  auto remove_temporaries = [&] {
    for (const auto& t : temporaries) std::remove(t.c_str());
  };
  for (const NamedTable& t : r.series) {
    const SeriesTarget target = series_target(c, f, t.name);
    if (target.temporary && f.plot.empty()) continue;
    if (target.temporary) {
      guards.push_back(std::make_unique<RemoveOnSignal>(target.path));
      temporaries.push_back(target.path);
    }
    std::ostringstream os;
    write_study_rows(os, t.table);
    write_file_atomically(target.path, os.str());
  }
  if (!f.plot.empty()) {
    std::vector<std::string> args;
    for (const std::string& a : figure_arguments(r.figure))
      args.push_back(a == "@plot" ? f.plot : a.rfind("@csv:", 0) == 0 ? series_target(c, f, a.substr(5)).path : a);
    try {
      run_python(plot_script(r.figure), args);
    } catch (...) {
      remove_temporaries();
      throw;
    }
  }
  remove_temporaries();
}

// The CSV (kept when --csv names it, else a temporary file for the figure only) and the figure.
void write_table_and_figure(const StudyOutputFlags& f, const std::string& stem, StudyReport& r, bool table_style) {
  if (f.csv.empty() && f.plot.empty()) return;
  const std::string path = f.csv.empty() ? "/tmp/blockdyn-" + stem + "-" + std::to_string(::getpid()) + ".csv" : f.csv;
  if (table_style)
    write_study_table(path, r.table, r.sidecar);
  else
    write_study_csv(path, r.table, r.sidecar);
  auto remove_temporary = [&] {
    if (!f.csv.empty()) return;
    std::remove(path.c_str());
    std::remove((path + ".json").c_str());
  };
  if (!f.plot.empty()) {
    std::vector<std::string> args{path, f.plot};
    const std::vector<std::string> more = figure_arguments(r.figure);
    args.insert(args.end(), more.begin(), more.end());
    try {
      run_python(plot_script(r.figure), args);
    } catch (...) {
      remove_temporary();
      throw;
    }
  }
  remove_temporary();
}

void run_command(const StudyCommand& c, const CLI::App& app, const StudyOutputFlags& f) {
  const bool table_style = c.outputs == StudyOutputs::Table, series = c.outputs == StudyOutputs::Series;
  if (table_style && !f.plot.empty() && (f.plot.size() < 5 || f.plot.substr(f.plot.size() - 4) != ".png"))
    throw UsageError("plot = '" + f.plot + "' must end in .png (an .svg is written beside it)");
  require_writable("plot", f.plot);
  require_writable(c.csv_flag, c.csv_flag == "csv-prefix" && !f.csv.empty() ? f.csv + "_phase.csv" : f.csv);
  require_writable(table_style ? "json" : "json-out", f.json_out);
  StudyRequest request;
  request.want_table = table_style || !f.csv.empty() || !f.plot.empty();
  request.figure = series && !f.plot.empty();
  for (const SeriesOutput& so : c.series_outputs) {
    require_writable(so.flag, f.series_paths.at(so.name));
    if (!f.series_paths.at(so.name).empty()) request.series.push_back(so.name);
  }
  if (!c.series_outputs.empty()) request.want_table = request.figure || !request.series.empty();
  std::unique_ptr<Progress> bar;
  std::size_t shown = 0;
  const ProgressMode mode = f.quiet ? ProgressMode::None : parse_progress_mode(f.progress);
  if (c.progress_flag)
    request.progress = [&bar, &shown, &c, mode](std::size_t done, std::size_t total) {
      if (!bar) bar = std::make_unique<Progress>(c.name, total, 0, mode);
      if (done > shown) bar->advance(done - shown);
      shown = std::max(shown, done);
    };
  std::vector<std::string> outputs{"--csv", "--csv-prefix", "--plot", "--json", "--json-out", "--quiet", "--progress"};
  for (const SeriesOutput& so : c.series_outputs) outputs.push_back("--" + so.flag);
  StudyReport r = run_study(c.name, settings_of(app, outputs), request);
  if (bar) bar->finish();
  if (series)
    write_series_and_figure(c, f, r);
  else
    write_table_and_figure(f, c.name, r, table_style);
  if (table_style) {
    if (!f.json_out.empty()) emit_json(r.summary, f.json_out);
    if (f.json_out != "-") std::fputs(r.text.c_str(), stdout);
    return;
  }
  if (!series && !f.csv.empty()) r.summary["csv"] = f.csv;
  if (!series && !f.plot.empty()) r.summary["plot"] = f.plot;
  if (!f.json_out.empty()) emit_json(r.summary, f.json_out);
  if (f.json_stdout) {
    emit_json(r.summary, "-");
    return;
  }
  if (!f.quiet) std::fputs(r.text.c_str(), stdout);
}

void add_study(CLI::App& app, const StudyCommand& c) {
  CLI::App* s = app.add_subcommand(c.name, cli_text(c.description));
  add_spec_options(*s, c.options);
  auto f = std::make_shared<StudyOutputFlags>();
  if (c.outputs == StudyOutputs::Table) {
    s->add_option("--csv", f->csv, "write the table here (a JSON sidecar <csv>.json is written beside it)");
    s->add_option("--plot", f->plot, "write a plot here (PNG; an SVG with the same stem beside it)");
    s->add_option("--json", f->json_out, "write the JSON summary here ('-': stdout)");
  } else if (c.outputs == StudyOutputs::Series) {
    if (c.series_outputs.empty())
      s->add_option("--" + c.csv_flag, f->csv,
                    c.csv_flag == "csv-prefix" ? "write the series as PREFIX_<name>.csv" : "write the series CSV here");
    for (const SeriesOutput& so : c.series_outputs)
      s->add_option("--" + so.flag, f->series_paths[so.name], cli_text(so.help));
    s->add_option("--plot", f->plot, "write the figure here (PNG + SVG)");
    s->add_flag("--json", f->json_stdout, "print the JSON summary on stdout");
    s->add_option("--json-out", f->json_out, "also write the JSON summary to this file");
  } else {
    s->add_flag("--json", f->json_stdout, "print the JSON summary on stdout instead of a table");
    s->add_option("--json-out", f->json_out, "also write the JSON summary to this file");
    s->add_option("--csv", f->csv, "write the table (CSV + .json sidecar)");
    s->add_option("--plot", f->plot, "plot the table (PNG; SVG beside it)");
  }
  if (c.progress_flag)
    s->add_option("--progress", f->progress, "auto, bar, plain or none")
        ->check(CLI::IsMember({"auto", "bar", "plain", "none"}));
  if (c.quiet_flag) s->add_flag("--quiet", f->quiet, "no summary lines, no progress");
  s->callback([&c, s, f] { run_command(c, *s, *f); });
}

const bool studies_registered = [] {
  for (const StudyCommand& c : study_commands())
    command_registry().push_back({c.order, [&c](CLI::App& app) { add_study(app, c); }});
  return true;
}();

}  // namespace

void write_study_rows(std::ostream& os, const StudyTable& t) { write_csv(os, t); }

void write_study_csv(const std::string& path, const StudyTable& t, const nlohmann::ordered_json& sidecar) {
  std::ostringstream os;
  write_study_rows(os, t);
  write_file_atomically(path, os.str());
  emit_json(sidecar, path + ".json", "sidecar");
}

void write_study_table(const std::string& path, const StudyTable& t, nlohmann::ordered_json meta) {
  meta["csv"] = path;
  meta["columns"] = t.columns;
  write_study_csv(path, t, meta);
}

}  // namespace blockdyn::cli
