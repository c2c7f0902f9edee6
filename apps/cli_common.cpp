// SPDX-License-Identifier: Apache-2.0
#include "cli_common.hpp"
#include "cli_registry.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn::cli {

std::vector<CommandEntry>& command_registry() {
  static std::vector<CommandEntry> r;
  return r;
}

void add_block_options(CLI::App& app, BlockParams& p) {
  app.add_option("--r", p.r, "aspect ratio width/height (> 0)")->capture_default_str();
  app.add_option("--mu", p.mu, "friction coefficient (>= 0)")->capture_default_str();
  app.add_option("--k", p.k, "non-dimensional foundation stiffness k a b/(m g) (> 0)")->capture_default_str();
}

void add_tolerance_options(CLI::App& app, IntegratorOptions& o) {
  app.add_option("--rtol", o.rtol, "relative tolerance of the integrator, in (0, 1)")->capture_default_str();
  app.add_option("--atol", o.atol, "absolute tolerance (scaled by 1/k for y), in (0, 1)")->capture_default_str();
}

std::string& current_command() {
  thread_local std::string name;  // per thread: the Python module may run commands concurrently
  return name;
}

void emit_json(const nlohmann::ordered_json& j, const std::string& path, const char* kind) {
  nlohmann::ordered_json out;
  out["schema"] = schema_name(current_command(), kind);
  for (auto it = j.begin(); it != j.end(); ++it) out[it.key()] = it.value();
  const std::string text = dump_json(out) + "\n";
  if (path.empty() || path == "-") {
    std::cout << text << std::flush;
  } else {
    write_file_atomically(path, text);
  }
}

std::string python_dir() {
  if (const char* e = std::getenv("BLOCKDYN_PYTHON_DIR")) return e;
  auto has_scripts = [](const std::string& d) { return ::access((d + "/plotkit.py").c_str(), R_OK) == 0; };
  // Installed: share/blockdyn/python beside the program's bin/ (relocatable: a package installs
  // under /usr, a user under any prefix); run from the build: the source tree.
  char exe[4096];
  const ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n > 0) {
    std::string dir(exe, std::size_t(n));
    dir = dir.substr(0, dir.find_last_of('/'));  // .../bin
    const std::string d = dir.substr(0, dir.find_last_of('/')) + "/share/blockdyn/python";
    if (has_scripts(d)) return d;
  }
  if (has_scripts(BLOCKDYN_PYTHON_DIR)) return BLOCKDYN_PYTHON_DIR;
  return BLOCKDYN_INSTALLED_PYTHON_DIR;
}

static std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void run_python(const std::string& script, const std::vector<std::string>& args) {
  std::ostringstream cmd;
  cmd << "MPLBACKEND=Agg /usr/bin/python3 " << shell_quote(python_dir() + "/" + script);
  for (const auto& a : args) cmd << ' ' << shell_quote(a);
  const int rc = std::system(cmd.str().c_str());
  if (rc != 0)
    throw std::runtime_error("plotting failed (" + script + ", exit " +
                             std::to_string(WIFEXITED(rc) ? WEXITSTATUS(rc) : rc) +
                             "); is python3-matplotlib installed for /usr/bin/python3?");
}

void require_range(const std::string& field, double v, double lo, double hi, bool lo_incl, bool hi_incl) {
  const bool ok = std::isfinite(v) && (lo_incl ? v >= lo : v > lo) && (hi_incl ? v <= hi : v < hi);
  if (!ok) {
    std::ostringstream os;
    os << field << " = " << v << " is out of range: must be finite and in " << (lo_incl ? "[" : "(")
       << lo << ", " << hi << (hi_incl ? "]" : ")");
    throw UsageError(os.str());
  }
}

}  // namespace blockdyn::cli
