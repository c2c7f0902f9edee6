// SPDX-License-Identifier: Apache-2.0
#include "assembly_flags.hpp"

namespace blockdyn::cli {

void add_assembly_options(CLI::App& app, AssemblyFlags& f) {
  auto absent = [&app](const char* name) { return app.get_option_no_throw(name) == nullptr; };
  auto opt = [&](const char* name, auto& field, const std::string& help) -> CLI::Option* {
    return absent(name) ? app.add_option(name, field, help) : nullptr;
  };
  auto flag = [&](const char* name, bool& field, const std::string& help) {
    if (absent(name)) app.add_flag(name, field, help);
  };
  auto members = [](CLI::Option* o, std::initializer_list<std::string> names) {
    if (o) o->check(CLI::IsMember(std::vector<std::string>(names)));
  };
  members(opt("--preset", f.preset,
              "block (one block), trilith (seed 002: two columns and a lintel), column (n drums), arch (voussoirs)"),
          {"block", "trilith", "column", "arch"});
  members(opt("--contact", f.contact,
              "contact law: deformable (spring-dashpot + elastic Coulomb, default) or rigid (unilateral, Coulomb, "
              "Newton impacts; see --scheme)"),
          {"deformable", "rigid"});
  opt("--slenderness", f.preset_opt.slenderness, "column (or block) height / width (default 4)");
  opt("--drums", f.preset_opt.drums, "column: number of drums, 1 to 8 (default 4)");
  opt("--block-width", f.preset_opt.block_width, "width b of the columns or block [m] (default 0.12)");
  opt("--thickness", f.preset_opt.thickness, "out-of-plane depth [m] (default 0.06)");
  opt("--density", f.preset_opt.density, "density [kg/m^3] (default 2700)");
  opt("--lintel-length", f.preset_opt.lintel_length, "trilith: lintel length [m] (default: column height)");
  opt("--overhang", f.preset_opt.overhang,
      "trilith: lintel beyond each column's outer face [m] (default 0: flush, seed 002)");
  opt("--voussoirs", f.preset_opt.voussoirs, "arch: number of equal voussoirs (default 9; at most 24 in the dynamics)");
  opt("--thickness-ratio", f.preset_opt.thickness_ratio,
      "arch: ring thickness / centreline radius, in (0, 2) (default 0.15)");
  opt("--radius", f.preset_opt.radius, "arch: centreline radius [m] (default 1)");
  opt("--embrace", f.preset_opt.embrace, "arch: angle spanned [deg], in (0, 180] (default 180: semicircular)");
  opt("--phi-s", f.phi_s, "friction angle column-ground [deg], 0 to 90 (90: no sliding; default 90)");
  opt("--phi-l", f.phi_l, "friction angle between blocks [deg], 0 to 90 (default 90)");
  opt("--phi-s-kinetic", f.phi_s_kinetic,
      "kinetic friction angle column-ground [deg], 0 to phi-s (default: phi-s; static friction holds a "
      "contact at rest up to phi-s, a sliding one feels this)");
  opt("--phi-l-kinetic", f.phi_l_kinetic, "kinetic friction angle between blocks [deg], 0 to phi-l (default: phi-l)");
  opt("--tilt", f.tilt, "initial rotation [rad] of the assembly's rocking mode, at rest (default 0)");
  opt("--normal-stiffness", f.k_normal, "normal stiffness per contact point [N/m] (default 1e7)");
  opt("--tangential-stiffness", f.k_tangential, "tangential stiffness per point [N/m] (default normal / 3)");
  opt("--restitution", f.restitution,
      "deformable: restitution of a flat drop, sets the dashpots, in [0.001, 1] (default 0.5); rigid: "
      "Newton's coefficient in [0, 1] (default 0)");
  opt("--collapse-rotation", f.collapse_rotation,
      "collapse mode 1 when a block's |theta| reaches this fraction of atan(width/height) (default 1)");
  opt("--min-bearing", f.min_bearing,
      "collapse mode 2 when the overlap of two blocks' faces falls to this length [m] (default 0)");
  opt("--g", f.g, "gravity [m/s^2] (default 9.81)");
  members(opt("--scheme", f.scheme,
              "rigid: event-driven (default up to 8 blocks: exact events, each mode's contact forces, impacts "
              "where they occur; windows of chattering contacts handed to time-stepping) or time-stepping "
              "(Moreau-Jean, fixed --step, events known to a step; default above 8 blocks)"),
          {"event-driven", "time-stepping"});
  opt("--step", f.step,
      "rigid: Moreau-Jean time step [s] (default 1e-4): the whole run with --scheme time-stepping, the "
      "windows of chattering contacts with event-driven");
  flag("--columns-rock-only", f.rock_only,
       "rigid: seed 001's 5-DOF restriction - the blocks on the ground only rock (no sliding, plastic "
       "impacts); a block leaving the ground is reported, not integrated");
}

}  // namespace blockdyn::cli
