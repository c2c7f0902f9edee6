// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/forced_model_settings.hpp"

#include "blockdyn/base/number_text.hpp"

#include "blockdyn/commands/assembly_settings.hpp"
#include "blockdyn/commands/rigid3d_run.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "blockdyn/analysis/forced/forced_body3d.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/family/family.hpp"
#include "blockdyn/model/rigid_ground/rigid_params.hpp"

namespace blockdyn {

namespace {

void refuse(const Settings& s, const std::vector<std::string>& names, const std::string& why) {
  for (const std::string& n : names)
    if (s.has(n)) throw std::invalid_argument(std::string("`") + n + "` " + why);
}

void check_values(const Settings& s) {
  if (auto mu_k = s.number("mu-k"); mu_k && !(std::isfinite(*mu_k) && *mu_k >= 0.0))
    throw std::invalid_argument("mu-k = " + number_text(*mu_k) + " is out of range: must be finite and >= 0");
  if (auto e = s.number("restitution"); e && !(std::isfinite(*e) && *e >= 0.0 && *e <= 1.0))
    throw std::invalid_argument("restitution = " + number_text(*e) + " is out of range: must be in [0, 1]");
}

ForcedModel block_model(const Settings& s, const Family& family) {
  if (!s.has("width") || !s.has("height"))
    throw std::invalid_argument("`width` and `height` are needed for `model` " + std::string(family.name));
  RigidBlockParams rp;
  rp.shape = {*s.number("width"), *s.number("height"), s.number("mass", 1.0), s.number("g", 9.81)};
  const double mu_s = s.number("mu-s", 0.7);
  rp.interface = {mu_s, s.number("mu-k", mu_s)};
  const std::string impact = s.text("impact", to_string(ImpactLaw::Housner));
  const std::optional<ImpactLaw> law = impact_law_from_string(impact);
  if (!law) throw std::invalid_argument("`impact` = '" + impact + "' is not one of: housner, newton");
  rp.impact = *law;
  if (auto e = s.number("restitution")) rp.restitution = *e;
  return forced_block_model(rp, *family.rigid_ground);
}

ForcedModel assembly_model(const Settings& s, const Family& family) {
  const std::string preset = s.text("preset");
  if (preset.empty()) throw std::invalid_argument("`model` assembly needs `preset` block|trilith|column|arch");
  PresetOptions po = preset_geometry_from(s, preset);
  po.contact = contact_kind_from("`contact`", s.text("contact", to_string(ContactKind::Deformable)));
  const double phi_s = s.number("phi-s", 90), phi_l = s.number("phi-l", 90);
  require_in_range("phi-s", phi_s, 0, 90);
  require_in_range("phi-l", phi_l, 0, 90);
  const std::optional<double> e = s.number("restitution");
  for (ContactLaw* l : {&po.ground_law, &po.block_law}) {
    const double phi = l == &po.ground_law ? phi_s : phi_l;
    l->mu_s = l->mu_k = phi >= 90 ? kNoSlipFriction : std::tan(phi * M_PI / 180);
    if (info(po.contact).plastic_impacts)
      l->restitution = e.value_or(0.0);
    else if (e)
      l->restitution = *e;
  }
  Assembly a = make_preset(preset, po);
  const bool rock_only = s.flag("columns-rock-only");
  if (rock_only) restrict_to_rocking_on_ground(a);

  nlohmann::ordered_json description = {
      {"model", family.name}, {"preset", preset}, {"contact", to_string(a.contact)}, {"blocks", a.blocks.size()},
      {"phi_s", phi_s},       {"phi_l", phi_l},   {"slenderness", po.slenderness},   {"columns_rock_only", rock_only}};
  return forced_assembly_model(a, std::move(description));
}

ForcedModel body3d_model(const Settings& s, const Family&) {
  return forced_body3d_model(body3d_from(s), body3d_friction_from(s), s.number("incidence", 0.0));
}

const std::vector<std::string>& assembly_only_options() {
  static const std::vector<std::string> n = [] {
    std::vector<std::string> out{"preset", "contact", "phi-s", "phi-l", "columns-rock-only"};
    for (const std::string& o : preset_geometry_option_names())
      if (o != "tilt") out.push_back(o);
    return out;
  }();
  return n;
}

const char* const kNotBlock = "applies to `model` assembly only";
const char* const kNot3d = "applies to `model` rigid3d only";
const std::vector<std::string> kBody3dOnly = {"shape", "depth", "incidence"};

// The assembly's options the 3D body does not share (it has a radius and a density of its own).
std::vector<std::string> not_body3d_options() {
  std::vector<std::string> out;
  for (const std::string& o : assembly_only_options())
    if (o != "radius" && o != "density") out.push_back(o);
  return out;
}

}  // namespace

// The families' entries (family_registry.cpp). The blocks' Lyapunov runs default to tight
// tolerances; an assembly's tangent carries the stiff contact modes, which the integrator must
// resolve: at 1e-6 its chaos-map exponent agrees with 1e-8 to a few per cent at a hundredth of the
// cost (docs/forced-chaos.md).
const ForcedFamily& housner_forced() {
  static const ForcedFamily f{.refused = {{assembly_only_options(), kNotBlock},
                                          {{"mu-s", "mu-k", "impact"}, "applies to `model` rigid only"},
                                          {kBody3dOnly, kNot3d}},
                              .build = block_model,
                              .lyapunov_rtol = 1e-10,
                              .lyapunov_atol = 1e-12};
  return f;
}

const ForcedFamily& rigid_forced() {
  static const ForcedFamily f{.refused = {{assembly_only_options(), kNotBlock}, {kBody3dOnly, kNot3d}},
                              .build = block_model,
                              .lyapunov_rtol = 1e-10,
                              .lyapunov_atol = 1e-12};
  return f;
}

const ForcedFamily& assembly_forced() {
  static const ForcedFamily f{
      .refused = {{{"width", "height", "mass", "g", "mu-s", "mu-k", "impact"},
                   "applies to `model` housner|rigid only (an assembly's blocks and friction come from `preset` and "
                   "`phi-s`/`phi-l`)"},
                  {kBody3dOnly, kNot3d}},
      .build = assembly_model,
      .lyapunov_rtol = 1e-8,
      .lyapunov_atol = 1e-10,
      .chaos_map_rtol = 1e-6,
      .chaos_map_atol = 1e-8,
      .initial_state = false,
      .friction_angles = true};
  return f;
}

// The 3D body: the planar analyses' motion along `incidence`; its runs start at rest (no --w0),
// and it has no tangent (no Lyapunov exponent) nor a cycle trace yet.
const ForcedFamily& rigid3d_forced() {
  static const ForcedFamily f{.refused = {{not_body3d_options(), kNotBlock}},
                              .build = body3d_model,
                              .lyapunov_rtol = 1e-10,
                              .lyapunov_atol = 1e-12,
                              .initial_state = false,
                              .spatial = true};
  return f;
}

const std::vector<std::string>& forced_model_option_names() {
  static const std::vector<std::string> n = [] {
    std::vector<std::string> out{"model",  "width",       "height",   "mass",    "g",     "mu-s",  "mu-k",
                                 "impact", "restitution", "preset",   "contact", "phi-s", "phi-l", "columns-rock-only",
                                 "shape",  "depth",       "incidence"};
    for (const std::string& o : preset_geometry_option_names())
      if (o != "tilt") out.push_back(o);
    return out;
  }();
  return n;
}

ForcedModelChoice forced_model_choice(const Settings& s) {
  ForcedModelChoice c;
  c.model = s.text("model", c.model);
  c.family = &forced_family(c.model);
  c.preset = s.text("preset");
  c.contact = s.text("contact", c.contact);
  c.phi_s = s.number("phi-s", c.phi_s);
  c.phi_l = s.number("phi-l", c.phi_l);
  c.columns_rock_only = s.flag("columns-rock-only");
  return c;
}

const Family& forced_family(const std::string& name) {
  return family_named("`model`", name, [](const Family& f) { return f.forced != nullptr; });
}

ForcedModel forced_model_from(const Settings& s) {
  const Family& family = forced_family(s.text("model", ForcedModelChoice{}.model));
  for (const auto& [options, why] : family.forced->refused) refuse(s, options, why);
  check_values(s);
  return family.forced->build(s, family);
}

}  // namespace blockdyn
