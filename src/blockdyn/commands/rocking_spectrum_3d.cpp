// SPDX-License-Identifier: Apache-2.0
// `blockdyn rocking-spectrum --model rigid3d`: the spectrum of a box in space over a suite of one-
// to three-component records and incidences (analysis/forced/rocking_spectrum_3d.hpp), on the
// sweep runner, with the critical incidence.
#include <cmath>
#include <memory>
#include <stdexcept>

#include "blockdyn/analysis/forced/rocking_spectrum_3d.hpp"
#include "blockdyn/analysis/sweep/grid_table.hpp"
#include "blockdyn/base/number_text.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/forced_model_settings.hpp"
#include "blockdyn/commands/motion_info.hpp"
#include "blockdyn/commands/record_suite.hpp"
#include "blockdyn/commands/rocking_spectrum.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

namespace {

ComponentRecords spectrum_records(const StudyOptions& so) {
  if (so.given("suite") && so.given("record")) throw std::invalid_argument("`suite` and `record`: give one of them");
  ComponentRecords r;
  if (!so.given("suite")) {
    r.h1.push_back(record_from(so.given_settings()));
    r.names.push_back(r.h1.back()->source());
    return r;
  }
  const SuiteRecords files = suite_records(so.text("suite"));
  auto load = [](const std::string& f) { return std::make_shared<const Accelerogram>(load_accelerogram(f, "suite")); };
  for (const std::string& f : files.h1) {
    r.h1.push_back(load(f));
    r.names.push_back(f.substr(f.find_last_of('/') + 1));
  }
  for (const std::string& f : files.h2) r.h2.push_back(load(f));
  for (const std::string& f : files.v) r.v.push_back(load(f));
  return r;
}

// The family's model of a box of the given size, with the body options given (mass, g, friction,
// impact law).
SpatialModelAt spatial_model(const StudyOptions& so, const Family& family) {
  Settings base;
  base.add("model", family.name);
  for (const char* n : {"mass", "g", "mu-s", "mu-k", "impact", "restitution"})
    if (so.given(n)) base.add(n, so.text(n));
  return [base](const BoxSize& s) {
    Settings m = base;
    m.set("width", format_double(s.width));
    m.set("depth", format_double(s.depth));
    m.set("height", format_double(s.height));
    return forced_model_from(m);
  };
}

json point_json(const RockingSpectrum3dPoint& pt, const ComponentRecords& rec) {
  return {{"p", pt.p},
          {"scale", pt.scale},
          {"incidence", pt.incidence},
          {"record", rec.names[pt.record]},
          {"max_abs_rotation_over_alpha", pt.max_tilt_over_alpha},
          {"overturned", pt.overturned},
          {"outside_model", pt.outside_model},
          {"overturn_time", pt.overturn_time ? json(*pt.overturn_time) : json(nullptr)}};
}

json incidence_json(const CriticalIncidence& c) {
  return {{"incidence", c.incidence},
          {"runs", c.runs},
          {"n_overturned", c.overturned},
          {"n_outside_model", c.outside_model},
          {"median_max_abs_rotation_over_alpha", finite_or_null(c.median_tilt_over_alpha)}};
}

std::vector<RockingSpectrum3dPoint> points_of_3d(const Table& t, const RockingSpectrum3dOptions& o) {
  const std::size_t cr = t.column("max_abs_rotation_over_alpha"), co = t.column("overturned"),
                    cm = t.column("outside_model"), ct = t.column("overturn_time");
  std::vector<RockingSpectrum3dPoint> pts;
  const std::size_t np = o.p.size(), ns = o.scales.size(), na = o.incidences.size();
  for (const TableRow& r : t.rows) {
    RockingSpectrum3dPoint pt;
    pt.p = o.p[r.index % np];
    pt.scale = o.scales[(r.index / np) % ns];
    pt.incidence = o.incidences[(r.index / (np * ns)) % na];
    pt.record = r.index / (np * ns * na);
    pt.max_tilt_over_alpha = r.cells[cr].number();
    pt.overturned = r.cells[co].integer() == 1;
    pt.outside_model = r.cells[cm].integer() == 1;
    pt.overturn_time = r.cells[ct].optional_number();
    pts.push_back(pt);
  }
  return pts;
}

StudyReport spectrum_3d_report(const Table& t, const RockingSpectrum3dOptions& o, const ComponentRecords& rec,
                               const json& definition) {
  StudyReport rep;
  json& j = rep.summary;
  j["run"] = run_info();
  j["definition"] = definition;
  j["units"] = "p in rad/s, times in s, incidences in degrees, the largest tilt over alpha";
  const std::vector<RockingSpectrum3dPoint> pts = points_of_3d(t, o);
  json rows = json::array();
  for (const RockingSpectrum3dPoint& pt : pts) rows.push_back(point_json(pt, rec));
  j["rows"] = rows;
  const std::vector<CriticalIncidence> all = incidence_summary(pts, o);
  json inc = json::array();
  for (const CriticalIncidence& c : all) inc.push_back(incidence_json(c));
  j["incidences"] = inc;
  j["critical_incidence"] = critical_of(all).incidence;
  json by_p = json::array();
  for (double p : o.p)
    for (double s : o.scales) {
      std::vector<RockingSpectrum3dPoint> at;
      for (const RockingSpectrum3dPoint& pt : pts)
        if (pt.p == p && pt.scale == s) at.push_back(pt);
      json c = incidence_json(critical_of(incidence_summary(at, o)));
      by_p.push_back({{"p", p}, {"scale", s}, {"critical", c}});
    }
  j["critical_incidence_by_p"] = by_p;
  std::size_t over = 0, outside = 0;
  for (const RockingSpectrum3dPoint& pt : pts) over += pt.overturned, outside += pt.outside_model;
  append_text(rep.text,
              "rocking spectrum (3D): %zu runs, %zu overturned, %zu outside the model; critical incidence %s deg",
              pts.size(), over, outside, number_text(j["critical_incidence"].get<double>(), 6).c_str());
  return rep;
}

}  // namespace

