// SPDX-License-Identifier: Apache-2.0
// `blockdyn simulate`: one run of any model family (winkler, housner, rigid) from flags or a TOML
// scenario; JSON summary, CSV trajectory, plot.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <unistd.h>

#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/csv_table.hpp"
#include "blockdyn/io/scenario.hpp"
#include "blockdyn/simulation/rigid_trajectory.hpp"
#include "blockdyn/simulation/winkler_trajectory.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "ground_flags.hpp"
#include "trajectory_target.hpp"

namespace blockdyn::cli {
namespace {

struct SimulateFlags {
  std::string scenario_file;
  std::string model = "winkler";
  BlockParams p;
  IntegratorOptions integ;
  std::string ic = "ic1";
  double w0 = 0, x0 = 0, y0 = 0, vx0 = 0, vy0 = 0, vw0 = 0;
  double t_end = 10, output_interval = 0.01;
  std::string trajectory, plot, json_out, units = "nondim", animate;
  int animate_frames = 120;
  bool json = false, quiet = false, timing = false;
  int timing_repeat = 1;
  double max_output_rows = 1e7;
  GroundFlags ground;
  PhysicalBlock phys;  // --height --width ... (physical input)
  double restitution = 0, mu_s = 0.7, mu_k = 0.7;
  std::string impact = "housner";
};

// Physical-block flags: name, field, help.
struct PhysFlag {
  const char* name;
  double PhysicalBlock::*plain;
  std::optional<double> PhysicalBlock::*opt;
  const char* help;
  bool winkler_only;
};
const PhysFlag kPhysFlags[] = {
    {"--height", &PhysicalBlock::height, nullptr, "block height [m] (physical block; housner/rigid: required)", false},
    {"--width", &PhysicalBlock::width, nullptr, "block width [m] (physical block; housner/rigid: required)", false},
    {"--g", &PhysicalBlock::g, nullptr, "gravity [m/s^2] (default 9.81)", false},
    {"--mass", nullptr, &PhysicalBlock::mass, "block mass [kg] (housner/rigid: default 1)", false},
    {"--density", nullptr, &PhysicalBlock::density, "density [kg/m^3] (with --thickness, instead of --mass)", false},
    {"--thickness", nullptr, &PhysicalBlock::thickness, "out-of-plane depth [m]", false},
    {"--subgrade-modulus", nullptr, &PhysicalBlock::subgrade_modulus, "winkler: modulus [N/m^3] (with --thickness)", true},
    {"--line-stiffness", nullptr, &PhysicalBlock::line_stiffness, "winkler: stiffness per unit length and depth [N/m^2]", true},
};

void add_physical_flags(CLI::App& s, SimulateFlags& f) {
  for (const PhysFlag& pf : kPhysFlags) {
    if (pf.plain) {
      s.add_option(pf.name, f.phys.*pf.plain, pf.help);
    } else {
      s.add_option_function<double>(pf.name, [&f, pf](double v) { f.phys.*pf.opt = v; }, pf.help);
    }
  }
}

// Applies the physical-block flags on top of the scenario's [physical] block (if any).
void apply_physical_flags(const CLI::App& s, const SimulateFlags& f, Scenario& sc) {
  const bool rigid = is_rigid_family(sc.model);
  bool any = false;
  for (const PhysFlag& pf : kPhysFlags) {
    if (!given(s, pf.name)) continue;
    if (rigid && pf.winkler_only) throw UsageError(std::string(pf.name) + " belongs to the winkler model (--model winkler)");
    any = true;
  }
  if (!any) return;
  if (!rigid && (given(s, "--r") || given(s, "--k")))
    throw UsageError("--r/--k and a physical block (--height, --width, ...) both given: use one");
  PhysicalBlock pb = sc.physical.value_or(PhysicalBlock{});
  if (!rigid) pb.mu = given(s, "--mu") ? f.p.mu : (sc.physical ? pb.mu : sc.params.mu);
  for (const PhysFlag& pf : kPhysFlags) {
    if (!given(s, pf.name)) continue;
    if (pf.plain)
      pb.*pf.plain = f.phys.*pf.plain;
    else
      pb.*pf.opt = f.phys.*pf.opt;
  }
  sc.physical = pb;
  if (!rigid) {
    sc.params = to_nondimensional(pb);
    if (!given(s, "--units")) sc.units = "physical";
  }
}

// Flags that belong to one family only: a clear error instead of a silently ignored option.
void check_family_flags(const CLI::App& s, const Scenario& sc) {
  const bool rigid = is_rigid_family(sc.model);
  const char* winkler_only[] = {"--r", "--k", "--mu", "--ic", "--units"};
  const char* rigid_only[] = {"--restitution", "--mu-s", "--mu-k", "--impact"};
  const char* rigid3_only[] = {"--mu-s", "--mu-k", "--impact", "--x0", "--y0", "--vx0", "--vy0"};
  if (rigid) {
    for (const char* n : winkler_only)
      if (given(s, n)) throw UsageError(std::string(n) + " belongs to the winkler model, not to --model " + sc.model);
  } else {
    for (const char* n : rigid_only)
      if (given(s, n)) throw UsageError(std::string(n) + " belongs to --model housner|rigid, not to winkler");
  }
  if (sc.model == "housner")
    for (const char* n : rigid3_only)
      if (given(s, n)) throw UsageError(std::string(n) + " belongs to --model rigid (housner has one degree of freedom)");
}

Scenario build_scenario(const CLI::App& s, const SimulateFlags& f) {
  Scenario sc = f.scenario_file.empty() ? Scenario{} : load_scenario(f.scenario_file);
  if (given(s, "--model")) sc.model = f.model;
  check_family_flags(s, sc);
  if (given(s, "--r")) sc.params.r = f.p.r;
  if (given(s, "--mu")) sc.params.mu = f.p.mu;
  if (given(s, "--k")) sc.params.k = f.p.k;
  if (given(s, "--rtol")) sc.options.integrator.rtol = f.integ.rtol;
  if (given(s, "--atol")) sc.options.integrator.atol = f.integ.atol;
  if (given(s, "--method")) sc.options.integrator.method = f.integ.method;
  if (given(s, "--t-end")) sc.options.t_end = f.t_end;
  if (given(s, "--output-interval")) sc.output_interval = f.output_interval;
  if (given(s, "--ic")) sc.initial.set = f.ic;
  if (given(s, "--w0")) sc.initial.w0 = f.w0;
  if (given(s, "--x0")) sc.initial.x0 = f.x0;
  if (given(s, "--y0")) sc.initial.y0 = f.y0;
  if (given(s, "--vx0")) sc.initial.vx0 = f.vx0;
  if (given(s, "--vy0")) sc.initial.vy0 = f.vy0;
  if (given(s, "--vw0")) sc.initial.vw0 = f.vw0;
  if (given(s, "--trajectory")) sc.trajectory = f.trajectory;
  if (given(s, "--plot")) sc.plot = f.plot;
  if (given(s, "--units")) sc.units = f.units;
  if (given(s, "--restitution")) sc.restitution = f.restitution;
  if (given(s, "--mu-s")) {
    sc.interface.mu_s = f.mu_s;
    if (!given(s, "--mu-k")) sc.interface.mu_k = f.mu_s;
  }
  if (given(s, "--mu-k")) sc.interface.mu_k = f.mu_k;
  if (given(s, "--impact")) sc.impact = *impact_law_from_string(f.impact);
  apply_ground_flags(s, f.ground, sc.ground);
  apply_physical_flags(s, f, sc);
  validate(sc.ground);
  validate(sc.options);
  require_range("output-interval", sc.output_interval, 0.0, 1e300);
  require_writable("plot", sc.plot);
  require_animation(f.animate, f.animate_frames);
  require_writable("trajectory", sc.trajectory);
  require_writable("json-out", f.json_out);
  if (!sc.trajectory.empty() || !sc.plot.empty() || !f.animate.empty())
    require_sample_count("output-interval", sc.output_interval, sc.options.t_end - sc.options.t_start, f.max_output_rows);
  if (!is_rigid_family(sc.model)) {
    validate(sc.params);
    if (sc.units != "nondim" && sc.units != "physical")
      throw UsageError("units = '" + sc.units + "' is not one of: nondim, physical");
    if (sc.units == "physical" && !sc.physical)
      throw UsageError("units = physical needs a physical block (--height --width ... or [physical] in the scenario)");
  }
  return sc;
}

// Streams the Winkler run's events to the JSON spool and forwards everything to the trajectory
// sink (if any): the event list is never held in memory.
class EventSpoolSink final : public SimulationSink {
 public:
  EventSpoolSink(SimulationSink* next, JsonEventSpool* spool) : next_(next), spool_(spool) {}
  void on_start(const WinklerBlock& m, double t, const BlockMode& md, const BlockStateVec& z) override {
    if (next_) next_->on_start(m, t, md, z);
  }
  void on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& s, double t0, double t1,
                  const BlockMode& md) override {
    if (next_) next_->on_segment(m, s, t0, t1, md);
  }
  void on_event(const WinklerBlock& m, const EventRecord& e) override {
    if (spool_) spool_->add(to_json(e));
    if (next_) next_->on_event(m, e);
  }
  bool keep_going() const override { return !next_ || next_->keep_going(); }
  bool needs_dense() const override { return next_ && next_->needs_dense(); }

