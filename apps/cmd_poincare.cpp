// SPDX-License-Identifier: Apache-2.0
// `blockdyn poincare`: the Poincare section w = 0 of one orbit (thesis sec. 5.2.1, Figs. 5.3-5.14):
// CSV of the crossing states (y, y', w', x, x') and plots of the (y, y') and (y, w') projections.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "blockdyn/analysis/winkler/poincare.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "chaos_cli.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
namespace {

struct PoincareFlags {
  BlockParams p;
  IntegratorOptions integ;
  IcFlags ic;
  double t_end = 500, t_min = 0;
  std::string direction = "both", csv, plot, json_out;
  bool json = false;
};

void run(const CLI::App& s, PoincareFlags& f) {
  validate(f.p);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  require_writable("csv", f.csv);
  const SimulationOptions so = orbit_run_options(f.t_end, f.integ);
  require_range("t-min", f.t_min, 0.0, f.t_end);
  const BlockStateVec z0 = ic_state(s, f.ic, f.p);
  const CrossingDirection dir = f.direction == "positive"   ? CrossingDirection::Positive
                                : f.direction == "negative" ? CrossingDirection::Negative
                                                            : CrossingDirection::Both;
  PoincareCollector col(f.p, dir, f.t_min);
  const SimulationResult r = simulate(f.p, {}, z0, so, &col);
  const auto& pts = col.points();

  std::string csv = f.csv;
  const bool temp = csv.empty() && !f.plot.empty();
  if (temp) csv = temp_path("poincare", ".csv");
  if (!csv.empty()) {
    AtomicFile file(csv);
    write_poincare_csv(file.stream(), pts);
    file.commit();
  }
  if (!f.plot.empty()) {
    char title[256];
    std::snprintf(title, sizeof title, "Poincare map w=0: r=%g k=%g mu=%g %s, t<=%g", f.p.r, f.p.k, f.p.mu,
                  f.ic.ic.c_str(), r.t_final);
    run_python("plot_poincare.py", {csv, f.plot, title});
    if (temp) std::remove(csv.c_str());
  }
  double max_w = 0, e_lo = INFINITY, e_hi = -INFINITY;
  for (const auto& q : pts) {
    max_w = std::max(max_w, std::fabs(q.w));
    e_lo = std::min(e_lo, q.energy);
    e_hi = std::max(e_hi, q.energy);
  }
  nlohmann::ordered_json j = summary_head(f.p, f.integ, f.ic, z0);
  j["options"] = {{"t_end", f.t_end}, {"t_min", f.t_min}, {"direction", f.direction}};
  j["status"] = to_string(r.status);
  j["t_final"] = r.t_final;
  j["crossings"] = pts.size();
  j["ihor"] = r.ihor;
  j["max_abs_w_at_crossings"] = max_w;
  j["energy_at_crossings"] = {{"min", pts.empty() ? NAN : e_lo}, {"max", pts.empty() ? NAN : e_hi}};
  j["energy_initial"] = r.initial_energy.total();
  j["max_abs_energy_balance_error"] = r.max_abs_energy_error;
  if (!emit_summary(j, f.json, f.json_out)) {
    std::printf("%zu crossings of w = 0 up to t = %.6g (status %s); max |w| there %.3g\n", pts.size(), r.t_final,
                to_string(r.status), max_w);
  }
}

void add(CLI::App& app) {
  auto f = std::make_shared<PoincareFlags>();
  CLI::App* s = app.add_subcommand("poincare", "Poincare section w = 0: crossing states (y, y', w', x, x') and plots");
  add_orbit_options(*s, f->p, f->integ, f->ic);
  s->add_option("--t-end", f->t_end, "final time (> 0)")->capture_default_str();
  s->add_option("--t-min", f->t_min, "record crossings from this time on (drop a transient)")->capture_default_str();
  s->add_option("--direction", f->direction, "crossings to keep: both, positive (w' > 0), negative")
      ->check(CLI::IsMember({"both", "positive", "negative"}))
      ->capture_default_str();
  s->add_option("--csv", f->csv, "write the crossings CSV here");
  add_summary_options(*s, f->plot, "plot the (y, y') and (y, w') projections (PNG + SVG)", f->json, f->json_out);
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(51, add);

}  // namespace
}  // namespace blockdyn::cli
