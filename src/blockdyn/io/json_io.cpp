// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/json_io.hpp"

#include <cmath>

#include "blockdyn/version.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

json to_json(const WinklerParams& p) {
  return {{"r", p.r}, {"mu", p.mu}, {"k", p.k}, {"alpha", p.alpha()}, {"inertia", p.inertia()}};
}

json to_json(const GroundComponent& c) {
  json j = {{"constant", c.constant}, {"amplitude", c.amplitude}, {"frequency", c.frequency},   {"phase", c.phase},
            {"t_start", c.t_start},   {"duration", c.duration},   {"pulse", to_string(c.pulse)}};
  if (c.record) {
    j["record"] = {{"source", c.record->source()},      {"samples", c.record->size()}, {"dt_s", c.record->dt()},
                   {"duration_s", c.record->t_last()},  {"peak_g", c.record->peak()},  {"scale", c.scale},
                   {"time_unit_s", c.record_time_unit}, {"digest", c.record->digest()}};
  } else {
    j["record"] = nullptr;
  }
  return j;
}

json to_json(const GroundMotion& g) {
  return {{"horizontal", to_json(g.horizontal)}, {"vertical", to_json(g.vertical)}};
}

json to_json(const IntegratorOptions& o) {
  return {{"method", to_string(resolved_method(o))},
          {"event_location", "envelope scan (end values and rates, interior samples), TOMS748 on the dense output"},
          {"rtol", o.rtol},
          {"atol", o.atol},
          {"event_samples", o.event_samples},
          {"max_steps", o.max_steps}};
}

json state_json(const WinklerState& z) {
  return {{"x", z[kX]}, {"y", z[kH] + 0.5}, {"w", z[kW]}, {"vx", z[kVX]}, {"vy", z[kVY]}, {"vw", z[kVW]}};
}

json state_json(const WinklerState& z, const UnitScales& s) {
  return {{"x_m", z[kX] * s.length},
          {"y_m", (z[kH] + 0.5) * s.length},
          {"w_rad", z[kW]},
          {"vx_m_per_s", z[kVX] * s.velocity},
          {"vy_m_per_s", z[kVY] * s.velocity},
          {"vw_rad_per_s", z[kVW] * s.angular_velocity}};
}

json to_json(const Energy& e) {
  return {{"kinetic_x", e.kinetic_x}, {"kinetic_y", e.kinetic_y}, {"rotation", e.rotation},
          {"gravity", e.gravity},     {"springs", e.springs},     {"total", e.total()}};
}

json to_json(const WinklerEventRecord& e) {
  return {{"t", e.t},
          {"kind", to_string(e.kind)},
          {"from", to_string(e.from.regime)},
          {"to", to_string(e.to.regime)},
          {"ihor", e.upright_passages},
          {"state", state_json(e.z)}};
}

static json pose_json(const std::array<double, 6>& q) {
  return {{"x", q[0]}, {"y", q[1]}, {"w", q[2]}, {"vx", q[3]}, {"vy", q[4]}, {"vw", q[5]}};
}

json to_json(const RigidEventRecord& e) {
  json j = {{"t", e.t}, {"kind", to_string(e.kind)}};
  if (e.kind == RigidEventKind::Impact) {
    j["corner"] = corner_name(e.corner);
    j["vw_before"] = e.vw_before;
    j["vw_after"] = e.vw_after;
  }
  if (e.kind == RigidEventKind::AmbiguousOnset) {
    // The chosen mechanism first, then the others consistent at the same instant.
    json names = json::array({to_string(e.to)});
    for (Mechanism m : kMechanisms)
      if (m != e.to && (e.mechanisms & mechanism_bit(m))) names.push_back(to_string(m));
    j["mechanisms"] = names;
    j["chosen"] = to_string(e.to);
    j["rule"] = "static friction holds where it can, then the most closed contacts";
  }
  if (e.kind == RigidEventKind::Impact || e.kind == RigidEventKind::Mode) {
    j["from"] = to_string(e.from);
    j["to"] = to_string(e.to);
    j["pivot"] = e.pivot ? json(corner_name(e.pivot)) : json(nullptr);
    j["slip"] = e.slip;
  }
  j["state"] = pose_json(e.state);
  return j;
}

json to_json(const RunTiming& t) { return {{"integration_wall_s", t.wall_s}, {"integration_cpu_s", t.cpu_s}}; }

std::string schema_name(const std::string& command, const std::string& kind) {
  return "blockdyn." + command + "." + kind + "/" + std::to_string(kJsonSchemaVersion);
}

json run_info() { return {{"program", "blockdyn"}, {"version", kVersion}, {"git", kGitDescribe}}; }

