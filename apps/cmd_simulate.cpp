// SPDX-License-Identifier: Apache-2.0
// `blockdyn simulate`: one run of any registered model family (winkler, housner, rigid, assembly)
// from flags or a TOML scenario; the library prepares and runs it, the outputs are written here.
#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "assembly_flags.hpp"
#include "blockdyn/commands/ground_settings.hpp"
#include "blockdyn/commands/simulate_run.hpp"
#include "blockdyn/family/family.hpp"
#include "blockdyn/units/physical_units.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "simulate_output.hpp"

namespace blockdyn::cli {
// Each command's own names (add, Flags, ...) in its own namespace: the files build as one unity.
namespace cmd_simulate {
namespace {

struct SimulateFlags {
  std::string scenario_file;
  std::string model = "winkler";
  WinklerParams p;
  IntegratorOptions integ;
  std::string ic = "ic1";
  double w0 = 0, x0 = 0, y0 = 0, vx0 = 0, vy0 = 0, vw0 = 0;
  double t_end = 10;
  std::string units = "nondim";
  PhysicalBlock phys;  // --height --width ... (physical input)
  double restitution = 0, mu_s = 0.7, mu_k = 0.7;
  std::string impact = "housner";
  AssemblyFlags assembly;
  SimulateOutputFlags out;
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
    {"--line-stiffness", nullptr, &PhysicalBlock::line_stiffness,
     "winkler: stiffness per unit length and depth [N/m^2]"},
};

void add_physical_flags(CLI::App& s, SimulateFlags& f) {
  for (const PhysFlag& pf : kPhysFlags) {
    if (pf.plain) {
      s.add_option(pf.name, f.phys.*pf.plain, pf.help);
    } else {
      s.add_option_function<double>(
          pf.name, [&f, pf](double v) { f.phys.*pf.opt = v; }, pf.help);
    }
  }
}

// The model's options go to the library as Settings (one vocabulary and validation for the
// command line and Python); the family named by --model reads them.
void run(const CLI::App& s, const SimulateFlags& f) {
  const auto prepared = prepare_run(settings_of(s, simulate_output_flag_names()));
  const auto [trajectory, plot] = prepared->scenario_outputs();
  run_and_write(*prepared, f.out, given(s, "--trajectory") || trajectory.empty() ? f.out.trajectory : trajectory,
                given(s, "--plot") || plot.empty() ? f.out.plot : plot);
}

void add(CLI::App& app) {
  auto f = std::make_shared<SimulateFlags>();
  CLI::App* s = app.add_subcommand(
      "simulate",
      "integrate one block (winkler, housner or rigid model) from flags or a TOML scenario, a block "
      "assembly (--model assembly, the options of `blockdyn assembly`), or a 3D box or cylinder (--model rigid3d)");
  s->add_option("scenario", f->scenario_file, "TOML scenario file (flags given as well override it)");
  std::string models;
  std::vector<std::string> names;
  for (const Family& fam : families()) {
    models += (models.empty() ? "" : ", ") + std::string(fam.name) + " (" + fam.description + ")";
    names.emplace_back(fam.name);
  }
  s->add_option("--model", f->model, "model family: " + models + "; default " + families().front().name)
      ->check(CLI::IsMember(names));
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
                "final time: seconds with a physical block and for housner/rigid/assembly, else non-dimensional "
                "(default 10)");
  s->add_option("--units", f->units, "winkler: nondim, or physical (needs a physical block: flags or [physical])");
  add_simulate_output_flags(*s, f->out, 0.01);
  add_spec_options(*s, ground_options());
  add_physical_flags(*s, *f);
  add_assembly_options(*s, f->assembly);  // --model assembly (the options `blockdyn assembly` has)
  // The options a family alone has, as it describes them (those another family shares are there).
  for (const Family& fam : families())
    if (fam.own_options)
      for (const StudyOption& o : fam.own_options())
        if (!s->get_option_no_throw("--" + o.name)) add_spec_options(*s, {o});
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(10, add);

}  // namespace
}  // namespace cmd_simulate
}  // namespace blockdyn::cli
