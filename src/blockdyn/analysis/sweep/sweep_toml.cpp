// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/sweep_toml.hpp"

#include <set>

#include "blockdyn/io/toml_read.hpp"

namespace blockdyn {

namespace {

using toml_read::fail;
using toml_read::number;
using toml_read::opt_number;
using toml_read::string;

void check_keys(const toml::table& t, const std::string& where, const std::set<std::string>& allowed) {
  const std::string key = toml_read::first_unknown_key(t, allowed);
  if (key.empty()) return;
  fail(where.empty() ? key : where + "." + key, "unknown key (allowed" +
                                                    (where.empty() ? std::string() : " in [" + where + "]") + ": " +
                                                    toml_read::joined(allowed) + ")");
}

long integer(const toml::node& n, const std::string& key) {
  if (!n.is_integer()) fail(key, "must be an integer");
  return long(*n.value<std::int64_t>());
}

bool boolean(const toml::node& n, const std::string& key) {
  if (!n.is_boolean()) fail(key, "must be true or false");
  return *n.value<bool>();
}

const toml::table* sub(const toml::table& t, const char* key) {
  return toml_read::sub_table(t, key, key, ", e.g. [" + std::string(key) + "]");
}

SweepAxis read_axis(const toml::node& n, const std::string& name, AxisSpacing default_spacing) {
  const std::string key = "axes." + name;
  if (n.is_string()) return parse_axis(name, *n.value<std::string>(), default_spacing);
  if (n.is_integer() || n.is_floating_point()) return axis_list(name, {number(n, key)});
  if (const toml::array* a = n.as_array()) {
    std::vector<double> v;
    for (const auto& e : *a) v.push_back(number(e, key + "[]"));
    return axis_list(name, std::move(v));
  }
  if (const toml::table* t = n.as_table()) {
    if (t->contains("values")) {
      check_keys(*t, key, {"values"});
      return read_axis(*t->get("values"), name, default_spacing);
    }
    check_keys(*t, key, {"min", "max", "points", "spacing"});
    for (const char* req : {"min", "max", "points"})
      if (!t->contains(req)) fail(key + "." + req, "is required for a range (or give values = [...])");
    AxisSpacing sp = default_spacing;
    if (const toml::node* s = t->get("spacing")) {
      const std::string v = string(*s, key + ".spacing");
      if (v == "log")
        sp = AxisSpacing::Log;
      else if (v == "linear" || v == "lin")
        sp = AxisSpacing::Linear;
      else
        fail(key + ".spacing", "'" + v + "' is not one of: log, linear");
    }
    return axis_range(name, number(*t->get("min"), key + ".min"), number(*t->get("max"), key + ".max"),
                      integer(*t->get("points"), key + ".points"), sp);
  }
  fail(key, "must be a number, a list, a \"min:max:points\" string or a {min, max, points} table");
}

}  // namespace

SweepSpec parse_sweep(const std::string& text, const std::string& source) {
  const toml::table root = toml_read::parse(text, source);
  SweepSpec s;
  check_keys(root, "", {"axes", "initial", "run", "output"});
  if (const auto* a = sub(root, "axes")) {
    check_keys(*a, "axes", {"k", "r", "inv_r", "mu"});
    if (a->contains("r") && a->contains("inv_r")) fail("axes", "give either r or inv_r, not both");
    if (const auto* n = a->get("k")) s.k = read_axis(*n, "k", AxisSpacing::Log);
    if (const auto* n = a->get("r")) s.r = read_axis(*n, "r", AxisSpacing::Linear);
    if (const auto* n = a->get("inv_r")) s.r = read_axis(*n, "inv_r", AxisSpacing::Linear);
    if (const auto* n = a->get("mu")) s.mu = read_axis(*n, "mu", AxisSpacing::Linear);
  }
  if (const auto* i = sub(root, "initial")) {
    check_keys(*i, "initial", {"set", "w0", "w0_over_alpha", "x0", "y0", "vx0", "vy0", "vw0"});
    if (const auto* n = i->get("set")) {
      s.initial.sets.clear();
      if (const toml::array* arr = n->as_array()) {
        for (const auto& e : *arr) s.initial.sets.push_back(string(e, "initial.set[]"));
      } else {
        s.initial.sets.push_back(string(*n, "initial.set"));
      }
    }
    s.initial.w0 = opt_number(*i, "initial", "w0");
    s.initial.w0_over_alpha = opt_number(*i, "initial", "w0_over_alpha");
    toml_read::read_state_overrides(*i, "initial", s.initial);
  }
  if (const auto* r = sub(root, "run")) {
    check_keys(*r, "run",
               {"t_end", "rtol", "atol", "max_steps", "event_samples", "method", "track_energy", "stop_at_first_flight",
                "stop_at_ihor"});
    WinklerRunOptions& o = s.options;
    if (auto v = opt_number(*r, "run", "t_end")) o.t_end = *v;
    if (auto v = opt_number(*r, "run", "rtol")) o.integrator.rtol = *v;
    if (auto v = opt_number(*r, "run", "atol")) o.integrator.atol = *v;
    if (auto v = toml_read::opt_string(*r, "run", "method")) o.integrator.method = toml_read::method(*v, "run.method");
    if (const auto* n = r->get("max_steps")) o.integrator.max_steps = integer(*n, "run.max_steps");
    if (const auto* n = r->get("event_samples")) o.integrator.event_samples = int(integer(*n, "run.event_samples"));
    if (const auto* n = r->get("track_energy")) o.track_energy = boolean(*n, "run.track_energy");
    if (const auto* n = r->get("stop_at_first_flight"))
      o.stop_at_first_flight = boolean(*n, "run.stop_at_first_flight");
    if (const auto* n = r->get("stop_at_ihor")) o.stop_at_upright_passages = integer(*n, "run.stop_at_ihor");
  }
  if (const auto* o = sub(root, "output")) {
    check_keys(*o, "output", {"csv", "plot", "plot_column", "metrics"});
    if (const auto* n = o->get("csv")) s.output = string(*n, "output.csv");
    if (const auto* n = o->get("plot")) s.plot = string(*n, "output.plot");
    if (const auto* n = o->get("plot_column")) s.plot_column = string(*n, "output.plot_column");
    if (const auto* n = o->get("metrics")) {
      const toml::array* arr = n->as_array();
      if (!arr) fail("output.metrics", "must be a list of metric names");
      for (const auto& e : *arr) s.metrics.push_back(string(e, "output.metrics[]"));
    }
  }
  return s;
}

SweepSpec load_sweep(const std::string& path) { return parse_sweep(toml_read::read_file(path, "sweep file"), path); }

}  // namespace blockdyn
