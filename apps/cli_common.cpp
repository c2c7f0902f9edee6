// SPDX-License-Identifier: Apache-2.0
#include "cli_common.hpp"
#include "cli_registry.hpp"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/simulation/run_options.hpp"

namespace blockdyn::cli {

std::vector<CommandEntry>& command_registry() {
  static std::vector<CommandEntry> r;
  return r;
}

Settings settings_of(const CLI::App& app, const std::vector<std::string>& exclude) {
  Settings s;
  for (const CLI::Option* o : app.get_options()) {
    if (o->count() == 0) continue;
    const std::string name = o->get_lnames().empty() ? o->get_name() : o->get_lnames().front();
    if (std::find(exclude.begin(), exclude.end(), "--" + name) != exclude.end()) continue;
    if (o->results().empty()) s.add(name, "true");
    for (const std::string& v : o->results()) s.add(name, v);
  }
  return s;
}

void add_spec_options(CLI::App& app, const std::vector<StudyOption>& specs) {
  for (const StudyOption& o : specs) {
    std::string names = "--" + o.name;
    for (const std::string& a : o.aliases) names += ",--" + a;
    if (o.is_flag) {
      app.add_flag(names)->description(cli_text(o.help));
      continue;
    }
    CLI::Option* opt = app.add_option(names)->description(cli_text(o.help));
    if (!o.default_value.empty()) opt->default_str(o.default_value);
    // A list: "a,b,c", several values after the flag, or the flag repeated (as CLI11's vectors took).
    if (o.is_list)
      opt->expected(1, CLI::detail::expected_max_vector_size)
          ->allow_extra_args(true)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  }
}

void add_block_options(CLI::App& app, WinklerParams& p) {
  app.add_option("--r", p.r, "aspect ratio width/height (> 0)")->default_str(number_text(p.r));
  app.add_option("--mu", p.mu, "friction coefficient (>= 0)")->default_str(number_text(p.mu));
  app.add_option("--k", p.k, "non-dimensional foundation stiffness k a b/(m g) (> 0)")->default_str(number_text(p.k));
}

void add_tolerance_options(CLI::App& app, IntegratorOptions& o) {
  app.add_option("--rtol", o.rtol, rtol_help())->default_str(number_text(o.rtol));
  app.add_option("--atol", o.atol, atol_help())->default_str(number_text(o.atol));
  add_method_option(app, o);
}

void add_method_option(CLI::App& app, IntegratorOptions& o) {
  // A command whose own --method means something else (lyapunov) gets --integrator-method.
  const char* flag = app.get_option_no_throw("--method") ? "--integrator-method" : "--method";
  app.add_option_function<std::string>(
         flag, [&o](const std::string& name) { o.method = method_from_string(name).value_or(Method::Auto); },
         "Runge-Kutta pair: dopri5 (Dormand-Prince 5(4)), dop853 (8(5,3), 7th-order dense output) or auto "
         "(dop853 when rtol < 1e-6; default)")
      ->check(CLI::IsMember({"auto", "dopri5", "dop853"}));
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

void emit_json(const nlohmann::ordered_json& j, const std::string& path, const JsonEventSpool& events,
               const char* kind) {
  nlohmann::ordered_json out;
  out["schema"] = schema_name(current_command(), kind);
  for (auto it = j.begin(); it != j.end(); ++it) out[it.key()] = it.value();
  if (path.empty() || path == "-") {
    events.write_document(out, std::cout);
    std::cout << "\n" << std::flush;
  } else {
    AtomicFile file(path);
    events.write_document(out, file.stream());
    file.stream() << "\n";
    file.commit();
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
  // The script's stderr goes to a temporary file: on failure its last line is the reason.
  char err_path[] = "/tmp/blockdyn-plot-XXXXXX";
  const int fd = ::mkstemp(err_path);
  if (fd >= 0) ::close(fd);
  const RemoveOnSignal guard(err_path);
  std::ostringstream cmd;
  cmd << "MPLBACKEND=Agg /usr/bin/python3 " << shell_quote(python_dir() + "/" + script);
  for (const auto& a : args) cmd << ' ' << shell_quote(a);
  if (fd >= 0) cmd << " 2>" << shell_quote(err_path);
  const int rc = std::system(cmd.str().c_str());
  std::string last;
  if (fd >= 0) {
    std::ifstream in(err_path);
    for (std::string line; std::getline(in, line);)
      if (!line.empty()) last = line;
    std::remove(err_path);
  }
  if (rc != 0) {
    if (last.find("ModuleNotFoundError") != std::string::npos)
      throw std::runtime_error("plotting failed (" + script + "): " + last +
                               "; install python3-matplotlib and python3-numpy for /usr/bin/python3");
    throw std::runtime_error("plotting failed (" + script + ", exit " +
                             std::to_string(WIFEXITED(rc) ? WEXITSTATUS(rc) : rc) + ")" +
                             (last.empty() ? std::string() : ": " + last));
  }
}

void require_writable(const std::string& field, const std::string& path) {
  if (path.empty() || path == "-") return;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw UsageError(field + " = '" + path + "' is a directory");
  const auto slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  if (::access(dir.c_str(), W_OK) != 0)
    throw UsageError(field + " = '" + path + "': cannot write in '" + dir + "': " + std::strerror(errno));
}

void require_sample_count(const std::string& field, double interval, double span, double max_samples) {
  try {
    blockdyn::require_sample_count(field, interval, span, max_samples);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

void require_range(const std::string& field, double v, double lo, double hi, bool lo_incl, bool hi_incl) {
  try {
    require_in_range(field, v, lo, hi, lo_incl, hi_incl);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

void require_animation(const std::string& path, int frames) {
  require_writable("animate", path);
  if (!path.empty()) {
    const auto dot = path.find_last_of('.');
    const std::string ext = dot == std::string::npos ? "" : path.substr(dot);
    if (ext != ".gif" && ext != ".mp4") throw UsageError("animate = '" + path + "' must end in .gif or .mp4");
  }
  require_range("animate-frames", frames, 2, 5000);
}

}  // namespace blockdyn::cli
