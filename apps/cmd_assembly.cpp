// SPDX-License-Identifier: Apache-2.0
// `blockdyn assembly` (also `blockdyn simulate --model assembly`): a block assembly (one block, seed
// 002's trilith, a column of drums, or any assembly from a TOML file) with deformable or rigid
// unilateral frictional contacts, shaken by the ground. Parse, call the library, write.
#include <memory>

#include "assembly_flags.hpp"
#include "blockdyn/commands/ground_settings.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "simulate_output.hpp"

namespace blockdyn::cli {
// Each command's own names (add, Flags, ...) in its own namespace: the files build as one unity.
namespace cmd_assembly {
namespace {

struct Flags {
  std::string file;
  AssemblyFlags model;
  double t_end = 10, rtol = 1e-8, atol = 1e-10;
  IntegratorOptions integrator;
  SimulateOutputFlags out;
};

void add(CLI::App& app) {
  auto f = std::make_shared<Flags>();
  CLI::App* s = app.add_subcommand(
      "assembly",
      "a block assembly (block, trilith, column of drums, or a TOML file) with deformable unilateral "
      "frictional contacts under ground motion (SI units: s, m, Hz, g); the same as simulate --model assembly");
  s->add_option("file", f->file, "assembly file (TOML: [[block]], [[interface]], [contact])");
  add_assembly_options(*s, f->model);
  s->add_option("--t-end", f->t_end, "duration [s] (default 10)");
  s->add_option("--rtol", f->rtol, "relative tolerance (default 1e-8)");
  s->add_option("--atol", f->atol, "absolute tolerance in m, rad, m/s, rad/s, J (default 1e-10)");
  add_method_option(*s, f->integrator);
  add_simulate_output_flags(*s, f->out, 0.01);
  add_spec_options(*s, ground_options());
  s->callback([s, f] {
    Settings settings = settings_of(*s, simulate_output_flag_names());
    settings.add("model", "assembly");
    run_and_write(*prepare_run(settings), f->out);
  });
}

RegisterCommand reg(12, add);

}  // namespace
}  // namespace cmd_assembly
}  // namespace blockdyn::cli
