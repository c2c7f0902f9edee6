#include "blockdyn/io/json_io.hpp"

#include <cmath>

#include "blockdyn/version.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

json to_json(const BlockParams& p) {
  return {{"r", p.r}, {"mu", p.mu}, {"k", p.k}, {"alpha", p.alpha()}, {"inertia", p.inertia()}};
}

static json component_json(const GroundComponent& c) {
  return {{"constant", c.constant}, {"amplitude", c.amplitude}, {"frequency", c.frequency},
          {"phase", c.phase},       {"t_start", c.t_start},     {"duration", c.duration}};
}

json to_json(const GroundMotion& g) {
  return {{"horizontal", component_json(g.horizontal)}, {"vertical", component_json(g.vertical)}};
}

json to_json(const IntegratorOptions& o) {
  return {{"method", "dopri5(4) dense output, TOMS748 event location"},
          {"rtol", o.rtol},
          {"atol", o.atol},
          {"atol_scaling", "h: atol/k, y': atol/sqrt(k) (for k > 1)"},
          {"event_samples", o.event_samples},
          {"max_steps", o.max_steps}};
}

json state_json(const BlockStateVec& z) {
  return {{"x", z[kX]}, {"y", z[kH] + 0.5}, {"w", z[kW]}, {"vx", z[kVX]}, {"vy", z[kVY]}, {"vw", z[kVW]}};
}

json state_json(const BlockStateVec& z, const UnitScales& s) {
  return {{"x_m", z[kX] * s.length},           {"y_m", (z[kH] + 0.5) * s.length},
          {"w_rad", z[kW]},                    {"vx_m_per_s", z[kVX] * s.velocity},
          {"vy_m_per_s", z[kVY] * s.velocity}, {"vw_rad_per_s", z[kVW] * s.angular_velocity}};
}

json to_json(const Energy& e) {
  return {{"kinetic_x", e.kinetic_x}, {"kinetic_y", e.kinetic_y}, {"rotation", e.rotation},
          {"gravity", e.gravity},     {"springs", e.springs},     {"total", e.total()}};
}

json to_json(const EventRecord& e) {
  return {{"t", e.t},
          {"kind", to_string(e.kind)},
          {"from", to_string(e.from.regime)},
          {"to", to_string(e.to.regime)},
          {"ihor", e.ihor},
          {"state", state_json(e.z)}};
}

json run_info() {
  return {{"program", "blockdyn"}, {"version", kVersion}, {"git", kGitDescribe}};
}

static json opt_or_null(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

json result_json(const BlockParams& p, const GroundMotion& g, const SimulationOptions& o,
                 const SimulationResult& r, const PhysicalBlock* phys) {
  json j;
  j["run"] = run_info();
  j["parameters"] = to_json(p);
  j["ground_motion"] = to_json(g);
  j["tolerances"] = to_json(o.integrator);
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
  j["ihor"] = r.ihor;
  j["first_flight_time"] = opt_or_null(r.first_flight_time);
  j["ihor_at_first_flight"] = r.first_flight_time ? json(r.ihor_at_first_flight) : json(nullptr);
  j["overturn_time"] = opt_or_null(r.overturn_time);
  j["ihor_at_overturn"] = r.overturn_time ? json(r.ihor_at_overturn) : json(nullptr);
  j["max_abs_energy_error"] = r.max_abs_energy_error;
  j["max_abs_energy_change"] = r.max_abs_energy_change;
  j["work_friction"] = r.work_friction();
  j["work_nonpotential"] = r.work_nonpotential();
  j["work_ground"] = r.work_ground();
  j["steps"] = r.stats.accepted;
  j["rejected_steps"] = r.stats.rejected;
  j["rhs_evals"] = r.stats.rhs_evals;
  json counts = json::object();
  for (int k = 0; k < kNumEventKinds; ++k)
    if (r.event_counts[k]) counts[to_string(EventKind(k))] = r.event_counts[k];
  j["event_counts"] = counts;
  json ev = json::array();
  for (const auto& e : r.events) ev.push_back(to_json(e));
  j["events"] = ev;
  if (phys) {
    const UnitScales s = scales_of(*phys);
    j["physical"] = {{"height_m", phys->height}, {"width_m", phys->width}, {"mass_kg", s.mass},
                     {"g_m_per_s2", phys->g},    {"time_scale_s", s.time},
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

static void sanitize(json& j) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) j = nullptr;
  else if (j.is_structured())
    for (auto& v : j) sanitize(v);
}

std::string dump_json(const json& j, int indent) {
  json c = j;
  sanitize(c);
  return c.dump(indent);
}

}  // namespace blockdyn
