// SPDX-License-Identifier: Apache-2.0
// blockdyn._core: the library for Python. Runs are made from memory: options go to the library as
// Settings (the same vocabulary and validation as the command line), results come back as NumPy
// columns and the JSON summary's text, and the integration runs without the GIL. Runs that write
// files (a trajectory CSV, a JSON summary, figures) go through the command line's writers, called
// directly, in the same run that fills the columns.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <variant>
#include <vector>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/grid_studies.hpp"
#include "blockdyn/commands/limit_analysis_command.hpp"
#include "blockdyn/commands/map_study.hpp"
#include "blockdyn/commands/motion_generate.hpp"
#include "blockdyn/commands/motion_info.hpp"
#include "blockdyn/commands/option_spec.hpp"
#include "blockdyn/commands/simulate_run.hpp"
#include "blockdyn/commands/study_command.hpp"
#include "blockdyn/commands/sweep_settings.hpp"
#include "blockdyn/family/family.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/progress.hpp"
#include "blockdyn/version.hpp"
#include "cli_common.hpp"
#include "cli_run.hpp"
#include "simulate_output.hpp"
#include "table_files.hpp"

namespace py = pybind11;
using namespace blockdyn;

namespace {

// Option names in the library's text, as Python's keywords.
std::string python_text(std::string_view text) { return blockdyn::spell_options(text, "", true); }

}  // namespace

