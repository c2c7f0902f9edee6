// SPDX-License-Identifier: Apache-2.0
#pragma once
// Helpers shared by the flight and stability subcommands (cmd_flight.cpp, cmd_stability.cpp):
// common options, CSV tables with JSON sidecars, JSON views of boundary results.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "blockdyn/analysis/sweep/boundary_search.hpp"
#include "blockdyn/analysis/winkler/ic_choice.hpp"
#include "blockdyn/analysis/winkler/study_options.hpp"
#include "cli_common.hpp"

namespace blockdyn::cli::bounds {

using json = nlohmann::ordered_json;

// Output flags every study command has.
struct OutputFlags {
  std::string csv, plot, json_out;
  int threads = 0;
};

// --t-end --rtol --atol --max-steps --threads --csv --plot --json.
void add_run_options(CLI::App& app, StudyRunOptions& run, double default_t_end);
void add_output_options(CLI::App& app, OutputFlags& out);
// Validates run options and thread count (UsageError naming the field).
void check_run_options(const StudyRunOptions& run, const OutputFlags& out);

IcChoice parse_ic(const std::string& s);  // UsageError on a bad name
std::vector<double> parse_list(const std::string& field, const std::string& text);  // "0,0.1,0.2"

std::string num(double v);  // %.17g; "nan" for NaN
json run_options_json(const StudyRunOptions& run);
json boundary_json(const BoundaryResult& b, bool with_samples = false);
// The value of a boundary for a CSV cell: the value when found, NaN otherwise.
double cell(const BoundaryResult& b);

// A CSV table written atomically with a JSON sidecar <path>.json (meta + column list).
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
};
void write_table(const std::string& path, const Table& t, json meta);

// Where the CSV goes: --csv, or a temporary file when only a plot is asked (empty: none).
std::string csv_target(const OutputFlags& out, const std::string& stem);
// Writes CSV (if any), runs the plot script (if asked), removes a temporary CSV, emits JSON.
void finish(const OutputFlags& out, const std::string& csv_path, const Table& t, const json& meta,
            const std::string& script, const std::vector<std::string>& plot_args, const json& summary);

}  // namespace blockdyn::cli::bounds
