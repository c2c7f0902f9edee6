// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/scenario_settings.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/ground_settings.hpp"
#include "blockdyn/family/family.hpp"
#include "blockdyn/model/rigid_ground/rigid_params.hpp"
#include "blockdyn/simulation/rigid_ground_model.hpp"

namespace blockdyn {

namespace {

// Physical-block options: name, field (plain or optional), winkler only.
struct PhysOption {
  const char* name;
  double PhysicalBlock::*plain;
  std::optional<double> PhysicalBlock::*opt;
  bool winkler_only;
};
const PhysOption kPhysOptions[] = {
    {"height", &PhysicalBlock::height, nullptr, false},
    {"width", &PhysicalBlock::width, nullptr, false},
    {"g", &PhysicalBlock::g, nullptr, false},
    {"mass", nullptr, &PhysicalBlock::mass, false},
    {"density", nullptr, &PhysicalBlock::density, false},
    {"thickness", nullptr, &PhysicalBlock::thickness, false},
    {"subgrade-modulus", nullptr, &PhysicalBlock::subgrade_modulus, true},
    {"line-stiffness", nullptr, &PhysicalBlock::line_stiffness, true},
};

// Options that belong to one family only: a clear error instead of a silently ignored option.
void check_family_options(const Settings& s, const std::string& model) {
  const RigidGroundModel* rigid = scenario_family(model).rigid_ground;
  if (rigid) {
    for (const char* n : {"r", "k", "mu", "ic", "units"})
      if (s.has(n))
        throw std::invalid_argument(std::string("`") + n + "` belongs to the winkler model, not to `model` " + model);
  } else {
    for (const char* n : {"restitution", "mu-s", "mu-k", "impact"})
      if (s.has(n))
        throw std::invalid_argument(std::string("`") + n + "` belongs to `model` housner|rigid, not to winkler");
  }
  if (rigid && !rigid->friction)
    for (const char* n : {"mu-s", "mu-k", "impact", "x0", "y0", "vx0", "vy0"})
      if (s.has(n))
        throw std::invalid_argument(std::string("`") + n +
                                    "`"
                                    " belongs to `model` rigid (housner has one degree of freedom)");
}

// The physical-block options on top of the scenario's [physical] block (if any).
void apply_physical(const Settings& s, Scenario& sc) {
  const bool rigid = scenario_family(sc.model).rigid_ground != nullptr;
  bool any = false;
  for (const PhysOption& po : kPhysOptions) {
    if (!s.has(po.name)) continue;
    if (rigid && po.winkler_only)
      throw std::invalid_argument(std::string("`") + po.name + "` belongs to the winkler model (`model` winkler)");
    any = true;
  }
  if (!any) return;
  if (!rigid && (s.has("r") || s.has("k")))
    throw std::invalid_argument("`r`/`k` and a physical block (`height`, `width`, ...) both given: use one");
  PhysicalBlock pb = sc.physical.value_or(PhysicalBlock{});
  if (!rigid) pb.mu = s.has("mu") ? sc.params.mu : (sc.physical ? pb.mu : sc.params.mu);
  for (const PhysOption& po : kPhysOptions) {
    if (!s.has(po.name)) continue;
    if (po.plain)
      pb.*po.plain = *s.number(po.name);
    else
      pb.*po.opt = *s.number(po.name);
  }
  sc.physical = pb;
  if (!rigid) {
    sc.params = to_nondimensional(pb);
    if (!s.has("units")) sc.units = "physical";
  }
}

void apply_initial(const Settings& s, Scenario& sc) {
  if (s.has("ic")) {
    const std::string v = s.text("ic");
    if (v != "ic1" && v != "ic2" && v != "custom")
      throw std::invalid_argument("`ic` = '" + v + "' is not one of: ic1, ic2, custom");
    sc.initial.set = v;
  }
  for (auto [name, field] : {std::pair{"w0", &InitialSpec::w0},
                             {"x0", &InitialSpec::x0},
                             {"y0", &InitialSpec::y0},
                             {"vx0", &InitialSpec::vx0},
                             {"vy0", &InitialSpec::vy0},
                             {"vw0", &InitialSpec::vw0}})
    if (auto v = s.number(name)) sc.initial.*field = *v;
}

}  // namespace

const std::vector<std::string>& scenario_option_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n{"scenario", "model",           "r",           "mu",   "k",    "rtol",  "atol", "method",
                               "t-end",    "output-interval", "ic",          "w0",   "x0",   "y0",    "vx0",  "vy0",
                               "vw0",      "units",           "restitution", "mu-s", "mu-k", "impact"};
    for (const PhysOption& po : kPhysOptions) n.emplace_back(po.name);
    for (const std::string& g : ground_option_names()) n.push_back(g);
    return n;
  }();
  return names;
}

Scenario scenario_from(const Settings& s) {
  Scenario sc = s.has("scenario") ? load_scenario(s.text("scenario")) : Scenario{};
  if (s.has("model")) {
    sc.model = scenario_family(s.text("model")).name;
  }
  check_family_options(s, sc.model);
  sc.params.r = s.number("r", sc.params.r);
  sc.params.mu = s.number("mu", sc.params.mu);
  sc.params.k = s.number("k", sc.params.k);
  apply_integrator_settings(s, sc.options.integrator);
  sc.options.t_end = s.number("t-end", sc.options.t_end);
  sc.output_interval = s.number("output-interval", sc.output_interval);
  apply_initial(s, sc);
  sc.units = s.text("units", sc.units);
  if (auto e = s.number("restitution")) sc.restitution = *e;
  if (auto mu = s.number("mu-s")) {
    sc.interface.mu_s = *mu;
    if (!s.has("mu-k")) sc.interface.mu_k = *mu;
  }
  sc.interface.mu_k = s.number("mu-k", sc.interface.mu_k);
  if (s.has("impact")) {
    const std::string v = s.text("impact");
    const auto law = impact_law_from_string(v);
    if (!law) throw std::invalid_argument("`impact` = '" + v + "' is not one of: housner, newton");
    sc.impact = *law;
  }
  apply_ground_settings(s, sc.ground);
  apply_physical(s, sc);
  validate(sc.ground);
  validate(sc.options);
  require_in_range("output-interval", sc.output_interval, 0.0, 1e300);
  if (!scenario_family(sc.model).rigid_ground) {
    validate(sc.params);
    if (sc.units != "nondim" && sc.units != "physical")
      throw std::invalid_argument("units = '" + sc.units + "' is not one of: nondim, physical");
    if (sc.units == "physical" && !sc.physical)
      throw std::invalid_argument(
          "units = physical needs a physical block (`height` `width` ... or [physical] in the scenario)");
  }
  return sc;
}

}  // namespace blockdyn