namespace {

using Samples = std::pair<std::vector<double>, std::vector<double>>;
using OptionValue = std::variant<std::string, Samples>;
using OptionList = std::vector<std::pair<std::string, OptionValue>>;

// Options the Python functions may pass besides the model's (they change nothing in the run).
const std::vector<std::string> kQuietOptions{"quiet", "max-output-rows"};

Settings settings_of(const OptionList& options) {
  Settings s;
  for (const auto& [name, value] : options) {
    if (const auto* text = std::get_if<std::string>(&value)) {
      s.add(name, *text);
    } else {
      const auto& [t, a] = std::get<Samples>(value);
      const std::string field = "--" + Settings::canonical(name);
      if (t.size() != a.size())
        throw std::invalid_argument(field + ": times and accelerations differ in length (" + std::to_string(t.size()) +
                                    " and " + std::to_string(a.size()) + ")");
      s.add_record(name, std::make_shared<const Accelerogram>(t, a, field + " (arrays)"));
      s.add(name, "(arrays)");
    }
  }
  return s;
}

// One run prepared from its options (parsed and validated while the GIL is held).
struct Prepared {
  std::shared_ptr<const PreparedRun> run;
  double max_rows = 1e7;
  std::string command;  // names the summary's schema, as the command line's
};

Prepared prepare(const OptionList& options, const std::string& command) {
  Settings model;
  const Settings all = settings_of(options);
  for (const std::string& n : all.names()) {
    if (std::find(kQuietOptions.begin(), kQuietOptions.end(), n) != kQuietOptions.end()) continue;
    if (auto r = all.record(n)) model.add_record(n, r);
    for (const std::string& v : all.values(n)) model.add(n, v);
  }
  return Prepared{prepare_run(model), all.number("max-output-rows", 1e7), command};
}

struct Outcome {
  ColumnTable table;
  nlohmann::ordered_json events = nlohmann::ordered_json::array();
  SimulateReport report;
  std::string summary_text;  // the summary as `blockdyn simulate --json` prints it
};

void execute(const Prepared& p, bool trajectory, Outcome& o) {
  SimulateOutputs out;
  out.trajectory = trajectory ? &o.table : nullptr;
  out.max_output_rows = p.max_rows;
  out.on_event = [&o](const nlohmann::ordered_json& e) { o.events.push_back(e); };
  o.report = p.run->run(out);
}

// The summary's text, exactly as `blockdyn simulate --json` prints it; without the GIL (on the
// worker thread, so that simulate_many's threads also share this part).
void finish_summary(const Prepared& p, Outcome& o) {
  nlohmann::ordered_json doc;
  doc["schema"] = schema_name(p.command, "summary");
  for (auto it = o.report.summary.begin(); it != o.report.summary.end(); ++it) doc[it.key()] = std::move(it.value());
  doc["events"] = std::move(o.events);
  o.summary_text = dump_json(doc);
}

// The same run writing the files asked for (by the command line's writers) and keeping its columns.
void execute_with_files(const Prepared& p, const std::map<std::string, std::string>& files, Outcome& o) {
  cli::SimulateOutputFlags f;
  f.quiet = true;
  f.max_output_rows = p.max_rows;
  static const std::map<std::string, std::string cli::SimulateOutputFlags::*> kPaths{
      {"trajectory", &cli::SimulateOutputFlags::trajectory},
      {"plot", &cli::SimulateOutputFlags::plot},
      {"animate", &cli::SimulateOutputFlags::animate},
      {"json-out", &cli::SimulateOutputFlags::json_out}};
  Settings frames;
  for (const auto& [name, value] : files) {
    if (const auto it = kPaths.find(name); it != kPaths.end())
      f.*(it->second) = value;
    else if (name == "animate-frames")
      frames.add(name, value);
    else
      throw std::invalid_argument("`" + name +
                                  "` is not an output of a run (trajectory, plot, animate, animate-frames, json-out)");
  }
  f.animate_frames = frames.small_integer("animate-frames", f.animate_frames);
  cli::RunCapture capture;
  capture.table = &o.table;
  capture.on_event = [&o](const nlohmann::ordered_json& e) { o.events.push_back(e); };
  // The JSON file's schema names the command, as the program's does.
  const std::string caller = std::exchange(cli::current_command(), p.command);
  try {
    o.report = cli::run_and_write(*p.run, f, f.trajectory, f.plot, capture);
  } catch (...) {
    cli::current_command() = caller;
    throw;
  }
  cli::current_command() = caller;
}

// (columns {name: array or list of str}, summary JSON text).
py::tuple to_python(Outcome& o) {
  py::dict cols;
  for (const ColumnTable::Column& c : o.table.data()) {
    if (c.is_text)
      cols[py::str(c.name)] = py::cast(c.texts);
    else
      cols[py::str(c.name)] = py::array_t<double>(py::ssize_t(c.numbers.size()), c.numbers.data());
  }
  return py::make_tuple(cols, std::move(o.summary_text));
}

// A cell as a CSV reader gives it: a quoted cell without its quotes ("" read as ").
std::string unquoted(const std::string& c) {
  if (c.size() < 2 || c.front() != '"' || c.back() != '"') return c;
  std::string s;
  for (std::size_t i = 1; i + 1 < c.size(); ++i) {
    s += c[i];
    if (c[i] == '"' && c[i + 1] == '"') ++i;
  }
  return s;
}

// A study's table as columns, as blockdyn's CSV reader gives them: numbers (empty cells NaN) where
// every cell is a number or empty, else text.
py::dict study_columns(const StudyTable& t) {
  py::dict cols;
  for (std::size_t j = 0; j < t.columns.size(); ++j) {
    std::vector<double> numbers;
    std::vector<std::string> texts;
    bool numeric = true;
    for (const auto& row : t.rows) {
      const std::string c = unquoted(j < row.size() ? row[j] : std::string());
      char* end = nullptr;
      const double v = c.empty() ? std::nan("") : std::strtod(c.c_str(), &end);
      numeric = numeric && (c.empty() || end == c.c_str() + c.size());
      numbers.push_back(v);
      texts.push_back(c);
    }
    if (numeric)
      cols[py::str(t.columns[j])] = py::array_t<double>(py::ssize_t(numbers.size()), numbers.data());
    else
      cols[py::str(t.columns[j])] = py::cast(texts);
  }
  return cols;
}

// A library call from options by name to a JSON document, without the GIL: the document's text.
std::string json_call(const std::function<nlohmann::ordered_json(const Settings&)>& call, const OptionList& options) {
  const Settings s = settings_of(options);
  nlohmann::ordered_json j;
  {
    py::gil_scoped_release release;
    j = call(s);
  }
  return dump_json(j);
}

// A runner table's rows, as a study's table.
StudyTable study_table_of(const Table& t) {
  StudyTable out;
  out.columns = t.columns;
  for (const TableRow& r : t.rows) out.rows.push_back(r.cells);
  return out;
}

// A sweep or map grid computed in memory on `threads` threads: (columns, sidecar JSON text).
py::tuple grid_in_memory(const PointTable& table, int threads) {
  Table t;
  {
    py::gil_scoped_release release;
    t = compute_table(table, threads, nullptr);
  }
  return py::make_tuple(study_columns(study_table_of(t)), dump_json(table_sidecar(table, "complete")));
}

// A table run on files: the user's `output`, else scratch files (removed when `scratch` goes)
// that the figure is made from.
Settings with_output(Settings s, const std::string& kind, bool resume, bool overwrite,
                     std::unique_ptr<cli::GridOutput>& scratch) {
  if (s.has("output")) return s;
  cli::GridRunFlags g;
  g.resume = resume;
  g.overwrite = overwrite;
  scratch = std::make_unique<cli::GridOutput>("`output`", "", kind, g, "");
  s.set("output", scratch->csv());
  return s;
}

// The runner's options of a table on files; usage errors name the option.
struct FileRun {
  int threads = 0;
  bool resume = false, overwrite = false;
  std::string progress = "none";
  double progress_interval = 10;
  SweepRunOptions options() const {
    if (resume && overwrite) throw std::invalid_argument("`resume` and `overwrite`: give only one");
    require_in_range("progress-interval", progress_interval, 0.0, 1e9, false);
    SweepRunOptions o;
    o.threads = threads;
    o.resume = resume;
    o.overwrite = overwrite;
    o.progress = parse_progress_mode(progress);
    o.progress_interval = progress_interval;
    return o;
  }
};

// The sidecar the runner wrote (none beside a FIFO or a device: the table's own then).
std::string sidecar_text(const SweepOutcome& out, const PointTable& table) {
  std::ifstream in(out.paths.sidecar);
  if (!in) return dump_json(table_sidecar(table, "complete"));
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// `blockdyn sweep` and `blockdyn map` on files, through the command line's writers.
void add_table_files(py::module_& m) {
  m.def(
      "sweep_files",
      [](const OptionList& options, int threads, bool resume, bool overwrite, const std::string& progress,
         double progress_interval) {
        const FileRun run{threads, resume, overwrite, progress, progress_interval};
        const SweepRunOptions o = run.options();
        std::unique_ptr<cli::GridOutput> scratch;
        const SweepDefinition d =
            sweep_definition(with_output(settings_of(options), "sweep", resume, overwrite, scratch));
        cli::GridRunResult r;
        {
          py::gil_scoped_release release;
          r = cli::write_sweep(d, o);
        }
        return py::make_tuple(study_columns(study_table_of(r.outcome.table)), sidecar_text(r.outcome, *d.table));
      },
      py::arg("options"), py::arg("threads") = 0, py::arg("resume") = false, py::arg("overwrite") = false,
      py::arg("progress") = "none", py::arg("progress_interval") = 10.0,
      "Runs `blockdyn sweep` on files (output, journal, sidecar, plot); returns (columns, sidecar JSON text).");
  m.def(
      "map_files",
      [](const OptionList& options, int threads, bool resume, bool overwrite, const std::string& progress,
         double progress_interval) {
        const FileRun run{threads, resume, overwrite, progress, progress_interval};
        const SweepRunOptions o = run.options();
        std::unique_ptr<cli::GridOutput> scratch;
        const Settings s = with_output(settings_of(options), "map", resume, overwrite, scratch);
        cli::MapFiles f;
        {
          py::gil_scoped_release release;
          f = cli::write_map(s, o);
        }
        return py::make_tuple(study_columns(study_table_of(f.grid.outcome.table)),
                              sidecar_text(f.grid.outcome, *f.table), study_columns(f.boundaries.table),
                              dump_json(f.boundaries.meta));
      },
      py::arg("options"), py::arg("threads") = 0, py::arg("resume") = false, py::arg("overwrite") = false,
      py::arg("progress") = "none", py::arg("progress_interval") = 10.0,
      "Runs `blockdyn map` on files (output, journal, sidecar, boundaries CSV, plot); returns (columns, sidecar "
      "JSON text, boundary columns, their meta JSON).");
}

// Runs of one model: prepared, single, many on threads.
void add_runs(py::module_& m) {
  py::class_<Prepared>(m, "Prepared", "a run's options, parsed and validated once (blockdyn.Simulator)")
      .def(py::init(&prepare), py::arg("options"), py::arg("command") = "simulate");
  m.def(
      "simulate",
      [](const Prepared& p, bool trajectory) {
        Outcome o;
        {
          py::gil_scoped_release release;
          execute(p, trajectory, o);
          finish_summary(p, o);
        }
        return to_python(o);
      },
      py::arg("prepared"), py::arg("trajectory") = true,
      "Runs one block; returns ({column: array}, summary JSON text).");
  m.def(
      "simulate_files",
      [](const Prepared& p, const std::map<std::string, std::string>& files) {
        Outcome o;
        {
          py::gil_scoped_release release;
          execute_with_files(p, files, o);
          finish_summary(p, o);
        }
        return to_python(o);
      },
      py::arg("prepared"), py::arg("files"),
      "Runs one block writing the files named ({output: path}: trajectory, plot, animate, animate-frames, "
      "json-out) as the command line writes them; returns ({column: array}, summary JSON text).");
  m.def(
      "simulate_many",
      [](const std::vector<Prepared>& runs, int threads, bool trajectory) {
        std::vector<Outcome> outs(runs.size());
        std::vector<std::exception_ptr> errors(runs.size());
        {
          py::gil_scoped_release release;
          const std::size_t n =
              std::max<std::size_t>(1, std::min<std::size_t>(std::size_t(resolve_threads(threads)), runs.size()));
          std::vector<std::thread> pool;
          for (std::size_t w = 0; w < n; ++w)
            pool.emplace_back([&, w] {
              for (std::size_t i = w; i < runs.size(); i += n) {
                try {
                  execute(runs[i], trajectory, outs[i]);
                  finish_summary(runs[i], outs[i]);
                } catch (...) {
                  errors[i] = std::current_exception();
                }
              }
            });
          for (auto& t : pool) t.join();
        }
        py::list result;
        for (std::size_t i = 0; i < runs.size(); ++i) {
          if (errors[i]) std::rethrow_exception(errors[i]);
          result.append(to_python(outs[i]));
        }
        return result;
      },
      py::arg("runs"), py::arg("threads") = 1, py::arg("trajectory") = true,
      "Runs many blocks on `threads` threads (each run on one thread: the results are those of serial calls).");
}

// The studies and grid analyses by name, from memory; the command line in process for the rest.
void add_studies(py::module_& m) {
  m.def(
      "study",
      [](const std::string& name, const OptionList& options, bool table,
         const std::vector<std::string>& series_wanted) {
        const Settings s = settings_of(options);
        StudyRequest request;
        request.want_table = table;
        request.series = series_wanted;
        StudyReport r;
        {
          py::gil_scoped_release release;
          r = run_study(name, s, request);
        }
        nlohmann::ordered_json doc;
        doc["schema"] = schema_name(name, "summary");
        for (auto it = r.summary.begin(); it != r.summary.end(); ++it) doc[it.key()] = it.value();
        py::dict series;
        for (const NamedTable& t : r.series) series[py::str(t.name)] = study_columns(t.table);
        return py::make_tuple(study_columns(r.table), dump_json(doc), r.text, series);
      },
      py::arg("name"), py::arg("options"), py::arg("table") = true, py::arg("series") = std::vector<std::string>{},
      "Runs a study (blockdyn.studies()); returns ({column: array or list}, summary JSON text, text, "
      "{series name: {column: array}}).");
  m.def(
      "grid_study",
      [](const std::string& name, const OptionList& options) {
        const Settings s = settings_of(options);
        StudyReport r;
        {
          py::gil_scoped_release release;
          r = run_grid_study(name, s);
        }
        nlohmann::ordered_json doc;
        doc["schema"] = schema_name(name, "summary");
        for (auto it = r.summary.begin(); it != r.summary.end(); ++it) doc[it.key()] = it.value();
        return py::make_tuple(study_columns(r.table), dump_json(doc), r.text);
      },
      py::arg("name"), py::arg("options"),
      "Runs a grid analysis (survival) in memory on its threads; returns ({column: array}, summary JSON text, text).");
  m.def(
      "sweep",
      [](const OptionList& options, int threads) {
        const SweepDefinition d = sweep_definition(settings_of(options));
        return grid_in_memory(*d.table, threads);
      },
      py::arg("options"), py::arg("threads") = 0,
      "Runs `blockdyn sweep`'s grid in memory; returns ({column: array or list}, sidecar JSON text).");
  m.def(
      "map",
      [](const OptionList& options, int threads) {
        const Settings s = settings_of(options);
        const MapStudy study = map_study(s);
        py::tuple grid = grid_in_memory(*study.table, threads);
        MapBoundaries b;
        {
          py::gil_scoped_release release;
          b = map_boundaries(s, threads);
        }
        return py::make_tuple(grid[0], grid[1], study_columns(b.table), dump_json(b.meta));
      },
      py::arg("options"), py::arg("threads") = 0,
      "Runs `blockdyn map` in memory; returns (columns, sidecar JSON text, boundary columns, their meta JSON).");
}

// Records, limit analysis, the registries (families, studies) and the command line in process.
void add_records_and_catalogues(py::module_& m) {
  m.def(
      "motion_generate",
      [](const OptionList& options) {
        return json_call([](const Settings& s) { return motion_generate(s); }, options);
      },
      py::arg("options"), "Writes a suite of synthetic records (`blockdyn motion generate`): motions.json's text.");
  m.def(
      "motion_info", [](const OptionList& options) { return json_call(motion_info, options); }, py::arg("options"),
      "A record's intensity measures and spectrum (`blockdyn motion info`): JSON text.");
  m.def(
      "limit_analysis", [](const OptionList& options) { return json_call(limit_analysis_run, options); },
      py::arg("options"), "Static limit analysis of an assembly (`blockdyn limit-analysis`): JSON text.");
  m.def(
      "families",
      [] {
        py::list l;
        for (const Family& f : families()) {
          py::dict d;
          d["name"] = f.name;
          d["description"] = f.description;
          d["scenario"] = f.scenario();
          d["rigid_ground"] = f.rigid_ground != nullptr;
          d["sweep"] = f.sweep != nullptr;
          d["forced"] = f.forced != nullptr;
          d["free_lyapunov"] = f.free_lyapunov != nullptr;
          py::list cols;
          for (std::string c, all = f.state_columns; !all.empty();) {
            const auto comma = all.find(',');
            c = all.substr(0, comma);
            all = comma == std::string::npos ? "" : all.substr(comma + 1);
            cols.append(c);
          }
          d["state_columns"] = cols;
          l.append(d);
        }
        return l;
      },
      "The registered model families, the default first: [{name, description, and what each takes part in}].");
  m.def(
      "studies",
      [] {
        py::dict d;
        for (const StudyCommand& c : study_commands()) {
          py::dict opts;
          for (const StudyOption& o : c.options)
            opts[py::str(o.name)] = py::make_tuple(o.default_value, python_text(o.help));
          d[py::str(c.name)] = py::make_tuple(python_text(c.description), opts);
        }
        return d;
      },
      "{study name: (description, {option: (default, help)})}");
  m.def(
      "run_cli",
      [](const std::vector<std::string>& args) {
        blockdyn::cli::CliOutcome r;
        {
          py::gil_scoped_release release;  // simulations and sweeps run without the GIL
          r = blockdyn::cli::run_cli(args);
        }
        return py::make_tuple(r.code, r.error);
      },
      py::arg("args"), "Runs `blockdyn <args...>`; returns (exit code, error message). 2 means invalid input.");
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "blockdyn's library for Python (use the functions of the blockdyn package)";
  // The library's messages name options in backticks: Python spells them as keywords (t_end).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, python_text(e.what()).c_str());
    } catch (const std::out_of_range& e) {
      PyErr_SetString(PyExc_IndexError, python_text(e.what()).c_str());
    } catch (const std::range_error& e) {
      PyErr_SetString(PyExc_ValueError, python_text(e.what()).c_str());
    } catch (const std::runtime_error& e) {
      PyErr_SetString(PyExc_RuntimeError, python_text(e.what()).c_str());
    }
  });
  m.attr("__version__") = blockdyn::kVersion;
  m.attr("git_describe") = blockdyn::kGitDescribe;
  add_runs(m);
  add_studies(m);
  add_table_files(m);
  add_records_and_catalogues(m);
}
