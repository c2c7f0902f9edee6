// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/simulate_run.hpp"

#include "blockdyn/base/number_text.hpp"

#include "blockdyn/model/assembly/interface_faces.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/assembly_settings.hpp"
#include "blockdyn/commands/scenario_settings.hpp"
#include "blockdyn/family/family.hpp"
#include "blockdyn/io/assembly_json.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"
#include "blockdyn/simulation/rigid_trajectory.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"
#include "blockdyn/simulation/winkler_trajectory.hpp"

namespace blockdyn {
namespace {

// " under record X (pga 0.36 g)" or " in free motion", for figure titles.
std::string motion_phrase(const GroundMotion& g, const char* hz = "Hz", const char* sec = "s") {
  return g.is_zero() ? " in free motion" : " under " + describe(g, hz, sec);
}

RunTiming fastest(const RunTiming& a, const RunTiming& b) { return b.cpu_s < a.cpu_s ? b : a; }

// The figure scripts' numbers, as the command line always wrote them (std::to_string).
std::string arg(double v) { return number_text(v); }

void require_rows(double interval, double span, double max_rows) {
  require_sample_count("output-interval", interval, span, max_rows);
}

// Hands each event record of a run to the caller's callback as JSON.
template <class Record>
class JsonEvents final : public EventSink<Record> {
 public:
  explicit JsonEvents(const std::function<void(const nlohmann::ordered_json&)>& f) : f_(f) {}
  void on_event(const Record& e) override { f_(to_json(e)); }

