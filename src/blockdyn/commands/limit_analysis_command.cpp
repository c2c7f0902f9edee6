// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/limit_analysis_command.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "blockdyn/analysis/masonry/limit_analysis.hpp"
#include "blockdyn/commands/assembly_settings.hpp"
#include "blockdyn/io/assembly_json.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/model/assembly/interface_faces.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

json xy(const Vec2& v) { return json::array({v.x, v.y}); }

json assembly_geometry_json(const Assembly& a) {
  json blocks = json::array();
  for (std::size_t b = 0; b < a.blocks.size(); ++b) {
    const AssemblyBlock& k = a.blocks[b];
    json outline = json::array();
    for (const Vec2& v : initial_outline(k)) outline.push_back(xy(v));
    blocks.push_back({{"block", b}, {"name", k.name}, {"mass", k.mass}, {"centre", {k.x, k.y}}, {"outline", outline}});
  }
  json ifs = json::array();
  for (std::size_t j = 0; j < a.interfaces.size(); ++j) {
    const AssemblyInterface& f = a.interfaces[j];
    ifs.push_back({{"interface", j},
                   {"lower", f.lower < 0 ? json("ground") : json(f.lower)},
                   {"upper", f.upper},
                   {"mu", f.law.mu_s >= kNoSlipFriction ? json(nullptr) : json(f.law.mu_s)}});
  }
  return {{"preset", a.preset}, {"g", a.g}, {"blocks", blocks}, {"interfaces", ifs}};
}

json analysis_json(const Assembly& a, const LimitAnalysis& r) {
  json j;
  j["direction"] = r.direction;
  j["status"] = r.status;
  j["lambda"] = r.status == "unstable" && r.mechanism.empty() ? json(nullptr) : json(r.lambda);
  j["a_h"] = j["lambda"].is_null() ? json(nullptr) : json(r.direction * r.lambda * a.g);
  j["sliding"] = r.sliding;
  j["exact_for_non_associative"] = r.exact_for_non_associative;
  json blocks = json::array();
  for (std::size_t b = 0; b * 3 < r.mechanism.size(); ++b)
    blocks.push_back(
        {{"block", b}, {"vx", r.mechanism[3 * b]}, {"vy", r.mechanism[3 * b + 1]}, {"omega", r.mechanism[3 * b + 2]}});
  json ifs = json::array();
  for (std::size_t i = 0; i < r.interfaces.size(); ++i) {
    const InterfaceMotion& m = r.interfaces[i];
    ifs.push_back({{"interface", i},
                   {"state", m.state},
                   {"hinge_end", m.hinge_end >= 0 ? json(m.hinge_end) : json(nullptr)},
                   {"normal_rates", {m.normal_rate[0], m.normal_rate[1]}},
                   {"slip_rate", m.slip_rate}});
  }
  j["mechanism"] = {{"blocks", blocks}, {"interfaces", ifs}};
  json thrust = json::array();
  for (std::size_t i = 0; i < r.thrust.size(); ++i) {
    const InterfaceThrust& t = r.thrust[i];
    thrust.push_back({{"interface", i},
                      {"normal", {t.normal[0], t.normal[1]}},
                      {"tangential", t.tangential},
                      {"points", {xy(t.point[0]), xy(t.point[1])}},
                      {"centre", t.bears ? xy(t.centre) : json(nullptr)},
                      {"eccentricity", t.bears ? json(t.eccentricity) : json(nullptr)}});
  }
  j["thrust"] = thrust;
  return j;
}

}  // namespace

const std::vector<StudyOption>& limit_analysis_options() {
  static const std::vector<StudyOption> options = {
      {"preset", "block, trilith, column or arch (or give an assembly FILE.toml)"},
      {"slenderness", "block/trilith/column: height / width (default 4)"},
      {"block-width", "block/trilith/column: width [m] (default 0.12)"},
      {"drums", "column: number of drums (default 4)"},
      {"lintel-length", "trilith: lintel length [m] (default: column height)"},
      {"overhang", "trilith: lintel beyond each column's outer face [m] (default 0)"},
      {"voussoirs", "arch: number of equal voussoirs (default 9)"},
      {"thickness-ratio", "arch: ring thickness / centreline radius, in (0, 2) (default 0.15)"},
      {"radius", "arch: centreline radius [m] (default 1)"},
      {"embrace", "arch: angle the arch spans [deg], in (0, 180] (default 180)"},
      {"thickness", "out-of-plane depth [m] (default 0.06)"},
      {"density", "density [kg/m^3] (default 2700)"},
      {"phi-s", "friction angle on the ground [deg] (90: no sliding; default 90)"},
      {"phi-l", "friction angle between blocks [deg] (default 90)"},
      {"g", "gravity [m/s^2] (lambda is a_H / g; default 9.81)"},
      {"direction", "1: a_H > 0 (inertial load towards -x), -1: a_H < 0", "1"},
      {"min-thickness", "arch: also the thinnest arch that stands under its own weight (min_thickness_ratio)", "",
       true},
      {"tolerance", "min-thickness: bisection tolerance on thickness / radius", "1e-7"}};
  return options;
}

