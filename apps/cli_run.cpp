// SPDX-License-Identifier: Apache-2.0
#include "cli_run.hpp"

#include <CLI/CLI.hpp>

#include <glob.h>
#include <unistd.h>
#include <algorithm>
#include <cctype>

#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <utility>

#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/io/input_files.hpp"
#include "blockdyn/version.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "mpi_sweep.hpp"

namespace blockdyn::cli {

namespace {

// An option given an empty value (--mu '') is an error, never a silent zero.
void reject_empty_values(CLI::App& app) {
  const CLI::Validator nonempty(
      [](std::string& v) { return v.empty() ? std::string("the value is empty") : std::string(); }, "", "NONEMPTY");
  for (CLI::Option* o : app.get_options())
    if (o->get_expected_min() > 0 && !o->get_positional()) o->check(nonempty);
  for (CLI::App* sub : app.get_subcommands({})) reject_empty_values(*sub);
}

// Lower-case extension with its dot ("" if none).
std::string extension_of(const std::string& path) {
  const auto slash = path.find_last_of('/'), dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot);
  for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// A file a command reads or writes, named by the option (or positional) that gives it.
struct NamedFile {
  std::string path, flag;
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string stem_of(const std::string& path) {
  const std::string e = extension_of(path);
  return path.substr(0, path.size() - e.size());
}

// The files an output option makes besides the one it names: a figure's SVG twin, a table's
// sidecar and journal, a suite directory's motions.json.
// `runner`: the command's table goes through the sweep runner (journal and sidecar beside it).
std::vector<std::string> files_of_output(const std::string& flag, const std::string& value, bool directory,
                                         bool runner) {
  if (directory) return {value + "/motions.json"};
  std::vector<std::string> f{value};
  if (flag == "--plot" || flag == "--plot-map") {
    if (extension_of(value) != ".svg") f.push_back(stem_of(value) + ".svg");
  } else if (runner && (flag == "--csv" || flag == "--out" || flag == "--output")) {
    const SweepPaths p = sweep_paths(value);
    f.push_back(p.journal);
    f.push_back(p.sidecar);
  } else if (flag == "--csv") {
    f.push_back(value + ".json");  // a study's sidecar
  }
  return f;
}

bool is_output_flag(const std::string& flag) {
  static const char* const kOutputs[] = {"--out",      "--output", "--json-out", "--csv",     "--trajectory", "--trace",
                                         "--twin-csv", "--plot",   "--plot-map", "--animate", "--poincare",   "--json"};
  return std::find(std::begin(kOutputs), std::end(kOutputs), flag) != std::end(kOutputs);
}

bool is_input_flag(const std::string& flag) { return ends_with(flag, "record") || ends_with(flag, "records"); }

// The inputs given on the command line: positional files and the record options (a glob of
// records expanded), those that exist.
std::vector<NamedFile> given_inputs(const CLI::App& sub) {
  std::vector<NamedFile> in;
  for (const CLI::Option* o : sub.get_options()) {
    if (o->count() == 0) continue;
    const std::string flag = o->get_lnames().empty() ? o->get_name() : "--" + o->get_lnames().front();
    if (!o->get_positional() && !is_input_flag(flag)) continue;
    for (const std::string& v : o->results()) {
      if (ends_with(flag, "records")) {
        glob_t g{};
        if (::glob(v.c_str(), 0, nullptr, &g) == 0)
          for (std::size_t i = 0; i < g.gl_pathc && i < 100000; ++i) in.push_back({g.gl_pathv[i], flag});
        ::globfree(&g);
      } else if (::access(v.c_str(), F_OK) == 0) {
        in.push_back({v, o->get_positional() ? o->get_name() : flag});
      }
    }
  }
  return in;
}

// Every output a command was given, checked before it runs (a figure's format found unwritable
// after an hour's run, or two outputs overwriting each other, is a usage error, not a loss): no
// two outputs (with the files they make beside them) name the same file, none names an input,
// each can be written (its directory exists and is writable), figures have a format matplotlib
// writes, animations are .gif or .mp4.
void check_outputs(CLI::App& sub, bool runner) {
  static const char* const kFigures[] = {".png", ".pdf",  ".svg",  ".jpg", ".jpeg",
                                         ".tif", ".tiff", ".webp", ".eps", ".ps"};
  std::vector<NamedFile> outputs;
  std::vector<std::string> suite_dirs;  // directory outputs: their records are outputs too
  for (const CLI::Option* o : sub.get_options()) {
    if (o->count() == 0 || o->get_positional() || o->get_expected_min() == 0) continue;
    const std::string flag = "--" + (o->get_lnames().empty() ? o->get_name() : o->get_lnames().front());
    if (!is_output_flag(flag)) continue;
    const std::string value = o->as<std::string>();
    if (value.empty() || value == "-") continue;
    const std::string field = flag.substr(2);
    const bool directory = o->get_group() == kDirectoryOutputs;
    if (flag == "--plot" || flag == "--plot-map") {
      const std::string e = extension_of(value);
      if (std::find(std::begin(kFigures), std::end(kFigures), e) == std::end(kFigures))
        throw UsageError(field + " = '" + value +
                         "': a figure must end in .png, .pdf, .svg, .jpg, .tif, .webp or .eps");
    }
    if (flag == "--animate" && extension_of(value) != ".gif" && extension_of(value) != ".mp4")
      throw UsageError("animate = '" + value + "' must end in .gif or .mp4");
    if (directory) suite_dirs.push_back(value);
    for (const std::string& f : files_of_output(flag, value, directory, runner)) {
      for (const NamedFile& other : outputs)
        if (same_file(f, other.path))
          throw UsageError(field + " = '" + value + "'" + (f == value ? "" : " (its file '" + f + "')") +
                           " is also written by " + other.flag.substr(2) + " ('" + other.path +
                           "'): each output needs its own file");
      outputs.push_back({f, flag});
    }
  }
  // A suite directory's records: any other file there named as the generator names its records.
  for (const std::string& dir : suite_dirs)
    for (const NamedFile& o : outputs) {
      const auto slash = o.path.find_last_of('/');
      const std::string base = slash == std::string::npos ? o.path : o.path.substr(slash + 1);
      if (o.flag != "--out" && same_file(slash == std::string::npos ? "." : o.path.substr(0, slash), dir) &&
          (base == "motions.json" ||
           (ends_with(base, ".AT2") && (base.rfind("rezaeian_", 0) == 0 || base.rfind("pulse_", 0) == 0))))
        throw UsageError(o.flag.substr(2) + " = '" + o.path + "' is a file of the suite written into out = '" + dir +
                         "': give another name");
    }
  for (const NamedFile& in : given_inputs(sub))
    for (const NamedFile& o : outputs)
      if (same_file(in.path, o.path))
        throw UsageError(o.flag.substr(2) + " = '" + o.path + "' is the input " + in.flag +
                         (in.path == o.path ? "" : " ('" + in.path + "')") +
                         ": an output never overwrites an input; give another name");
  // Then each can be written: not a directory, in a directory we may write in.
  for (const NamedFile& o : outputs)
    if (std::find(suite_dirs.begin(), suite_dirs.end(), o.path) == suite_dirs.end() &&
        (o.flag != "--out" || suite_dirs.empty()))
      require_writable(o.flag.substr(2), o.path);
}

void check_outputs_before_running(CLI::App& app, const std::vector<std::string>& runners) {
  for (CLI::App* sub : app.get_subcommands({})) {
    const bool runner = std::find(runners.begin(), runners.end(), sub->get_name()) != runners.end();
    sub->parse_complete_callback([sub, runner] { check_outputs(*sub, runner); });
    check_outputs_before_running(*sub, runners);
  }
}

}  // namespace

CliOutcome run_cli(const std::vector<std::string>& args) {
  CLI::App app{"blockdyn: nonsmooth dynamics of rigid blocks (Winkler foundation, rigid ground)"};
  app.set_version_flag("--version", std::string(kVersion) + " (" + kGitDescribe + ")");
  app.require_subcommand(1);
  auto reg = command_registry();
  std::sort(reg.begin(), reg.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
  std::vector<std::string> refusing_mpi, runners;
  for (const auto& c : reg) {
    c.add(app);
    (c.mpi == MpiUse::Refuses ? refusing_mpi : runners).push_back(app.get_subcommands({}).back()->get_name());
  }
  reject_empty_values(app);
  check_outputs_before_running(app, runners);
  clear_inputs();  // the files this command reads: none yet
  // The subcommand names the schema of its JSON outputs.
  current_command().clear();
  for (const auto& a : args)
    if (!a.empty() && a[0] != '-') {
      current_command() = a;
      break;
    }
  const int ranks = launched_by_mpi() ? launcher_world_size() : 1;
  if (ranks > 1 && std::find(refusing_mpi.begin(), refusing_mpi.end(), current_command()) != refusing_mpi.end())
    return {2, "MPI: `blockdyn " + current_command() + "` does not distribute its work over MPI ranks (launched with " +
                   std::to_string(ranks) +
                   "): run it without mpirun (sweep, map, survival, spectrum, response-curve and rocking-spectrum "
                   "distribute)"};
  // A first word that names no command is said so (CLI11 would only say one is required).
  if (!current_command().empty()) {
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands({})) known = known || sub->check_name(current_command());
    if (!known) return {2, "'" + current_command() + "' is not a blockdyn command (blockdyn --help lists them)"};
  }
  // CLI11 parses the arguments in reverse order from a vector.
  std::vector<std::string> rev(args.rbegin(), args.rend());
  CliOutcome out;
  try {
    app.parse(rev);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {  // --help, --version
      app.exit(e, std::cout, std::cerr);
      return out;
    }
    // Every usage error exits 2 (CLI11's own codes are not part of the contract).
    out = {2, e.what()};
  } catch (const std::invalid_argument& e) {
    out = {2, cli_text(e.what())};
  } catch (const std::exception& e) {
    out = {1, cli_text(e.what())};
  }
  return out;
}

}  // namespace blockdyn::cli
