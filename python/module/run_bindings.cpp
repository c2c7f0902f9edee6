// SPDX-License-Identifier: Apache-2.0
// Runs of one model from Python: prepared once, run singly or many on threads without the GIL,
// from memory, or writing the files asked for with the command line's writers in the same run.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/commands/simulate_run.hpp"
#include "blockdyn/io/json_io.hpp"
#include "cli_common.hpp"
#include "python_options.hpp"
#include "simulate_output.hpp"

namespace blockdyn::python {
namespace {

// Options the Python functions may pass besides the model's (they change nothing in the run).
const std::vector<std::string> kQuietOptions{"quiet", "max-output-rows"};

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

}  // namespace

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

}  // namespace blockdyn::python
