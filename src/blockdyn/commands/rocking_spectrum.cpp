// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/rocking_spectrum.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include "blockdyn/analysis/forced/forced_model.hpp"
#include "blockdyn/analysis/forced/rocking_spectrum.hpp"
#include "blockdyn/analysis/sweep/grid_table.hpp"
#include "blockdyn/base/number_text.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/motion_info.hpp"
#include "blockdyn/family/family.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/model/rigid_ground/rigid_params.hpp"
#include "blockdyn/simulation/rigid_ground_model.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

std::vector<StudyOption> rocking_spectrum_options() {
  return {{"model", "housner (default), rigid (3 DOF, Coulomb friction) or rigid3d (a box in space)", "housner"},
          {"record", "the ground motion: PEER .AT2 (g) or CSV 't, a' (s, g)"},
          {"suite",
           "rigid3d: a directory written by `motion generate` (one to three components: h1 along `incidence`, h2 "
           "across it, v vertical), instead of `record`"},
          {"incidence", "rigid3d: h1's direction from the box's width axis, degrees: one angle, A:B:N or a list", "0"},
          {"depth-ratio", "rigid3d: the box's depth over its width (its width b = 2 R sin alpha)", "1"},
          {"scale", "factor on the record", "1"},
          {"scales", "record scale factors, comma separated (a second axis; instead of `scale`)", "", false, true},
          {"alpha", "slenderness angle alpha = atan(b/h) [rad], in (0, pi/4]"},
          {"p-values", "frequency parameters p = sqrt(3 g / (4 R)) [rad/s], comma separated", "", false, true},
          {"p-min", "smallest p of a geometric range [rad/s]"},
          {"p-max", "largest p [rad/s]"},
          {"p-points", "number of p values"},
          {"t-end", "duration of every run [s] (default: the record's end + `t-after`)"},
          {"t-after", "simulated time after the record's end [s]", "5"},
          {"mass", "block mass [kg]", "1"},
          {"g", "gravity [m/s^2]", "9.81"},
          {"restitution", "housner: rocking restitution (default Housner's); rigid, rigid3d: Newton's e_n"},
          {"mu-s", "rigid: static friction", "0.7"},
          {"mu-k", "rigid: kinetic friction (default mu-s)"},
          {"impact", "rigid: impact law housner or newton (rigid3d: newton, its default)", "housner"},
          {"threads", "worker threads (0: all cores)", "0"}};
}

}  // namespace

std::vector<double> rocking_p_values(const StudyOptions& o) {
  const bool list = o.given("p-values");
  const bool range = o.given("p-min") || o.given("p-max") || o.given("p-points");
  if (list == range)
    throw std::invalid_argument(list ? "give `p-values` or `p-min`/`p-max`/`p-points`, not both"
                                     : "give `p-values` P1,P2,... or `p-min` `p-max` `p-points`");
  std::vector<double> p;
  if (list) {
    p = o.numbers("p-values");
  } else {
    const double lo = o.given("p-min") ? o.number("p-min") : 0.0, hi = o.given("p-max") ? o.number("p-max") : 0.0;
    const long n = o.given("p-points") ? o.integer("p-points") : 0;
    require_in_range("p-min", lo, 0, 1e4, false);
    require_in_range("p-max", hi, lo, 1e4);
    require_in_range("p-points", double(n), 1, 100000);
    for (long i = 0; i < n; ++i) p.push_back(n == 1 ? lo : lo * std::pow(hi / lo, double(i) / double(n - 1)));
  }
  for (double x : p) require_in_range("p-values", x, 0, 1e4, false);
  return p;
}