 private:
  const std::function<void(const nlohmann::ordered_json&)>& f_;
};

long total_events(const WinklerResult& r) {
  long n = 0;
  for (long c : r.event_counts) n += c;
  return n;
}

std::string winkler_text(const WinklerResult& r, double seconds) {
  const double ts = seconds > 0 ? seconds : 1.0;
  const char* unit = seconds > 0 ? " s" : "";
  char buf[1024];
  std::string s;
  std::snprintf(buf, sizeof buf, "status: %s at t = %.10g%s\n", to_string(r.status), r.t_final * ts, unit);
  s += buf;
  std::snprintf(buf, sizeof buf, "ihor: %ld, first flight: %s%s\n", r.upright_passages,
                r.first_flight_time ? std::to_string(*r.first_flight_time * ts).c_str() : "none",
                r.first_flight_time ? unit : "");
  s += buf;
  std::snprintf(buf, sizeof buf, "events: %ld, steps: %ld, rhs evaluations: %ld\n", total_events(r), r.stats.accepted,
                r.stats.rhs_evals);
  s += buf;
  std::snprintf(buf, sizeof buf,
                "energy: E0 = %.10g, max |E - E0| = %.3g, max |balance error| = %.3g, friction work = %.6g\n",
                r.initial_energy.total(), r.max_abs_energy_change, r.max_abs_energy_error, r.work_friction());
  return s + buf;
}

std::string rigid_text(const RigidResult& r, double alpha) {
  char buf[1024];
  std::string s;
  std::snprintf(buf, sizeof buf, "model: %s, status: %s at t = %.10g s, final mechanism: %s\n", r.model.c_str(),
                to_string(r.status), r.t_final, to_string(r.final_mode));
  s += buf;
  if (!r.note.empty()) s += "note: " + r.note + "\n";
  std::snprintf(buf, sizeof buf,
                "max |w| = %.6g rad (%.4g alpha) at t = %.6g s, impacts: %ld, mechanism changes: %ld\n",
                r.max_abs_rotation, r.max_abs_rotation / alpha, r.t_max_abs_rotation, r.impacts, r.mode_changes);
  s += buf;
  std::snprintf(buf, sizeof buf, "steps: %ld, rhs evaluations: %ld, max |energy balance error| = %.3g J\n",
                r.stats.accepted, r.stats.rhs_evals, r.max_abs_energy_error);
  return s + buf;
}

}  // namespace

SimulateReport run_winkler(const Scenario& given, const SimulateOutputs& out) {
  Scenario sc = given;
  // With a physical block every time is in seconds and every frequency in Hz.
  if (sc.physical) {
    const double tau = scales_of(*sc.physical).time;
    sc.options.t_end /= tau;
    sc.options.t_start /= tau;
    sc.output_interval /= tau;
    sc.ground = in_time_unit(sc.ground, tau);
  }
  const WinklerState z0 = initial_state(sc);
  std::optional<UnitScales> scales;
  if (sc.units == "physical") scales = scales_of(*sc.physical);
  std::optional<WinklerTrajectory> rows;
  if (out.trajectory) {
    require_rows(sc.output_interval, sc.options.t_end - sc.options.t_start, out.max_output_rows);
    rows.emplace(*out.trajectory, sc.output_interval, scales);
  }
  sc.options.record_events = false;  // counted in the result, streamed to on_event
  JsonEvents<WinklerEventRecord> events(out.on_event);
  WinklerResult r =
      simulate(sc.params, sc.ground, z0, sc.options, rows ? &*rows : nullptr, out.on_event ? &events : nullptr);
  for (int i = 1; i < out.timing_repeat; ++i)
    r.timing = fastest(r.timing, simulate(sc.params, sc.ground, z0, sc.options).timing);
  SimulateReport rep;
  rep.summary.defer([params = sc.params, ground = sc.ground, options = sc.options, r, physical = sc.physical] {
    return result_json(params, ground, options, r, physical ? &*physical : nullptr);
  });
  rep.text.defer([r, tau_s = sc.physical ? scales_of(*sc.physical).time : 0.0] { return winkler_text(r, tau_s); });
  rep.timing = r.timing;
  rep.figure.defer([params = sc.params, ground = sc.ground, physical = sc.physical.has_value(), r] {
    char head[160];
    std::snprintf(head, sizeof head, "winkler block r = %.4g, mu = %.4g, k = %.4g", params.r, params.mu, params.k);
    char tail[96];
    std::snprintf(tail, sizeof tail, ": %s at t = %.6g", to_string(r.status), r.t_final);
    const std::string title = head + motion_phrase(ground, physical ? "Hz" : "/t_ref", physical ? "s" : "t_ref") + tail;
    SimulateFigure fig;
    fig.plot = FigureSpec{"trajectory", {}, {{"alpha", {arg(params.alpha())}}, {"title", {title}}}};
    fig.animation = FigureSpec{
        "block", {}, {{"model", {"winkler"}}, {"width", {arg(params.r)}}, {"height", {"1"}}, {"title", {title}}}};
    return fig;
  });
  return rep;
}

namespace {

std::string block_title(const RigidGroundModel& m, const RigidBlockParams& p) {
  char buf[256];
  if (!m.friction)
    std::snprintf(buf, sizeof buf, "housner block %.4g m x %.4g m, e = %.4g", p.shape.width, p.shape.height, p.e());
  else
    std::snprintf(buf, sizeof buf, "rigid block %.4g m x %.4g m, mu_s %.3g, mu_k %.3g, %s impacts (e = %.3g)",
                  p.shape.width, p.shape.height, p.interface.mu_s, p.interface.mu_k, to_string(p.impact), p.e());
  return buf;
}

template <class Model, class Simulate>
SimulateReport run_rigid_family(const Scenario& sc, const SimulateOutputs& out, const RigidGroundModel& m,
                                Simulate&& sim) {
  const RigidBlockParams p = rigid_params(sc);
  RigidInitial init;
  init.w0 = sc.initial.w0.value_or(0.0);
  init.vw0 = sc.initial.vw0.value_or(0.0);
  init.x0 = sc.initial.x0;
  init.y0 = sc.initial.y0;
  init.vx0 = sc.initial.vx0;
  init.vy0 = sc.initial.vy0;
  RigidRunOptions o;
  o.t_start = sc.options.t_start;
  o.t_end = sc.options.t_end;
  o.integrator = sc.options.integrator;
  o.record_events = false;  // counted in the result, streamed to on_event
  std::optional<RigidTrajectory<Model>> rows;
  if (out.trajectory) {
    require_rows(sc.output_interval, o.t_end - o.t_start, out.max_output_rows);
    rows.emplace(*out.trajectory, sc.output_interval);
  }
  JsonEvents<RigidEventRecord> events(out.on_event);
  RigidResult r = sim(p, sc.ground, init, o, rows ? &*rows : nullptr, out.on_event ? &events : nullptr);
  for (int i = 1; i < out.timing_repeat; ++i)
    r.timing = fastest(r.timing, sim(p, sc.ground, init, o, nullptr, nullptr).timing);
  SimulateReport rep;
  rep.timing = r.timing;
  // What the summary, the text and the figure are built from when read: kept once, shared.
  struct Kept {
    RigidBlockParams p;
    RigidGroundModel m;
    GroundMotion ground;
    RigidRunOptions o;
    RigidResult r;
    std::string model;
  };
  const auto k = std::make_shared<const Kept>(Kept{p, m, sc.ground, o, std::move(r), sc.model});
  rep.summary.defer([k] { return rigid_result_json(k->p, k->m, k->ground, k->o, k->r); });
  rep.text.defer([k] { return rigid_text(k->r, k->p.shape.alpha()); });
  rep.figure.defer([k] {
    const std::string title = block_title(k->m, k->p) + motion_phrase(k->ground);
    const std::string status = to_string(k->r.status);
    SimulateFigure fig;
    fig.plot = FigureSpec{
        "rigid",
        {},
        {{"alpha", {arg(k->p.shape.alpha())}}, {"model", {k->model}}, {"status", {status}}, {"title", {title}}}};
    fig.animation = FigureSpec{"block",
                               {},
                               {{"model", {k->model}},
                                {"width", {arg(k->p.shape.width)}},
                                {"height", {arg(k->p.shape.height)}},
                                {"title", {title + ": " + status}}}};
    return fig;
  });
  return rep;
}

}  // namespace

SimulateReport run_housner(const Scenario& sc, const SimulateOutputs& out) {
  return run_rigid_family<HousnerBlock>(sc, out, housner_on_rigid_ground(),
                                        [](const RigidBlockParams& p, const GroundMotion& g, const RigidInitial& in,
                                           const RigidRunOptions& o, Observer<HousnerBlock>* obs, RigidEventSink* ev) {
                                          return simulate_housner(p.shape, p.restitution, g, in, o, obs, ev);
                                        });
}

SimulateReport run_rigid(const Scenario& sc, const SimulateOutputs& out) {
  return run_rigid_family<RigidBlock>(
      sc, out, three_dof_on_rigid_ground(),
      [](const RigidBlockParams& p, const GroundMotion& g, const RigidInitial& in, const RigidRunOptions& o,
         Observer<RigidBlock>* obs, RigidEventSink* ev) { return simulate_rigid(p, g, in, o, obs, ev); });
}

namespace {

class PreparedBlock final : public PreparedRun {
 public:
  explicit PreparedBlock(Scenario sc) : sc_(std::move(sc)) {}
  SimulateReport run(const SimulateOutputs& out) const override { return run_scenario(sc_, out); }
  std::pair<std::string, std::string> scenario_outputs() const override { return {sc_.trajectory, sc_.plot}; }

