// SPDX-License-Identifier: Apache-2.0
#include "forced_model.hpp"

#include <cmath>

#include "blockdyn/io/json_io.hpp"
#include "blockdyn/simulation/assembly_simulation.hpp"
#include "blockdyn/simulation/rigid_probe.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"
#include "cli_common.hpp"

namespace blockdyn::cli {

void add_forced_model_flags(CLI::App& s, ForcedModelFlags& f, const std::vector<std::string>& extra_models) {
  std::vector<std::string> models = extra_models;
  for (const char* m : {"housner", "rigid", "assembly"}) models.push_back(m);
  std::string help = "housner, rigid (a block on rigid ground) or assembly (with --preset)";
  for (const auto& m : extra_models) help += ", or " + m;
  s.add_option("--model", f.model, help)->check(CLI::IsMember(models));
  s.add_option("--width", f.width, "housner/rigid: block width [m]");
  s.add_option("--height", f.height, "housner/rigid: block height [m]");
  s.add_option("--mass", f.mass, "housner/rigid: mass [kg] (default 1)");
  s.add_option("--g", f.g, "gravity [m/s^2] (default 9.81)");
  s.add_option("--mu-s", f.mu_s, "rigid: static friction (default 0.7)");
  s.add_option("--mu-k", f.mu_k, "rigid: kinetic friction (default mu-s)");
  s.add_option("--impact", f.impact, "rigid: housner or newton")->check(CLI::IsMember({"housner", "newton"}));
  s.add_option("--restitution", f.restitution, "restitution (housner/rigid as in simulate; assembly as in assembly)");
  s.add_option("--preset", f.preset, "assembly: block, trilith or column")->check(CLI::IsMember({"block", "trilith", "column"}));
  s.add_option("--contact", f.contact, "assembly: deformable or rigid")->check(CLI::IsMember({"deformable", "rigid"}));
  s.add_option("--slenderness", f.preset_opt.slenderness, "assembly: height / width (default 4)");
  s.add_option("--block-width", f.preset_opt.block_width, "assembly: width [m] (default 0.12)");
  s.add_option("--drums", f.preset_opt.drums, "assembly column: drums (default 4)");
  s.add_option("--phi-s", f.phi_s, "assembly: friction angle on the ground [deg] (default 90)");
  s.add_option("--phi-l", f.phi_l, "assembly: friction angle between blocks [deg] (default 90)");
  s.add_flag("--columns-rock-only", f.columns_rock_only,
             "assembly, rigid law: the blocks on the ground only rock (no sliding, plastic impacts): seed 001's 5-DOF "
             "trilith");
}

void add_excitation_grid_flags(CLI::App& s, SurvivalOptions& o) {
  s.add_option("--excitation", o.excitation, "harmonic (default), half-sine, half-cosine or rect (pulses last pi/Omega)")
      ->check(CLI::IsMember({"harmonic", "half-sine", "half-cosine", "rect"}));
  s.add_option("--phase", o.phase, "phase of cos(Omega t + phase) [rad] (default 0)");
  s.add_option("--omega-min", o.omega_min, "smallest omega = Omega/p (default 1)");
  s.add_option("--omega-max", o.omega_max, "largest omega (default 20)");
  s.add_option("--omega-points", o.omega_points, "omegas, uniform (default 10)");
  s.add_option("--t-end", o.t_end, "duration of each run [s] (default 20): the transient window");
  s.add_option("--periods", o.periods, "duration of each run in forcing periods (instead of --t-end)");
  s.add_option("--threads", o.threads, "worker threads (0: all cores; default 0)");
}

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

namespace {

// Flags of another family are refused, not ignored; a value given is checked, never read as
// "not given" (the defaults are marked by not giving the flag).
void check_family_flags(const CLI::App& s, const ForcedModelFlags& f) {
  const std::vector<std::string> assembly_only = {"--preset",      "--contact", "--slenderness", "--block-width",
                                                  "--drums",       "--phi-s",   "--phi-l",       "--columns-rock-only"};
  if (f.model == "housner" || f.model == "rigid") refuse(s, assembly_only, "applies to --model assembly only");
  if (f.model == "housner") refuse(s, {"--mu-s", "--mu-k", "--impact"}, "applies to --model rigid only");
  if (f.model == "assembly")
    refuse(s, {"--width", "--height", "--mass", "--g", "--mu-s", "--mu-k", "--impact"},
           "applies to --model housner|rigid only (an assembly's blocks and friction come from --preset and "
           "--phi-s/--phi-l)");
  if (given(s, "--mu-k") && !(std::isfinite(f.mu_k) && f.mu_k >= 0.0))
    throw UsageError("mu-k = " + std::to_string(f.mu_k) + " is out of range: must be finite and >= 0");
  if (given(s, "--restitution") && !(std::isfinite(f.restitution) && f.restitution >= 0.0 && f.restitution <= 1.0))
    throw UsageError("restitution = " + std::to_string(f.restitution) + " is out of range: must be in [0, 1]");
}

}  // namespace

ForcedModel build_forced_model(const CLI::App& s, const ForcedModelFlags& f) {
  ForcedModel fm;
  check_family_flags(s, f);
  if (f.model == "housner" || f.model == "rigid") {
    if (!given(s, "--width") || !given(s, "--height")) throw UsageError("--width and --height are needed for --model " + f.model);
    RigidBlockParams rp;
    rp.shape = {f.width, f.height, f.mass, f.g};
    rp.interface = {f.mu_s, given(s, "--mu-k") ? f.mu_k : f.mu_s};
    rp.impact = f.impact == "newton" ? ImpactLaw::Newton : ImpactLaw::Housner;
    if (given(s, "--restitution")) rp.restitution = f.restitution;
    try {
      validate(rp);
      if (f.model == "housner") housner_coefficient(rp.shape, rp.restitution);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    fm.alpha = rp.shape.alpha();
    fm.p = rp.shape.p();
    fm.width = rp.shape.width;
    fm.description = to_json(rp, f.model);
    fm.overturn_rule = "|theta| reaches pi/2";
    fm.tolerances = to_json(RigidRunOptions{}.integrator);
    const bool housner = f.model == "housner";
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
      out.invalid = r.status == SimStatus::Invalid || r.status == SimStatus::NumericalFailure;
      if (r.status == SimStatus::Overturned) {
        out.collapse_mode = 1;
        out.t_failure = r.overturn_time;
      }
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
  if (f.preset.empty()) throw UsageError("--model assembly needs --preset block|trilith|column");
  PresetOptions po = f.preset_opt;
  po.rigid_contacts = f.contact == "rigid";
  require_range("phi-s", f.phi_s, 0, 90);
  require_range("phi-l", f.phi_l, 0, 90);
  for (ContactLaw* l : {&po.ground_law, &po.block_law}) {
    const double phi = l == &po.ground_law ? f.phi_s : f.phi_l;
    l->mu_s = l->mu_k = phi >= 90 ? kNoSlipFriction : std::tan(phi * M_PI / 180);
    if (po.rigid_contacts) l->restitution = given(s, "--restitution") ? f.restitution : 0.0;
    else if (given(s, "--restitution")) l->restitution = f.restitution;
  }
  Assembly a;
  try {
    a = make_preset(f.preset, po);
    if (f.columns_rock_only) {
      if (!po.rigid_contacts) throw UsageError("--columns-rock-only (seed 001's 5-DOF restriction) needs --contact rigid");
      // As `blockdyn assembly --columns-rock-only`: no sliding and plastic impacts on the ground.
      a.rock_only_on_ground = true;
      for (AssemblyInterface& i : a.interfaces)
        if (i.lower < 0) {
          i.law.mu_s = i.law.mu_k = kNoSlipFriction;
          i.law.restitution = 0.0;
        }
    }
    validate(a);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  fm.alpha = std::atan2(a.blocks[0].width, a.blocks[0].height);
  fm.width = a.blocks[0].width;
  fm.p = std::sqrt(0.75 * a.g / (0.5 * std::hypot(a.blocks[0].width, a.blocks[0].height)));
  fm.description = {{"model", "assembly"}, {"preset", f.preset}, {"contact", a.contact}, {"blocks", a.blocks.size()},
                    {"phi_s", f.phi_s}, {"phi_l", f.phi_l}, {"slenderness", po.slenderness},
                    {"columns_rock_only", f.columns_rock_only}};
  fm.overturn_rule = "collapse mode 1 (rotation) or 2 (bearing)";
  fm.tolerances = to_json(AssemblyRunOptions{}.integrator);
  if (po.rigid_contacts) fm.tolerances["moreau_jean_step_s"] = AssemblyRunOptions{}.step;
  fm.traced = [a](const GroundMotion& g, double t_end, RunProbe* probe) {
    AssemblyRunOptions ao;
    ao.t_end = t_end;
    ao.record_events = false;
    const AssemblyResult r = simulate_assembly(a, g, ao, nullptr, probe);
    SurvivalOutcome out;
    out.moved = r.motion != "rest";
    out.collapse_mode = r.collapse_mode;
    out.t_failure = r.t_failure;
    out.invalid = r.status == "invalid";
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

}  // namespace blockdyn::cli
