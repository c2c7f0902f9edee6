// SPDX-License-Identifier: Apache-2.0
#pragma once
// A study: an analysis whose options are named (with defaults and help), which computes a table
// and a summary. The command line registers every study as a subcommand from its description
// (apps/cmd_studies.cpp) and the Python module calls the same function (blockdyn.study), so an
// analysis is written once, in the library, and reaches both front ends by one registration.
#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/commands/figure_spec.hpp"

#include "blockdyn/analysis/winkler/study_options.hpp"
#include "blockdyn/commands/option_spec.hpp"
#include "blockdyn/commands/settings.hpp"
#include "blockdyn/io/table_cell.hpp"

namespace blockdyn {

// How a study's outputs are named on the command line (both are contracts of existing commands).
enum class StudyOutputs {
  // --csv F (with its sidecar F.json: the meta, the csv path and the column names), --plot F.png,
  // --json F|- (the summary), --threads N. The table is always computed.
  Table,
  // --csv F (sidecar: the study's own), --plot F, --json (summary on stdout, no text), --json-out F,
  // --threads N for some. The table is computed only when a CSV or plot is wanted; the summary
  // names them ("csv", "plot").
  SummaryFirst,
  // Series of one orbit: --csv-prefix P (P_<name>.csv per table) or --csv F (the one table), no
  // sidecars; --plot F, --json (stdout), --json-out F. Tables only when a CSV or plot is wanted.
  Series,
};

// A study's table: cells (numbers, integers, labels), formatted only by the CSV writer.
using StudyTable = CellTable;

struct NamedTable {
  std::string name;  // the file's suffix: P_<name>.csv
  StudyTable table;
};

struct StudyReport {
  StudyTable table;
  std::vector<NamedTable> series;  // Series studies' tables
  nlohmann::ordered_json sidecar;  // the JSON beside the CSV
  nlohmann::ordered_json summary;  // the JSON summary
  std::string text;                // the summary for a person (printed unless JSON goes to stdout)
  // The figure (table studies: drawn from the table's CSV and the figure's path, then its inputs;
  // series studies: its inputs name the series ("@csv:<name>") and the figure ("@plot")).
  FigureSpec figure;
  // Further figures: (the output that names the figure, the figure).
  std::vector<std::pair<std::string, FigureSpec>> more_figures{};
};

struct StudyRequest {
  bool want_table = true;  // SummaryFirst studies skip the table's work when false
  // Series studies: the series asked for by name (empty: every one when want_table); a figure
  // wants every series its script reads.
  std::vector<std::string> series;
  bool figure = false;
  // Called as points complete (done of total), from one thread at a time; may be empty.
  std::function<void(std::size_t done, std::size_t total)> progress;

  bool wants(const std::string& series_name) const;  // figure, asked, or every one
  bool asked(const std::string& series_name) const;  // named in `series`
  void advance(std::size_t done, std::size_t total) const {
    if (progress) progress(done, total);
  }
};

// A series written to its own flag's file (Series studies other than csv-prefix ones).
struct SeriesOutput {
  std::string name;  // the series' name in StudyReport::series
  std::string flag;  // "out", "trace", ...
  std::string help;
};

struct StudyCommand {
  std::string name;         // the subcommand: "flight-time"
  std::string description;  // for --help
  int order = 0;            // position in --help
  StudyOutputs outputs = StudyOutputs::Table;
  std::vector<StudyOption> options;  // without the output options
  StudyReport (*run)(const Settings&, const StudyRequest&) = nullptr;
  std::string csv_flag = "csv";                // Series: "csv-prefix" (P_<name>.csv per table) or "csv" (one table)
  std::vector<SeriesOutput> series_outputs{};  // Series: each series to its own flag (instead of csv_flag)
  bool quiet_flag = false;                     // --quiet: no text (and no progress)
  bool progress_flag = false;                  // --progress auto|bar|plain|none
};

// Every registered study, in --help order.
const std::vector<StudyCommand>& study_commands();
// The study named; throws std::invalid_argument listing the names.
const StudyCommand& study_command(const std::string& name);
// Runs a study from options given by name (refusing unknown ones and the output options).
StudyReport run_study(const std::string& name, const Settings& s, const StudyRequest& request = {});

// A study's options as given, else their defaults: values parsed on use, errors naming the option.
class StudyOptions {
 public:
  StudyOptions(const Settings& given, const std::vector<StudyOption>& specs);
  double number(const std::string& name) const;
  long integer(const std::string& name) const;
  int small_integer(const std::string& name) const;  // refused beyond an int's range, naming it
  std::string text(const std::string& name) const;
  bool flag(const std::string& name) const;
  // Every value given (each "a,b,c" or one number), else the default's; std::invalid_argument
  // naming the option.
  std::vector<double> numbers(const std::string& name) const;
  bool given(const std::string& name) const { return given_.has(name); }
  const Settings& given_settings() const { return given_; }
  // --t-end --rtol --atol --method --max-steps.
  StudyRunOptions run_options() const;
  int threads() const;  // --threads, in [0, 1024]

 private:
  const Settings& given_;
  Settings values_;
};

// The option lists many studies share.
std::vector<StudyOption> study_run_options(const std::string& default_t_end);  // t-end .. max-steps
StudyOption threads_option();
// `own`, then the run options (study_run_options) and --threads.
std::vector<StudyOption> with_run_options(std::vector<StudyOption> own, const std::string& default_t_end);

// A number as text for reports and titles: the shortest of %.15g / %.17g that reads back exactly
// ("nan" for NaN); a table's cell is Cell::shortest.
std::string cell_text(double v);
// printf into a report's text.
void append_text(std::string& to, const char* format, ...) __attribute__((format(printf, 2, 3)));
// {t_end, integrator}
nlohmann::ordered_json run_options_json(const StudyRunOptions& run);
// A boundary search's result: status, value (null unless found), bracket, evaluations [, samples].
nlohmann::ordered_json boundary_json(const BoundaryResult& b, bool with_samples = false);
// A boundary's value for a cell: the value when found, NaN otherwise.
double boundary_cell(const BoundaryResult& b);
// "0,0.1,0.2" as numbers; std::invalid_argument naming the field.
std::vector<double> parse_number_list(const std::string& field, const std::string& text);

// The registrations (one per file of studies).
void add_flight_studies(std::vector<StudyCommand>& to);
void add_stability_studies(std::vector<StudyCommand>& to);
void add_equilibrium_studies(std::vector<StudyCommand>& to);
void add_orbit_studies(std::vector<StudyCommand>& to);
void add_harmonic_studies(std::vector<StudyCommand>& to);
void add_chaos_studies(std::vector<StudyCommand>& to);
// `lyapunov` of the free Winkler block (its family's entry, family_registry.cpp).
StudyReport winkler_lyapunov_study(const StudyOptions& o, const StudyRequest& request);
void add_periodic_orbit_studies(std::vector<StudyCommand>& to);

}  // namespace blockdyn
