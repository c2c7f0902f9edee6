// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/rigid_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "blockdyn/analysis/sweep/sweep_spec.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/scenario.hpp"
#include "blockdyn/io/toml_read.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

namespace {

struct AxisDef {
  std::string name, what;
  bool friction_only;  // a parameter of the models with friction
  std::function<void(RigidSweepPoint&, double)> apply;
};

GroundComponent& comp(RigidSweepPoint& p, bool h) { return h ? p.ground.horizontal : p.ground.vertical; }

const std::vector<AxisDef>& axis_defs() {
  static const std::vector<AxisDef> defs = [] {
    std::vector<AxisDef> d = {
        {"height", "block height h [m]", false, [](RigidSweepPoint& p, double v) { p.block.shape.height = v; }},
        {"width", "block width b [m]", false, [](RigidSweepPoint& p, double v) { p.block.shape.width = v; }},
        {"b_over_h", "width / height (sets the width)", false,
         [](RigidSweepPoint& p, double v) { p.block.shape.width = v * p.block.shape.height; }},
        {"h_over_b", "slenderness height / width (sets the width)", false,
         [](RigidSweepPoint& p, double v) { p.block.shape.width = p.block.shape.height / v; }},
        {"mass", "block mass [kg]", false, [](RigidSweepPoint& p, double v) { p.block.shape.mass = v; }},
        {"mu", "static and kinetic friction together", true,
         [](RigidSweepPoint& p, double v) {
           p.block.interface = {v, v};
         }},
        {"mu_s", "static friction", true, [](RigidSweepPoint& p, double v) { p.block.interface.mu_s = v; }},
        {"mu_k", "kinetic friction", true, [](RigidSweepPoint& p, double v) { p.block.interface.mu_k = v; }},
        {"restitution", "restitution (housner law: rocking e; newton law: e_n)", false,
         [](RigidSweepPoint& p, double v) { p.block.restitution = v; }},
        {"w0", "initial rotation [rad]", false, [](RigidSweepPoint& p, double v) { p.initial.w0 = v; }},
        {"w0_over_alpha", "initial rotation / alpha", false,
         [](RigidSweepPoint& p, double v) { p.initial.w0 = v * p.block.shape.alpha(); }},
        {"vw0", "initial rotation rate [rad/s]", false, [](RigidSweepPoint& p, double v) { p.initial.vw0 = v; }},
    };
    for (bool h : {true, false}) {
      const std::string n = h ? "ground_h_" : "ground_v_";
      const std::string w = h ? "horizontal " : "vertical ";
      d.push_back({n + "constant", w + "constant acceleration [g]", false,
                   [h](RigidSweepPoint& p, double v) { comp(p, h).constant = v; }});
      d.push_back({n + "amplitude", w + "harmonic or pulse amplitude [g]", false,
                   [h](RigidSweepPoint& p, double v) { comp(p, h).amplitude = v; }});
      d.push_back({n + "frequency", w + "harmonic frequency [Hz]", false,
                   [h](RigidSweepPoint& p, double v) { comp(p, h).frequency = v; }});
      d.push_back({n + "phase", w + "harmonic phase [rad]", false,
                   [h](RigidSweepPoint& p, double v) { comp(p, h).phase = v; }});
      d.push_back({n + "duration", w + "pulse or motion duration [s]", false,
                   [h](RigidSweepPoint& p, double v) { comp(p, h).duration = v; }});
      d.push_back(
          {n + "start", w + "start time [s]", false, [h](RigidSweepPoint& p, double v) { comp(p, h).t_start = v; }});
      d.push_back(
          {n + "scale", w + "record scale factor", false, [h](RigidSweepPoint& p, double v) { comp(p, h).scale = v; }});
    }
    return d;
  }();
  return defs;
}

const AxisDef* find_def(const std::string& name) {
  for (const auto& d : axis_defs())
    if (d.name == name) return &d;
  return nullptr;
}

const std::vector<std::string> kResultColumns = {
    "status",       "t_final",        "final_mode",        "max_abs_rotation",        "max_abs_rotation_over_alpha",
    "overturned",   "overturn_time",  "first_uplift_time", "first_beyond_alpha_time", "impacts",
    "mode_changes", "energy_initial", "work_impact",       "work_friction",           "max_abs_energy_error",
    "steps",        "rhs_evals"};

std::string describe(const RigidSweepSpec& s, const RigidSweepPoint& p) {
  std::ostringstream os;
  os << "point " << p.index << " (";
  for (std::size_t a = 0; a < s.axes.size(); ++a) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", p.values[a]);
    os << (a ? ", " : "") << s.axes[a].name << "=" << buf;
  }
  return os.str() + ")";
}

