// SPDX-License-Identifier: Apache-2.0
// Runs of one model from Python: prepared once, run singly or many on threads without the GIL,
// from memory, or writing the files asked for with the command line's writers in the same run.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
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
  const Settings all = settings_of(options);
  const auto quiet = [](const std::string& n) {
    return std::find(kQuietOptions.begin(), kQuietOptions.end(), n) != kQuietOptions.end();
  };
  const std::vector<std::string> names = all.names();
  if (std::none_of(names.begin(), names.end(), quiet))
    return Prepared{prepare_run(all), all.number("max-output-rows", 1e7), command};
  Settings model;
  for (const std::string& n : names) {
    if (std::find(kQuietOptions.begin(), kQuietOptions.end(), n) != kQuietOptions.end()) continue;
    if (auto r = all.record(n)) model.add_record(n, r);
    for (const std::string& v : all.values(n)) model.add(n, v);
  }
  return Prepared{prepare_run(model), all.number("max-output-rows", 1e7), command};
}

// A run's summary for Python: the report's JSON and the events, printed as `blockdyn simulate
// --json` prints them only when Python first reads them (most runs never do).
struct RunSummary {
  SimulateReport report;
  nlohmann::ordered_json events = nlohmann::ordered_json::array();
  std::string command;
  std::optional<std::string> printed;
  const std::string& text() {
    if (!printed) {
      nlohmann::ordered_json doc;
      doc["schema"] = schema_name(command, "summary");
      nlohmann::ordered_json body = report.summary.take();
      for (auto it = body.begin(); it != body.end(); ++it) doc[it.key()] = std::move(it.value());
      doc["events"] = std::move(events);
      printed = dump_json(doc);
    }
    return *printed;
  }
};

struct Outcome {
  ColumnTable table;
  std::shared_ptr<RunSummary> summary = std::make_shared<RunSummary>();
};

void execute(const Prepared& p, bool trajectory, Outcome& o) {
  SimulateOutputs out;
  out.trajectory = trajectory ? &o.table : nullptr;
  out.max_output_rows = p.max_rows;
  RunSummary& s = *o.summary;
  out.on_event = [&s](const nlohmann::ordered_json& e) { s.events.push_back(e); };
  s.report = p.run->run(out);
  s.command = p.command;
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
  RunSummary& s = *o.summary;
  capture.on_event = [&s](const nlohmann::ordered_json& e) { s.events.push_back(e); };
  s.command = p.command;
  // The JSON file's schema names the command, as the program's does.
  const std::string caller = std::exchange(cli::current_command(), p.command);
  try {
    s.report = cli::run_and_write(*p.run, f, f.trajectory, f.plot, capture);
  } catch (...) {
    cli::current_command() = caller;
    throw;
  }
  cli::current_command() = caller;
}

// (columns {name: array or list of str}, the summary: its JSON text when read).
py::tuple to_python(Outcome& o) {
  py::dict cols;
  for (ColumnTable::Column& c : o.table.data()) {
    if (!c.is_text) {
      // The array takes the column's memory (no copy): a capsule owns it.
      auto* numbers = new std::vector<double>(std::move(c.numbers));
      const py::capsule owner(numbers, [](void* p) { delete static_cast<std::vector<double>*>(p); });
      cols[py::str(c.name)] = py::array_t<double>(py::ssize_t(numbers->size()), numbers->data(), owner);
      continue;
    }
    // Text as an object array; a column with every cell empty reads as NaN numbers (as from the CSV).
    const auto n = py::ssize_t(c.texts.size());
    if (std::all_of(c.texts.begin(), c.texts.end(), [](const std::string& x) { return x.empty(); })) {
      py::array_t<double> nan(n);
      std::fill(nan.mutable_data(), nan.mutable_data() + n, std::numeric_limits<double>::quiet_NaN());
      cols[py::str(c.name)] = std::move(nan);
      continue;
    }
    py::array texts(py::dtype("O"), std::vector<py::ssize_t>{n});
    auto** cells = static_cast<PyObject**>(texts.mutable_data());
    // A column's few distinct texts (modes, event kinds) made once, each cell a reference to one.
    std::vector<std::pair<const std::string*, py::str>> made;
    for (py::ssize_t i = 0; i < n; ++i) {
      const std::string& text = c.texts[std::size_t(i)];
      auto it = std::find_if(made.begin(), made.end(), [&](const auto& m) { return *m.first == text; });
      if (it == made.end()) it = made.insert(made.end(), {&text, py::str(text)});
      Py_XDECREF(cells[i]);
      cells[i] = it->second.inc_ref().ptr();
    }
    cols[py::str(c.name)] = std::move(texts);
  }
  return py::make_tuple(cols, o.summary);
}

