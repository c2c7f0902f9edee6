// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/motion_generate.hpp"

#include <dirent.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <stdexcept>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/base/number_text.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/motion_info.hpp"
#include "blockdyn/excitation/intensity_measures.hpp"
#include "blockdyn/excitation/stochastic_motion.hpp"
#include "blockdyn/io/at2_writer.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

// The components of a multi-component suite: two horizontal principal components and the vertical.
const char* const kComponentNames[] = {"h1", "h2", "v"};

struct Plan {
  std::string model, out;
  bool background = false;  // rezaeian records (alone, or under the pulse)
  RezaeianParams rz;        // the record's (or the first component's) targets and filter
  Modulation q;
  int components = 1;                 // 1, or 2 (h1, h2) or 3 (h1, h2, v)
  std::array<RezaeianParams, 3> rzc;  // each component's targets and filter
  std::array<Modulation, 3> qc;
  bool pulse = false;
  PulseParams pp;
  long count = 1;
  std::uint64_t seed = 1;
  int threads = 0;
};

const char* const kRezaeianOptions[] = {"arias", "d5-95", "t-mid", "f-mid", "f-slope", "zeta-f"};

std::size_t sample_count(const Plan& p) { return std::size_t(std::floor(p.rz.t_end / p.rz.dt + 1e-9)) + 1; }

// The bytes of one record's file: the header and at most 25 characters per sample, a newline per 5.
double record_bytes(const Plan& p) { return 200.0 + 25.2 * double(sample_count(p)); }

// Component c of record k draws its own stream: (seed, k + c 2^40); the first is the
// single-component record's.
std::uint64_t stream_index(std::size_t k, int c) { return std::uint64_t(k) + (std::uint64_t(c) << 40); }

// Work and disk are bounded before anything runs: a record's filter terms, and the suite's size
// against a budget and against the free space where it goes.
constexpr double kMaxRecordTerms = 2e10;              // about a minute of one core per record
constexpr double kMaxSuiteBytes = 16.0 * (1u << 30);  // 16 GiB of .AT2 files
void check_work(const Plan& p) {
  for (int c = 1; c < p.components; ++c) {
    const double terms = rezaeian_record_cost(p.rzc[std::size_t(c)]);
    if (terms > kMaxRecordTerms)
      throw std::invalid_argument(std::string(kComponentNames[c]) + "-zeta-f, " + kComponentNames[c] +
                                  "-f-mid: the filter's memory makes a record cost " + number_text(terms, 3) +
                                  " kernel terms (at most 2e10): raise them");
  }
  if (p.background) {
    const double terms = rezaeian_record_cost(p.rz);
    if (terms > kMaxRecordTerms)
      throw std::invalid_argument("zeta-f = " + number_text(p.rz.zeta_f) + ", f-mid = " + number_text(p.rz.f_mid) +
                                  " Hz, f-slope = " + number_text(p.rz.f_slope) +
                                  " Hz/s: the filter's memory makes a record cost " + number_text(terms, 3) +
                                  " kernel terms (at most 2e10): raise `zeta-f` or the filter frequency, or "
                                  "shorten `t-end`");
  }
  const double bytes = double(p.count) * double(p.components) * record_bytes(p);
  if (bytes > kMaxSuiteBytes)
    throw std::invalid_argument(
        "count = " + std::to_string(p.count) + " records of " + std::to_string(sample_count(p)) + " samples need " +
        number_text(std::round(bytes / 1e6)) +
        " MB of .AT2 files: at most 16 GiB per suite (lower `count` or `t-end`, or raise `dt`)");
  struct statvfs fs {};
  const auto slash = p.out.find_last_of('/');
  const std::string where = ::access(p.out.c_str(), F_OK) == 0 ? p.out
                            : slash == std::string::npos       ? std::string(".")
                                                               : p.out.substr(0, std::max<std::size_t>(slash, 1));
  if (::statvfs(where.c_str(), &fs) == 0) {
    const double free_bytes = double(fs.f_bavail) * double(fs.f_frsize);
    if (bytes > free_bytes)
      throw std::invalid_argument("out = '" + p.out + "': the suite needs " + number_text(std::round(bytes / 1e6)) +
                                  " MB and " + number_text(std::round(free_bytes / 1e6)) + " MB are free there");
  }
}

