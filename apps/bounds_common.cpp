// SPDX-License-Identifier: Apache-2.0
#include "bounds_common.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn::cli::bounds {

void add_run_options(CLI::App& app, StudyRunOptions& run, double default_t_end) {
  run.t_end = default_t_end;
  app.add_option("--t-end", run.t_end, "observation time of each run (> 0)")->capture_default_str();
  add_tolerance_options(app, run.integrator);
  app.add_option("--max-steps", run.integrator.max_steps,
                 "step cap per run; a run hitting it is reported as a numerical failure")
      ->capture_default_str();
}

void add_output_options(CLI::App& app, OutputFlags& out) {
  app.add_option("--threads", out.threads, "worker threads (0: all cores); output does not depend on it")
      ->capture_default_str();
  app.add_option("--csv", out.csv, "write the table here (a JSON sidecar <csv>.json is written beside it)");
  app.add_option("--plot", out.plot, "write a plot here (PNG; an SVG with the same stem beside it)");
  app.add_option("--json", out.json_out, "write the JSON summary here ('-': stdout)");
}

void check_run_options(const StudyRunOptions& run, const OutputFlags& out) {
  require_range("t-end", run.t_end, 0.0, 1e9, false, true);
  require_range("rtol", run.integrator.rtol, 0.0, 1.0, false, false);
  require_range("atol", run.integrator.atol, 0.0, 1.0, false, false);
  require_range("max-steps", double(run.integrator.max_steps), 1.0, 1e12);
  require_range("threads", out.threads, 0, 1024);
  if (!out.plot.empty() && out.plot.size() < 5)
    throw UsageError("plot = '" + out.plot + "' must be a file name ending in .png");
  if (!out.plot.empty() && out.plot.substr(out.plot.size() - 4) != ".png")
    throw UsageError("plot = '" + out.plot + "' must end in .png (an .svg is written beside it)");
  require_writable("plot", out.plot);
  require_writable("csv", out.csv);
  require_writable("json", out.json_out);
}

IcChoice parse_ic(const std::string& s) {
  try {
    return parse_ic_choice(s);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

std::vector<double> parse_list(const std::string& field, const std::string& text) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size())
      throw UsageError(field + " = '" + text + "' must be a comma-separated list of numbers");
    v.push_back(x);
  }
  if (v.empty()) throw UsageError(field + " must list at least one number");
  return v;
}

std::string num(double v) {
  if (std::isnan(v)) return "nan";
  // Shortest of %.15g / %.17g that reads back exactly (0.2 stays 0.2).
  char b[32];
  std::snprintf(b, sizeof b, "%.15g", v);
  if (std::strtod(b, nullptr) != v) std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

json run_options_json(const StudyRunOptions& run) {
  return {{"t_end", run.t_end}, {"integrator", to_json(run.integrator)}};
}

json boundary_json(const BoundaryResult& b, bool with_samples) {
  json j = {{"status", to_string(b.status)},
            {"value", b.found() ? json(b.value) : json(nullptr)},
            {"bracket", {b.lo, b.hi}},
            {"evaluations", b.evaluations}};
  if (!b.message.empty()) j["message"] = b.message;
  if (with_samples) {
    json s = json::array();
    for (const auto& x : b.samples) s.push_back({x.x, x.value});
    j["samples"] = s;
  }
  return j;
}

double cell(const BoundaryResult& b) { return b.found() ? b.value : std::nan(""); }

void write_table(const std::string& path, const Table& t, json meta) {
  std::ostringstream os;
  for (std::size_t i = 0; i < t.columns.size(); ++i) os << (i ? "," : "") << t.columns[i];
  os << '\n';
  for (const auto& row : t.rows) {
    for (std::size_t i = 0; i < row.size(); ++i) os << (i ? "," : "") << row[i];
    os << '\n';
  }
  write_file_atomically(path, os.str());
  meta["csv"] = path;
  meta["columns"] = t.columns;
  emit_json(meta, path + ".json", "sidecar");
}

std::string csv_target(const OutputFlags& out, const std::string& stem) {
  if (!out.csv.empty()) return out.csv;
  if (out.plot.empty()) return "";
  return "/tmp/blockdyn-" + stem + "-" + std::to_string(::getpid()) + ".csv";
}

void finish(const OutputFlags& out, const std::string& csv_path, const Table& t, const json& meta,
            const std::string& script, const std::vector<std::string>& plot_args, const json& summary) {
  if (!csv_path.empty()) write_table(csv_path, t, meta);
  if (!out.plot.empty()) {
    std::vector<std::string> args{csv_path, out.plot};
    args.insert(args.end(), plot_args.begin(), plot_args.end());
    try {
      run_python(script, args);
    } catch (...) {
      if (out.csv.empty()) {
        std::remove(csv_path.c_str());
        std::remove((csv_path + ".json").c_str());
      }
      throw;
    }
    if (out.csv.empty()) {
      std::remove(csv_path.c_str());
      std::remove((csv_path + ".json").c_str());
    }
  }
  if (!out.json_out.empty()) emit_json(summary, out.json_out);
}

}  // namespace blockdyn::cli::bounds