namespace {

// The spectrum's points as the runner's table holds them.
std::vector<RockingSpectrumPoint> points_of(const Table& t) {
  const std::size_t cp = t.column("p"), cs = t.column("scale"), cr = t.column("max_abs_rotation_over_alpha"),
                    co = t.column("overturned"), ct = t.column("overturn_time");
  std::vector<RockingSpectrumPoint> pts;
  for (const TableRow& r : t.rows) {
    RockingSpectrumPoint pt;
    pt.p = r.cells[cp].number();
    pt.scale = r.cells[cs].number();
    pt.max_abs_rotation_over_alpha = r.cells[cr].number();
    pt.overturned = r.cells[co].integer() == 1;
    pt.overturn_time = r.cells[ct].optional_number();
    pts.push_back(pt);
  }
  return pts;
}

json rows_json(const std::vector<RockingSpectrumPoint>& pts) {
  json rows = json::array();
  for (const RockingSpectrumPoint& r : pts)
    rows.push_back({{"p", r.p},
                    {"scale", r.scale},
                    {"max_abs_rotation_over_alpha", r.max_abs_rotation_over_alpha},
                    {"overturned", r.overturned},
                    {"overturn_time", r.overturn_time ? json(*r.overturn_time) : json(nullptr)}});
  return rows;
}

json overturning_scales_json(const std::vector<OverturningScale>& s) {
  json j = json::array();
  for (const OverturningScale& x : s)
    j.push_back({{"p", x.p}, {"min_overturning_scale", x.scale ? json(*x.scale) : json(nullptr)}});
  return j;
}

GridStudy rocking_grid(const Settings& given, const std::string& output) {
  const StudyOptions so(given, rocking_spectrum_options());
  const std::string model = so.text("model");
  const Family& family = family_named(
      "model", model, [](const Family& f) { return f.rigid_ground != nullptr || (f.forced && f.forced->spatial); });
  if (!family.rigid_ground) return rocking_grid_3d(so, family, output);
  for (const char* n : {"suite", "incidence", "depth-ratio"})
    if (so.given(n))
      throw std::invalid_argument(std::string("`") + n + "` applies to a body in space (`model` rigid3d)");
  const RigidGroundModel& m = *family.rigid_ground;
  if (!so.given("alpha")) throw std::invalid_argument("alpha: give the slenderness angle [rad]");
  const double alpha = so.number("alpha");
  require_in_range("alpha", alpha, 0, M_PI / 4, false);
  if (so.given("scale") && so.given("scales")) throw std::invalid_argument("`scale` and `scales`: give only one");
  RockingSpectrumOptions ax;
  ax.alpha = alpha;
  ax.p = rocking_p_values(so);
  ax.scales = so.given("scales") ? so.numbers("scales") : std::vector<double>{so.number("scale")};
  for (double x : ax.scales) require_in_range("scales", x, 0, 1e3, false);
  const double t_after = so.number("t-after");
  require_in_range("t-after", t_after, 0, 1e4);
  RigidBlockParams base;
  base.shape.mass = so.number("mass");
  base.shape.g = so.number("g");
  // The block's size comes from g and p: each is checked as given, before any size is made of it.
  require_in_range("g", base.shape.g, 0, 1e3, false);
  require_in_range("mass", base.shape.mass, 0, 1e12, false);
  if (!m.friction)
    for (const char* n : {"mu-s", "mu-k", "impact"})
      if (so.given(n)) throw std::invalid_argument(std::string("`") + n + "` applies to `model` rigid only");
  base.interface.mu_s = so.number("mu-s");
  base.interface.mu_k = so.given("mu-k") ? so.number("mu-k") : base.interface.mu_s;
  const auto law = impact_law_from_string(so.text("impact"));
  if (!law) throw std::invalid_argument("impact = '" + so.text("impact") + "' is not one of: housner, newton");
  base.impact = *law;
  if (so.given("restitution")) base.restitution = so.number("restitution");
  const auto rec = record_from(given);
  if (so.given("t-end") && so.given("t-after")) throw std::invalid_argument("`t-end` and `t-after`: give only one");
  const double t_end = so.given("t-end") ? so.number("t-end") : rec->t_last() + t_after;
  require_in_range("t-end", t_end, 0, 1e5, false);
  ax.t_end = t_end;
  // Every block of the grid is checked before any point runs (a restitution out of range, ...).
  for (double p : ax.p) forced_block_model(block_of_slenderness(base, alpha, p), m);
  const ForcedModel first = forced_block_model(block_of_slenderness(base, alpha, ax.p.front()), m);
  const json definition = {{"model", model},
                           {"record", rec->source()},
                           {"record_digest", rec->digest()},
                           {"alpha", alpha},
                           {"p", ax.p},
                           {"scales", ax.scales},
                           {"t_end", t_end},
                           {"block", first.description},
                           {"index", "p fastest, then scale"}};
  GridStudy g;
  g.table = std::make_shared<const GridTable>(
      "rocking-spectrum",
      std::vector<std::string>{"p", "scale", "width", "height", "max_abs_rotation_over_alpha", "overturned",
                               "overturn_time"},
      ax.p.size() * ax.scales.size(),
      [ax, base, &m, rec](std::size_t i, CellRow& row) {
        const RockingSpectrumPoint pt = rocking_spectrum_point(m, base, ax, rec, i);
        row.emplace_back(pt.p);
        row.emplace_back(pt.scale);
        row.emplace_back(pt.width);
        row.emplace_back(pt.height);
        row.emplace_back(pt.max_abs_rotation_over_alpha);
        row.emplace_back(pt.overturned ? 1 : 0);
        if (pt.overturn_time)
          row.emplace_back(*pt.overturn_time);
        else
          row.emplace_back();
      },
      definition, first.tolerances, output);
  g.threads = so.threads();
  g.finish = [ax, definition, alpha](const Table& t) {
    StudyReport rep;
    json& j = rep.summary;
    j["run"] = run_info();
    j["definition"] = definition;
    j["units"] = "p in rad/s, times in s, rotations over alpha";
    const std::vector<RockingSpectrumPoint> pts = points_of(t);
    j["rows"] = rows_json(pts);
    if (ax.scales.size() > 1) j["overturning_scales"] = overturning_scales_json(overturning_scales(pts, ax));
    std::size_t n_over = 0;
    for (const json& x : j["rows"]) n_over += x["overturned"].get<bool>();
    std::string record = definition.at("record").get<std::string>();
    record = record.substr(record.find_last_of('/') + 1);  // npos + 1 = 0: the whole name
    rep.figure = FigureSpec{"rocking_spectrum",
                            {"@csv:table", "@plot"},
                            {{"alpha", {format_double(alpha)}},
                             {"title",
                              {definition.at("model").get<std::string>() +
                               " blocks of alpha = " + number_text(alpha, 4) + " rad under " + record}}}};
    append_text(rep.text, "rocking spectrum: %zu points, %zu overturned", j["rows"].size(), n_over);
    return rep;
  };
  return g;
}

}  // namespace

GridStudyCommand rocking_spectrum_command() {
  return {"rocking-spectrum",
          "rocking spectrum of a record: the largest rotation over alpha and overturning versus the block's frequency "
          "parameter p (size), for one slenderness, optionally over record scales (threads, MPI, resumable)",
          16,
          rocking_spectrum_options(),
          rocking_grid,
          "out",
          "the points as CSV (the runner's table: journal and sidecar .json beside it)",
          {{"plot", "plot theta_max / alpha versus p, overturning marked (PNG + SVG)"}},
          "no summary line, no progress"};
}

}  // namespace blockdyn