// `components` and each extra component's targets (`h2-arias`, ..., `v-f-mid`; the first
// component's where not given, the vertical's arias and f-mid required).
void plan_components(const Settings& s, Plan& p) {
  const long n = s.integer("components", 1);
  if (n < 1 || n > 3) throw std::invalid_argument("components = " + std::to_string(n) + ": must be 1, 2 or 3");
  p.components = int(n);
  for (int c = 1; c < 3; ++c)
    for (const char* o : kRezaeianOptions) {
      const std::string name = std::string(kComponentNames[c]) + "-" + o;
      if (s.has(name) && c >= p.components)
        throw std::invalid_argument("`" + name + "` needs `components` " + std::to_string(c + 1));
    }
  p.rzc.fill(p.rz);
  p.qc.fill(p.q);
  if (p.components == 1) return;
  if (!p.background || p.pulse)
    throw std::invalid_argument("components = " + std::to_string(n) +
                                ": the components are rezaeian records (`model` rezaeian)");
  if (p.components == 3)
    for (const char* o : {"arias", "f-mid"})
      if (!s.has(std::string("v-") + o))
        throw std::invalid_argument(std::string("`v-") + o + "`: components = 3 needs the vertical's own target");
  for (int c = 1; c < p.components; ++c) {
    RezaeianParams& r = p.rzc[std::size_t(c)];
    const std::string pre = std::string(kComponentNames[c]) + "-";
    r.arias = s.number(pre + "arias", r.arias);
    r.d5_95 = s.number(pre + "d5-95", r.d5_95);
    r.t_mid = s.number(pre + "t-mid", r.t_mid);
    r.f_mid = s.number(pre + "f-mid", r.f_mid);
    r.f_slope = s.number(pre + "f-slope", r.f_slope);
    r.zeta_f = s.number(pre + "zeta-f", r.zeta_f);
    try {
      validate(r);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(pre + e.what());
    }
    p.qc[std::size_t(c)] = fit_modulation(r.arias, r.d5_95, r.t_mid, r.g);
  }
}

Plan plan_of(const Settings& given) {
  const Settings s = with_canonical_names(given, motion_generate_options());
  s.require_known(motion_generate_options(), {"threads", "overwrite"}, "motion generate");
  Plan p;
  p.model = s.text("model", "rezaeian");
  if (p.model != "rezaeian" && p.model != "pulse")
    throw std::invalid_argument("model = '" + p.model + "' is not one of: rezaeian, pulse");
  p.pulse = p.model == "pulse";
  p.background = !p.pulse || s.has("arias");
  if (!p.pulse)
    for (const char* n : {"pulse-pgv", "pulse-period", "gamma", "nu", "pulse-t0"})
      if (s.has(n)) throw std::invalid_argument(std::string("`") + n + "` belongs to `model` pulse");
  p.rz.dt = s.number("dt", 0.01);
  p.rz.g = s.number("g", 9.81);
  if (p.background) {
    for (const char* n : kRezaeianOptions)
      if (!s.has(n) && std::string(n) != "f-slope" && std::string(n) != "zeta-f")
        throw std::invalid_argument(std::string("`") + n +
                                    "`"
                                    ": the rezaeian model needs `arias` `d5-95` `t-mid` `f-mid`");
    p.rz.arias = *s.number("arias");
    p.rz.d5_95 = *s.number("d5-95");
    p.rz.t_mid = *s.number("t-mid");
    p.rz.f_mid = *s.number("f-mid");
    p.rz.f_slope = s.number("f-slope", 0.0);
    p.rz.zeta_f = s.number("zeta-f", 0.3);
    p.rz.f_highpass = s.number("f-highpass", 0.2);
  } else {
    for (const char* n : kRezaeianOptions)
      if (s.has(n))
        throw std::invalid_argument(std::string("`") + n + "` needs the background's `arias` (rezaeian targets)");
  }
  if (p.pulse) {
    p.pp.pgv = s.number("pulse-pgv", 0.0);
    p.pp.period = s.number("pulse-period", 0.0);
    p.pp.gamma = s.number("gamma", 2.0);
    p.pp.nu = s.number("nu", 0.0);
    p.pp.t0 = s.number("pulse-t0", p.background ? p.rz.t_mid : 0.5 * p.pp.gamma * p.pp.period);
  }
  const double t_min = p.pulse ? p.pp.t0 + 0.5 * p.pp.gamma * p.pp.period : 0.0;
  p.rz.t_end = s.number("t-end", p.background ? 0.0 : t_min + 5.0);
  if (!s.has("t-end") && p.background) throw std::invalid_argument("`t-end`: give the records' duration [s]");
  if (p.pulse) validate(p.pp, p.rz.dt, p.rz.t_end);
  if (p.background) {
    validate(p.rz);
    p.q = fit_modulation(p.rz.arias, p.rz.d5_95, p.rz.t_mid, p.rz.g);
  } else {
    require_in_range("dt", p.rz.dt, 1e-4, 1.0);
    require_in_range("t-end", p.rz.t_end, 10 * p.rz.dt, 1e4);
    require_in_range("g", p.rz.g, 0, 1e3, false);
  }
  plan_components(s, p);
  p.count = s.integer("count", 1);
  if (p.count < 1 || p.count > 100000)
    throw std::invalid_argument("count = " + std::to_string(p.count) + ": must be in [1, 100000]");
  const long seed = s.integer("seed", 1);
  if (seed < 0) throw std::invalid_argument("seed = " + std::to_string(seed) + ": must be >= 0");
  p.seed = std::uint64_t(seed);
  const long threads = s.integer("threads", 0);
  if (threads < 0 || threads > 1024)
    throw std::invalid_argument("threads = " + std::to_string(threads) + " is out of range: must be in [0, 1024]");
  p.threads = int(threads);
  p.out = s.text("out");
  if (p.out.empty()) throw std::invalid_argument("`out`: give the directory for the records");
  check_work(p);
  return p;
}

