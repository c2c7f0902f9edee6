// `blockdyn simulate`: one run from flags or a TOML scenario; JSON summary, CSV trajectory, plot.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <unistd.h>

#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/scenario.hpp"
#include "blockdyn/io/trajectory_csv.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
namespace {

struct SimulateFlags {
  std::string scenario_file;
  BlockParams p;
  IntegratorOptions integ;
  std::string ic = "ic1";
  double w0 = 0, x0 = 0, y0 = 0, vx0 = 0, vy0 = 0, vw0 = 0;
  double t_end = 10, output_interval = 0.01;
  std::string trajectory, plot, json_out, units = "nondim";
  bool json = false;
  GroundMotion ground;
  PhysicalBlock phys;  // --height --width ... (physical input)
};

// Physical-block flags: name, field, help.
struct PhysFlag {
  const char* name;
  double PhysicalBlock::*plain;
  std::optional<double> PhysicalBlock::*opt;
  const char* help;
};
const PhysFlag kPhysFlags[] = {
    {"--height", &PhysicalBlock::height, nullptr, "physical block: height a [m]"},
    {"--width", &PhysicalBlock::width, nullptr, "physical block: width b [m]"},
    {"--g", &PhysicalBlock::g, nullptr, "gravity [m/s^2] (default 9.81)"},
    {"--mass", nullptr, &PhysicalBlock::mass, "physical block: mass [kg]"},
    {"--density", nullptr, &PhysicalBlock::density, "physical block: density [kg/m^3] (with --thickness)"},
    {"--thickness", nullptr, &PhysicalBlock::thickness, "physical block: out-of-plane depth [m]"},
    {"--subgrade-modulus", nullptr, &PhysicalBlock::subgrade_modulus, "Winkler modulus [N/m^3] (with --thickness)"},
    {"--line-stiffness", nullptr, &PhysicalBlock::line_stiffness, "foundation stiffness per unit length and depth [N/m^2]"},
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
  bool any = false;
  for (const PhysFlag& pf : kPhysFlags) any |= s.count(pf.name) > 0;
  if (!any) return;
  if (s.count("--r") || s.count("--k"))
    throw UsageError("--r/--k and a physical block (--height, --width, ...) both given: use one");
  PhysicalBlock pb = sc.physical.value_or(PhysicalBlock{});
  pb.mu = s.count("--mu") ? f.p.mu : (sc.physical ? pb.mu : sc.params.mu);
  for (const PhysFlag& pf : kPhysFlags) {
    if (!s.count(pf.name)) continue;
    if (pf.plain) pb.*pf.plain = f.phys.*pf.plain;
    else pb.*pf.opt = f.phys.*pf.opt;
  }
  sc.physical = pb;
  sc.params = to_nondimensional(pb);
  if (!s.count("--units")) sc.units = "physical";
}

void add_ground_flags(CLI::App& s, SimulateFlags& f) {
  for (int i = 0; i < 2; ++i) {
    GroundComponent& c = i == 0 ? f.ground.horizontal : f.ground.vertical;
    const std::string n = i == 0 ? "--ground-h" : "--ground-v";
    const std::string what = i == 0 ? "horizontal" : "vertical";
    s.add_option(n, c.constant, "constant " + what + " ground acceleration (units of g)");
    s.add_option(n + "-amplitude", c.amplitude, what + " harmonic ground acceleration amplitude (g)");
    s.add_option(n + "-frequency", c.frequency, what + " harmonic frequency (cycles per unit time)");
    s.add_option(n + "-phase", c.phase, what + " harmonic phase (rad)");
    s.add_option(n + "-start", c.t_start, what + " ground motion start time");
    s.add_option(n + "-duration", c.duration, what + " ground motion duration (0: forever)");
  }
}


Scenario build_scenario(const CLI::App& s, const SimulateFlags& f) {
  Scenario sc = f.scenario_file.empty() ? Scenario{} : load_scenario(f.scenario_file);
  if (given(s, "--r")) sc.params.r = f.p.r;
  if (given(s, "--mu")) sc.params.mu = f.p.mu;
  if (given(s, "--k")) sc.params.k = f.p.k;
  if (given(s, "--rtol")) sc.options.integrator.rtol = f.integ.rtol;
  if (given(s, "--atol")) sc.options.integrator.atol = f.integ.atol;
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
  const char* comp[2] = {"--ground-h", "--ground-v"};
  for (int i = 0; i < 2; ++i) {
    GroundComponent& c = i == 0 ? sc.ground.horizontal : sc.ground.vertical;
    const GroundComponent& g = i == 0 ? f.ground.horizontal : f.ground.vertical;
    const std::string n = comp[i];
    if (given(s, n)) c.constant = g.constant;
    if (given(s, n + "-amplitude")) c.amplitude = g.amplitude;
    if (given(s, n + "-frequency")) c.frequency = g.frequency;
    if (given(s, n + "-phase")) c.phase = g.phase;
    if (given(s, n + "-start")) c.t_start = g.t_start;
    if (given(s, n + "-duration")) c.duration = g.duration;
  }
  apply_physical_flags(s, f, sc);
  validate(sc.params);
  validate(sc.ground);
  validate(sc.options);
  if (sc.units != "nondim" && sc.units != "physical")
    throw UsageError("units = '" + sc.units + "' is not one of: nondim, physical");
  if (sc.units == "physical" && !sc.physical)
    throw UsageError("units = physical needs a physical block (--height --width ... or [physical] in the scenario)");
  require_range("output-interval", sc.output_interval, 0.0, 1e300);
  return sc;
}

void print_summary(const SimulationResult& r) {
  std::printf("status: %s at t = %.10g\n", to_string(r.status), r.t_final);
  std::printf("ihor: %ld, first flight: %s\n", r.ihor,
              r.first_flight_time ? std::to_string(*r.first_flight_time).c_str() : "none");
  std::printf("events: %zu, steps: %ld, rhs evaluations: %ld\n", r.events.size(), r.stats.accepted,
              r.stats.rhs_evals);
  std::printf("energy: E0 = %.10g, max |E - E0| = %.3g, max |balance error| = %.3g, friction work = %.6g\n",
              r.initial_energy.total(), r.max_abs_energy_change, r.max_abs_energy_error, r.work_friction());
}

void run(const CLI::App& s, const SimulateFlags& f) {
  const Scenario sc = build_scenario(s, f);
  const BlockStateVec z0 = initial_state(sc);
  std::optional<UnitScales> scales;
  if (sc.units == "physical") scales = scales_of(*sc.physical);
  // The trajectory goes to a temporary file renamed on success (also when only a plot is asked).
  std::string csv_path = sc.trajectory;
  const bool temp_csv = csv_path.empty() && !sc.plot.empty();
  if (temp_csv) csv_path = "/tmp/blockdyn-trajectory-" + std::to_string(::getpid()) + ".csv";
  std::unique_ptr<AtomicFile> file;
  std::unique_ptr<TrajectoryCsvSink> sink;
  if (!csv_path.empty()) {
    file = std::make_unique<AtomicFile>(csv_path);
    sink = std::make_unique<TrajectoryCsvSink>(file->stream(), sc.output_interval, scales);
  }
  const SimulationResult r = simulate(sc.params, sc.ground, z0, sc.options, sink.get());
  if (file) file->commit();
  if (!sc.plot.empty()) {
    run_python("plot_trajectory.py", {csv_path, sc.plot});
    if (temp_csv) std::remove(csv_path.c_str());
  }
  const auto j = result_json(sc.params, sc.ground, sc.options, r, sc.physical ? &*sc.physical : nullptr);
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json)
    emit_json(j, "-");
  else
    print_summary(r);
}

