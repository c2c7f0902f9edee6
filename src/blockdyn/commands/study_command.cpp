// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/study_command.hpp"

#include "blockdyn/simulation/run_options.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "blockdyn/base/range_check.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

const std::vector<StudyCommand>& study_commands() {
  static const std::vector<StudyCommand> all = [] {
    std::vector<StudyCommand> v;
    add_flight_studies(v);
    add_stability_studies(v);
    add_equilibrium_studies(v);
    add_orbit_studies(v);
    add_harmonic_studies(v);
    add_chaos_studies(v);
    add_periodic_orbit_studies(v);
    for (const StudyCommand& c : v)  // a name twice would make two flags of one
      for (std::size_t i = 0; i < c.options.size(); ++i)
        for (std::size_t k = 0; k < i; ++k)
          if (c.options[i].name == c.options[k].name)
            throw std::logic_error("study " + c.name + ": option `" + c.options[i].name + "` twice");
    return v;
  }();
  return all;
}

const StudyCommand& study_command(const std::string& name) {
  std::string names;
  for (const StudyCommand& c : study_commands()) {
    if (c.name == name) return c;
    names += (names.empty() ? "" : ", ") + c.name;
  }
  throw std::invalid_argument("study '" + name + "' is not one of: " + names);
}

StudyReport run_study(const std::string& name, const Settings& s, const StudyRequest& request) {
  const StudyCommand& c = study_command(name);
  s.require_known(c.options, {}, name);
  return c.run(s, request);
}

bool StudyRequest::asked(const std::string& series_name) const {
  for (const std::string& n : series)
    if (n == series_name) return true;
  return false;
}

bool StudyRequest::wants(const std::string& series_name) const {
  return figure || (series.empty() ? want_table : asked(series_name));
}

StudyOptions::StudyOptions(const Settings& given, const std::vector<StudyOption>& specs) : given_(given) {
  for (const StudyOption& o : specs)
    if (!o.default_value.empty()) values_.set(o.name, o.default_value);
  for (const std::string& n : given.names()) {
    const std::vector<std::string> v = given.values(n);
    for (std::size_t i = 0; i < v.size(); ++i) i == 0 ? values_.set(n, v[i]) : values_.add(n, v[i]);
  }
}

std::vector<double> StudyOptions::numbers(const std::string& name) const {
  std::vector<double> out;
  for (const std::string& v : values_.values(name))
    for (double x : parse_number_list(name, v)) out.push_back(x);
  return out;
}

double StudyOptions::number(const std::string& name) const {
  const auto v = values_.number(name);
  if (!v) throw std::invalid_argument(std::string("`") + name + "` is required");
  return *v;
}

long StudyOptions::integer(const std::string& name) const {
  if (!values_.has(name)) throw std::invalid_argument(std::string("`") + name + "` is required");
  return values_.integer(name, 0);
}

int StudyOptions::small_integer(const std::string& name) const {
  const long v = integer(name);
  if (v < -2147483647L || v > 2147483647L)
    throw std::invalid_argument(name + " = " + std::to_string(v) +
                                " is out of range: must be at most 2147483647 in size");
  return int(v);
}

std::string StudyOptions::text(const std::string& name) const { return values_.text(name); }

bool StudyOptions::flag(const std::string& name) const { return given_.flag(name); }

StudyRunOptions StudyOptions::run_options() const {
  StudyRunOptions run;
  run.t_end = number("t-end");
  run.integrator.rtol = number("rtol");
  run.integrator.atol = number("atol");
  run.integrator.max_steps = integer("max-steps");
  const std::string m = text("method");
  const auto method = method_from_string(m);
  if (!method) throw std::invalid_argument("`method` = '" + m + "' is not one of: auto, dopri5, dop853");
  run.integrator.method = *method;
  require_in_range("t-end", run.t_end, 0.0, 1e9, false, true);
  require_in_range("rtol", run.integrator.rtol, 0.0, 1.0, false, false);
  require_in_range("atol", run.integrator.atol, 0.0, 1.0, false, false);
  require_in_range("max-steps", double(run.integrator.max_steps), 1.0, 1e12);
  return run;
}

int StudyOptions::threads() const {
  const long t = integer("threads");
  require_in_range("threads", double(t), 0, 1024);
  return int(t);
}

std::vector<StudyOption> study_run_options(const std::string& default_t_end) {
  const StudyRunOptions d;
  return {{"t-end", "observation time of each run (> 0)", default_t_end},
          {"rtol", rtol_help(), Settings::exact(d.integrator.rtol)},
          {"atol", atol_help(), Settings::exact(d.integrator.atol)},
          {"method",
           "Runge-Kutta pair: dopri5 (Dormand-Prince 5(4)), dop853 (8(5,3), 7th-order dense output) or auto "
           "(dop853 when rtol < 1e-6)",
           "auto"},
          {"max-steps", "step cap per run; a run hitting it is reported as a numerical failure",
           std::to_string(d.integrator.max_steps)}};
}

std::vector<StudyOption> with_run_options(std::vector<StudyOption> own, const std::string& default_t_end) {
  for (StudyOption& x : study_run_options(default_t_end)) own.push_back(std::move(x));
  own.push_back(threads_option());
  return own;
}

StudyOption threads_option() { return {"threads", "worker threads (0: all cores); output does not depend on it", "0"}; }

std::string cell_text(double v) { return csv_cell(Cell::shortest(v)); }

void append_text(std::string& to, const char* format, ...) {
  va_list args;
  va_start(args, format);
  va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  if (n > 0) {
    const std::size_t at = to.size();
    to.resize(at + std::size_t(n) + 1);
    std::vsnprintf(to.data() + at, std::size_t(n) + 1, format, again);
    to.resize(at + std::size_t(n));
  }
  va_end(again);
}

nlohmann::ordered_json run_options_json(const StudyRunOptions& run) {
  return {{"t_end", run.t_end}, {"integrator", to_json(run.integrator)}};
}

nlohmann::ordered_json boundary_json(const BoundaryResult& b, bool with_samples) {
  nlohmann::ordered_json j = {{"status", to_string(b.status)},
                              {"value", b.found() ? nlohmann::ordered_json(b.value) : nlohmann::ordered_json(nullptr)},
                              {"bracket", {b.lo, b.hi}},
                              {"evaluations", b.evaluations}};
  if (!b.message.empty()) j["message"] = b.message;
  if (with_samples) {
    nlohmann::ordered_json s = nlohmann::ordered_json::array();
    for (const auto& x : b.samples) s.push_back({x.x, x.value});
    j["samples"] = s;
  }
  return j;
}

double boundary_cell(const BoundaryResult& b) { return b.found() ? b.value : std::nan(""); }

std::vector<double> parse_number_list(const std::string& field, const std::string& text) {
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
      throw std::invalid_argument(field + " = '" + text + "' must be a comma-separated list of numbers");
    v.push_back(x);
  }
  if (v.empty()) throw std::invalid_argument(field + " must list at least one number");
  return v;
}

}  // namespace blockdyn