RigidResult run_point(const RigidSweepSpec& s, const RigidSweepPoint& p) {
  return s.model->simulate(p.block, p.ground, p.initial, s.options);
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& rigid_axis_catalog() {
  static const std::vector<std::pair<std::string, std::string>> c = [] {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& d : axis_defs()) out.emplace_back(d.name, d.what + (d.friction_only ? " (rigid only)" : ""));
    return out;
  }();
  return c;
}

std::size_t point_count(const RigidSweepSpec& s) {
  std::size_t n = 1;
  for (const auto& a : s.axes) n = std::min(n * a.values.size(), kMaxSweepPoints + 1);  // saturates
  return n;
}

RigidSweepPoint sweep_point(const RigidSweepSpec& s, std::size_t index) {
  RigidSweepPoint p;
  p.index = index;
  p.block = s.block;
  p.ground = s.ground;
  p.initial = s.initial;
  std::size_t i = index;
  p.values.resize(s.axes.size());
  for (std::size_t a = 0; a < s.axes.size(); ++a) {
    const std::size_t n = s.axes[a].values.size();
    p.values[a] = s.axes[a].values[i % n];
    i /= n;
  }
  // Axes are applied in catalog order (the width from b_over_h needs the height first, the tilt
  // from w0_over_alpha the final shape); a base w0_over_alpha uses each point's alpha.
  if (s.w0_over_alpha) p.initial.w0 = *s.w0_over_alpha * (p.block.shape.alpha());
  bool tilt_axis = false;
  for (const auto& d : axis_defs())
    for (std::size_t a = 0; a < s.axes.size(); ++a)
      if (s.axes[a].name == d.name) {
        d.apply(p, p.values[a]);
        tilt_axis |= d.name == "w0" || d.name == "w0_over_alpha";
      }
  if (s.w0_over_alpha && !tilt_axis) p.initial.w0 = *s.w0_over_alpha * p.block.shape.alpha();
  return p;
}

void validate(const RigidSweepSpec& s) {
  for (std::size_t a = 0; a < s.axes.size(); ++a) {
    const AxisDef* d = find_def(s.axes[a].name);
    if (!d) {
      std::string names;
      for (const auto& x : axis_defs()) names += (names.empty() ? "" : ", ") + x.name;
      throw std::invalid_argument("axes." + s.axes[a].name + ": not an axis of the " + s.model->name +
                                  " model (axes: " + names + ")");
    }
    if (d->friction_only && !s.model->friction)
      throw std::invalid_argument("axes." + d->name + ": belongs to the rigid model, not " + s.model->name);
    for (std::size_t b = 0; b < a; ++b)
      if (s.axes[b].name == s.axes[a].name) throw std::invalid_argument("axes." + s.axes[a].name + ": given twice");
    require_axis_range(s.axes[a], -1e300, true);
  }
  if (s.w0_over_alpha && s.initial.w0 != 0.0)
    throw std::invalid_argument("initial: give either w0 or w0_over_alpha, not both");
  validate(s.options);
  const std::size_t n = point_count(s);
  if (n == 0 || n > kMaxSweepPoints)
    throw std::invalid_argument("the sweep has " + std::to_string(n) + " points: must be in [1, 1e8]");
  for (std::size_t i = 0; i < n; ++i) {
    const RigidSweepPoint p = sweep_point(s, i);
    try {
      validate(p.block);
      validate(p.ground);
      s.model->check_initial(p.block, p.ground, p.initial);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(describe(s, p) + ": " + e.what());
    }
  }
}

