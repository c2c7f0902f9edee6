// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/api/motion_generate.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <stdexcept>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/api/motion_info.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/excitation/intensity_measures.hpp"
#include "blockdyn/excitation/stochastic_motion.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {
namespace {

using json = nlohmann::ordered_json;
using Invalid = std::invalid_argument;

struct Plan {
  std::string model, out;
  bool background = false;  // rezaeian records (alone, or under the pulse)
  RezaeianParams rz;
  Modulation q;
  bool pulse = false;
  PulseParams pp;
  long count = 1;
  std::uint64_t seed = 1;
  int threads = 0;
};

const char* const kRezaeianOptions[] = {"arias", "d5-95", "t-mid", "f-mid", "f-slope", "zeta-f"};

Plan plan_of(const Settings& s) {
  s.require_known(motion_generate_options(), {"threads", "overwrite"}, "motion generate");
  Plan p;
  p.model = s.text("model", "rezaeian");
  if (p.model != "rezaeian" && p.model != "pulse")
    throw Invalid("model = '" + p.model + "' is not one of: rezaeian, pulse");
  p.pulse = p.model == "pulse";
  p.background = !p.pulse || s.has("arias");
  if (!p.pulse)
    for (const char* n : {"pulse-pgv", "pulse-period", "gamma", "nu", "pulse-t0"})
      if (s.has(n)) throw Invalid(std::string("--") + n + " belongs to --model pulse");
  p.rz.dt = s.number("dt", 0.01);
  p.rz.g = s.number("g", 9.81);
  if (p.background) {
    for (const char* n : kRezaeianOptions)
      if (!s.has(n) && std::string(n) != "f-slope" && std::string(n) != "zeta-f")
        throw Invalid(std::string("--") + n + ": the rezaeian model needs --arias --d5-95 --t-mid --f-mid");
    p.rz.arias = *s.number("arias");
    p.rz.d5_95 = *s.number("d5-95");
    p.rz.t_mid = *s.number("t-mid");
    p.rz.f_mid = *s.number("f-mid");
    p.rz.f_slope = s.number("f-slope", 0.0);
    p.rz.zeta_f = s.number("zeta-f", 0.3);
    p.rz.f_highpass = s.number("f-highpass", 0.2);
  } else {
    for (const char* n : kRezaeianOptions)
      if (s.has(n)) throw Invalid(std::string("--") + n + " needs the background's --arias (rezaeian targets)");
  }
  if (p.pulse) {
    p.pp.pgv = s.number("pulse-pgv", 0.0);
    p.pp.period = s.number("pulse-period", 0.0);
    p.pp.gamma = s.number("gamma", 2.0);
    p.pp.nu = s.number("nu", 0.0);
    p.pp.t0 = s.number("pulse-t0", p.background ? p.rz.t_mid : 0.5 * p.pp.gamma * p.pp.period);
    validate(p.pp);
  }
  const double t_min = p.pulse ? p.pp.t0 + 0.5 * p.pp.gamma * p.pp.period : 0.0;
  p.rz.t_end = s.number("t-end", p.background ? 0.0 : t_min + 5.0);
  if (!s.has("t-end") && p.background) throw Invalid("--t-end: give the records' duration [s]");
  if (p.rz.t_end < t_min) throw Invalid("t-end: shorter than the pulse (it ends at " + std::to_string(t_min) + " s)");
  if (p.background) {
    validate(p.rz);
    p.q = fit_modulation(p.rz.arias, p.rz.d5_95, p.rz.t_mid, p.rz.g);
  } else {
    require_in_range("dt", p.rz.dt, 1e-4, 1.0);
    require_in_range("t-end", p.rz.t_end, 10 * p.rz.dt, 1e4);
    require_in_range("g", p.rz.g, 0, 1e3, false);
  }
  p.count = s.integer("count", 1);
  if (p.count < 1 || p.count > 100000) throw Invalid("count = " + std::to_string(p.count) + ": must be in [1, 100000]");
  const long seed = s.integer("seed", 1);
  if (seed < 0) throw Invalid("seed = " + std::to_string(seed) + ": must be >= 0");
  p.seed = std::uint64_t(seed);
  p.threads = int(s.integer("threads", 0));
  if (p.threads < 0 || p.threads > 1024) throw Invalid("threads: must be in [0, 1024]");
  p.out = s.text("out");
  if (p.out.empty()) throw Invalid("--out: give the directory for the records");
  return p;
}

void make_directory(const std::string& dir, bool overwrite) {
  struct stat st {};
  if (::stat(dir.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode)) throw Invalid("out = '" + dir + "' exists and is not a directory");
    if (::stat((dir + "/motions.json").c_str(), &st) == 0 && !overwrite)
      throw Invalid("out = '" + dir + "' already holds a suite (motions.json): give --overwrite or another directory");
    return;
  }
  if (::mkdir(dir.c_str(), 0777) != 0)
    throw Invalid("out = '" + dir + "': cannot create the directory (" + std::strerror(errno) + ")");
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

const std::vector<StudyOption>& motion_generate_options() {
  static const std::vector<StudyOption> options = {
      {"model", "rezaeian (site-based stochastic model) or pulse (near-fault velocity pulse)", "rezaeian"},
      {"arias", "target Arias intensity [m/s]"},
      {"d5-95", "target significant duration D5-95 [s]"},
      {"t-mid", "target time at 45 % of the Arias intensity [s]"},
      {"f-mid", "filter frequency at t-mid [Hz]"},
      {"f-slope", "its rate of change [Hz/s]", "0"},
      {"zeta-f", "filter damping ratio, in (0, 1)", "0.3"},
      {"f-highpass", "corner of the critically damped high-pass [Hz] (0: none)", "0.2"},
      {"pulse-pgv", "pulse: velocity amplitude A [m/s]"},
      {"pulse-period", "pulse: period T_p [s]"},
      {"gamma", "pulse: oscillatory character gamma (> 1)", "2"},
      {"nu", "pulse: phase nu [rad]", "0"},
      {"pulse-t0", "pulse: time of its peak [s] (default t-mid on a background, else gamma T_p / 2)"},
      {"dt", "sample spacing [s]", "0.01"},
      {"t-end", "duration of every record [s]"},
      {"count", "number of records", "1"},
      {"seed", "seed of the suite (record k: its own stream of (seed, k))", "1"},
      {"g", "gravity [m/s^2]: the records are written in g", "9.81"},
      {"out", "directory for the records (NAME_0001.AT2, ...) and motions.json"}};
  return options;
}

std::string at2_text(const std::vector<double>& a, double dt, const std::string& title) {
  std::string t = "PEER-format record written by blockdyn\n" + title +
                  "\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= " + std::to_string(a.size()) + ", DT= ";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g SEC\n", dt);
  t += buf;
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%17.9E", a[i]);
    t += buf;
    if (i % 5 == 4 || i + 1 == a.size()) t += '\n';
  }
  return t;
}

