// SPDX-License-Identifier: Apache-2.0
// `blockdyn spectrum`: overturning spectra of a rigid-ground block (housner, rigid) or of an
// assembly preset under a horizontal pulse: the smallest overturning amplitude per duration,
// with the safe islands above it (analysis/forced/overturning_spectrum.hpp).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "blockdyn/analysis/forced/overturning_spectrum.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/progress.hpp"
#include "blockdyn/simulation/assembly_simulation.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
namespace {

struct SpectrumFlags {
  std::string model = "housner", pulse = "rect", preset, contact = "deformable";
  double width = 0, height = 0, mass = 1, g = 9.81, mu_s = 0.7, mu_k = -1, restitution = -1;
  std::string impact = "housner";
  PresetOptions preset_opt;
  double phi_s = 90, phi_l = 90;
  std::vector<double> durations;
  double duration_min = 0, duration_max = 0;
  int duration_points = 0;
  SpectrumOptions spec;
  double t_after = 10.0;
  std::string csv, plot, json_out, progress = "auto";
  bool json = false, quiet = false;
};

std::vector<double> durations_of(const CLI::App& s, const SpectrumFlags& f) {
  const bool list = given(s, "--durations");
  const bool range = given(s, "--duration-min") || given(s, "--duration-max") || given(s, "--duration-points");
  if (list == range)
    throw UsageError(list ? "give --durations or --duration-min/--duration-max/--duration-points, not both"
                          : "give --durations D1,D2,... or --duration-min --duration-max --duration-points");
  if (list) return f.durations;
  require_range("duration-min", f.duration_min, 0, 1e4, false);
  require_range("duration-max", f.duration_max, f.duration_min, 1e4);
  require_range("duration-points", f.duration_points, 1, 100000);
  std::vector<double> d(f.duration_points);
  for (int i = 0; i < f.duration_points; ++i)
    d[i] = f.duration_points == 1 ? f.duration_min
                                  : f.duration_min * std::pow(f.duration_max / f.duration_min, double(i) / (f.duration_points - 1));
  return d;
}

GroundMotion pulse_motion(PulseShape shape, double amplitude, double duration) {
  GroundMotion g;
  g.horizontal.pulse = shape;
  g.horizontal.amplitude = amplitude;
  g.horizontal.duration = duration;
  return g;
}

void run(const CLI::App& s, const SpectrumFlags& f) {
  const auto shape = pulse_from_string(f.pulse);
  if (!shape || *shape == PulseShape::None) throw UsageError(std::string("pulse = '") + f.pulse + "' must be one of " + pulse_names());
  SpectrumOptions o = f.spec;
  o.durations = durations_of(s, f);
  require_range("t-after", f.t_after, 0, 1e4);
  require_range("threads", o.threads, 0, 1024);
  try {
    validate(o);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  require_writable("csv", f.csv);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  nlohmann::ordered_json model;
  OverturnTest test;
  double alpha = 0, p = 0;
  RigidBlockParams rp;
  Assembly asmb;
  if (f.model == "housner" || f.model == "rigid") {
    if (!given(s, "--width") || !given(s, "--height")) throw UsageError("--width and --height are needed for --model " + f.model);
    rp.shape = {f.width, f.height, f.mass, f.g};
    rp.interface = {f.mu_s, f.mu_k < 0 ? f.mu_s : f.mu_k};
    rp.impact = f.impact == "newton" ? ImpactLaw::Newton : ImpactLaw::Housner;
    if (f.restitution >= 0) rp.restitution = f.restitution;
    try {
      validate(rp);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    alpha = rp.shape.alpha();
    p = rp.shape.p();
    model = to_json(rp, f.model);
    const bool housner = f.model == "housner";
    const double t_after = f.t_after;
    test = [rp, housner, shape, t_after](double amplitude, double duration) {
      RigidRunOptions ro;
      ro.t_end = pulse_support(*shape) * duration + t_after;
      ro.record_events = false;
      const GroundMotion g = pulse_motion(*shape, amplitude, duration);
      const RigidResult r = housner ? simulate_housner(rp.shape, rp.restitution, g, {}, ro)
                                    : simulate_rigid(rp, g, {}, ro);
      return r.status == SimStatus::Overturned;
    };
  } else {
    if (f.preset.empty()) throw UsageError("--model assembly needs --preset block|trilith|column");
    PresetOptions po = f.preset_opt;
    po.rigid_contacts = f.contact == "rigid";
    for (ContactLaw* l : {&po.ground_law, &po.block_law}) {
      const double phi = l == &po.ground_law ? f.phi_s : f.phi_l;
      require_range(l == &po.ground_law ? "phi-s" : "phi-l", phi, 0, 90);
      l->mu_s = l->mu_k = phi >= 90 ? kNoSlipFriction : std::tan(phi * M_PI / 180);
      if (po.rigid_contacts) l->restitution = f.restitution >= 0 ? f.restitution : 0.0;
      else if (f.restitution >= 0) l->restitution = f.restitution;
    }
    try {
      asmb = make_preset(f.preset, po);
      validate(asmb);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    alpha = std::atan2(asmb.blocks[0].width, asmb.blocks[0].height);
    p = std::sqrt(0.75 * asmb.g / (0.5 * std::hypot(asmb.blocks[0].width, asmb.blocks[0].height)));
    model = {{"model", "assembly"}, {"preset", f.preset}, {"contact", asmb.contact}, {"blocks", asmb.blocks.size()}};
    const double t_after = f.t_after;
    test = [asmb, shape, t_after](double amplitude, double duration) {
      AssemblyRunOptions ao;
      ao.t_end = pulse_support(*shape) * duration + t_after;
      ao.record_events = false;
      return simulate_assembly(asmb, pulse_motion(*shape, amplitude, duration), ao).collapse_mode.has_value();
    };
  }
  Progress bar("spectrum", o.durations.size(), 0, f.quiet ? ProgressMode::None : parse_progress_mode(f.progress));
  const auto rows = overturning_spectrum(test, o, [&](std::size_t) { bar.advance(); });
  bar.finish();

  nlohmann::ordered_json j;
  j["run"] = run_info();
  j["model"] = model;
  j["pulse"] = to_string(*shape);
  j["alpha"] = alpha;
  j["p"] = p;
  j["units"] = "durations in s, amplitudes in g";
  j["options"] = {{"amplitude_min", o.amplitude_min}, {"amplitude_max", o.amplitude_max},
                  {"scan_points", o.scan_points}, {"rel_tol", o.rel_tol}, {"t_after", f.t_after},
                  {"overturn", f.model == "assembly" ? "collapse (mode 1 or 2)" : "|theta| reaches pi/2"}};
  nlohmann::ordered_json arr = nlohmann::ordered_json::array();
  long runs = 0;
  for (const SpectrumRow& r : rows) {
    nlohmann::ordered_json x;
    x["duration"] = r.duration;
    x["min_overturning_amplitude"] = r.min_overturning_amplitude ? nlohmann::ordered_json(*r.min_overturning_amplitude)
                                                                  : nlohmann::ordered_json(nullptr);
    x["at_scan_floor"] = r.at_scan_floor;
    if (*shape == PulseShape::Rect) x["linearised_rect"] = rect_pulse_overturning_linear(alpha, p, r.duration);
    nlohmann::ordered_json isl = nlohmann::ordered_json::array();
    for (const SpectrumIsland& i : r.safe_islands) isl.push_back({i.from, i.to});
    x["safe_islands"] = isl;
    x["runs"] = r.runs;
    runs += r.runs;
    arr.push_back(x);
  }
  j["rows"] = arr;
  j["runs"] = runs;
  if (!f.csv.empty() || !f.plot.empty()) {
    const std::string path = f.csv.empty() ? "/tmp/blockdyn-spectrum-" + std::to_string(::getpid()) + ".csv" : f.csv;
    {
      AtomicFile out(path);
      out.stream() << "duration,min_overturning_amplitude,linearised_rect,safe_islands\n";
      char buf[160];
      for (const auto& x : arr) {
        std::snprintf(buf, sizeof buf, "%.17g,", x["duration"].get<double>());
        out.stream() << buf;
        if (!x["min_overturning_amplitude"].is_null()) {
          std::snprintf(buf, sizeof buf, "%.17g", x["min_overturning_amplitude"].get<double>());
          out.stream() << buf;
        }
        out.stream() << ',';
        if (x.contains("linearised_rect")) {
          std::snprintf(buf, sizeof buf, "%.17g", x["linearised_rect"].get<double>());
          out.stream() << buf;
        }
        out.stream() << ',' << x["safe_islands"].size() << '\n';
      }
      out.commit();
    }
    if (!f.plot.empty()) {
      try {
        run_python("plot_spectrum.py", {path, f.plot, "--title",
                                        std::string(f.model) + " " + (f.preset.empty() ? "" : f.preset + " ") +
                                            to_string(*shape) + " pulse"});
      } catch (...) {
        if (f.csv.empty()) std::remove(path.c_str());
        throw;
      }
    }
    if (f.csv.empty()) std::remove(path.c_str());
  }
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json) emit_json(j, "-");
  if (!f.json && !f.quiet) {
    std::printf("duration [s]  min overturning amplitude [g]  safe islands above\n");
    for (const SpectrumRow& r : rows)
      std::printf("%12.6g  %29s  %zu\n", r.duration,
                  r.min_overturning_amplitude ? std::to_string(*r.min_overturning_amplitude).c_str() : "none in scan",
                  r.safe_islands.size());
    std::printf("%ld simulations\n", runs);
  }
}

void add(CLI::App& app) {
  auto f = std::make_shared<SpectrumFlags>();
  CLI::App* s = app.add_subcommand("spectrum",
                                   "overturning spectrum: the smallest pulse amplitude that overturns a block (or "
                                   "collapses an assembly), per pulse duration (s, g)");
  s->add_option("--model", f->model, "housner, rigid (a block on rigid ground) or assembly (with --preset)")
      ->check(CLI::IsMember({"housner", "rigid", "assembly"}));
  s->add_option("--pulse", f->pulse, std::string("pulse shape: ") + pulse_names() + " (default rect)");
  s->add_option("--durations", f->durations, "pulse durations t_p [s], comma separated")->delimiter(',');
  s->add_option("--duration-min", f->duration_min, "smallest duration [s] (geometric range)");
  s->add_option("--duration-max", f->duration_max, "largest duration [s]");
  s->add_option("--duration-points", f->duration_points, "number of durations");
  s->add_option("--amplitude-min", f->spec.amplitude_min, "smallest scanned amplitude [g] (default 0.01)");
  s->add_option("--amplitude-max", f->spec.amplitude_max, "largest scanned amplitude [g] (default 10)");
  s->add_option("--scan-points", f->spec.scan_points, "amplitudes scanned per duration, geometric (default 40)");
  s->add_option("--rel-tol", f->spec.rel_tol, "relative tolerance of the minimum (default 1e-6)");
  s->add_option("--t-after", f->t_after, "simulated time after the pulse [s] (default 10)");
  s->add_option("--threads", f->spec.threads, "worker threads (0: all cores; default 0)");
  s->add_option("--width", f->width, "housner/rigid: block width [m]");
  s->add_option("--height", f->height, "housner/rigid: block height [m]");
  s->add_option("--mass", f->mass, "housner/rigid: mass [kg] (default 1)");
  s->add_option("--g", f->g, "gravity [m/s^2] (default 9.81)");
  s->add_option("--mu-s", f->mu_s, "rigid: static friction (default 0.7)");
  s->add_option("--mu-k", f->mu_k, "rigid: kinetic friction (default mu-s)");
  s->add_option("--impact", f->impact, "rigid: housner or newton")->check(CLI::IsMember({"housner", "newton"}));
  s->add_option("--restitution", f->restitution, "restitution (housner/rigid as in simulate; assembly as in assembly)");
  s->add_option("--preset", f->preset, "assembly: block, trilith or column")->check(CLI::IsMember({"block", "trilith", "column"}));
  s->add_option("--contact", f->contact, "assembly: deformable or rigid")->check(CLI::IsMember({"deformable", "rigid"}));
  s->add_option("--slenderness", f->preset_opt.slenderness, "assembly: height / width (default 4)");
  s->add_option("--block-width", f->preset_opt.block_width, "assembly: width [m] (default 0.12)");
  s->add_option("--drums", f->preset_opt.drums, "assembly column: drums (default 4)");
  s->add_option("--phi-s", f->phi_s, "assembly: friction angle on the ground [deg] (default 90)");
  s->add_option("--phi-l", f->phi_l, "assembly: friction angle between blocks [deg] (default 90)");
  s->add_option("--csv", f->csv, "write the spectrum as CSV");
  s->add_option("--plot", f->plot, "plot the spectrum (PNG + SVG), with the linearised closed form for rect");
  s->add_flag("--json", f->json, "print the JSON summary");
  s->add_option("--json-out", f->json_out, "write the JSON summary here");
  s->add_option("--progress", f->progress, "auto, bar, plain or none")->check(CLI::IsMember({"auto", "bar", "plain", "none"}));
  s->add_flag("--quiet", f->quiet, "no table, no progress");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(13, add);

}  // namespace
}  // namespace blockdyn::cli