static json opt_or_null(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

json result_json(const WinklerParams& p, const GroundMotion& g, const WinklerRunOptions& o, const WinklerResult& r,
                 const PhysicalBlock* phys) {
  json j;
  j["run"] = run_info();
  j["model"] = "winkler";
  j["parameters"] = to_json(p);
  j["ground_motion"] = to_json(g);
  j["tolerances"] = to_json(o.integrator);
  j["tolerances"]["atol_scaling"] = "h: atol/k, y': atol/sqrt(k) (for k > 1)";
  j["t_start"] = o.t_start;
  j["t_end"] = o.t_end;
  j["initial_state"] = state_json(r.initial_state);
  j["initial_mode"] = to_string(r.initial_mode.regime);
  j["initial_energy"] = to_json(r.initial_energy);
  j["status"] = to_string(r.status);
  j["integrator_status"] = to_string(r.run_status);
  j["t_final"] = r.t_final;
  j["final_state"] = state_json(r.final_state);
  j["final_mode"] = to_string(r.final_mode.regime);
  j["final_energy"] = to_json(r.final_energy);
  j["ihor"] = r.upright_passages;
  j["first_flight_time"] = opt_or_null(r.first_flight_time);
  j["ihor_at_first_flight"] = r.first_flight_time ? json(r.upright_passages_at_first_flight) : json(nullptr);
  j["overturn_time"] = opt_or_null(r.overturn_time);
  j["ihor_at_overturn"] = r.overturn_time ? json(r.upright_passages_at_overturn) : json(nullptr);
  j["max_abs_energy_error"] = r.max_abs_energy_error;
  j["max_abs_energy_change"] = r.max_abs_energy_change;
  j["work_friction"] = r.work_friction();
  j["work_nonpotential"] = r.work_nonpotential();
  j["work_ground"] = r.work_ground();
  j["steps"] = r.stats.accepted;
  j["rejected_steps"] = r.stats.rejected;
  j["rejected_at_restart"] = r.stats.rejected_at_restart;
  j["rhs_evals"] = r.stats.rhs_evals;
  json counts = json::object();
  for (int k = 0; k < kNumEventKinds; ++k)
    if (r.event_counts[k]) counts[to_string(WinklerEventKind(k))] = r.event_counts[k];
  j["event_counts"] = counts;
  json ev = json::array();
  for (const auto& e : r.events) ev.push_back(to_json(e));
  j["events"] = ev;
  if (phys) {
    const UnitScales s = scales_of(*phys);
    j["physical"] = {{"height_m", phys->height},
                     {"width_m", phys->width},
                     {"mass_kg", s.mass},
                     {"g_m_per_s2", phys->g},
                     {"time_scale_s", s.time},
                     {"t_end_s", o.t_end * s.time},
                     {"t_final_s", r.t_final * s.time},
                     {"first_flight_time_s", r.first_flight_time ? json(*r.first_flight_time * s.time) : json(nullptr)},
                     {"overturn_time_s", r.overturn_time ? json(*r.overturn_time * s.time) : json(nullptr)},
                     {"initial_state", state_json(r.initial_state, s)},
                     {"final_state", state_json(r.final_state, s)},
                     {"initial_energy_J", r.initial_energy.total() * s.energy},
                     {"work_friction_J", r.work_friction() * s.energy}};
  }
  return j;
}

json rigid_result_json(const RigidBlockParams& p, const RigidGroundModel& m, const GroundMotion& g,
                       const RigidRunOptions& o, const RigidResult& r) {
  auto opt = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
  json j;
  j["run"] = run_info();
  j["model"] = r.model;
  j["units"] = "SI (s, m, rad, kg, N, J); ground accelerations in g";
  j["parameters"] = parameters_json(p, m);
  j["ground_motion"] = to_json(g);
  j["tolerances"] = to_json(o.integrator);
  j["tolerances"]["atol_scaling"] = m.atol_scaling;
  j["t_start"] = o.t_start;
  j["t_end"] = o.t_end;
  j["initial_state"] = pose_json(r.initial_state);
  j["initial_mode"] = to_string(r.initial_mode);
  j["status"] = to_string(r.status);
  j["integrator_status"] = to_string(r.run_status);
  j["note"] = r.note.empty() ? json(nullptr) : json(r.note);
  j["t_final"] = r.t_final;
  j["final_mode"] = to_string(r.final_mode);
  j["final_state"] = pose_json(r.final_state);
  j["max_abs_rotation"] = r.max_abs_rotation;
  j["max_abs_rotation_over_alpha"] = r.max_abs_rotation / p.shape.alpha();
  j["t_max_abs_rotation"] = r.t_max_abs_rotation;
  j["overturn_time"] = opt(r.overturn_time);
  j["first_motion_time"] = opt(r.first_motion_time);
  j["first_uplift_time"] = opt(r.first_uplift_time);
  j["first_beyond_alpha_time"] = opt(r.first_beyond_alpha_time);
  j["impacts"] = r.impacts;
  j["mode_changes"] = r.mode_changes;
  j["ambiguous_onsets"] = r.event_counts[int(RigidEventKind::AmbiguousOnset)];
  const double e_final = r.kinetic_final + r.potential_final;
  j["energy"] = {{"initial", r.energy_initial},
                 {"kinetic_final", r.kinetic_final},
                 {"potential_final", r.potential_final},
                 {"total_final", e_final},
                 {"work_friction", r.work_friction},
                 {"work_ground", r.work_ground},
                 {"work_impact", r.work_impact},
                 {"balance_final", e_final - r.energy_initial - r.work_friction - r.work_ground - r.work_impact}};
  j["max_abs_energy_error"] = r.max_abs_energy_error;
  j["max_abs_energy_change"] = r.max_abs_energy_change;
  j["steps"] = r.stats.accepted;
  j["rejected_steps"] = r.stats.rejected;
  j["rejected_at_restart"] = r.stats.rejected_at_restart;
  j["rhs_evals"] = r.stats.rhs_evals;
  json counts = json::object();
  for (int k = 0; k < kNumRigidEventKinds; ++k)
    if (r.event_counts[k]) counts[to_string(RigidEventKind(k))] = r.event_counts[k];
  j["event_counts"] = counts;
  json ev = json::array();
  for (const auto& e : r.events) ev.push_back(to_json(e));
  j["events"] = ev;
  return j;
}

static void sanitize(json& j) {
  if (j.is_number_float() && !std::isfinite(j.get<double>()))
    j = nullptr;
  else if (j.is_structured())
    for (auto& v : j) sanitize(v);
}

std::string dump_json(const json& j, int indent) {
  json c = j;
  sanitize(c);
  return c.dump(indent);
}

}  // namespace blockdyn