// Files a suite of this program may have left in dir: its records (NAME_0001.AT2 of either model)
// and the temporaries of an interrupted run.
bool is_suite_file(const std::string& name) {
  std::string stem = name;
  if (const auto tmp = stem.find(".AT2.tmp."); tmp != std::string::npos) stem = stem.substr(0, tmp + 4);
  for (const char* model : {"rezaeian_", "pulse_"}) {
    const std::string m(model);
    if (stem.rfind(m, 0) != 0 || stem.size() < m.size() + 5 || stem.compare(stem.size() - 4, 4, ".AT2") != 0) continue;
    std::string digits = stem.substr(m.size(), stem.size() - m.size() - 4);
    for (const char* c : {"_h1", "_h2", "_v"}) {
      const std::string suffix(c);
      if (digits.size() > suffix.size() && digits.compare(digits.size() - suffix.size(), suffix.size(), suffix) == 0) {
        digits.resize(digits.size() - suffix.size());
        break;
      }
    }
    if (!digits.empty() && std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      return true;
  }
  return false;
}

std::vector<std::string> suite_files(const std::string& dir) {
  std::vector<std::string> names;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (const dirent* e = ::readdir(d))
      if (is_suite_file(e->d_name)) names.push_back(e->d_name);
    ::closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

void make_directory(const std::string& dir, bool overwrite) {
  struct stat st {};
  if (::stat(dir.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode)) throw std::invalid_argument("out = '" + dir + "' exists and is not a directory");
    const bool has_suite = ::stat((dir + "/motions.json").c_str(), &st) == 0 || !suite_files(dir).empty();
    if (has_suite && !overwrite)
      throw std::invalid_argument(
          "out = '" + dir + "' already holds a suite (motions.json or records): give `overwrite` or another directory");
    return;
  }
  if (::mkdir(dir.c_str(), 0777) != 0)
    throw std::invalid_argument("out = '" + dir + "': cannot create the directory (" + std::strerror(errno) + ")");
}

// Checks a record before it is written: finite samples within what the readers take (|a| <= 100 g).
void check_samples(const Plan& p, const std::vector<double>& a, std::size_t k) {
  double peak = 0.0;
  for (double v : a) {
    if (!std::isfinite(v))
      throw std::invalid_argument("record " + std::to_string(k + 1) +
                                  ": the targets give samples that are not finite numbers");
    peak = std::fmax(peak, std::fabs(v));
  }
  if (peak > 100.0)
    throw std::invalid_argument((p.background ? "record " + std::to_string(k + 1) : std::string("the pulse")) +
                                " peaks at " + number_text(peak, 4) + " g, beyond the 100 g a record may hold: " +
                                (p.pulse ? "lower `pulse-pgv` or lengthen `pulse-period`" : "lower `arias`"));
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
      {"d5-95", "target significant duration D5-95 [s]", "", false, false, {"d595"}},
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
      {"components",
       "1, or 2 (two horizontal principal components h1, h2: NAME_0001_h1.AT2, ...) or 3 (and the "
       "vertical v), each an independent record with its own targets",
       "1"},
      {"h2-arias", "h2's target Arias intensity [m/s] (default: arias)"},
      {"h2-d5-95", "h2's target D5-95 [s] (default: d5-95)"},
      {"h2-t-mid", "h2's t-mid [s] (default: t-mid)"},
      {"h2-f-mid", "h2's filter frequency at t-mid [Hz] (default: f-mid)"},
      {"h2-f-slope", "h2's filter frequency rate [Hz/s] (default: f-slope)"},
      {"h2-zeta-f", "h2's filter damping (default: zeta-f)"},
      {"v-arias", "v's target Arias intensity [m/s] (components 3)"},
      {"v-d5-95", "v's target D5-95 [s] (default: d5-95)"},
      {"v-t-mid", "v's t-mid [s] (default: t-mid)"},
      {"v-f-mid", "v's filter frequency at t-mid [Hz] (components 3)"},
      {"v-f-slope", "v's filter frequency rate [Hz/s] (default: f-slope)"},
      {"v-zeta-f", "v's filter damping (default: zeta-f)"},
      {"seed", "seed of the suite (record k: its own stream of (seed, k))", "1"},
      {"g", "gravity [m/s^2]: the records are written in g", "9.81"},
      {"out", "directory for the records (NAME_0001.AT2, ...) and motions.json"}};
  return options;
}