 private:
  Scenario sc_;
};

}  // namespace

std::unique_ptr<PreparedRun> prepare_block(const Settings& s) {
  Scenario sc = scenario_from(s);
  if (family_named("`model`", sc.model).rigid_ground) (void)rigid_params(sc);  // invalid parameters fail here
  return std::make_unique<PreparedBlock>(std::move(sc));
}

namespace {

std::string assembly_text(const AssemblyResult& r) {
  char buf[512];
  std::string s;
  std::snprintf(buf, sizeof buf, "status: %s, motion: %s", to_string(r.status), r.motion.c_str());
  s += buf;
  if (r.collapse_mode) {
    std::snprintf(buf, sizeof buf, ", collapse mode %d at t* = %.9g s (block %d)", *r.collapse_mode, *r.t_failure,
                  r.failed_block);
    s += buf;
  }
  std::snprintf(buf, sizeof buf, ", t_final = %.9g s\n", r.t_final);
  s += buf;
  for (std::size_t b = 0; b < r.blocks.size(); ++b) {
    std::snprintf(buf, sizeof buf, "block %zu (%s): max |theta| = %.6g rad, max sliding = %.6g m\n", b,
                  r.blocks[b].name.c_str(), r.blocks[b].max_abs_rotation, r.blocks[b].max_abs_sliding);
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "events: %ld, steps: %ld, rhs evaluations: %ld\n", r.events_total, r.stats.accepted,
                r.stats.rhs_evals);
  s += buf;
  std::snprintf(buf, sizeof buf,
                "energy: E0 = %.9g J, max |balance error| = %.3g J, friction work = %.6g J, damping work = %.6g J\n",
                r.energy_initial.total, r.max_abs_energy_error, r.work_friction, r.work_normal);
  s += buf;
  if (!r.note.empty()) s += "note: " + r.note + "\n";
  return s;
}

class PreparedAssembly final : public PreparedRun {
 public:
  explicit PreparedAssembly(AssemblySetup s) : s_(std::move(s)) {}
  SimulateReport run(const SimulateOutputs& out) const override {
    AssemblyRunOptions o = s_.run;
    if (out.trajectory) require_rows(o.output_interval, o.t_end, out.max_output_rows);
    o.record_events = false;  // counted in the result, streamed to on_event
    JsonEvents<AssemblyEventRecord> events(out.on_event);
    if (out.on_event) o.events = &events;
    const Assembly& a = s_.assembly;
    const RunClock clock;
    const AssemblyResult r = simulate_assembly(a, s_.ground, o, out.trajectory);
    SimulateReport rep;
    rep.timing = clock.elapsed();  // with the trajectory's rows, if any
    rep.summary = assembly_result_json(a, s_.ground, o, r);
    rep.text = assembly_text(r);
    char verdict[256];
    std::snprintf(verdict, sizeof verdict, ": %s, %s%s at t = %.6g s", to_string(r.status), r.motion.c_str(),
                  r.collapse_mode ? (" mode " + std::to_string(*r.collapse_mode)).c_str() : "", r.t_final);
    const std::string title =
        a.preset + " (" + std::to_string(a.blocks.size()) + " blocks)" + motion_phrase(s_.ground) + verdict;
    std::string sizes;
    for (const AssemblyBlock& b : a.blocks) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%s%.17g,%.17g", sizes.empty() ? "" : ",", b.width, b.height);
      sizes += buf;
    }
    SimulateFigure fig;
    fig.plot = FigureSpec{"assembly", {}, {{"title", {title}}}};
    fig.animation = FigureSpec{"assembly", {}, {{"title", {title}}, {"sizes", {sizes}}}};
    std::string polygons;
    bool any_polygon = false;
    for (const AssemblyBlock& b : a.blocks) {
      any_polygon = any_polygon || !b.vertices.empty();
      if (!polygons.empty()) polygons += ";";
      std::string one;
      for (const Vec2& v : block_outline(b)) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%s%.17g,%.17g", one.empty() ? "" : " ", v.x, v.y);
        one += buf;
      }
      polygons += one;
    }
    if (any_polygon) fig.animation.options.push_back({"polygons", {polygons}});
    rep.figure = std::move(fig);
    return rep;
  }

 private:
  AssemblySetup s_;
};

}  // namespace

std::unique_ptr<PreparedRun> prepare_assembly(const Settings& s) {
  return std::make_unique<PreparedAssembly>(assembly_from(s));
}

std::unique_ptr<PreparedRun> prepare_run(const Settings& s) {
  const std::string model = s.text("model");
  const Family& f = model.empty() ? families().front() : family_named("`model`", model);
  s.require_known(f.options(), "`model` " + std::string(f.name));
  return f.prepare(s);
}

SimulateReport run_scenario(const Scenario& sc, const SimulateOutputs& out) {
  if (out.timing_repeat < 1 || out.timing_repeat > 1000)
    throw std::invalid_argument("timing-repeat = " + std::to_string(out.timing_repeat) + " is out of range: [1, 1000]");
  const Family& f = family_named("`model`", sc.model);
  if (!f.scenario()) throw std::invalid_argument("`model` " + sc.model + " is not described by a scenario");
  return f.run_scenario(sc, out);
}

}  // namespace blockdyn
