// SPDX-License-Identifier: Apache-2.0
#include "cli_run.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <utility>

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

// Every output a command was given, checked before it runs (a figure's format found unwritable
// after an hour's run, or two outputs overwriting each other, is a usage error, not a loss): no
// two outputs name the same file, each can be written (its directory exists and is writable),
// figures have a format matplotlib writes, animations are .gif or .mp4.
void check_outputs(CLI::App& sub) {
  static const char* const kOutputs[] = {"--out",   "--output",   "--json-out", "--csv",      "--trajectory",
                                         "--trace", "--twin-csv", "--plot",     "--plot-map", "--animate"};
  static const char* const kFigures[] = {".png", ".pdf",  ".svg",  ".jpg", ".jpeg",
                                         ".tif", ".tiff", ".webp", ".eps", ".ps"};
  std::vector<std::pair<std::string, std::string>> seen;  // (absolute path, flag)
  for (const char* name : kOutputs) {
    const CLI::Option* o = sub.get_option_no_throw(name);
    if (!o || o->count() == 0 || o->get_group() == kDirectoryOutputs) continue;
    const std::string value = o->as<std::string>();
    if (value.empty() || value == "-") continue;
    const std::string flag(name), field = flag.substr(2);
    if (flag == "--plot" || flag == "--plot-map") {
      const std::string e = extension_of(value);
      if (std::find(std::begin(kFigures), std::end(kFigures), e) == std::end(kFigures))
        throw UsageError(field + " = '" + value +
                         "': a figure must end in .png, .pdf, .svg, .jpg, .tif, .webp or .eps");
    }
    if (flag == "--animate" && extension_of(value) != ".gif" && extension_of(value) != ".mp4")
      throw UsageError("animate = '" + value + "' must end in .gif or .mp4");
    require_writable(field, value);  // not a directory, in a directory we may write in
    std::error_code ec;
    const std::string key = std::filesystem::weakly_canonical(std::filesystem::absolute(value, ec), ec).string();
    for (const auto& [path, other] : seen)
      if (path == key)
        throw UsageError(field + " = '" + value + "' is also given as " + other + ": each output needs its own file");
    seen.emplace_back(key, flag);
  }
}

void check_outputs_before_running(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands({})) {
    sub->parse_complete_callback([sub] { check_outputs(*sub); });
    check_outputs_before_running(*sub);
  }
}

}  // namespace

CliOutcome run_cli(const std::vector<std::string>& args) {
  CLI::App app{"blockdyn: nonsmooth dynamics of rigid blocks (Winkler foundation, rigid ground)"};
  app.set_version_flag("--version", std::string(kVersion) + " (" + kGitDescribe + ")");
  app.require_subcommand(1);
  auto reg = command_registry();
  std::sort(reg.begin(), reg.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
  std::vector<std::string> refusing_mpi;
  for (const auto& c : reg) {
    c.add(app);
    if (c.mpi == MpiUse::Refuses) refusing_mpi.push_back(app.get_subcommands({}).back()->get_name());
  }
  reject_empty_values(app);
  check_outputs_before_running(app);
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
    out = {2, e.what()};
  } catch (const std::exception& e) {
    out = {1, e.what()};
  }
  return out;
}

}  // namespace blockdyn::cli
