// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/assembly_settings.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/ground_settings.hpp"
#include "blockdyn/io/assembly_file.hpp"

namespace blockdyn {

namespace {

// The option values with the command line's defaults.
struct Values {
  std::string file, preset;
  ContactKind contact;
  double phi_s, phi_l, tilt, k_normal, k_tangential, restitution, collapse_rotation, min_bearing, g;
  std::optional<double> phi_s_kinetic, phi_l_kinetic;
  // The law's traits (contact_kind.hpp).
  const ContactKindInfo& law() const { return info(contact); }
};

Values values_of(const Settings& s) {
  Values v;
  v.file = s.text("file", s.text("scenario"));
  v.preset = s.text("preset");
  v.contact = contact_kind_from("`contact`", s.text("contact", to_string(ContactKind::Deformable)));
  v.phi_s = s.number("phi-s", 90);
  v.phi_l = s.number("phi-l", 90);
  v.phi_s_kinetic = s.number("phi-s-kinetic");
  v.phi_l_kinetic = s.number("phi-l-kinetic");
  v.tilt = s.number("tilt", 0);
  v.k_normal = s.number("normal-stiffness", 1e7);
  v.k_tangential = s.number("tangential-stiffness", -1);
  // The rigid law's Newton restitution defaults to 0 (a plastic contact, as Housner's block).
  v.restitution = s.number("restitution", v.law().plastic_impacts ? 0.0 : 0.5);
  v.collapse_rotation = s.number("collapse-rotation", 1.0);
  v.min_bearing = s.number("min-bearing", 0.0);
  v.g = s.number("g", 9.81);
  return v;
}

void check_values(const Settings& s, const Values& v) {
  if (v.file.empty() == v.preset.empty())
    throw std::invalid_argument(v.file.empty() ? "give `preset` block|trilith|column|arch or an assembly FILE.toml"
                                               : "give either `preset` or an assembly file, not both");
  require_in_range("phi-s", v.phi_s, 0, 90);
  require_in_range("phi-l", v.phi_l, 0, 90);
  // The kinetic angles lie between 0 and the static ones (the file's, or the options').
  if (v.phi_s_kinetic)
    require_in_range("phi-s-kinetic", *v.phi_s_kinetic, 0, v.file.empty() || s.has("phi-s") ? v.phi_s : 90);
  if (v.phi_l_kinetic)
    require_in_range("phi-l-kinetic", *v.phi_l_kinetic, 0, v.file.empty() || s.has("phi-l") ? v.phi_l : 90);
  require_in_range("tilt", v.tilt, -1.5, 1.5, false, false);
  require_in_range("normal-stiffness", v.k_normal, 1, 1e13);
  if (s.has("tangential-stiffness")) require_in_range("tangential-stiffness", v.k_tangential, 1, 1e13);
  require_in_range("restitution", v.restitution, v.law().plastic_impacts ? 0.0 : 1e-3, 1);
  const std::string scheme = s.text("scheme", "event-driven");
  if (scheme != "event-driven" && scheme != "time-stepping")
    throw std::invalid_argument("`scheme` = '" + scheme + "' is not one of: event-driven, time-stepping");
  if (!v.law().schemes && s.has("scheme")) throw std::invalid_argument("`scheme` belongs to `contact` rigid");
  for (const char* n : {"normal-stiffness", "tangential-stiffness"})
    if (!v.law().springs && s.has(n))
      throw std::invalid_argument(std::string("`") + n + "` belongs to `contact` deformable");
  if (v.law().schemes && scheme == "time-stepping")
    for (const char* n : {"rtol", "atol", "method"})
      if (s.has(n))
        throw std::invalid_argument(std::string("`") + n +
                                    "`"
                                    " belongs to `scheme` event-driven (time-stepping has `step`)");
  if (!v.law().schemes && s.has("step")) throw std::invalid_argument("`step` belongs to `contact` rigid");
  if (s.flag("columns-rock-only") && scheme == "event-driven" && s.has("scheme"))
    throw std::invalid_argument(
        "`columns-rock-only` (seed 001's 5-DOF restriction) is integrated by `scheme` time-stepping only");
  require_in_range("collapse-rotation", v.collapse_rotation, 0, 10, false);
  require_in_range("min-bearing", v.min_bearing, 0, 1e3);
  require_in_range("g", v.g, 0, 1e3, false);
}

ContactLaw preset_law(const Values& v, double phi, const char* field) {
  ContactLaw l;
  l.k_normal = v.k_normal;
  l.k_tangential = v.k_tangential;
  l.restitution = v.restitution;
  l.mu_s = l.mu_k = friction_of_angle(phi, field);
  return l;
}

void set_kinetic(ContactLaw& l, const std::optional<double>& phi_kinetic, const char* field) {
  if (phi_kinetic) l.mu_k = friction_of_angle(*phi_kinetic, field);
}

Assembly from_file(const Settings& s, const Values& v) {
  for (const std::string& n : preset_geometry_option_names())
    if (s.has(n))
      throw std::invalid_argument(std::string("`") + n + "` belongs to `preset` (an assembly file gives its blocks)");
  Assembly a = read_assembly_file(v.file);
  // Options given override the file's contact laws.
  for (AssemblyInterface& i : a.interfaces) {
    ContactLaw& l = i.law;
    if (s.has("normal-stiffness")) l.k_normal = v.k_normal;
    if (s.has("tangential-stiffness")) l.k_tangential = v.k_tangential;
    if (s.has("restitution")) l.restitution = v.restitution;
    const bool ground = i.lower < 0;
    if (ground && s.has("phi-s")) l.mu_s = l.mu_k = friction_of_angle(v.phi_s, "phi-s");
    if (!ground && s.has("phi-l")) l.mu_s = l.mu_k = friction_of_angle(v.phi_l, "phi-l");
    set_kinetic(l, ground ? v.phi_s_kinetic : v.phi_l_kinetic, ground ? "phi-s-kinetic" : "phi-l-kinetic");
  }
  apply_default_restitution(a, v.law().plastic_impacts);  // one default per law: the presets' (0.5 deformable, 0 rigid)
  if (s.has("g")) a.g = v.g;
  a.contact = v.contact;
  return a;
}

Assembly from_preset(const Settings& s, const Values& v) {
  PresetOptions o = preset_geometry_from(s, v.preset);
  o.tilt = v.tilt;
  o.ground_law = preset_law(v, v.phi_s, "phi-s");
  o.block_law = preset_law(v, v.phi_l, "phi-l");
  set_kinetic(o.ground_law, v.phi_s_kinetic, "phi-s-kinetic");
  set_kinetic(o.block_law, v.phi_l_kinetic, "phi-l-kinetic");
  o.contact = v.contact;
  if (v.preset == "arch" && s.has("tilt"))
    throw std::invalid_argument("`tilt` belongs to `preset` block|trilith|column");
  Assembly a = make_preset(v.preset, o);
  a.g = v.g;
  return a;
}

// Options that belong to some presets only, and those presets.
const std::vector<std::pair<std::string, std::vector<std::string>>>& preset_only_options() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> t{
      {"slenderness", {"block", "trilith", "column"}},
      {"block-width", {"block", "trilith", "column"}},
      {"drums", {"column"}},
      {"lintel-length", {"trilith"}},
      {"overhang", {"trilith"}},
      {"voussoirs", {"arch"}},
      {"thickness-ratio", {"arch"}},
      {"radius", {"arch"}},
      {"embrace", {"arch"}}};
  return t;
}

}  // namespace