json limit_analysis_run(const Settings& given) {
  given.require_known(limit_analysis_options(), {"file"}, "limit-analysis");
  const auto start = std::chrono::steady_clock::now();
  const long direction = given.integer("direction", 1);
  if (direction != 1 && direction != -1)
    throw std::invalid_argument("direction = " + std::to_string(direction) + " must be 1 or -1");
  Settings s;
  for (const std::string& n : given.names())
    if (n != "direction" && n != "min-thickness" && n != "tolerance")
      for (const std::string& v : given.values(n)) s.add(n, v);
  s.add("contact", "rigid");  // no settlement: the blocks as drawn
  const Assembly a = assembly_geometry_from(s, kMaxStaticBlocks);
  const LimitAnalysis r = limit_analysis(a, int(direction));
  json j;
  j["schema"] = "blockdyn.limit-analysis/1";
  j["run"] = run_info();
  j["units"] = "SI (m, kg, N); lambda = a_H / g, a_H the constant horizontal ground acceleration";
  j["assembly"] = assembly_geometry_json(a);
  j["friction"] =
      "associative Coulomb (the linear programme's pyramid |T| <= mu N per interface; sliding dilates): exact for "
      "mechanisms without sliding, an upper estimate for non-associative friction when the mechanism slides";
  j["solver"] = {{"lp",
                  "GLPK's floating-point simplex; its optimal basis solved again in double precision and certified "
                  "(primal and dual feasible to 1e-9), else GLPK's exact (rational) simplex from it"}};
  j.update(analysis_json(a, r));
  if (given.flag("min-thickness")) {
    if (a.preset != "arch") throw std::invalid_argument("`min-thickness` needs `preset` arch");
    const double tol = given.number("tolerance", 1e-7);
    if (!(tol >= 1e-9 && tol <= 1e-2))
      throw std::invalid_argument("tolerance = " + Settings::exact(tol) + " must be in [1e-9, 1e-2]");
    const PresetOptions geometry = preset_geometry_from(s, "arch");
    const MinThickness m = min_thickness_ratio(geometry, tol);
    j["min_thickness_ratio"] = m.ratio;
    j["min_thickness"] = {{"ratio", m.ratio},
                          {"thickness_m", m.ratio * geometry.radius},
                          {"tolerance", tol},
                          {"evaluations", m.evaluations},
                          {"voussoirs", geometry.voussoirs},
                          {"embrace_deg", geometry.embrace},
                          {"assembly", assembly_geometry_json(m.arch)},
                          {"analysis", analysis_json(m.arch, m.at_minimum)}};
  } else if (given.has("tolerance")) {
    throw std::invalid_argument("`tolerance` belongs to `min-thickness`");
  }
  j["timing_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return j;
}

std::string limit_analysis_text(const json& j) {
  std::string out;
  char buf[512];
  const auto& a = j["assembly"];
  std::snprintf(buf, sizeof buf, "limit-analysis: %s, %zu blocks, %zu interfaces, direction %+d\n",
                a["preset"].get<std::string>().c_str(), a["blocks"].size(), a["interfaces"].size(),
                j["direction"].get<int>());
  out += buf;
  if (j["lambda"].is_null()) {
    out += "status unstable: no distribution of contact forces holds the blocks under their own weight\n";
  } else {
    std::snprintf(
        buf, sizeof buf, "lambda = %.10g (a_H = %.6g m/s^2), status %s%s\n", j["lambda"].get<double>(),
        j["a_h"].get<double>(), j["status"].get<std::string>().c_str(),
        j["sliding"].get<bool>() ? " (the mechanism slides: an upper estimate for non-associative friction)" : "");
    out += buf;
    for (const auto& m : j["mechanism"]["interfaces"]) {
      const std::string st = m["state"].get<std::string>();
      if (st == "closed") continue;
      std::snprintf(buf, sizeof buf, "  interface %d: %s%s\n", m["interface"].get<int>(), st.c_str(),
                    st == "hinge" ? (m["hinge_end"].get<int>() == 0 ? " at end 0" : " at end 1") : "");
      out += buf;
    }
  }
  if (j.contains("min_thickness_ratio")) {
    std::snprintf(buf, sizeof buf, "min_thickness_ratio = %.8g (%d voussoirs, embrace %.6g deg; %d analyses)\n",
                  j["min_thickness_ratio"].get<double>(), j["min_thickness"]["voussoirs"].get<int>(),
                  j["min_thickness"]["embrace_deg"].get<double>(), j["min_thickness"]["evaluations"].get<int>());
    out += buf;
  }
  return out;
}

}  // namespace blockdyn
