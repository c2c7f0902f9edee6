// SPDX-License-Identifier: Apache-2.0
// `blockdyn response-curve`: the largest rotation theta_MAX / alpha (and, for assemblies, the
// largest slip between blocks over the block width) versus omega = Omega / p for several
// amplitudes beta, under a_H = beta alpha g cos(Omega t + phase) (seed 001 Figs. 4-7, seed 002
// Figs. 3, 10-11), over a transient window (--t-end) or a number of forcing periods; or, for
// assemblies, versus the friction angle between blocks phi_l (seed 002 Figs. 4-5). The points
// run on the sweep runner (threads, MPI, journal, resume, progress).
#include <cstdio>
#include <memory>

#include "blockdyn/analysis/forced/survival_table.hpp"
#include "blockdyn/analysis/sweep/sweep_axis.hpp"
#include "blockdyn/io/json_io.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "forced_model.hpp"
#include "grid_run.hpp"

namespace blockdyn::cli {
namespace {

struct CurveFlags {
  SurvivalOptions o;
  GridRunFlags g;
  double omega = 0;
  std::string phi_s_values, phi_l_values;
  std::string out, plot, json_out, progress = "auto";
  bool json = false, quiet = false;
};

// A friction-angle axis (deg, in (0, 90]) from --phi-X-values, or the single --phi-X value.
std::vector<double> phi_axis(const CLI::App& s, const std::string& name, const std::string& spec, double single) {
  const std::string flag = "--" + name + "-values";
  if (!given(s, flag)) return {single};
  if (given(s, "--" + name)) throw UsageError(flag + " and --" + name + ": give only one");
  try {
    SweepAxis a = parse_axis(name + "-values", spec, AxisSpacing::Linear);
    for (double v : a.values)
      if (!(v > 0 && v <= 90)) throw std::invalid_argument(name + "-values: each angle must be in (0, 90] deg");
    return a.values;
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

void plot_curve(const CurveFlags& f, const ForcedModelChoice& m, const SurvivalOptions& o, const std::string& csv,
                const std::vector<double>& phi_s, const std::vector<double>& phi_l, bool versus_phi) {
  std::string title = m.label() + ", " + o.excitation + (versus_phi ? ", omega = " + short_number(o.omega_min) : "");
  if (m.assembly()) {
    title += ", " + m.contact + " law" + (m.columns_rock_only ? " (columns only rock)" : "");
    if (phi_s.size() == 1) title += ", phi_s = " + short_number(phi_s[0]);
    if (phi_l.size() == 1) title += ", phi_l = " + short_number(phi_l[0]);
  }
  run_python("plot_response_curve.py", {csv, f.plot, "--title", title, "--x", versus_phi ? "phi_l" : "omega"});
}

// The amplitudes and frequencies: --betas, and --omega (one frequency) or the omega range.
SurvivalOptions curve_options(const CLI::App& s, const CurveFlags& f) {
  SurvivalOptions o = f.o;
  if (o.betas.empty()) throw UsageError("--betas B1,B2,... is needed (the amplitudes, in units of alpha g)");
  o.beta_points = int(o.betas.size());
  if (given(s, "--omega")) {
    for (const char* n : {"--omega-min", "--omega-max", "--omega-points"})
      if (given(s, n)) throw UsageError(std::string("--omega and ") + n + ": give one frequency or a range");
    require_range("omega", f.omega, 0, 1e4, false);
    o.omega_min = o.omega_max = f.omega;
    o.omega_points = 1;
  }
  require_range("threads", o.threads, 0, 1024);
  if (given(s, "--t-end") && given(s, "--periods")) throw UsageError("give --t-end or --periods, not both");
  try {
    validate(o);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return o;
}

// One model per friction pair (phi_s outer), built before any point runs.
std::vector<ForcedModel> friction_models(const CLI::App& s, bool assembly, const std::vector<double>& phi_s,
                                         const std::vector<double>& phi_l) {
  std::vector<ForcedModel> models;
  const Settings given_flags = settings_of(s);
  for (double ps : phi_s)
    for (double pl : phi_l) {
      Settings m = given_flags;
      if (assembly) {
        m.set("phi-s", Settings::exact(ps));
        m.set("phi-l", Settings::exact(pl));
      }
      models.push_back(forced_model_from(m));
    }
  return models;
}

void run(const CLI::App& s, const CurveFlags& f) {
  const SurvivalOptions o = curve_options(s, f);
  const bool friction_axes = given(s, "--phi-s-values") || given(s, "--phi-l-values");
  const ForcedModelChoice choice = forced_model_choice(s);
  if (friction_axes && !choice.assembly())
    throw UsageError("phi-s-values, phi-l-values: friction angles belong to --model assembly");
  const std::vector<double> phi_s = phi_axis(s, "phi-s", f.phi_s_values, choice.phi_s);
  const std::vector<double> phi_l = phi_axis(s, "phi-l", f.phi_l_values, choice.phi_l);
  const bool versus_phi = phi_l.size() > 1;
  if (versus_phi && o.omega_points > 1)
    throw UsageError("omega: give one frequency (--omega W) for a curve versus phi-l");
  const GridOutput out("--out", f.out, "response-curve", f.g, f.json_out);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  const std::vector<ForcedModel> models = friction_models(s, choice.assembly(), phi_s, phi_l);
  const ForcedModel& fm = models.front();
  const bool assembly = choice.assembly();
  const std::size_t nw = std::size_t(o.omega_points), nl = phi_l.size(), ns = phi_s.size(), nb = o.betas.size();

  using json = nlohmann::ordered_json;
  const json options = {{"excitation", o.excitation},
                        {"phase", o.phase},
                        {"t_end", o.periods > 0 ? json(nullptr) : json(o.t_end)},
                        {"periods", o.periods},
                        {"versus", versus_phi ? "phi_l" : "omega"}};
  json model = fm.description;
  if (assembly) {
    model["phi_s"] = phi_s;
    model["phi_l"] = phi_l;
  }
  const json definition = {
      {"model", model},     {"alpha", fm.alpha},
      {"p", fm.p},          {"width", fm.width},
      {"betas", o.betas},   {"omega", {{"min", o.omega_min}, {"max", o.omega_max}, {"points", o.omega_points}}},
      {"options", options}, {"index", "i_omega + n_omega * (i_phi_l + n_phi_l * (i_phi_s + n_phi_s * i_beta))"}};
  std::vector<std::string> cols = survival_columns();
  for (const char* c : {"phi_s", "phi_l", "theta_max_over_alpha", "max_sliding_over_b"}) cols.push_back(c);
  const GridTable table(
      "response-curve", cols, nw * nl * ns * nb,
      [&](std::size_t i, RowBuilder& row) {
        const std::size_t iw = i % nw, il = (i / nw) % nl, is = (i / (nw * nl)) % ns, ib = i / (nw * nl * ns);
        const ForcedModel& m = models[is * nl + il];
        const double omega = grid_value(o.omega_min, o.omega_max, o.omega_points, int(iw));
        const SurvivalPoint p = survival_point(m.run, o, m.alpha, m.p, o.betas[ib], omega);
        add_survival_cells(p, row);
        if (assembly) {
          row.add(phi_s[is]);
          row.add(phi_l[il]);
        } else {
          row.empty();
          row.empty();
        }
        row.add(p.max_abs_rotation / m.alpha);
        row.add(p.max_sliding / m.width);
      },
      definition, fm.tolerances, out.csv());
  const GridRunResult res = run_grid(table, f.g, o.threads, f.progress, f.quiet);
  if (!res.root) return;

  const Table t = read_table(out.csv(), table.header());
  json j;
  j["run"] = run_info();
  j["model"] = model;
  j["alpha"] = fm.alpha;
  j["p"] = fm.p;
  j["width"] = fm.width;
  j["units"] =
      "a_H = beta alpha g cos(omega p t + phase); rotations over alpha, slips over the block width; "
      "friction angles in deg";
  j["options"] = options;
  j["tolerances"] = fm.tolerances;
  j["points"] = response_curve_points(t, assembly);
  if (!f.plot.empty()) plot_curve(f, choice, o, out.csv(), phi_s, phi_l, versus_phi);
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json) emit_json(j, "-");
  if (!f.json && !f.quiet) std::printf("%zu points %s\n", t.rows.size(), grid_run_note(res).c_str());
}

void add(CLI::App& app) {
  auto f = std::make_shared<CurveFlags>();
  CLI::App* s = app.add_subcommand("response-curve",
                                   "largest rotation theta_MAX / alpha (and slip between blocks / b) versus omega = "
                                   "Omega/p for several beta, or versus the friction angle phi_l, under a_H = beta "
                                   "alpha g cos(Omega t + phase) (threads, MPI, resumable)");
  add_forced_model_flags(*s);
  s->add_option("--betas", f->o.betas, "amplitudes beta, comma separated (a_H = beta alpha g ...)")->delimiter(',');
  add_excitation_grid_flags(*s, f->o);
  s->add_option("--omega", f->omega, "one frequency omega = Omega/p (instead of --omega-min/max/points)");
  s->add_option("--phi-l-values", f->phi_l_values,
                "assembly: friction angles between blocks [deg], \"v1,v2,...\" or \"min:max:points\"; more than one "
                "makes phi_l the curve's abscissa (seed 002 Figs. 4-5; needs one --omega)");
  s->add_option("--phi-s-values", f->phi_s_values,
                "assembly: friction angles on the ground [deg], \"v1,v2,...\" or \"min:max:points\" (one curve each)");
  s->add_option("--out", f->out, "the points as CSV (the runner's table: journal and sidecar .json beside it)");
  s->add_option("--plot", f->plot,
                "plot theta_MAX / alpha (and the slip) versus omega or phi_l, one curve per beta "
                "and phi_s (PNG + SVG)");
  add_grid_report_flags(*s, f->g, f->json, f->json_out, f->progress, f->quiet, "no summary line, no progress");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(15, add, MpiUse::Distributes);

}  // namespace
}  // namespace blockdyn::cli
