// SPDX-License-Identifier: Apache-2.0
#pragma once
// Helpers shared by the subcommands: option groups, validation, output, plotting.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "blockdyn/commands/option_spec.hpp"
#include "blockdyn/commands/settings.hpp"
#include "blockdyn/integrate/integrator_options.hpp"
#include "blockdyn/io/json_event_spool.hpp"
#include "blockdyn/model/winkler/winkler_params.hpp"

namespace blockdyn::cli {

// The library's text (messages, help) as the command line spells it: each option named in
// backticks becomes --name (spell_options, commands/option_spec.hpp).
inline std::string cli_text(std::string_view text) { return spell_options(text, "--", false); }

// Thrown for invalid user input: main prints "error: <what>" and exits with status 2.
struct UsageError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// Whether the user gave option `name` (flags override scenario/definition files only then).
inline bool given(const CLI::App& app, const std::string& name) { return app.count(name) > 0; }
// Flags that only another family reads: an error names the first one given ("--x " + why).
inline void refuse(const CLI::App& s, const std::vector<std::string>& flags, const std::string& why) {
  for (const auto& fl : flags)
    if (given(s, fl)) throw UsageError(fl + " " + why);
}

// The options given on the command line, as the library's Settings (names without dashes), less
// the ones in `exclude` (the command's own output flags, e.g. "--plot").
Settings settings_of(const CLI::App& app, const std::vector<std::string>& exclude = {});

// Options the library describes (commands/option_spec.hpp), unbound: read back with settings_of.
void add_spec_options(CLI::App& app, const std::vector<StudyOption>& specs);

// --r --mu --k bound to p (defaults kept unless given).
void add_block_options(CLI::App& app, WinklerParams& p);
// --rtol --atol bound to o.
void add_tolerance_options(CLI::App& app, IntegratorOptions& o);
// --method dopri5|dop853|auto (part of add_tolerance_options; alone for commands with their own tolerances).
void add_method_option(CLI::App& app, IntegratorOptions& o);

// The subcommand being run (set by main before parsing): names the schema of its JSON outputs.
std::string& current_command();
// Writes JSON to `path` atomically, or to stdout when path is "-" or empty, with a first key
// "schema": "blockdyn.<command>.<kind>/<version>" (docs/output-formats.md); kind is "summary"
// (the --json / --json-out document) or "sidecar" (the JSON beside a CSV table).
void emit_json(const nlohmann::ordered_json& j, const std::string& path, const char* kind = "summary");
// The same with the "events" member's value taken from a spool (written as the run went).
void emit_json(const nlohmann::ordered_json& j, const std::string& path, const JsonEventSpool& events,
               const char* kind = "summary");

// Directory holding the matplotlib scripts (env BLOCKDYN_PYTHON_DIR overrides).
std::string python_dir();
// Runs /usr/bin/python3 <python_dir>/<script> args...; throws on failure.
void run_python(const std::string& script, const std::vector<std::string>& args);

// A sampling interval that would produce more than max_samples samples over `span` (a trajectory
// with output-interval 1e-300) is a usage error naming the field; interval <= 0 is left to the
// caller (often "every step").
void require_sample_count(const std::string& field, double interval, double span, double max_samples = 1e7);

// The option group of an output that names a directory (motion generate --out): the command
// checks it itself; the file checks made before every run pass it by.
inline const std::string kDirectoryOutputs = "Output directory";

// Throws UsageError (naming the field) unless a file can be written at path: not a directory, in
// an existing writable directory. Checked before computing, so a bad path costs no work.
void require_writable(const std::string& field, const std::string& path);

// --animate F.gif|F.mp4 and --animate-frames: a writable path with a known extension, 2 to 5000
// frames.
void require_animation(const std::string& path, int frames);
// Throws UsageError unless v is finite and in [lo, hi] (inclusive flags).
void require_range(const std::string& field, double v, double lo, double hi, bool lo_incl = true, bool hi_incl = true);

}  // namespace blockdyn::cli
