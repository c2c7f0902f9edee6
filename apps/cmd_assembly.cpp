// SPDX-License-Identifier: Apache-2.0
// `blockdyn assembly`: a block assembly (one block, seed 002's trilith, a column of drums, or any
// assembly from a TOML file) with deformable unilateral frictional contacts, shaken by the ground.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "blockdyn/io/csv_table.hpp"
#include "blockdyn/io/assembly_file.hpp"
#include "blockdyn/io/assembly_json.hpp"
#include "blockdyn/io/json_event_spool.hpp"
#include "blockdyn/simulation/assembly_simulation.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "ground_flags.hpp"
#include "trajectory_target.hpp"

namespace blockdyn::cli {
namespace {

struct AssemblyFlags {
  std::string file, preset, contact = "deformable";
  PresetOptions preset_opt;
  double phi_s = 90, phi_l = 90, tilt = 0;
  double phi_s_kinetic = -1, phi_l_kinetic = -1;  // < 0: the static angle
  double k_normal = 1e7, k_tangential = -1, restitution = 0.5;
  double collapse_rotation = 1.0, min_bearing = 0.0, g = 9.81;
  AssemblyRunOptions run;
  GroundFlags ground;
  std::string trajectory, plot, animate, json_out;
  int animate_frames = 120;
  bool json = false, quiet = false, rock_only = false;
  double max_output_rows = 1e7;
};

// The kinetic friction of an interface from its flag (absent: equal to the static one).
void set_kinetic(ContactLaw& l, double phi_kinetic, const char* field) {
  if (phi_kinetic < 0) return;
  l.mu_k = friction_of_angle(phi_kinetic, field);
}

ContactLaw law_from_flags(const CLI::App& s, const AssemblyFlags& f, double phi, const char* field) {
  ContactLaw l;
  l.k_normal = f.k_normal;
  l.k_tangential = f.k_tangential;
  // The rigid law's Newton restitution defaults to 0 (a plastic contact, as Housner's block).
  l.restitution = f.contact == "rigid" && !given(s, "--restitution") ? 0.0 : f.restitution;
  try {
    l.mu_s = l.mu_k = friction_of_angle(phi, field);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return l;
}

Assembly build(const CLI::App& s, const AssemblyFlags& f) {
  if (f.file.empty() == f.preset.empty())
    throw UsageError(f.file.empty() ? "give --preset block|trilith|column or an assembly FILE.toml"
                                    : "give either --preset or an assembly file, not both");
  require_range("phi-s", f.phi_s, 0, 90);
  require_range("phi-l", f.phi_l, 0, 90);
  // The kinetic angles lie between 0 and the static ones (the file's, or the flags').
  if (given(s, "--phi-s-kinetic"))
    require_range("phi-s-kinetic", f.phi_s_kinetic, 0, f.file.empty() || given(s, "--phi-s") ? f.phi_s : 90);
  if (given(s, "--phi-l-kinetic"))
    require_range("phi-l-kinetic", f.phi_l_kinetic, 0, f.file.empty() || given(s, "--phi-l") ? f.phi_l : 90);
  require_range("tilt", f.tilt, -1.5, 1.5, false, false);
  require_range("normal-stiffness", f.k_normal, 1, 1e13);
  if (given(s, "--tangential-stiffness")) require_range("tangential-stiffness", f.k_tangential, 1, 1e13);
  const bool rigid = f.contact == "rigid";
  require_range("restitution", f.restitution, rigid ? 0.0 : 1e-3, 1);
  if (rigid)
    for (const char* n : {"--normal-stiffness", "--tangential-stiffness", "--rtol", "--atol", "--method"})
      if (given(s, n)) throw UsageError(std::string(n) + " belongs to --contact deformable (the rigid law has --step)");
  if (!rigid && given(s, "--step")) throw UsageError("--step belongs to --contact rigid");
  require_range("collapse-rotation", f.collapse_rotation, 0, 10, false);
  require_range("min-bearing", f.min_bearing, 0, 1e3);
  require_range("g", f.g, 0, 1e3, false);
  Assembly a;
  try {
    if (!f.file.empty()) {
      for (const char* n : {"--slenderness", "--drums", "--block-width", "--thickness", "--density", "--lintel-length",
                            "--overhang", "--tilt"})
        if (given(s, n)) throw UsageError(std::string(n) + " belongs to --preset (an assembly file gives its blocks)");
      a = read_assembly_file(f.file);
      // Flags given on the command line override the file's contact laws.
      for (AssemblyInterface& i : a.interfaces) {
        ContactLaw& l = i.law;
        if (given(s, "--normal-stiffness")) l.k_normal = f.k_normal;
        if (given(s, "--tangential-stiffness")) l.k_tangential = f.k_tangential;
        if (given(s, "--restitution")) l.restitution = f.restitution;
        const bool ground = i.lower < 0;
        if (ground && given(s, "--phi-s")) l.mu_s = l.mu_k = friction_of_angle(f.phi_s, "phi-s");
        if (!ground && given(s, "--phi-l")) l.mu_s = l.mu_k = friction_of_angle(f.phi_l, "phi-l");
        set_kinetic(l, ground ? f.phi_s_kinetic : f.phi_l_kinetic, ground ? "phi-s-kinetic" : "phi-l-kinetic");
      }
      if (given(s, "--g")) a.g = f.g;
      a.contact = f.contact;
    } else {
      PresetOptions o = f.preset_opt;
      o.tilt = f.tilt;
      o.ground_law = law_from_flags(s, f, f.phi_s, "phi-s");
      o.block_law = law_from_flags(s, f, f.phi_l, "phi-l");
      set_kinetic(o.ground_law, f.phi_s_kinetic, "phi-s-kinetic");
      set_kinetic(o.block_law, f.phi_l_kinetic, "phi-l-kinetic");
      o.rigid_contacts = rigid;
      if (given(s, "--drums") && f.preset != "column") throw UsageError("--drums belongs to --preset column");
      for (const char* n : {"--lintel-length", "--overhang"})
        if (given(s, n) && f.preset != "trilith") throw UsageError(std::string(n) + " belongs to --preset trilith");
      a = make_preset(f.preset, o);
      a.g = f.g;
    }
    if (f.rock_only) {
      if (!rigid) throw UsageError("--columns-rock-only (seed 001's 5-DOF restriction) needs --contact rigid");
      // No sliding and plastic impacts on the ground: the blocks standing on it only rock.
      a.rock_only_on_ground = true;
      for (AssemblyInterface& i : a.interfaces)
        if (i.lower < 0) {
          i.law.mu_s = i.law.mu_k = kNoSlip;
          i.law.restitution = 0.0;
        }
    }
    if (given(s, "--collapse-rotation") || f.file.empty()) a.collapse_rotation = f.collapse_rotation;
    if (given(s, "--min-bearing") || f.file.empty()) a.min_bearing = f.min_bearing;
    validate(a);
  } catch (const UsageError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return a;
}

void print_summary(const AssemblyResult& r) {
  std::printf("status: %s, motion: %s", r.status.c_str(), r.motion.c_str());
  if (r.collapse_mode) std::printf(", collapse mode %d at t* = %.9g s (block %d)", *r.collapse_mode, *r.t_failure, r.failed_block);
  std::printf(", t_final = %.9g s\n", r.t_final);
  for (std::size_t b = 0; b < r.blocks.size(); ++b)
    std::printf("block %zu (%s): max |theta| = %.6g rad, max sliding = %.6g m\n", b, r.blocks[b].name.c_str(),
                r.blocks[b].max_abs_rotation, r.blocks[b].max_abs_sliding);
  std::printf("events: %ld, steps: %ld, rhs evaluations: %ld\n", r.events_total, r.steps, r.rhs_evals);
  std::printf("energy: E0 = %.9g J, max |balance error| = %.3g J, friction work = %.6g J, damping work = %.6g J\n",
              r.energy_initial.total, r.max_abs_energy_error, r.work_friction, r.work_normal);
  if (!r.note.empty()) std::printf("note: %s\n", r.note.c_str());
}

void run(const CLI::App& s, const AssemblyFlags& f) {
  const Assembly a = build(s, f);
  GroundMotion g;
  apply_ground_flags(s, f.ground, g);
  AssemblyRunOptions o = f.run;
  require_range("t-end", o.t_end, 0, 1e7, false);
  require_range("step", o.step, 1e-7, 1e-2);
  require_range("rtol", o.integrator.rtol, 1e-14, 1e-2);
  require_range("atol", o.integrator.atol, 1e-16, 1e-2);
  require_range("output-interval", o.output_interval, 0, 1e7);
  if (!f.trajectory.empty() || !f.plot.empty() || !f.animate.empty())
    require_sample_count("output-interval", o.output_interval, o.t_end, f.max_output_rows);
  require_writable("trajectory", f.trajectory);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  require_animation(f.animate, f.animate_frames);
  TrajectoryTarget target(f.trajectory, f.plot.empty() ? f.animate : f.plot);
  // Events go straight to a spool of the JSON summary (only when one is asked for): memory stays
  // flat however long the run.
  std::unique_ptr<JsonEventSpool> spool;
  if (f.json || !f.json_out.empty()) {
    spool = std::make_unique<JsonEventSpool>();
    o.on_event = [&spool](const AssemblyEventRecord& e) { spool->add(to_json(e)); };
  }
  o.record_events = false;
  AssemblyResult r;
  std::optional<CsvTable> table;
  if (target.file) table.emplace(target.file->stream());
  try {
    r = simulate_assembly(a, g, o, table ? &*table : nullptr);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  char title[256];
  std::snprintf(title, sizeof title, "%s (%zu blocks): %s, %s%s at t = %.6g s", a.preset.c_str(), a.blocks.size(),
                r.status.c_str(), r.motion.c_str(),
                r.collapse_mode ? (" mode " + std::to_string(*r.collapse_mode)).c_str() : "", r.t_final);
  std::string sizes;
  for (const AssemblyBlock& b : a.blocks) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%.17g,%.17g", sizes.empty() ? "" : ",", b.width, b.height);
    sizes += buf;
  }
  target.figures_and_clean({{"plot_assembly.py", f.plot, {"--title", title}},
                            {"animate_assembly.py", f.animate,
                             {"--frames", std::to_string(f.animate_frames), "--title", title, "--sizes", sizes}}});
  if (spool) {
    const auto j = assembly_result_json(a, g, o, r);
    if (!f.json_out.empty()) emit_json(j, f.json_out, *spool);
    if (f.json) emit_json(j, "-", *spool);
  }
  if (!f.json && !f.quiet) print_summary(r);
}

void add(CLI::App& app) {
  auto f = std::make_shared<AssemblyFlags>();
  CLI::App* s = app.add_subcommand(
      "assembly", "a block assembly (block, trilith, column of drums, or a TOML file) with deformable unilateral "
                  "frictional contacts under ground motion (SI units: s, m, Hz, g)");
  s->add_option("file", f->file, "assembly file (TOML: [[block]], [[interface]], [contact])");
  s->add_option("--preset", f->preset, "block (one block), trilith (seed 002: two columns and a lintel), column (n drums)")
      ->check(CLI::IsMember({"block", "trilith", "column"}));
  s->add_option("--contact", f->contact,
                "contact law: deformable (spring-dashpot + elastic Coulomb, default) or rigid (unilateral, Coulomb, "
                "Newton impacts; Moreau-Jean time-stepping)")
      ->check(CLI::IsMember({"deformable", "rigid"}));
  s->add_option("--slenderness", f->preset_opt.slenderness, "column (or block) height / width (default 4)");
  s->add_option("--drums", f->preset_opt.drums, "column: number of drums, 1 to 8 (default 4)");
  s->add_option("--block-width", f->preset_opt.block_width, "width b of the columns or block [m] (default 0.12)");
  s->add_option("--thickness", f->preset_opt.thickness, "out-of-plane depth [m] (default 0.06)");
  s->add_option("--density", f->preset_opt.density, "density [kg/m^3] (default 2700)");
  s->add_option("--lintel-length", f->preset_opt.lintel_length, "trilith: lintel length [m] (default: column height)");
  s->add_option("--overhang", f->preset_opt.overhang,
                "trilith: lintel beyond each column's outer face [m] (default 0: flush, seed 002)");
  s->add_option("--phi-s", f->phi_s, "friction angle column-ground [deg], 0 to 90 (90: no sliding; default 90)");
  s->add_option("--phi-l", f->phi_l, "friction angle between blocks [deg], 0 to 90 (default 90)");
  s->add_option("--phi-s-kinetic", f->phi_s_kinetic,
                "kinetic friction angle column-ground [deg], 0 to phi-s (default: phi-s; static friction holds a "
                "contact at rest up to phi-s, a sliding one feels this)");
  s->add_option("--phi-l-kinetic", f->phi_l_kinetic,
                "kinetic friction angle between blocks [deg], 0 to phi-l (default: phi-l)");
  s->add_option("--tilt", f->tilt, "initial rotation [rad] of the assembly's rocking mode, at rest (default 0)");
  s->add_option("--normal-stiffness", f->k_normal, "normal stiffness per contact point [N/m] (default 1e7)");
  s->add_option("--tangential-stiffness", f->k_tangential, "tangential stiffness per point [N/m] (default normal / 3)");
  s->add_option("--restitution", f->restitution,
                "deformable: restitution of a flat drop, sets the dashpots, in [0.001, 1] (default 0.5); rigid: "
                "Newton's coefficient in [0, 1] (default 0)");
  s->add_option("--collapse-rotation", f->collapse_rotation,
                "collapse mode 1 when a block's |theta| reaches this fraction of atan(width/height) (default 1)");
  s->add_option("--min-bearing", f->min_bearing,
                "collapse mode 2 when the overlap of two blocks' faces falls to this length [m] (default 0)");
  s->add_option("--g", f->g, "gravity [m/s^2] (default 9.81)");
  s->add_option("--step", f->run.step, "rigid: time step [s] (default 1e-4)");
  s->add_flag("--columns-rock-only", f->rock_only,
              "rigid: seed 001's 5-DOF restriction - the blocks on the ground only rock (no sliding, plastic "
              "impacts); a block leaving the ground is reported, not integrated");
  s->add_option("--t-end", f->run.t_end, "duration [s] (default 10)");
  s->add_option("--rtol", f->run.integrator.rtol, "relative tolerance (default 1e-8)");
  s->add_option("--atol", f->run.integrator.atol, "absolute tolerance in m, rad, m/s, rad/s, J (default 1e-10)");
  add_method_option(*s, f->run.integrator);
  s->add_option("--output-interval", f->run.output_interval, "trajectory interval [s] (0: every step; default 0.01)");
  s->add_option("--max-output-rows", f->max_output_rows, "refuse a trajectory of more rows than this (default 1e7)");
  s->add_option("--trajectory", f->trajectory, "write the trajectory CSV here");
  s->add_option("--plot", f->plot, "write a figure of the motion (PNG; an SVG beside it)");
  s->add_option("--animate", f->animate, "write an animation: F.gif (Pillow) or F.mp4 (ffmpeg)");
  s->add_option("--animate-frames", f->animate_frames, "frames of the animation (default 120)");
  s->add_flag("--json", f->json, "print the JSON summary on stdout");
  s->add_option("--json-out", f->json_out, "also write the JSON summary to this file");
  s->add_flag("--quiet", f->quiet, "no text summary on stdout");
  add_ground_flags(*s, f->ground);
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(12, add);

}  // namespace
}  // namespace blockdyn::cli
