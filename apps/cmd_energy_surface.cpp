// SPDX-License-Identifier: Apache-2.0
// `blockdyn energy-surface`: projections of the energy surface onto the (y, y') and (w, w') planes
// with the trajectory overlaid (thesis sec. 5.1, Figs. 5.1-5.2); with --ic surface the initial
// state itself is built on a prescribed energy (Figs. 5.8-5.11).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <memory>

#include "blockdyn/analysis/winkler/energy_surface.hpp"
#include "blockdyn/analysis/winkler/swings.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "chaos_cli.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
namespace {

struct SurfaceFlags {
  BlockParams p;
  IntegratorOptions integ;
  IcFlags ic;
  double t_end = 200, phase_dt = 0.05, surface_energy = 0;
  int n = 401;
  std::string csv_prefix, plot, json_out;
  bool json = false;
};

void run(const CLI::App& s, SurfaceFlags& f) {
  validate(f.p);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  const SimulationOptions so = orbit_run_options(f.t_end, f.integ);
  require_range("phase-dt", f.phase_dt, 0.0, f.t_end, false, true);
  require_sample_count("phase-dt", f.phase_dt, f.t_end);
  require_range("n", f.n, 2, 100000);
  const BlockStateVec z0 = ic_state(s, f.ic, f.p);
  const double e0 = energy(f.p, z0).total();
  const double E = s.count("--surface-energy") ? f.surface_energy : e0;
  require_range("surface-energy", E, -0.5 / f.p.k, 1e6);

  SwingOptions sw;
  sw.phase_dt = f.phase_dt;
  sw.quadrature_dt = f.t_end;  // only the phase samples are wanted
  sw.min_samples_per_step = 1;
  SwingAccumulator acc(f.p, sw);
  const SimulationResult r = simulate(f.p, {}, z0, so, &acc);

  const auto heave = heave_projection(f.p, E, f.n);
  const auto rock = rock_projection(f.p, E, f.n);
  // How far the sampled trajectory gets outside the projections (should be <= rounding + the
  // integration error for mu = 0, and negative margins when friction dissipates).
  double heave_excess = -INFINITY, rock_excess = -INFINITY;
  for (const PhaseSample& q : acc.phase()) {
    const double h = q.s.y - 0.5;
    heave_excess = std::max(heave_excess, 0.5 * q.s.vy * q.s.vy + heave_potential(f.p, h) - E);
    rock_excess = std::max(rock_excess, 0.5 * f.p.inertia() * q.s.vw * q.s.vw + rock_potential(f.p, q.s.w) - E);
  }

  std::string prefix = f.csv_prefix;
  const bool temp = prefix.empty() && !f.plot.empty();
  if (temp) prefix = temp_path("energy", "");
  if (!prefix.empty()) {
    AtomicFile fh(prefix + "_heave.csv");
    fh.stream() << "y,v_min,vy_max\n" << std::setprecision(17);
    for (const auto& b : heave) fh.stream() << b.y << ',' << b.v_min << ',' << b.vy_max << '\n';
    fh.commit();
    AtomicFile fr(prefix + "_rock.csv");
    fr.stream() << "w,u,vw_free,vw_contact\n" << std::setprecision(17);
    for (const auto& b : rock) fr.stream() << b.w << ',' << b.u << ',' << b.vw_free << ',' << b.vw_contact << '\n';
    fr.commit();
    AtomicFile fp(prefix + "_phase.csv");
    write_phase_csv(fp.stream(), acc.phase());
    fp.commit();
  }
  if (!f.plot.empty()) {
    char title[256];
    std::snprintf(title, sizeof title, "r=%g k=%g mu=%g %s, E=%.6g, w0=%.4g y0=%.6g y0'=%.6g", f.p.r, f.p.k, f.p.mu,
                  f.ic.ic.c_str(), E, z0[kW], z0[kH] + 0.5, z0[kVY]);
    run_python("plot_energy_surface.py",
               {prefix + "_heave.csv", prefix + "_rock.csv", prefix + "_phase.csv", f.plot, title});
    if (temp)
      for (const char* suf : {"_heave.csv", "_rock.csv", "_phase.csv"}) std::remove((prefix + suf).c_str());
  }
  nlohmann::ordered_json j = summary_head(f.p, f.integ, f.ic, z0);
  j["options"] = {{"t_end", f.t_end}, {"phase_dt", f.phase_dt}, {"n", f.n}};
  j["surface_energy"] = E;
  j["status"] = to_string(r.status);
  j["t_final"] = r.t_final;
  j["samples"] = acc.phase().size();
  j["max_heave_excess"] = heave_excess;
  j["max_rock_excess"] = rock_excess;
  j["max_abs_energy_balance_error"] = r.max_abs_energy_error;
  if (!emit_summary(j, f.json, f.json_out)) {
    std::printf("E = %.12g; initial y' = %.12g; trajectory to t = %.6g (%s)\n", E, z0[kVY], r.t_final,
                to_string(r.status));
    std::printf("largest excess over the projections: (y, y') %.3g, (w, w') %.3g\n", heave_excess, rock_excess);
  }
}

void add(CLI::App& app) {
  auto f = std::make_shared<SurfaceFlags>();
  CLI::App* s = app.add_subcommand(
      "energy-surface", "energy-surface projections on (y, y') and (w, w') with the trajectory; ICs on a given energy");
  add_orbit_options(*s, f->p, f->integ, f->ic);
  s->add_option("--t-end", f->t_end, "final time (> 0)")->capture_default_str();
  s->add_option("--phase-dt", f->phase_dt, "trajectory sampling interval (> 0)")->capture_default_str();
  s->add_option("--surface-energy", f->surface_energy, "energy of the drawn surface (default: the initial energy)");
  s->add_option("--n", f->n, "boundary points per projection, in [2, 100000]")->capture_default_str();
  s->add_option("--csv-prefix", f->csv_prefix, "write PREFIX_heave.csv, PREFIX_rock.csv, PREFIX_phase.csv");
  add_summary_options(*s, f->plot, "plot the projections and the trajectory (PNG + SVG)", f->json, f->json_out);
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(53, add);

}  // namespace
}  // namespace blockdyn::cli
