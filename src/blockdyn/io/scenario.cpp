// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/scenario.hpp"

#include "blockdyn/family/family.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include "blockdyn/io/toml_read.hpp"
#include "blockdyn/model/winkler/initial_conditions.hpp"

namespace blockdyn {

namespace {

using toml_read::fail;
using toml_read::opt_number;
using toml_read::opt_string;

void check_keys(const toml::table& t, const std::string& where, const std::set<std::string>& allowed) {
  const std::string key = toml_read::first_unknown_key(t, allowed);
  if (!key.empty()) fail(where, "unknown key '" + key + "' (allowed: " + toml_read::joined(allowed) + ")");
}

void read(const toml::table& t, const std::string& where, const char* key, double& out) {
  if (auto v = opt_number(t, where, key)) out = *v;
}

const toml::table* sub(const toml::table& t, const std::string& where, const char* key) {
  return toml_read::sub_table(t, key, where + "." + key);
}

void read_component(const toml::table& t, const std::string& where, const std::string& base, GroundComponent& c) {
  check_keys(t, where,
             {"constant", "amplitude", "frequency", "phase", "t_start", "duration", "pulse", "record", "scale"});
  if (auto v = opt_string(t, where, "pulse")) {
    const auto p = pulse_from_string(*v);
    if (!p) fail(where + ".pulse", "'" + *v + "' is not one of: " + pulse_names());
    c.pulse = *p;
  }
  if (auto v = opt_string(t, where, "record")) {
    const std::string path = (!base.empty() && !v->empty() && (*v)[0] != '/') ? base + "/" + *v : *v;
    c.record = std::make_shared<const Accelerogram>(load_accelerogram(path, where + ".record"));
  }
  read(t, where, "scale", c.scale);
  read(t, where, "constant", c.constant);
  read(t, where, "amplitude", c.amplitude);
  read(t, where, "frequency", c.frequency);
  read(t, where, "phase", c.phase);
  read(t, where, "t_start", c.t_start);
  read(t, where, "duration", c.duration);
}

}  // namespace

const Family& scenario_family(const std::string& name, const std::string& field) {
  return family_named(field, name, [](const Family& f) { return f.scenario(); });
}

Scenario parse_scenario(const std::string& text, const std::string& source, const std::string& base) {
  const toml::table root = toml_read::parse(text, source);
  Scenario s;
  check_keys(root, source, {"model", "block", "physical", "interface", "impact", "initial", "run", "ground", "output"});
  if (auto v = opt_string(root, source, "model")) {
    s.model = scenario_family(*v, "model").name;
  }
  const bool rigid = scenario_family(s.model, "model").rigid_ground != nullptr;
  if (rigid && root.contains("block"))
    fail("block", "[block] (r, mu, k) belongs to the winkler model; give the " + s.model + " block in [physical]");
  if (!rigid && (root.contains("interface") || root.contains("impact")))
    fail(root.contains("interface") ? "interface" : "impact", "belongs to the housner/rigid models (model = ...)");
  if (const auto* f = sub(root, source, "interface")) {
    check_keys(*f, "interface", {"mu_s", "mu_k"});
    read(*f, "interface", "mu_s", s.interface.mu_s);
    s.interface.mu_k = s.interface.mu_s;
    read(*f, "interface", "mu_k", s.interface.mu_k);
  }
  if (const auto* f = sub(root, source, "impact")) {
    check_keys(*f, "impact", {"law", "restitution"});
    if (auto v = opt_string(*f, "impact", "law")) {
      const auto l = impact_law_from_string(*v);
      if (!l) fail("impact.law", "'" + *v + "' is not one of: housner, newton");
      s.impact = *l;
    }
    s.restitution = opt_number(*f, "impact", "restitution");
  }
  if (const auto* b = sub(root, source, "block")) {
    check_keys(*b, "block", {"r", "mu", "k"});
    read(*b, "block", "r", s.params.r);
    read(*b, "block", "mu", s.params.mu);
    read(*b, "block", "k", s.params.k);
  }
  if (root.contains("block") && root.contains("physical"))
    fail("block", "[block] (r, mu, k) and [physical] both given: describe the block once");
  if (const auto* p = sub(root, source, "physical")) {
    if (rigid)
      check_keys(*p, "physical", {"height", "width", "mass", "density", "thickness", "g"});
    else
      check_keys(*p, "physical",
                 {"height", "width", "mass", "density", "thickness", "subgrade_modulus", "line_stiffness", "g", "mu"});
    PhysicalBlock pb;
    pb.mu = s.params.mu;
    read(*p, "physical", "height", pb.height);
    read(*p, "physical", "width", pb.width);
    read(*p, "physical", "g", pb.g);
    read(*p, "physical", "mu", pb.mu);
    pb.mass = opt_number(*p, "physical", "mass");
    pb.density = opt_number(*p, "physical", "density");
    pb.thickness = opt_number(*p, "physical", "thickness");
    pb.subgrade_modulus = opt_number(*p, "physical", "subgrade_modulus");
    pb.line_stiffness = opt_number(*p, "physical", "line_stiffness");
    s.physical = pb;
    if (!rigid) s.params = to_nondimensional(pb);
  }
  if (const auto* i = sub(root, source, "initial")) {
    check_keys(*i, "initial", {"set", "w0", "x0", "y0", "vx0", "vy0", "vw0"});
    if (rigid && i->contains("set"))
      fail("initial.set", "ic1/ic2/custom belong to the winkler model; give w0, vw0, ...");
    if (auto v = opt_string(*i, "initial", "set")) s.initial.set = *v;
    s.initial.w0 = opt_number(*i, "initial", "w0");
    toml_read::read_state_overrides(*i, "initial", s.initial);
  }
  if (const auto* r = sub(root, source, "run")) {
    check_keys(*r, "run",
               {"t_end", "t_start", "rtol", "atol", "output_interval", "max_steps", "event_samples", "method"});
    if (auto v = toml_read::opt_string(*r, "run", "method"))
      s.options.integrator.method = toml_read::method(*v, "run.method");
    read(*r, "run", "t_end", s.options.t_end);
    read(*r, "run", "t_start", s.options.t_start);
    read(*r, "run", "rtol", s.options.integrator.rtol);
    read(*r, "run", "atol", s.options.integrator.atol);
    read(*r, "run", "output_interval", s.output_interval);
    if (auto v = toml_read::opt_integer(*r, "run", "max_steps", 1, 1'000'000'000'000))
      s.options.integrator.max_steps = long(*v);
    if (auto v = toml_read::opt_integer(*r, "run", "event_samples", 1, 64))
      s.options.integrator.event_samples = int(*v);
  }
  if (const auto* g = sub(root, source, "ground")) {
    check_keys(*g, "ground", {"horizontal", "vertical"});
    if (const auto* h = sub(*g, "ground", "horizontal"))
      read_component(*h, "ground.horizontal", base, s.ground.horizontal);
    if (const auto* v = sub(*g, "ground", "vertical")) read_component(*v, "ground.vertical", base, s.ground.vertical);
  }
  if (const auto* o = sub(root, source, "output")) {
    check_keys(*o, "output", {"trajectory", "plot", "units"});
    if (auto v = opt_string(*o, "output", "trajectory")) s.trajectory = *v;
    if (auto v = opt_string(*o, "output", "plot")) s.plot = *v;
    if (auto v = opt_string(*o, "output", "units")) s.units = *v;
  }
  return s;
}

Scenario load_scenario(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const std::string base = slash == std::string::npos ? "" : path.substr(0, slash);
  return parse_scenario(toml_read::read_file(path, "scenario file"), path, base);
}

RigidBlockParams rigid_params(const Scenario& s) {
  RigidBlockParams p;
  if (!s.physical)
    throw std::invalid_argument("the " + s.model +
                                " model needs the block's width and height (`width` `height`, or [physical])");
  const PhysicalBlock& b = *s.physical;
  if (b.width == 0.0)
    throw std::invalid_argument("width is missing: give the block's width [m] (`width`, physical.width)");
  if (b.height == 0.0)
    throw std::invalid_argument("height is missing: give the block's height [m] (`height`, physical.height)");
  p.shape.width = b.width;
  p.shape.height = b.height;
  p.shape.g = b.g;
  if (b.mass && b.density) throw std::invalid_argument("physical block: mass and density both given: give one");
  if (b.mass || (b.density && b.thickness))
    p.shape.mass = mass_of(b);
  else if (b.density || b.thickness)
    throw std::invalid_argument("density needs thickness (and thickness density) to give the mass");
  p.interface = s.interface;
  p.impact = s.impact;
  p.restitution = s.restitution;
  validate(p);
  return p;
}

WinklerState initial_state(const Scenario& s) {
  const InitialSpec& in = s.initial;
  WinklerState z{};
  if (in.set == "ic1") {
    z = ic1(s.params, in.w0);
  } else if (in.set == "ic2") {
    z = ic2(s.params);
    if (in.w0) z[kW] = *in.w0;
  } else if (in.set == "custom") {
    z[kW] = in.w0.value_or(0.0);
    z[kH] = in.y0 ? *in.y0 - 0.5 : -1.0 / s.params.k;
    z[kX] = 0.0;
  } else {
    throw std::invalid_argument("initial.set = '" + in.set + "' is not one of: ic1, ic2, custom");
  }
  if (in.x0) z[kX] = *in.x0;
  if (in.y0) z[kH] = *in.y0 - 0.5;
  if (in.vx0) z[kVX] = *in.vx0;
  if (in.vy0) z[kVY] = *in.vy0;
  if (in.vw0) z[kVW] = *in.vw0;
  // Name the offending component (order of StateIndex: x, h = y - 1/2, w, x', y', w').
  const char* names[6] = {"x0", "y0", "w0", "vx0", "vy0", "vw0"};
  for (std::size_t i = 0; i < 6; ++i)
    if (!std::isfinite(z[i]))
      throw std::invalid_argument(std::string("initial.") + names[i] + " = " + number_text(z[i]) +
                                  " is out of range: must be finite");
  return z;
}

}  // namespace blockdyn