json motion_generate(const Settings& s, const std::function<void(std::size_t, std::size_t)>& progress) {
  const Plan p = plan_of(s);
  // The pulse alone, checked before anything is made (it is the same in every record).
  if (p.pulse && !p.background) {
    std::vector<double> a(sample_count(p));
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = pulse_acceleration(p.pp, double(i) * p.rz.dt, p.rz.g);
    check_samples(p, a, 0);
  }
  make_directory(p.out, s.flag("overwrite"));
  const std::size_t n = sample_count(p);
  const int width = std::max(4, int(std::to_string(p.count).size()));
  const std::string tmp_suffix = ".tmp." + std::to_string(::getpid());
  // Record k's files: NAME_k.AT2, or NAME_k_h1.AT2, NAME_k_h2.AT2 (, NAME_k_v.AT2).
  const std::size_t nc = std::size_t(p.components);
  std::vector<std::string> names(std::size_t(p.count) * nc);
  for (std::size_t k = 0; k < std::size_t(p.count); ++k) {
    std::string digits = std::to_string(k + 1);
    digits.insert(0, std::size_t(std::max(0, width - int(digits.size()))), '0');
    for (std::size_t c = 0; c < nc; ++c)
      names[k * nc + c] =
          p.model + "_" + digits + (nc > 1 ? std::string("_") + kComponentNames[c] : std::string()) + ".AT2";
  }
  // Every record is made, checked and written under a temporary name; only when all are done do
  // they replace the suite (an error leaves the directory as it was).
  auto remove_temporaries = [&] {
    for (const std::string& name : names) std::remove((p.out + "/" + name + tmp_suffix).c_str());
  };
  std::mutex done_lock;
  std::size_t done = 0;
  std::vector<json> rows;
  try {
    rows = parallel_map<json>(std::size_t(p.count), p.threads, [&](std::size_t k) {
      json row;
      for (std::size_t c = 0; c < nc; ++c) {
        const std::string& name = names[k * nc + c];
        GeneratedRecord r;
        if (p.background) r = rezaeian_record(p.rzc[c], p.qc[c], p.seed, stream_index(k, int(c)));
        if (r.a.empty()) r.a.assign(n, 0.0);
        if (p.pulse)
          for (std::size_t i = 0; i < n; ++i) r.a[i] += pulse_acceleration(p.pp, double(i) * p.rz.dt, p.rz.g);
        check_samples(p, r.a, k);
        const std::string title = p.model + " record " + std::to_string(k + 1) +
                                  (nc > 1 ? std::string(" component ") + kComponentNames[c] : std::string()) +
                                  " of seed " + std::to_string(p.seed);
        std::ofstream out(p.out + "/" + name + tmp_suffix, std::ios::binary | std::ios::trunc);
        out << at2_text(r.a, p.rz.dt, title);
        out.flush();
        if (!out) throw std::runtime_error("cannot write '" + p.out + "/" + name + "'");
        // The file reads back to the very samples written; its measures are the record's.
        const IntensityMeasures m = intensity_measures(Accelerogram(r.a, p.rz.dt, name), p.rz.g);
        json one = {{"file", name}};
        const json measures = measures_json(m);
        for (auto it = measures.begin(); it != measures.end(); ++it) one[it.key()] = it.value();
        one["baseline_correction"] = r.baseline_correction;
        // A multi-component record: the first component's file and measures, and every component's.
        if (c == 0) row = one;
        if (nc > 1) row["components"][kComponentNames[c]] = one;
      }
      if (progress) {
        const std::lock_guard<std::mutex> lock(done_lock);
        progress(++done, std::size_t(p.count));
      }
      return row;
    });
  } catch (...) {
    remove_temporaries();
    throw;
  }
  // The old suite's records go (a smaller suite must not leave records for the next *.AT2 glob).
  auto ours = [&](const std::string& f) {
    return f.size() > tmp_suffix.size() && f.compare(f.size() - tmp_suffix.size(), tmp_suffix.size(), tmp_suffix) == 0;
  };
  for (const std::string& old : suite_files(p.out))
    if (!ours(old) && std::find(names.begin(), names.end(), old) == names.end())
      std::remove((p.out + "/" + old).c_str());
  for (const std::string& name : names)
    if (std::rename((p.out + "/" + name + tmp_suffix).c_str(), (p.out + "/" + name).c_str()) != 0)
      throw std::runtime_error("cannot rename '" + p.out + "/" + name + tmp_suffix + "': " + std::strerror(errno));
  json j;
  j["schema"] = schema_name("motion-generate", "summary");
  j["run"] = run_info();
  j["model"] = p.model;
  j["seed"] = p.seed;
  j["count"] = p.count;
  if (p.components > 1) {
    json names_of = json::array(), targets;
    for (int c = 0; c < p.components; ++c) {
      const RezaeianParams& r = p.rzc[std::size_t(c)];
      names_of.push_back(kComponentNames[c]);
      targets[kComponentNames[c]] = {{"arias", r.arias}, {"d5_95", r.d5_95},     {"t_mid", r.t_mid},
                                     {"f_mid", r.f_mid}, {"f_slope", r.f_slope}, {"zeta_f", r.zeta_f}};
    }
    j["components"] = names_of;
    j["component_targets"] = targets;
  }
  j["dt"] = p.rz.dt;
  j["t_end"] = p.rz.t_end;
  j["g"] = p.rz.g;
  if (p.background) {
    j["targets"] = {{"arias", p.rz.arias}, {"d5_95", p.rz.d5_95}, {"t_mid", p.rz.t_mid}};
    j["filter"] = {
        {"f_mid", p.rz.f_mid}, {"f_slope", p.rz.f_slope}, {"zeta_f", p.rz.zeta_f}, {"f_highpass", p.rz.f_highpass}};
    const double c1 = p.q.c1();
    j["modulation"] = {
        {"c1", std::isfinite(c1) ? json(c1) : json(nullptr)}, {"log_c1", p.q.log_c1}, {"c2", p.q.c2}, {"c3", p.q.c3}};
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
