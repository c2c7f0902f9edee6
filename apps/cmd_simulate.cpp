// SPDX-License-Identifier: Apache-2.0
// `blockdyn simulate`: one run of any model family (winkler, housner, rigid) from flags or a TOML
// scenario; JSON summary, CSV trajectory, plot.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <unistd.h>

#include "blockdyn/api/scenario_settings.hpp"
#include "blockdyn/api/simulate_run.hpp"
#include "blockdyn/io/csv_table.hpp"
#include "blockdyn/io/json_io.hpp"
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
};
const PhysFlag kPhysFlags[] = {
    {"--height", &PhysicalBlock::height, nullptr, "block height [m] (physical block; housner/rigid: required)"},
    {"--width", &PhysicalBlock::width, nullptr, "block width [m] (physical block; housner/rigid: required)"},
    {"--g", &PhysicalBlock::g, nullptr, "gravity [m/s^2] (default 9.81)"},
    {"--mass", nullptr, &PhysicalBlock::mass, "block mass [kg] (housner/rigid: default 1)"},
    {"--density", nullptr, &PhysicalBlock::density, "density [kg/m^3] (with --thickness, instead of --mass)"},
    {"--thickness", nullptr, &PhysicalBlock::thickness, "out-of-plane depth [m]"},
    {"--subgrade-modulus", nullptr, &PhysicalBlock::subgrade_modulus, "winkler: modulus [N/m^3] (with --thickness)"},
    {"--line-stiffness", nullptr, &PhysicalBlock::line_stiffness, "winkler: stiffness per unit length and depth [N/m^2]"},
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

// The model's options go to the library as Settings (scenario_from: one validation for the command
// line and Python); the output flags stay here.
Scenario build_scenario(const CLI::App& s, const SimulateFlags& f) {
  Settings settings = settings_of(s, {"--trajectory", "--plot", "--animate", "--animate-frames", "--json", "--json-out",
                                      "--quiet", "--timing", "--timing-repeat", "--max-output-rows"});
  Scenario sc = scenario_from(settings);
  if (given(s, "--trajectory")) sc.trajectory = f.trajectory;
  if (given(s, "--plot")) sc.plot = f.plot;
  require_writable("plot", sc.plot);
  require_animation(f.animate, f.animate_frames);
  require_writable("trajectory", sc.trajectory);
  require_writable("json-out", f.json_out);
  return sc;
}

bool wants_json(const SimulateFlags& f) { return f.json || !f.json_out.empty(); }

void run(const CLI::App& s, const SimulateFlags& f) {
  const Scenario sc = build_scenario(s, f);
  TrajectoryTarget target(sc.trajectory, sc.plot.empty() ? f.animate : sc.plot);
  std::optional<CsvTable> table;
  if (target.file) table.emplace(target.file->stream());
  // Events go to a spool of the JSON summary as the run makes them: O(1) memory whatever its length.
  std::unique_ptr<JsonEventSpool> spool;
  if (wants_json(f)) spool = std::make_unique<JsonEventSpool>();
  SimulateOutputs out;
  out.trajectory = table ? &*table : nullptr;
  out.max_output_rows = f.max_output_rows;
  if (spool) out.on_event = [&spool](const nlohmann::ordered_json& e) { spool->add(e); };
  out.timing_repeat = f.timing_repeat;
  const SimulateReport rep = run_scenario(sc, out);
  std::vector<std::string> animate_args = rep.figure.animate_args;
  animate_args.insert(animate_args.end(), {"--frames", std::to_string(f.animate_frames)});
  target.figures_and_clean({{rep.figure.plot_script, sc.plot, rep.figure.plot_args},
                            {"animate_block.py", f.animate, animate_args}});
  if (spool) {
    nlohmann::ordered_json j = rep.summary;
    if (f.timing) j["timing"] = to_json(rep.timing);
    if (!f.json_out.empty()) emit_json(j, f.json_out, *spool);
    if (f.json) emit_json(j, "-", *spool);
  }
  if (!f.json && !f.quiet) std::fputs(rep.text.c_str(), stdout);
  if (f.timing && !f.json && !f.quiet)
    std::printf("integration: %.6g s CPU, %.6g s wall\n", rep.timing.cpu_s, rep.timing.wall_s);
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