nlohmann::ordered_json definition_json(const RigidSweepSpec& s) {
  json j;
  j["format"] = "blockdyn-sweep-rigid-1";
  j["model"] = s.model->name;
  j["order"] = "index = i_0 + n_0 * (i_1 + n_1 * (...)), axes in the order listed";
  json axes = json::array();
  for (const auto& a : s.axes) axes.push_back(to_json(a));
  j["axes"] = axes;
  j["base"] = parameters_json(s.block, *s.model);
  j["ground_motion"] = to_json(s.ground);
  json init = {{"w0", s.initial.w0}, {"vw0", s.initial.vw0}};
  if (s.w0_over_alpha) init["w0_over_alpha"] = *s.w0_over_alpha;
  for (auto [k, v] :
       {std::pair{"x0", s.initial.x0}, {"y0", s.initial.y0}, {"vx0", s.initial.vx0}, {"vy0", s.initial.vy0}})
    if (v) init[k] = *v;
  j["initial"] = init;
  j["run"] = {{"t_start", s.options.t_start}, {"t_end", s.options.t_end}, {"track_energy", s.options.track_energy}};
  return j;
}

RigidSweepEvaluator::RigidSweepEvaluator(RigidSweepSpec spec) : spec_(std::move(spec)) {
  n_ = point_count(spec_);
  spec_.options.record_events = false;
  columns_.push_back("index");
  for (const auto& a : spec_.axes) columns_.push_back(a.name);
  columns_.insert(columns_.end(), kResultColumns.begin(), kResultColumns.end());
  header_ = csv_header(columns_);
  fingerprint_ = fingerprint_hex(dump_json(definition_json(spec_), -1) + "\n" + header_);
}

nlohmann::ordered_json RigidSweepEvaluator::tolerances() const { return to_json(spec_.options.integrator); }

SweepRow RigidSweepEvaluator::row(std::size_t index) const {
  if (index >= n_) throw std::out_of_range("sweep point index out of range");
  const RigidSweepPoint p = sweep_point(spec_, index);
  CellRow b;
  b.emplace_back(p.index);
  for (double v : p.values) b.emplace_back(v);
  SweepRow out;
  RigidResult r;
  try {
    r = run_point(spec_, p);
  } catch (const std::exception& e) {
    out.error = e.what();
    b.emplace_back(std::string("error"));
    for (std::size_t i = 1; i < kResultColumns.size(); ++i) b.emplace_back();
    out.cells = std::move(b);
    return out;
  }
  auto opt = [&](const std::optional<double>& v) {
    if (v)
      b.emplace_back(*v);
    else
      b.emplace_back();
  };
  b.emplace_back(std::string(to_string(r.status)));
  b.emplace_back(r.t_final);
  b.emplace_back(std::string(to_string(r.final_mode)));
  b.emplace_back(r.max_abs_rotation);
  b.emplace_back(r.max_abs_rotation / p.block.shape.alpha());
  b.emplace_back(r.status == SimStatus::Overturned ? 1L : 0L);
  opt(r.overturn_time);
  opt(r.first_uplift_time);
  opt(r.first_beyond_alpha_time);
  b.emplace_back(r.impacts);
  b.emplace_back(r.mode_changes);
  b.emplace_back(r.energy_initial);
  b.emplace_back(r.work_impact);
  b.emplace_back(r.work_friction);
  if (spec_.options.track_energy)
    b.emplace_back(r.max_abs_energy_error);
  else
    b.emplace_back();
  b.emplace_back(r.stats.accepted);
  b.emplace_back(r.stats.rhs_evals);
  if (!r.note.empty()) out.error = r.note;
  out.cells = std::move(b);
  return out;
}