const std::vector<std::string>& preset_names() {
  static const std::vector<std::string> n{"block", "trilith", "column", "arch"};
  return n;
}

const std::vector<std::string>& preset_geometry_option_names() {
  static const std::vector<std::string> n = [] {
    std::vector<std::string> out{"thickness", "density", "tilt"};
    for (const auto& [name, presets] : preset_only_options()) out.push_back(name);
    return out;
  }();
  return n;
}

PresetOptions preset_geometry_from(const Settings& s, const std::string& preset) {
  std::string names;
  bool known = false;
  for (const std::string& p : preset_names()) {
    names += (names.empty() ? "" : ", ") + p;
    known = known || p == preset;
  }
  if (!known) throw std::invalid_argument("`preset` = '" + preset + "' is not one of: " + names);
  for (const auto& [name, presets] : preset_only_options()) {
    if (!s.has(name)) continue;
    std::string owners;
    bool ok = false;
    for (const std::string& p : presets) {
      owners += (owners.empty() ? "" : "|") + p;
      ok = ok || p == preset;
    }
    if (!ok) throw std::invalid_argument(std::string("`") + name + "` belongs to `preset` " + owners);
  }
  PresetOptions o;
  o.slenderness = s.number("slenderness", o.slenderness);
  o.drums = s.small_integer("drums", int(o.drums));
  o.block_width = s.number("block-width", o.block_width);
  o.thickness = s.number("thickness", o.thickness);
  o.density = s.number("density", o.density);
  o.lintel_length = s.number("lintel-length", o.lintel_length);
  o.overhang = s.number("overhang", o.overhang);
  o.voussoirs = s.small_integer("voussoirs", int(o.voussoirs));
  o.thickness_ratio = s.number("thickness-ratio", o.thickness_ratio);
  o.radius = s.number("radius", o.radius);
  o.embrace = s.number("embrace", o.embrace);
  return o;
}

