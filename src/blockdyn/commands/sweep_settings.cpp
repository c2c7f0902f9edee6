// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/sweep_settings.hpp"

#include "blockdyn/simulation/run_options.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "blockdyn/analysis/sweep/rigid_sweep.hpp"
#include "blockdyn/analysis/sweep/sweep_evaluator.hpp"
#include "blockdyn/analysis/sweep/sweep_toml.hpp"
#include "blockdyn/commands/ground_settings.hpp"
#include "blockdyn/family/family.hpp"
#include "blockdyn/io/scenario.hpp"
#include "blockdyn/io/toml_read.hpp"
#include "blockdyn/model/rigid_ground/rigid_params.hpp"

namespace blockdyn {

namespace {

const char* const kWinklerOnly[] = {"k", "r", "inv-r", "mu", "ic", "metric", "stop-at-first-flight", "stop-at-ihor"};
const char* const kRigidOnly[] = {"axis", "width", "height", "mass", "g", "mu-s", "mu-k", "restitution", "impact"};

// "ic1, ic2" -> {"ic1", "ic2"} (spaces dropped).
std::vector<std::string> split_list(const std::string& text) {
  std::string compact;
  for (char c : text)
    if (c != ' ') compact += c;
  std::vector<std::string> out;
  std::istringstream in(compact);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  if (compact.empty() || compact.back() == ',') out.emplace_back();
  return out;
}

// The initial-state overrides and the run's options both families share.
template <class Initial, class Options>
void apply_state_and_run(const Settings& s, Initial& initial, Options& options) {
  if (s.has("x0")) initial.x0 = *s.number("x0");
  if (s.has("y0")) initial.y0 = *s.number("y0");
  if (s.has("vx0")) initial.vx0 = *s.number("vx0");
  if (s.has("vy0")) initial.vy0 = *s.number("vy0");
  if (s.has("vw0")) initial.vw0 = *s.number("vw0");
  options.t_end = s.number("t-end", options.t_end);
  apply_integrator_settings(s, options.integrator);
  options.integrator.max_steps = s.integer("max-steps", options.integrator.max_steps);
  if (s.flag("no-energy")) options.track_energy = false;
}

// --w0 and --w0-over-alpha (one of them): the tilt, absolute or per point.
template <class Set>
void apply_tilt(const Settings& s, Set&& set) {
  if (s.has("w0") && s.has("w0-over-alpha")) throw std::invalid_argument("`w0` and `w0-over-alpha`: give only one");
  if (s.has("w0")) set(*s.number("w0"), false);
  if (s.has("w0-over-alpha")) set(*s.number("w0-over-alpha"), true);
}

void set_output(const Settings& s, std::string& output, std::string& plot, std::string& plot_column) {
  output = s.text("output", output);
  plot = s.text("plot", plot);
  plot_column = s.text("plot-column", plot_column);
  if (output.empty()) throw std::invalid_argument("output: the CSV path is empty");
}

SweepPlotAxis plot_axis(const SweepAxis& a) { return {a.name, a.values, a.is_range && a.spacing == AxisSpacing::Log}; }

}  // namespace

SweepDefinition winkler_sweep(const Settings& s, const Family& family) {
  for (const char* n : kRigidOnly)
    if (s.has(n)) throw std::invalid_argument(std::string("`") + n + "` belongs to `model` housner|rigid sweeps");
  SweepSpec sp = s.has("definition") ? load_sweep(s.text("definition")) : SweepSpec{};
  if (s.has("r") && s.has("inv-r")) throw std::invalid_argument("`r` and `inv-r`: give only one aspect-ratio axis");
  if (s.has("k")) sp.k = parse_axis("k", s.text("k"), AxisSpacing::Log);
  if (s.has("r")) sp.r = parse_axis("r", s.text("r"), AxisSpacing::Linear);
  if (s.has("inv-r")) sp.r = parse_axis("inv_r", s.text("inv-r"), AxisSpacing::Linear);
  if (s.has("mu")) sp.mu = parse_axis("mu", s.text("mu"), AxisSpacing::Linear);
  if (s.has("ic")) sp.initial.sets = split_list(s.text("ic"));
  apply_tilt(s, [&](double v, bool over_alpha) {
    (over_alpha ? sp.initial.w0_over_alpha : sp.initial.w0) = v;
    (over_alpha ? sp.initial.w0 : sp.initial.w0_over_alpha).reset();
  });
  apply_state_and_run(s, sp.initial, sp.options);
  if (s.flag("stop-at-first-flight")) sp.options.stop_at_first_flight = true;
  sp.options.stop_at_upright_passages = s.integer("stop-at-ihor", sp.options.stop_at_upright_passages);
  if (s.has("metric")) sp.metrics = s.values("metric");
  set_output(s, sp.output, sp.plot, sp.plot_column);
  validate(sp);
  SweepDefinition d;
  d.model = family.name;
  auto table = std::make_shared<SweepEvaluator>(sp);
  d.definition = definition_json(sp);
  d.table = table;
  d.output = sp.output;
  d.plot = sp.plot;
  d.plot_column = sp.plot_column.empty() ? "first_flight_time" : sp.plot_column;
  d.plot_axes = {plot_axis(sp.k), plot_axis(sp.r), plot_axis(sp.mu)};
  if (sp.initial.sets.size() > 1) d.held.push_back("ic=" + sp.initial.sets.front());
  d.t_end = sp.options.t_end;
  return d;
}

std::vector<std::pair<std::string, std::string>> winkler_sweep_axes() {
  return {{"k", "foundation stiffness (`k`; [axes] k in a definition file)"},
          {"r", "aspect ratio width/height (`r`), or inv_r its inverse (`inv-r`)"},
          {"mu", "friction coefficient (`mu`)"},
          {"ic", "initial-condition sets ic1, ic2, custom (`ic`)"}};
}

namespace {

void apply_block(const Settings& s, RigidSweepSpec& sp) {
  BlockShape& shape = sp.block.shape;
  shape.width = s.number("width", shape.width);
  shape.height = s.number("height", shape.height);
  shape.mass = s.number("mass", shape.mass);
  shape.g = s.number("g", shape.g);
  if (s.has("mu-s")) {
    sp.block.interface.mu_s = *s.number("mu-s");
    if (!s.has("mu-k")) sp.block.interface.mu_k = sp.block.interface.mu_s;  // mu_k defaults to mu_s
  }
  sp.block.interface.mu_k = s.number("mu-k", sp.block.interface.mu_k);
  if (s.has("restitution")) sp.block.restitution = *s.number("restitution");
  if (s.has("impact")) {
    const auto law = impact_law_from_string(s.text("impact"));
    if (!law) throw std::invalid_argument("`impact` = '" + s.text("impact") + "' is not one of: housner, newton");
    sp.block.impact = *law;
  }
}

void add_axes(const Settings& s, RigidSweepSpec& sp) {
  for (const std::string& a : s.values("axis")) {
    const auto eq = a.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument("`axis` '" + a + "': expected NAME=SPEC, e.g. ground_h_amplitude=0.1:1:20");
    const std::string name = a.substr(0, eq);
    for (const auto& x : sp.axes)
      if (x.name == name)
        throw std::invalid_argument("`axis` " + name + ": given twice (or also in the definition file)");
    sp.axes.push_back(parse_axis(name, a.substr(eq + 1), AxisSpacing::Linear));
  }
}

}  // namespace

SweepDefinition rigid_sweep(const Settings& s, const Family& family) {
  const std::string model = family.name;
  for (const char* n : kWinklerOnly)
    if (s.has(n))
      throw std::invalid_argument(std::string("`") + n + "` belongs to the winkler sweep, not to `model` " + model);
  RigidSweepSpec sp;
  if (s.has("definition"))
    sp = load_rigid_sweep(s.text("definition"), *family.rigid_ground);
  else
    sp.block.shape.width = sp.block.shape.height = 0.0;  // the block must be given
  sp.model = family.rigid_ground;
  apply_block(s, sp);
  apply_ground_settings(s, sp.ground);
  apply_tilt(s, [&](double v, bool over_alpha) {
    if (over_alpha) {
      sp.w0_over_alpha = v;
      sp.initial.w0 = 0.0;
    } else {
      sp.initial.w0 = v;
      sp.w0_over_alpha.reset();
    }
  });
  apply_state_and_run(s, sp.initial, sp.options);
  add_axes(s, sp);
  set_output(s, sp.output, sp.plot, sp.plot_column);
  bool has_width = sp.block.shape.width > 0, has_height = sp.block.shape.height > 0;
  for (const auto& a : sp.axes) {
    has_width |= a.name == "width" || a.name == "b_over_h" || a.name == "h_over_b";
    has_height |= a.name == "height";
  }
  if (!has_width || !has_height)
    throw std::invalid_argument(std::string("the ") + model + " sweep needs the block's " +
                                (has_width ? "height" : "width") +
                                ": `width` and `height` [m] (or [physical] in the definition, or an axis)");
  validate(sp);
  SweepDefinition d;
  d.model = model;
  auto table = std::make_shared<RigidSweepEvaluator>(sp);
  d.definition = table->definition();
  d.table = table;
  d.output = sp.output;
  d.plot = sp.plot;
  d.plot_column = sp.plot_column.empty() ? "max_abs_rotation_over_alpha" : sp.plot_column;
  for (const auto& a : sp.axes) d.plot_axes.push_back(plot_axis(a));
  d.t_end = sp.options.t_end;
  return d;
}

const std::vector<StudyOption>& sweep_options() {
  static const std::vector<StudyOption> options = [] {
    std::vector<StudyOption> o = {
        {"model", "model family: winkler (default), housner, rigid, rigid3d"},
        {"axis",
         "housner/rigid/rigid3d: an axis NAME=SPEC (repeatable; the first varies fastest), e.g. "
         "ground_h_amplitude=0.1:1:20 (see `list-axes`)",
         "", false, true},
        {"width", "housner/rigid: block width [m]"},
        {"height", "housner/rigid: block height [m]"},
        {"mass", "housner/rigid: block mass [kg] (default 1)"},
        {"g", "housner/rigid: gravity [m/s^2] (default 9.81)"},
        {"mu-s", "rigid: static friction (default 0.7)"},
        {"mu-k", "rigid: kinetic friction (default mu-s)"},
        {"restitution", "housner/rigid: restitution in [0, 1]"},
        {"impact", "rigid: impact law housner or newton"}};
    for (const StudyOption& g : ground_options()) o.push_back(g);
    const std::vector<StudyOption> rest = {
        {"k", "stiffness axis, e.g. 1e2:1e8:40 (log) or 1e4,1e5"},
        {"r", "aspect-ratio axis r = width/height, e.g. 0.1:1:10 or 0.2"},
        {"inv-r", "slenderness axis 1/r, e.g. 1:20:30"},
        {"mu", "friction axis, e.g. 0.2 or 0.1,0.2,0.3"},
        {"ic", "initial-condition sets, comma-separated: ic1, ic2, custom"},
        {"w0", "initial tilt w0 (ic1 tilt; ic2/custom: w)"},
        {"w0-over-alpha", "initial tilt as a fraction of alpha = atan(r), in [-1, 1]"},
        {"x0", "initial x (overrides the set)"},
        {"y0", "initial y (overrides the set)"},
        {"vx0", "initial x' (overrides the set)"},
        {"vy0", "initial y' (overrides the set)"},
        {"vw0", "initial w' (overrides the set)"},
        {"t-end", "final time of every run (default 30; housner/rigid 10)"},
        {"rtol", rtol_help()},
        {"atol", atol_help()},
        {"method", "Runge-Kutta pair: dopri5, dop853 or auto (dop853 when rtol < 1e-6; default)"},
        {"max-steps", "step limit per run (> 0)"},
        {"stop-at-first-flight", "stop each run at its first take-off", "", true},
        {"stop-at-ihor", "stop each run once ihor reaches N (0: never)"},
        {"no-energy", "do not track the energy balance (max_abs_energy_error left empty)", "", true},
        {"metric", "extra per-point columns by name (repeatable; see `list-metrics`)", "", false, true},
        {"plot", "plot (PNG, SVG beside it): 1-D line or 2-D map of `plot-column`"},
        {"plot-column", "column to plot (default first_flight_time; housner/rigid max_abs_rotation_over_alpha)"}};
    o.insert(o.end(), rest.begin(), rest.end());
    // A settings sweep's families (rigid3d): their own options, where the list has no such name.
    for (const Family& f : families()) {
      if (!f.result_keys || !f.own_options) continue;
      for (const StudyOption& x : f.own_options()) {
        const bool listed = std::any_of(o.begin(), o.end(), [&](const StudyOption& y) { return y.name == x.name; });
        if (!listed) o.push_back({x.name, std::string(f.name) + ": " + x.help, "", x.is_flag, x.is_list, x.aliases});
      }
    }
    return o;
  }();
  return options;
}

const Family& sweep_family(const Settings& s) {
  std::string model = families().front().name;
  if (s.has("model")) {
    model = s.text("model");
  } else if (s.has("definition")) {
    const std::string file = s.text("definition");
    const toml::table root = toml_read::parse(toml_read::read_file(file, "sweep file"), file);
    if (const auto v = root["model"].value<std::string>()) model = *v;
  }
  return family_named("model", model, [](const Family& f) { return f.sweep != nullptr; });
}

SweepDefinition sweep_definition(const Settings& s) {
  s.require_known(sweep_options(), {"definition", "output"}, "sweep");
  const Family& f = sweep_family(s);
  return f.sweep(s, f);
}

}  // namespace blockdyn