json motion_generate(const Settings& s, const std::function<void(std::size_t, std::size_t)>& progress) {
  const Plan p = plan_of(s);
  make_directory(p.out, s.flag("overwrite"));
  const std::size_t n = std::size_t(std::floor(p.rz.t_end / p.rz.dt + 1e-9)) + 1;
  const int width = std::max(4, int(std::to_string(p.count).size()));
  std::mutex done_lock;
  std::size_t done = 0;
  const std::vector<json> rows = parallel_map<json>(std::size_t(p.count), p.threads, [&](std::size_t k) {
    GeneratedRecord r;
    if (p.background) r = rezaeian_record(p.rz, p.q, p.seed, k);
    if (r.a.empty()) r.a.assign(n, 0.0);
    if (p.pulse)
      for (std::size_t i = 0; i < n; ++i) r.a[i] += pulse_acceleration(p.pp, double(i) * p.rz.dt, p.rz.g);
    char name[64];
    std::snprintf(name, sizeof name, "%s_%0*zu.AT2", p.model.c_str(), width, k + 1);
    const std::string text =
        at2_text(r.a, p.rz.dt, p.model + " record " + std::to_string(k + 1) + " of seed " + std::to_string(p.seed));
    write_file_atomically(p.out + "/" + name, text);
    // Measured on the file as written (the samples rounded to 10 digits).
    const IntensityMeasures m = intensity_measures(parse_at2(text, name), p.rz.g);
    json row = {{"file", name}};
    const json measures = measures_json(m);
    for (auto it = measures.begin(); it != measures.end(); ++it) row[it.key()] = it.value();
    row["baseline_correction"] = r.baseline_correction;
    if (progress) {
      const std::lock_guard<std::mutex> lock(done_lock);
      progress(++done, std::size_t(p.count));
    }
    return row;
  });
  json j;
  j["schema"] = schema_name("motion-generate", "summary");
  j["run"] = run_info();
  j["model"] = p.model;
  j["seed"] = p.seed;
  j["count"] = p.count;
  j["dt"] = p.rz.dt;
  j["t_end"] = p.rz.t_end;
  j["g"] = p.rz.g;
  if (p.background) {
    j["targets"] = {{"arias", p.rz.arias}, {"d5_95", p.rz.d5_95}, {"t_mid", p.rz.t_mid}};
    j["filter"] = {
        {"f_mid", p.rz.f_mid}, {"f_slope", p.rz.f_slope}, {"zeta_f", p.rz.zeta_f}, {"f_highpass", p.rz.f_highpass}};
    j["modulation"] = {{"c1", p.q.c1}, {"c2", p.q.c2}, {"c3", p.q.c3}};
  }
  if (p.pulse)
    j["pulse"] = {{"pgv", p.pp.pgv}, {"period", p.pp.period}, {"gamma", p.pp.gamma}, {"nu", p.pp.nu}, {"t0", p.pp.t0}};
  j["units"] = {{"pga", "g"}, {"pgv", "m/s"}, {"pgd", "m"}, {"arias", "m/s"}, {"times", "s"}};
  j["records"] = rows;
  json med;
  for (const char* key : {"pga", "pgv", "arias", "d5_95", "t_mid", "mean_period"}) {
    std::vector<double> v;
    for (const json& r : rows) v.push_back(r[key].get<double>());
    med[key] = median(v);
  }
  j["median"] = med;
  write_file_atomically(p.out + "/motions.json", dump_json(j) + "\n");
  return j;
}

}  // namespace blockdyn
