// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/assembly_json.hpp"

#include "blockdyn/io/json_io.hpp"
#include "blockdyn/model/assembly/assembly_model.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

namespace {

json law_json(const ContactLaw& l, double damping, ContactKind contact) {
  if (!info(contact).springs)
    return {{"law", to_string(contact)}, {"restitution", l.restitution}, {"mu_s", l.mu_s}, {"mu_k", l.mu_k}};
  return {{"law", to_string(contact)},
          {"k_normal", l.k_normal},
          {"k_tangential", l.k_tangential > 0 ? l.k_tangential : l.k_normal / 3.0},
          {"restitution", l.damping >= 0 ? json(nullptr) : json(l.restitution)},
          {"damping", damping},
          {"mu_s", l.mu_s},
          {"mu_k", l.mu_k}};
}

json energy_json(const AssemblyEnergy& e) {
  return {{"kinetic", e.kinetic},
          {"gravity", e.gravity},
          {"normal_spring", e.normal_spring},
          {"tangential_spring", e.tangential_spring},
          {"total", e.total}};
}

}  // namespace

json to_json(const Assembly& a) {
  json j;
  j["preset"] = a.preset;
  j["g"] = a.g;
  j["collapse_rotation"] = a.collapse_rotation;
  j["min_bearing"] = a.min_bearing;
  j["columns_rock_only"] = a.rock_only_on_ground;
  json blocks = json::array();
  for (const AssemblyBlock& b : a.blocks) {
    json k = {{"name", b.name}, {"width", b.width},       {"height", b.height},
              {"mass", b.mass}, {"inertia", b.inertia()}, {"initial_state", {b.x, b.y, b.theta, b.vx, b.vy, b.omega}}};
    if (!b.vertices.empty()) {
      // A polygon: its vertices about the centre of mass, unturned (width, height: its bounding box).
      json v = json::array();
      for (const Vec2& p : b.vertices) v.push_back({p.x, p.y});
      k["vertices"] = v;
    }
    blocks.push_back(k);
  }
  j["blocks"] = blocks;
  return j;
}

json to_json(const AssemblyEventRecord& e) {
  json x = {{"t", e.t}, {"kind", assembly_event_name(e.kind)}, {"block", e.block >= 0 ? json(e.block) : json(nullptr)}};
  if (e.interface >= 0) x["interface"] = e.interface;
  if (e.end >= 0) x["end"] = e.end;
  if (e.collapse_mode) x["collapse_mode"] = e.collapse_mode;
  x["pose"] = e.pose;
  return x;
}

json assembly_result_json(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o,
                          const AssemblyResult& r) {
  auto opt = [](const auto& v) { return v ? json(*v) : json(nullptr); };
  json j;
  j["run"] = run_info();
  j["model"] = "assembly";
  j["contact"] = to_string(a.contact);
  j["units"] = "SI (s, m, rad, kg, N, J); ground accelerations in g";
  j["assembly"] = to_json(a);
  json ifs = json::array();
  for (std::size_t i = 0; i < a.interfaces.size(); ++i) {
    const AssemblyInterface& f = a.interfaces[i];
    ifs.push_back({{"lower", f.lower < 0 ? json("ground") : json(f.lower)},
                   {"upper", f.upper},
                   {"contact", law_json(f.law, i < r.damping.size() ? r.damping[i] : 0.0, a.contact)}});
  }
  j["assembly"]["interfaces"] = ifs;
  j["ground_motion"] = to_json(g);
  j["tolerances"] = to_json(o.integrator);
  j["tolerances"]["atol_units"] = "m, rad, m/s, rad/s, J (absolute, per component)";
  j["t_end"] = o.t_end;
  j["status"] = to_string(r.status);
  j["motion"] = r.motion;
  j["collapse_mode"] = opt(r.collapse_mode);
  j["t_failure"] = opt(r.t_failure);
  j["failed_block"] = r.failed_block >= 0 ? json(r.failed_block) : json(nullptr);
  j["integrator_status"] = to_string(r.run_status);
  j["note"] = r.note.empty() ? json(nullptr) : json(r.note);
  j["t_final"] = r.t_final;
  json blocks = json::array();
  for (const AssemblyBlockSummary& b : r.blocks)
    blocks.push_back({{"name", b.name},
                      {"max_abs_rotation", b.max_abs_rotation},
                      {"t_max_abs_rotation", b.t_max_abs_rotation},
                      {"max_abs_rotation_over_limit", b.max_abs_rotation / b.rotation_limit},
                      {"max_abs_sliding", b.max_abs_sliding},
                      {"final_state", b.final_state}});
  j["blocks"] = blocks;
  json faces = json::array();
  for (const AssemblyInterfaceSummary& f : r.interfaces)
    faces.push_back({{"lower", f.lower < 0 ? json("ground") : json(f.lower)},
                     {"upper", f.upper},
                     {"max_abs_sliding", f.max_abs_sliding},
                     {"final_overlap", f.final_overlap},
                     {"opens", f.opens},
                     {"slips", f.slips}});
  j["interfaces"] = faces;
  j["energy"] = {{"initial", energy_json(r.energy_initial)},
                 {"final", energy_json(r.energy_final)},
                 {"work_ground", r.work_ground},
                 {"work_normal_damping", r.work_normal},
                 {"work_friction", r.work_friction},
                 {"work_end_switches", r.work_switch},
                 {"balance_final", r.energy_final.total - r.energy_initial.total - r.work_ground - r.work_normal -
                                       r.work_friction - r.work_switch}};
  j["max_abs_energy_error"] = r.max_abs_energy_error;
  if (info(a.contact).schemes) {
    j["scheme"] = to_string(effective_scheme(a, o));
    j["step"] = o.step;
    if (effective_scheme(a, o) == AssemblyScheme::EventDriven)
      j["time_stepping"] = {{"windows", r.time_stepping_windows},
                            {"time", r.time_stepping_time},
                            {"steps", r.time_stepping_steps},
                            {"reason", r.time_stepping_windows > 0 ? json(r.time_stepping_reason) : json(nullptr)}};
    j["impacts"] = r.impacts;
    j["contact_solves"] = {{"direct", r.direct_solves},
                           {"lemke", r.lemke_solves},
                           {"active_set_iterations", r.active_set_iterations},
                           {"gauss_seidel", r.gauss_seidel_solves},
                           {"gauss_seidel_sweeps", r.gauss_seidel_sweeps}};
  }
  j["max_abs_energy_change"] = r.max_abs_energy_change;
  j["steps"] = r.stats.accepted;
  j["rejected_steps"] = r.stats.rejected;
  j["rhs_evals"] = r.stats.rhs_evals;
  json counts = json::object();
  for (int k = 0; k < int(r.event_counts.size()); ++k)
    if (r.event_counts[k] && k != kAssemblyBearingCollapse) {
      const char* name = assembly_event_name(k);
      long n = r.event_counts[k];
      if (k == kAssemblyRotationCollapse) n += r.event_counts[kAssemblyBearingCollapse];
      counts[name] = n;
    }
  if (r.event_counts[kAssemblyBearingCollapse] && !r.event_counts[kAssemblyRotationCollapse])
    counts["failure"] = r.event_counts[kAssemblyBearingCollapse];
  j["event_counts"] = counts;
  j["events_total"] = r.events_total;
  json ev = json::array();
  for (const AssemblyEventRecord& e : r.events) ev.push_back(to_json(e));
  j["events"] = ev;
  return j;
}

}  // namespace blockdyn