// Runs n blocks on `threads` threads without the GIL, run(i, outcome) doing run i (preparing it
// too, where it is given as options). The calling thread is one of the n: it makes each finished
// run's arrays (with the GIL) as soon as it is done and otherwise takes runs itself, so n threads
// are busy on n cores, the conversion overlapping the other workers' runs.
py::list run_many(std::size_t count, int threads, const std::function<void(std::size_t, Outcome&)>& run) {
  std::vector<Outcome> outs(count);
  std::vector<std::exception_ptr> errors(count);
  std::vector<py::object> made(count);
  auto convert = [&](std::size_t i) {
    if (errors[i]) return;
    py::gil_scoped_acquire hold;
    try {
      made[i] = to_python(outs[i]);
    } catch (...) {
      errors[i] = std::current_exception();  // raised once the workers are joined
    }
    outs[i].table = ColumnTable{};  // the columns are in the arrays now
  };
  {
    py::gil_scoped_release release;
    const std::size_t n = std::max<std::size_t>(1, std::min<std::size_t>(std::size_t(resolve_threads(threads)), count));
    std::mutex lock;
    std::condition_variable finished;
    std::vector<std::size_t> ready;    // done, not converted yet
    std::atomic<std::size_t> next{0};  // the next run to take: the runs' costs differ
    auto run_one = [&](std::size_t i) {
      try {
        run(i, outs[i]);
      } catch (...) {
        errors[i] = std::current_exception();
      }
      {
        const std::lock_guard<std::mutex> g(lock);
        ready.push_back(i);
      }
      finished.notify_one();
    };
    std::vector<std::thread> pool;
    for (std::size_t w = 1; w < n; ++w)
      pool.emplace_back([&] {
        for (std::size_t i = next++; i < count; i = next++) run_one(i);
      });
    std::vector<std::size_t> batch;
    for (std::size_t converted = 0; converted < count;) {
      {
        std::unique_lock<std::mutex> g(lock);
        if (ready.empty() && next.load() >= count) finished.wait(g, [&] { return !ready.empty(); });
        batch.swap(ready);
      }
      for (std::size_t i : batch) convert(i);
      converted += batch.size();
      batch.clear();
      if (converted < count) {
        const std::size_t i = next++;
        if (i < count) run_one(i);
      }
    }
    for (auto& t : pool) t.join();
  }
  py::list result;
  for (std::size_t i = 0; i < count; ++i) {
    if (errors[i]) std::rethrow_exception(errors[i]);
    result.append(std::move(made[i]));
  }
  return result;
}

}  // namespace

// Runs of one model: prepared, single, many on threads.
void add_runs(py::module_& m) {
  py::class_<RunSummary, std::shared_ptr<RunSummary>>(m, "RunSummary",
                                                      "a run's summary, printed as JSON when first read")
      .def("text", &RunSummary::text, "the summary as `blockdyn simulate --json` prints it");
  py::class_<Prepared>(m, "Prepared", "a run's options, parsed and validated once (blockdyn.Simulator)")
      .def(py::init(&prepare), py::arg("options"), py::arg("command") = "simulate");
  m.def(
      "simulate",
      [](const Prepared& p, bool trajectory) {
        Outcome o;
        {
          py::gil_scoped_release release;
          execute(p, trajectory, o);
        }
        return to_python(o);
      },
      py::arg("prepared"), py::arg("trajectory") = true, "Runs one block; returns ({column: array}, RunSummary).");
  m.def(
      "simulate_files",
      [](const Prepared& p, const std::map<std::string, std::string>& files) {
        Outcome o;
        {
          py::gil_scoped_release release;
          execute_with_files(p, files, o);
        }
        return to_python(o);
      },
      py::arg("prepared"), py::arg("files"),
      "Runs one block writing the files named ({output: path}: trajectory, plot, animate, animate-frames, "
      "json-out) as the command line writes them; returns ({column: array}, RunSummary).");
  m.def(
      "simulate_many",
      [](const std::vector<Prepared>& runs, int threads, bool trajectory) {
        return run_many(runs.size(), threads, [&](std::size_t i, Outcome& o) { execute(runs[i], trajectory, o); });
      },
      py::arg("runs"), py::arg("threads") = 1, py::arg("trajectory") = true,
      "Runs many prepared blocks on `threads` threads (each run on one thread: the results are those of serial "
      "calls).");
  m.def(
      "simulate_many_options",
      [](const std::vector<OptionList>& runs, int threads, bool trajectory) {
        return run_many(runs.size(), threads,
                        [&](std::size_t i, Outcome& o) { execute(prepare(runs[i], "simulate"), trajectory, o); });
      },
      py::arg("runs"), py::arg("threads") = 1, py::arg("trajectory") = true,
      "Runs many blocks given by their options, each prepared and run on one of `threads` threads (the results "
      "are those of serial calls).");
}

}  // namespace blockdyn::python