 private:
  SimulationSink* next_;
  JsonEventSpool* spool_;
};

// The rigid family's events to the JSON spool.
class RigidEventSpool final : public RigidEventSink {
 public:
  explicit RigidEventSpool(JsonEventSpool& spool) : spool_(spool) {}
  void on_event(const RigidEventRecord& e) override { spool_.add(to_json(e)); }

 private:
  JsonEventSpool& spool_;
};

long total_events(const SimulationResult& r) {
  long n = 0;
  for (long c : r.event_counts) n += c;
  return n;
}

// seconds: the time scale of a physical block (times printed in s), 0 for non-dimensional runs.
void print_summary(const SimulationResult& r, double seconds) {
  const double ts = seconds > 0 ? seconds : 1.0;
  const char* unit = seconds > 0 ? " s" : "";
  std::printf("status: %s at t = %.10g%s\n", to_string(r.status), r.t_final * ts, unit);
  std::printf("ihor: %ld, first flight: %s%s\n", r.ihor,
              r.first_flight_time ? std::to_string(*r.first_flight_time * ts).c_str() : "none",
              r.first_flight_time ? unit : "");
  std::printf("events: %ld, steps: %ld, rhs evaluations: %ld\n", total_events(r), r.stats.accepted,
              r.stats.rhs_evals);
  std::printf("energy: E0 = %.10g, max |E - E0| = %.3g, max |balance error| = %.3g, friction work = %.6g\n",
              r.initial_energy.total(), r.max_abs_energy_change, r.max_abs_energy_error, r.work_friction());
}

void print_summary(const RigidResult& r, double alpha) {
  std::printf("model: %s, status: %s at t = %.10g s, final mechanism: %s\n", r.model.c_str(), to_string(r.status),
              r.t_final, to_string(r.final_mode));
  if (!r.note.empty()) std::printf("note: %s\n", r.note.c_str());
  std::printf("max |w| = %.6g rad (%.4g alpha) at t = %.6g s, impacts: %ld, mechanism changes: %ld\n",
              r.max_abs_rotation, r.max_abs_rotation / alpha, r.t_max_abs_rotation, r.impacts, r.mode_changes);
  std::printf("steps: %ld, rhs evaluations: %ld, max |energy balance error| = %.3g J\n", r.stats.accepted,
              r.stats.rhs_evals, r.max_abs_energy_error);
}


// --timing-repeat: the run repeated in-process (no outputs), the least CPU time kept: the
// integration with warm caches and code pages, as a benchmark wants it.
RunTiming fastest(const RunTiming& a, const RunTiming& b) { return b.cpu_s < a.cpu_s ? b : a; }

bool wants_json(const SimulateFlags& f) { return f.json || !f.json_out.empty(); }

// The JSON summary (only when asked for), its event list from the spool.
void emit(nlohmann::ordered_json j, const SimulateFlags& f, const JsonEventSpool& events, const RunTiming& timing) {
  if (f.timing) j["timing"] = to_json(timing);
  if (!f.json_out.empty()) emit_json(j, f.json_out, events);
  if (f.json) emit_json(j, "-", events);
}

void print_timing(const SimulateFlags& f, const RunTiming& t) {
  if (f.timing && !f.json && !f.quiet)
    std::printf("integration: %.6g s CPU, %.6g s wall\n", t.cpu_s, t.wall_s);
}

void run_winkler(const SimulateFlags& f, Scenario sc) {
  // With a physical block every time is in seconds and every frequency in Hz.
  if (sc.physical) {
    const double tau = scales_of(*sc.physical).time;
    sc.options.t_end /= tau;
    sc.options.t_start /= tau;
    sc.output_interval /= tau;
    sc.ground = in_time_unit(sc.ground, tau);
  }
  const BlockStateVec z0 = initial_state(sc);
  std::optional<UnitScales> scales;
  if (sc.units == "physical") scales = scales_of(*sc.physical);
  TrajectoryTarget target(sc.trajectory, sc.plot.empty() ? f.animate : sc.plot);
  std::optional<CsvTable> table;
  std::unique_ptr<WinklerTrajectory> sink;
  if (target.file) {
    table.emplace(target.file->stream());
    sink = std::make_unique<WinklerTrajectory>(*table, sc.output_interval, scales);
  }
  // Events are counted in the result and, for the JSON summary, streamed to a spool: the run holds
  // O(1) memory whatever its length.
  std::unique_ptr<JsonEventSpool> spool;
  if (wants_json(f)) spool = std::make_unique<JsonEventSpool>();
  sc.options.record_events = false;
  EventSpoolSink tee(sink.get(), spool.get());
  SimulationResult r = simulate(sc.params, sc.ground, z0, sc.options, (sink || spool) ? &tee : nullptr);
  for (int i = 1; i < f.timing_repeat; ++i) r.timing = fastest(r.timing, simulate(sc.params, sc.ground, z0, sc.options).timing);
  char title[256];
  std::snprintf(title, sizeof title, "winkler block r = %.4g, mu = %.4g, k = %.4g: %s at t = %.6g", sc.params.r,
                sc.params.mu, sc.params.k, to_string(r.status), r.t_final);
  target.figures_and_clean(
      {{"plot_trajectory.py", sc.plot, {"--alpha", std::to_string(sc.params.alpha()), "--title", title}},
       {"animate_block.py", f.animate,
        {"--model", "winkler", "--width", std::to_string(sc.params.r), "--height", "1", "--frames",
         std::to_string(f.animate_frames), "--title", title}}});
  if (spool) emit(result_json(sc.params, sc.ground, sc.options, r, sc.physical ? &*sc.physical : nullptr), f, *spool, r.timing);
  if (!f.json && !f.quiet) print_summary(r, sc.physical ? scales_of(*sc.physical).time : 0.0);
  print_timing(f, r.timing);
}

std::string block_title(const std::string& model, const RigidBlockParams& p) {
  char buf[256];
  if (model == "housner")
    std::snprintf(buf, sizeof buf, "housner block %.4g m x %.4g m, e = %.4g", p.shape.width, p.shape.height, p.e());
  else
    std::snprintf(buf, sizeof buf, "rigid block %.4g m x %.4g m, mu_s %.3g, mu_k %.3g, %s impacts (e = %.3g)",
                  p.shape.width, p.shape.height, p.interface.mu_s, p.interface.mu_k, to_string(p.impact), p.e());
  return buf;
}

template <class Model, class Simulate>
void run_rigid_family(const SimulateFlags& f, const Scenario& sc, Simulate&& sim) {
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
  o.record_events = false;  // counted; streamed to the spool for the JSON summary
  TrajectoryTarget target(sc.trajectory, sc.plot.empty() ? f.animate : sc.plot);
  std::optional<CsvTable> table;
  std::unique_ptr<RigidTrajectory<Model>> csv;
  if (target.file) {
    table.emplace(target.file->stream());
    csv = std::make_unique<RigidTrajectory<Model>>(*table, sc.output_interval);
  }
  std::unique_ptr<JsonEventSpool> spool;
  std::unique_ptr<RigidEventSpool> spool_sink;
  if (wants_json(f)) {
    spool = std::make_unique<JsonEventSpool>();
    spool_sink = std::make_unique<RigidEventSpool>(*spool);
  }
  RigidResult r = sim(p, sc.ground, init, o, csv.get(), spool_sink.get());
  for (int i = 1; i < f.timing_repeat; ++i) r.timing = fastest(r.timing, sim(p, sc.ground, init, o, nullptr, nullptr).timing);
  target.figures_and_clean(
      {{"plot_rigid.py", sc.plot,
        {"--alpha", std::to_string(p.shape.alpha()), "--model", sc.model, "--status", to_string(r.status), "--title",
         block_title(sc.model, p)}},
       {"animate_block.py", f.animate,
        {"--model", sc.model, "--width", std::to_string(p.shape.width), "--height", std::to_string(p.shape.height),
         "--frames", std::to_string(f.animate_frames), "--title",
         block_title(sc.model, p) + ": " + to_string(r.status)}}});
  if (spool) emit(rigid_result_json(p, sc.ground, o, r), f, *spool, r.timing);
  if (!f.json && !f.quiet) print_summary(r, p.shape.alpha());
  print_timing(f, r.timing);
}

void run(const CLI::App& s, const SimulateFlags& f) {
  const Scenario sc = build_scenario(s, f);
  if (sc.model == "housner") {
    run_rigid_family<HousnerBlock>(f, sc, [](const RigidBlockParams& p, const GroundMotion& g, const RigidInitial& in,
                                             const RigidRunOptions& o, Observer<HousnerBlock>* obs,
                                             RigidEventSink* events) {
      return simulate_housner(p.shape, p.restitution, g, in, o, obs, events);
    });
  } else if (sc.model == "rigid") {
    run_rigid_family<RigidBlock>(f, sc, [](const RigidBlockParams& p, const GroundMotion& g, const RigidInitial& in,
                                           const RigidRunOptions& o, Observer<RigidBlock>* obs,
                                           RigidEventSink* events) {
      return simulate_rigid(p, g, in, o, obs, events);
    });
  } else {
    run_winkler(f, sc);
  }
}

void add(CLI::App& app) {
  auto f = std::make_shared<SimulateFlags>();
  CLI::App* s = app.add_subcommand("simulate",
                                   "integrate one block (winkler, housner or rigid model) from flags or a TOML scenario");
  s->add_option("scenario", f->scenario_file, "TOML scenario file (flags given as well override it)");
  s->add_option("--model", f->model,
                "model family: winkler (block on a Winkler foundation, non-dimensional unless a physical block is "
                "given), housner (1-DOF rocking on rigid ground), rigid (3-DOF, five mechanisms); default winkler")
      ->check(CLI::IsMember({"winkler", "housner", "rigid"}));
  add_block_options(*s, f->p);
  add_tolerance_options(*s, f->integ);
  s->add_option("--ic", f->ic, "winkler: initial conditions ic1 (tilted, at rest), ic2 (upright, impulse), custom")
      ->check(CLI::IsMember({"ic1", "ic2", "custom"}));
  s->add_option("--w0", f->w0, "initial rotation w [rad] (winkler ic1: the release tilt, default alpha/2)");
  s->add_option("--vw0", f->vw0, "initial rotation rate w' [rad per time unit]");
  s->add_option("--x0", f->x0, "initial x of the centre");
  s->add_option("--y0", f->y0, "initial y of the centre (rigid: default standing on the lowest corner)");
  s->add_option("--vx0", f->vx0, "initial x' (rigid: default rotation about the corner on the ground)");
  s->add_option("--vy0", f->vy0, "initial y'");
  s->add_option("--restitution", f->restitution,
                "housner/rigid: restitution in [0, 1] (housner law: the rocking coefficient, default Housner's "
                "1 - 1.5 sin^2 alpha; newton law: e_n, default 0)");
  s->add_option("--mu-s", f->mu_s, "rigid: static friction coefficient (default 0.7)");
  s->add_option("--mu-k", f->mu_k, "rigid: kinetic friction coefficient, <= mu-s (default: mu-s)");
  s->add_option("--impact", f->impact, "rigid: impact law housner (default) or newton")
      ->check(CLI::IsMember({"housner", "newton"}));
  s->add_option("--t-end", f->t_end,
                "final time: seconds with a physical block and for housner/rigid, else non-dimensional (default 10)");
  s->add_option("--output-interval", f->output_interval, "trajectory output interval (0: every step; default 0.01)");
  s->add_option("--max-output-rows", f->max_output_rows,
                "refuse a trajectory of more rows than this at the output interval (default 1e7, ~4 GB)");
  s->add_option("--trajectory", f->trajectory, "write the trajectory CSV here");
  s->add_option("--plot", f->plot, "write a plot of the motion (PNG; an SVG is written beside it)");
  s->add_option("--animate", f->animate, "write an animation of the motion: F.gif (Pillow) or F.mp4 (ffmpeg)");
  s->add_option("--animate-frames", f->animate_frames, "frames of the animation, uniform in time (default 120)");
  s->add_option("--units", f->units, "winkler: nondim, or physical (needs a physical block: flags or [physical])");
  s->add_flag("--json", f->json, "print the JSON summary on stdout");
  s->add_option("--json-out", f->json_out, "also write the JSON summary to this file");
  s->add_flag("--quiet", f->quiet, "no text summary on stdout");
  s->add_flag("--timing", f->timing,
              "report the integration's wall and CPU time (JSON: timing.integration_wall_s, integration_cpu_s; "
              "not reproducible, so off by default)");
  s->add_option("--timing-repeat", f->timing_repeat,
                "with --timing: repeat the integration this many times in-process and report the least CPU time "
                "(a warm measurement for benchmarks; default 1)")
      ->check(CLI::Range(1, 1000));
  add_ground_flags(*s, f->ground);
  add_physical_flags(*s, *f);
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(10, add);

}  // namespace
}  // namespace blockdyn::cli