GridStudy rocking_grid_3d(const StudyOptions& so, const Family& family, const std::string& output) {
  if (!so.given("alpha")) throw std::invalid_argument("alpha: give the slenderness angle [rad]");
  RockingSpectrum3dOptions o;
  o.alpha = so.number("alpha");
  require_in_range("alpha", o.alpha, 0, M_PI / 4, false);
  o.p = rocking_p_values(so);
  if (so.given("scale") && so.given("scales")) throw std::invalid_argument("`scale` and `scales`: give only one");
  o.scales = so.given("scales") ? so.numbers("scales") : std::vector<double>{so.number("scale")};
  for (double x : o.scales) require_in_range("scales", x, 0, 1e3, false);
  o.incidences = incidences_of(so.given_settings());
  o.depth_ratio = so.number("depth-ratio");
  require_in_range("depth-ratio", o.depth_ratio, 0, 100, false);
  o.g = so.number("g");
  require_in_range("g", o.g, 0, 1e3, false);
  if (so.given("t-end") && so.given("t-after")) throw std::invalid_argument("`t-end` and `t-after`: give only one");
  if (so.given("t-end")) o.t_end = so.number("t-end");
  o.t_after = so.number("t-after");
  require_in_range("t-after", o.t_after, 0, 1e4);
  if (o.t_end) require_in_range("t-end", *o.t_end, 0, 1e5, false);
  const auto rec = std::make_shared<const ComponentRecords>(spectrum_records(so));
  const SpatialModelAt model = spatial_model(so, family);
  // Every body of the spectrum is checked before any point runs.
  for (double p : o.p) model(box_of_slenderness(o.alpha, p, o.depth_ratio, o.g));
  const ForcedModel first = model(box_of_slenderness(o.alpha, o.p.front(), o.depth_ratio, o.g));
  json records = json::array();
  for (std::size_t k = 0; k < rec->size(); ++k)
    records.push_back({{"name", rec->names[k]}, {"digest", rec->h1[k]->digest()}});
  const json definition = {{"model", family.name},
                           {"records", records},
                           {"components", rec->h2.empty() ? (rec->v.empty() ? 1 : 2) : (rec->v.empty() ? 2 : 3)},
                           {"alpha", o.alpha},
                           {"p", o.p},
                           {"scales", o.scales},
                           {"incidences", o.incidences},
                           {"depth_ratio", o.depth_ratio},
                           {"t_end", o.t_end ? json(*o.t_end) : json(nullptr)},
                           {"t_after", o.t_end ? json(nullptr) : json(o.t_after)},
                           {"body", first.description},
                           {"index", "p fastest, then scale, incidence, record"}};
  GridStudy g;
  g.table = std::make_shared<const GridTable>(
      "rocking-spectrum",
      std::vector<std::string>{"p", "scale", "incidence", "record", "width", "depth", "height",
                               "max_abs_rotation_over_alpha", "overturned", "outside_model", "overturn_time"},
      o.size(*rec),
      [o, rec, model](std::size_t i, CellRow& row) {
        const RockingSpectrum3dPoint pt = rocking_spectrum_3d_point(model, o, *rec, i);
        row.insert(row.end(), {pt.p, pt.scale, pt.incidence, rec->names[pt.record], pt.size.width, pt.size.depth,
                               pt.size.height, pt.max_tilt_over_alpha, pt.overturned ? 1 : 0, pt.outside_model ? 1 : 0,
                               Cell::maybe(pt.overturn_time)});
      },
      definition, first.tolerances, output);
  g.threads = so.threads();
  g.finish = [o, rec, definition](const Table& t) { return spectrum_3d_report(t, o, *rec, definition); };
  return g;
}

}  // namespace blockdyn