RigidSweepSpec parse_rigid_sweep(const std::string& text, const std::string& source, const RigidGroundModel& model,
                                 const std::string& base_dir) {
  toml::table root = toml_read::parse(text, source);
  RigidSweepSpec s;
  toml::table output_t;
  std::optional<double> w0_over_alpha;
  // Axes in the order they are written (the first varies fastest); toml++ iterates by key, so
  // they are ordered by their source line (read before the table is copied, which drops it).
  struct Listed {
    std::string name;
    toml::node_type type;
    std::optional<std::string> text;
    std::vector<double> values;
    std::uint32_t line;
  };
  std::vector<Listed> listed;
  if (const auto* a = toml_read::sub_table(root, "axes", "axes")) {
    for (const auto& [k, v] : *a) {
      Listed l{std::string(k.str()), v.type(), std::nullopt, {}, v.source().begin.line};
      if (const auto* str = v.as_string())
        l.text = str->get();
      else if (v.is_number())
        l.values.push_back(toml_read::number(v, "axes." + l.name));
      else if (const auto* arr = v.as_array())
        for (const auto& e : *arr) l.values.push_back(toml_read::number(e, "axes." + l.name + "[]"));
      else
        toml_read::fail("axes." + l.name, "must be a number, a list or a \"min:max:points[:log|:lin]\" string");
      listed.push_back(std::move(l));
    }
  }
  std::stable_sort(listed.begin(), listed.end(), [](const Listed& x, const Listed& y) { return x.line < y.line; });
  if (const auto* o = toml_read::sub_table(root, "output", "output")) output_t = *o;
  if (auto* i = root["initial"].as_table()) {
    w0_over_alpha = toml_read::opt_number(*i, "initial", "w0_over_alpha");
    i->erase("w0_over_alpha");
  }
  root.erase("axes");
  root.erase("output");
  std::ostringstream rest;
  rest << root;
  const Scenario sc = parse_scenario(rest.str(), source, base_dir);
  if (sc.model != model.name)
    throw std::invalid_argument(source + ": model = '" + sc.model + "': this reader is for " + model.name + " sweeps");
  s.model = &model;
  s.ground = sc.ground;
  s.initial.w0 = sc.initial.w0.value_or(0.0);
  s.initial.vw0 = sc.initial.vw0.value_or(0.0);
  s.initial.x0 = sc.initial.x0;
  s.initial.y0 = sc.initial.y0;
  s.initial.vx0 = sc.initial.vx0;
  s.initial.vy0 = sc.initial.vy0;
  s.w0_over_alpha = w0_over_alpha;
  s.options.t_start = sc.options.t_start;
  s.options.t_end = sc.options.t_end;
  s.options.integrator = sc.options.integrator;
  s.block.interface = sc.interface;
  s.block.impact = sc.impact;
  s.block.restitution = sc.restitution;
  s.block.shape.width = s.block.shape.height = 0.0;  // the block must be given ([physical] or axes)
  if (sc.physical) {
    const PhysicalBlock& pb = *sc.physical;
    s.block.shape.width = pb.width;
    s.block.shape.height = pb.height;
    s.block.shape.g = pb.g;
    if (pb.mass || (pb.density && pb.thickness)) s.block.shape.mass = mass_of(pb);
  }
  for (const Listed& l : listed)
    s.axes.push_back(l.text ? parse_axis(l.name, *l.text, AxisSpacing::Linear) : axis_list(l.name, l.values));
  const std::string key = toml_read::first_unknown_key(output_t, {"csv", "plot", "plot_column"});
  if (!key.empty()) toml_read::fail("output." + key, "unknown key (allowed: csv, plot, plot_column)");
  if (auto v = toml_read::opt_string(output_t, "output", "csv")) s.output = *v;
  if (auto v = toml_read::opt_string(output_t, "output", "plot")) s.plot = *v;
  if (auto v = toml_read::opt_string(output_t, "output", "plot_column")) s.plot_column = *v;
  return s;
}

RigidSweepSpec load_rigid_sweep(const std::string& path, const RigidGroundModel& model) {
  const auto slash = path.find_last_of('/');
  return parse_rigid_sweep(toml_read::read_file(path, "sweep file"), path, model,
                           slash == std::string::npos ? "" : path.substr(0, slash));
}

}  // namespace blockdyn