const std::vector<std::string>& assembly_option_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n{"model",
                               "file",
                               "scenario",
                               "preset",
                               "contact",
                               "slenderness",
                               "drums",
                               "block-width",
                               "thickness",
                               "density",
                               "lintel-length",
                               "overhang",
                               "voussoirs",
                               "thickness-ratio",
                               "radius",
                               "embrace",
                               "phi-s",
                               "phi-l",
                               "phi-s-kinetic",
                               "phi-l-kinetic",
                               "tilt",
                               "normal-stiffness",
                               "tangential-stiffness",
                               "restitution",
                               "collapse-rotation",
                               "min-bearing",
                               "g",
                               "step",
                               "scheme",
                               "columns-rock-only",
                               "t-end",
                               "rtol",
                               "atol",
                               "method",
                               "output-interval"};
    for (const std::string& g : ground_option_names()) n.push_back(g);
    return n;
  }();
  return names;
}

Assembly assembly_geometry_from(const Settings& s, int max_blocks) {
  const Values v = values_of(s);
  check_values(s, v);
  Assembly a = v.file.empty() ? from_preset(s, v) : from_file(s, v);
  if (s.flag("columns-rock-only")) restrict_to_rocking_on_ground(a);
  if (s.has("collapse-rotation") || v.file.empty()) a.collapse_rotation = v.collapse_rotation;
  if (s.has("min-bearing") || v.file.empty()) a.min_bearing = v.min_bearing;
  validate(a, max_blocks);
  return a;
}

AssemblySetup assembly_from(const Settings& s) {
  AssemblySetup setup;
  setup.assembly = assembly_geometry_from(s, kMaxDynamicBlocks);
  apply_ground_settings(s, setup.ground);
  AssemblyRunOptions& o = setup.run;
  o.t_end = s.number("t-end", o.t_end);
  o.step = s.number("step", o.step);
  o.scheme = !s.has("scheme")                         ? AssemblyScheme::Auto
             : s.text("scheme", "") == "event-driven" ? AssemblyScheme::EventDriven
                                                      : AssemblyScheme::TimeStepping;
  // Above kEventDrivenMaxBlocks blocks the rigid law's default is time-stepping, whose options
  // are not the integrator's.
  if (info(setup.assembly.contact).schemes && effective_scheme(setup.assembly, o) == AssemblyScheme::TimeStepping)
    for (const char* n : {"rtol", "atol", "method"})
      if (s.has(n))
        throw std::invalid_argument(std::string("`") + n +
                                    "`"
                                    " belongs to `scheme` event-driven (time-stepping, the rigid law's " +
                                    "default above " + std::to_string(kEventDrivenMaxBlocks) + " blocks, has `step`)");
  apply_integrator_settings(s, o.integrator);
  o.output_interval = s.number("output-interval", o.output_interval);
  validate(o);
  return setup;
}

}  // namespace blockdyn
