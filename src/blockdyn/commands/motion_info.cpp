// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/motion_info.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <utility>

#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/study_command.hpp"
#include "blockdyn/excitation/intensity_measures.hpp"
#include "blockdyn/excitation/response_spectrum.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

// --periods, else a logarithmic grid from --period-min to --period-max.
std::vector<double> periods_of(const Settings& s) {
  const bool grid = s.has("period-min") || s.has("period-max") || s.has("period-points");
  if (s.has("periods") && grid) throw std::invalid_argument("`periods` and `period-min`/max/points: give one of them");
  std::vector<double> p;
  if (s.has("periods")) {
    for (const std::string& v : s.values("periods"))
      for (double x : parse_number_list("periods", v)) p.push_back(x);
  } else {
    const double lo = s.number("period-min", 0.02), hi = s.number("period-max", 5.0);
    const long n = s.integer("period-points", 60);
    require_in_range("period-min", lo, 0.0, 1e4, false);
    require_in_range("period-max", hi, lo, 1e4);
    if (n < 1 || n > 100000)
      throw std::invalid_argument("period-points = " + std::to_string(n) + " is out of range: must be in [1, 100000]");
    for (long i = 0; i < n; ++i) p.push_back(n == 1 ? lo : lo * std::pow(hi / lo, double(i) / double(n - 1)));
  }
  if (p.empty() || p.size() > 100000) throw std::invalid_argument("periods: give 1 to 100000 periods");
  for (double x : p) require_in_range("periods", x, 0.0, 1e4, false);
  return p;
}

}  // namespace

const std::vector<StudyOption>& motion_info_options() {
  static const std::vector<StudyOption> options = {
      {"spectrum", "also the pseudo-acceleration spectrum Sa(T) (g) of a damped linear oscillator", "", true},
      {"periods", "the spectrum's periods (s), e.g. 0.1,0.2,0.5 (implies `spectrum`)", "", false, true},
      {"period-min", "smallest period of a logarithmic grid (s; default 0.02; implies `spectrum`)"},
      {"period-max", "largest period (s; default 5)"},
      {"period-points", "periods of the grid (default 60)"},
      {"damping", "the oscillator's damping ratio, in [0, 1)", "0.05"},
      {"g", "gravity converting the record's g to m/s^2", "9.81"}};
  return options;
}

json motion_info(const Settings& s) {
  s.require_known(motion_info_options(), {"record"}, "motion info");
  const double g = s.number("g", 9.81), damping = s.number("damping", 0.05);
  require_in_range("g", g, 0.0, 1e3, false);
  require_in_range("damping", damping, 0.0, 1.0, true, false);
  const bool spectrum =
      s.flag("spectrum") || s.has("periods") || s.has("period-min") || s.has("period-max") || s.has("period-points");
  const std::vector<double> periods = spectrum ? periods_of(s) : std::vector<double>{};
  const std::shared_ptr<const Accelerogram> held = record_from(s);
  const Accelerogram& rec = *held;
  const IntensityMeasures m = intensity_measures(rec, g);
  json j;
  j["schema"] = schema_name("motion-info", "summary");
  j["run"] = run_info();
  j["record"] = {{"source", rec.source()},
                 {"samples", rec.size()},
                 {"dt", rec.uniform() ? json(rec.dt()) : json(nullptr)},
                 {"t_first", rec.time(0)},
                 {"duration", m.duration}};
  j["g"] = g;
  const json measures = measures_json(m);
  for (auto it = measures.begin(); it != measures.end(); ++it) j[it.key()] = it.value();
  j["units"] = {{"pga", "g"}, {"pgv", "m/s"}, {"pgd", "m"}, {"arias", "m/s"}, {"times", "s"}, {"sa", "g"}, {"sd", "m"}};
  if (spectrum) {
    j["damping"] = damping;
    json rows = json::array();
    for (const SpectralOrdinate& o : response_spectrum(rec, periods, damping, g))
      rows.push_back({{"period", o.period}, {"sa", o.sa}, {"sd", o.sd}, {"t_peak", o.t_peak}});
    j["spectrum"] = rows;
  }
  return j;
}

std::shared_ptr<const Accelerogram> record_from(const Settings& s) {
  if (auto r = s.record("record")) return r;
  if (!s.has("record")) throw std::invalid_argument("record: give a record file (PEER .AT2, or CSV 't, a' in s, g)");
  return std::make_shared<const Accelerogram>(load_accelerogram(s.text("record"), "record"));
}

json measures_json(const IntensityMeasures& m) {
  const std::pair<const char*, double> measures[] = {{"pga", m.pga},
                                                     {"pgv", m.pgv},
                                                     {"pgd", m.pgd},
                                                     {"arias", m.arias},
                                                     {"d5_95", m.d5_95},
                                                     {"t5", m.t5},
                                                     {"t95", m.t95},
                                                     {"t_mid", m.t_mid},
                                                     {"mean_period", m.mean_period},
                                                     {"final_velocity", m.final_velocity},
                                                     {"final_displacement", m.final_displacement}};
  json j;
  for (const auto& [key, value] : measures) j[key] = finite_or_null(value);
  return j;
}

std::string motion_info_text(const json& j) {
  std::string t;
  auto line = [&t](const char* fmt, auto... v) {
    char buf[256];
    std::snprintf(buf, sizeof buf, fmt, v...);
    t += buf;
  };
  auto num = [](const json& v) { return v.is_null() ? std::nan("") : v.get<double>(); };
  line("record: %s, %zu samples over %.6g s\n", j["record"]["source"].get<std::string>().c_str(),
       j["record"]["samples"].get<std::size_t>(), j["record"]["duration"].get<double>());
  line("pga %.6g g, pgv %.6g m/s, pgd %.6g m\n", num(j["pga"]), num(j["pgv"]), num(j["pgd"]));
  line("Arias intensity %.6g m/s, D5-95 %.6g s (%.6g to %.6g s), t_mid %.6g s\n", num(j["arias"]), num(j["d5_95"]),
       num(j["t5"]), num(j["t95"]), num(j["t_mid"]));
  line("mean period %.6g s; at the end v = %.3g m/s, d = %.3g m\n", num(j["mean_period"]), num(j["final_velocity"]),
       num(j["final_displacement"]));
  if (j.contains("spectrum")) {
    line("spectrum (damping %.3g): period [s]  Sa [g]\n", num(j["damping"]));
    for (const json& r : j["spectrum"]) line("  %10.5g  %10.5g\n", num(r["period"]), num(r["sa"]));
  }
  return t;
}

}  // namespace blockdyn