void add(CLI::App& app) {
  auto f = std::make_shared<SimulateFlags>();
  CLI::App* s = app.add_subcommand("simulate", "integrate one block from initial conditions (flags or a TOML scenario)");
  s->add_option("scenario", f->scenario_file, "TOML scenario file (flags given as well override it)");
  add_block_options(*s, f->p);
  add_tolerance_options(*s, f->integ);
  s->add_option("--ic", f->ic, "initial conditions: ic1 (tilted, at rest), ic2 (upright, impulse), custom")
      ->check(CLI::IsMember({"ic1", "ic2", "custom"}));
  s->add_option("--w0", f->w0, "initial tilt w (ic1 override, default alpha/2; custom state)");
  s->add_option("--x0", f->x0, "initial x (overrides the set's value)");
  s->add_option("--y0", f->y0, "initial y of the centre (overrides)");
  s->add_option("--vx0", f->vx0, "initial x' (overrides)");
  s->add_option("--vy0", f->vy0, "initial y' (overrides)");
  s->add_option("--vw0", f->vw0, "initial w' (overrides)");
  s->add_option("--t-end", f->t_end, "final time (non-dimensional, > 0)")->capture_default_str();
  s->add_option("--output-interval", f->output_interval, "trajectory output interval (0: every step)")
      ->capture_default_str();
  s->add_option("--trajectory", f->trajectory, "write the trajectory CSV here");
  s->add_option("--plot", f->plot, "write a plot of the motion (PNG; an SVG is written beside it)");
  s->add_option("--units", f->units, "nondim, or physical (needs a physical block: flags or [physical])");
  s->add_flag("--json", f->json, "print the JSON summary on stdout");
  s->add_option("--json-out", f->json_out, "also write the JSON summary to this file");
  add_ground_flags(*s, *f);
  add_physical_flags(*s, *f);
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(10, add);

}  // namespace
}  // namespace blockdyn::cli
