// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/forced_model.hpp"

#include "blockdyn/analysis/masonry/limit_analysis.hpp"
#include "blockdyn/model/assembly/interface_faces.hpp"

#include <cmath>
#include <optional>

#include "blockdyn/analysis/forced/cycle_detection.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/simulation/assembly_simulation.hpp"
#include "blockdyn/simulation/rigid_ground_model.hpp"
#include "blockdyn/simulation/rigid_probe.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"

namespace blockdyn {
namespace {

// A run that, under harmonic motion, also records block 0's dominant cycle (stroboscopic
// samples at t = k T; the detection window fitted to the run's length).
SurvivalRun with_cycle(const std::function<SurvivalOutcome(const GroundMotion&, double, RunProbe*)>& traced,
                       ImpactRule rule) {
  return [traced, rule](const GroundMotion& g, double t_end) {
    const GroundComponent& h = g.horizontal;
    if (!(h.frequency > 0 && h.amplitude != 0 && !h.has_pulse() && !h.record && g.vertical.is_zero()))
      return traced(g, t_end, nullptr);
    ForcedTrace tr(0.0, 1.0 / h.frequency, 1);
    tr.keep_events_of(0);
    SurvivalOutcome out = traced(g, t_end, &tr);
    if (out.moved && !out.invalid) out.cycle = dominant_cycle(tr, 0, rule, CycleOptions{}, out.t_failure);
    return out;
  };
}

}  // namespace

ForcedModel forced_block_model(const RigidBlockParams& rp, const RigidGroundModel& m) {
  const bool housner = !m.friction;  // Housner's 1-DOF block: its own probe, Lyapunov and impact rule
  validate(rp);
  if (housner) housner_coefficient(rp.shape, rp.restitution);
  ForcedModel fm;
  fm.alpha = rp.shape.alpha();
  fm.p = rp.shape.p();
  fm.width = rp.shape.width;
  fm.description = parameters_json(rp, m);
  fm.overturn_rule = "|theta| reaches pi/2";
  fm.tolerances = to_json(RigidRunOptions{}.integrator);
  fm.traced = [rp, housner](const GroundMotion& g, double t_end, RunProbe* probe) {
    RigidRunOptions ro;
    ro.t_end = t_end;
    ro.record_events = false;
    RigidResult r;
    if (housner) {
      std::optional<RigidProbeObserver<HousnerBlock>> obs;
      if (probe) obs.emplace(*probe);
      r = simulate_housner(rp.shape, rp.restitution, g, {}, ro, obs ? &*obs : nullptr);
    } else {
      std::optional<RigidProbeObserver<RigidBlock>> obs;
      if (probe) obs.emplace(*probe);
      r = simulate_rigid(rp, g, {}, ro, obs ? &*obs : nullptr);
    }
    SurvivalOutcome out;
    out.moved = r.first_motion_time.has_value();
    out.max_abs_rotation = r.max_abs_rotation;
    classify_block_end(out, r.status, r.overturn_time);
    return out;
  };
  fm.impact_rule = ImpactRule::VelocityJump;
  fm.block_names = {"block"};
  fm.impact_definition = housner ? "a pivot change at theta = 0 (the velocity jump theta'+ = e theta'-)"
                                 : "every velocity jump: a corner hitting the ground (pivot change or landing)";
  fm.run = with_cycle(fm.traced, fm.impact_rule);
  fm.lyapunov = [rp, housner](const GroundMotion& g, const ForcedLyapunovOptions& o, const RigidInitial& init) {
    return housner ? housner_lyapunov(rp.shape, rp.restitution, g, init, o) : rigid_lyapunov(rp, g, init, o);
  };
  return fm;
}

ForcedModel forced_assembly_model(const Assembly& a, nlohmann::ordered_json description) {
  validate(a);
  ForcedModel fm;
  fm.alpha = std::atan2(a.blocks[0].width, a.blocks[0].height);
  fm.width = a.blocks[0].width;
  fm.p = std::sqrt(0.75 * a.g / (0.5 * std::hypot(a.blocks[0].width, a.blocks[0].height)));
  bool polygons = false;
  for (const AssemblyBlock& b : a.blocks) polygons = polygons || !b.vertices.empty();
  if (polygons) {
    // No first block stands for an arch: alpha is the angle whose tangent is the static collapse
    // multiplier (a rectangle's b/h: the block's own alpha), p and the width those of the
    // assembly's bounding box at rest.
    fm.alpha = std::atan(std::fmax(limit_analysis(a, +1).lambda, 1e-6));
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (const AssemblyBlock& b : a.blocks)
      for (const Vec2& v : initial_outline(b)) {
        x0 = std::fmin(x0, v.x);
        x1 = std::fmax(x1, v.x);
        y0 = std::fmin(y0, v.y);
        y1 = std::fmax(y1, v.y);
      }
    fm.width = x1 - x0;
    fm.p = std::sqrt(0.75 * a.g / (0.5 * std::hypot(x1 - x0, y1 - y0)));
  }
  fm.description = std::move(description);
  fm.linearisable = info(a.contact).linearisable;
  fm.overturn_rule = "collapse mode 1 (rotation) or 2 (bearing)";
  fm.tolerances = to_json(AssemblyRunOptions{}.integrator);
  if (info(a.contact).schemes) {
    fm.tolerances["rigid_scheme"] = to_string(effective_scheme(a, AssemblyRunOptions{}));
    fm.tolerances["moreau_jean_step_s"] = AssemblyRunOptions{}.step;
  }
  fm.traced = [a](const GroundMotion& g, double t_end, RunProbe* probe) {
    AssemblyRunOptions ao;
    ao.t_end = t_end;
    ao.record_events = false;
    const AssemblyResult r = simulate_assembly(a, g, ao, nullptr, probe);
    SurvivalOutcome out;
    out.moved = r.motion != "rest";
    out.collapse_mode = r.collapse_mode;
    out.t_failure = r.t_failure;
    out.invalid = r.status == SimStatus::Invalid;
    for (const auto& b : r.blocks) out.max_abs_rotation = std::fmax(out.max_abs_rotation, b.max_abs_rotation);
    for (const auto& i : r.interfaces)
      if (i.lower >= 0) out.max_sliding = std::fmax(out.max_sliding, i.max_abs_sliding);
    return out;
  };
  fm.impact_rule = ImpactRule::Passage;
  for (const auto& b : a.blocks) fm.block_names.push_back(b.name);
  fm.impact_definition =
      "a passage of the block's rotation through 0 after it lifted (a contact end under it opened since the "
      "previous impact); theta' before: at the closing of the end that begins the impact";
  fm.run = with_cycle(fm.traced, fm.impact_rule);
  fm.lyapunov = [a](const GroundMotion& g, const ForcedLyapunovOptions& o, const RigidInitial&) {
    return assembly_lyapunov(a, g, o);
  };
  return fm;
}

}  // namespace blockdyn
