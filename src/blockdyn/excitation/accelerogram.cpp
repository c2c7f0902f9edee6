// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/excitation/accelerogram.hpp"

#include "blockdyn/base/content_hash.hpp"
#include "blockdyn/base/number_text.hpp"
#include "blockdyn/io/input_files.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <sys/stat.h>

namespace blockdyn {

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw std::invalid_argument(source + ": " + what);
}

// One decimal number (Fortran 'D' exponents accepted; hex, inf and nan refused).
bool to_number(const std::string& tok, double& v) { return parse_decimal(tok, v); }

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string cur;
  for (char c : text) {
    if (c == '\n') {
      lines.push_back(cur);
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  if (!cur.empty()) lines.push_back(cur);
  return lines;
}

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// NPTS and DT from the 4th header line of an AT2 file.
void parse_at2_counts(const std::string& line, const std::string& where, long& npts, double& dt) {
  std::string s = upper(line);
  for (char& c : s)
    if (c == ',' || c == '=' || c == ';' || c == ':') c = ' ';
  std::istringstream in(s);
  std::vector<std::string> tok;
  for (std::string t; in >> t;) tok.push_back(t);
  std::vector<double> nums;
  std::vector<std::string> words;
  double n_after_npts = NAN, n_after_dt = NAN;
  std::string last_word;
  for (const auto& t : tok) {
    double v;
    if (to_number(t, v)) {
      nums.push_back(v);
      if (last_word == "NPTS" && std::isnan(n_after_npts)) n_after_npts = v;
      if (last_word == "DT" && std::isnan(n_after_dt)) n_after_dt = v;
      last_word.clear();
    } else {
      words.push_back(t);
      last_word = t;
    }
  }
  double n = NAN, d = NAN;
  if (!std::isnan(n_after_npts) && !std::isnan(n_after_dt)) {  // "NPTS= 7807, DT= .005 SEC"
    n = n_after_npts;
    d = n_after_dt;
  } else if (nums.size() >= 2) {  // "3930 0.00500 NPTS, DT" (numbers in the order of the names)
    const auto ip = std::find(words.begin(), words.end(), "NPTS");
    const auto id = std::find(words.begin(), words.end(), "DT");
    if (ip == words.end() || id == words.end())
      fail(where, "line 4 must give NPTS and DT (e.g. 'NPTS=  7807, DT=   .00500 SEC'), found '" + line + "'");
    n = ip < id ? nums[0] : nums[1];
    d = ip < id ? nums[1] : nums[0];
  } else {
    fail(where, "line 4 must give NPTS and DT (e.g. 'NPTS=  7807, DT=   .00500 SEC'), found '" + line + "'");
  }
  if (!(n >= 2) || n != std::floor(n) || n > double(kMaxRecordSamples))
    fail(where, "NPTS = " + number_text(n) + " is out of range: must be an integer in [2, " +
                    std::to_string(kMaxRecordSamples) + "]");
  if (!(d >= kMinRecordDt) || !std::isfinite(d) || d > 10.0)
    fail(where, "DT = " + number_text(d) + " is out of range: must be in [1e-6, 10] s");
  npts = long(n);
  dt = d;
}

// The quantity and units line 3 of an AT2 file states: acceleration in g is read; a velocity or
// displacement series, or accelerations in other units, are refused (never read as g).
void check_at2_units(const std::string& line, const std::string& where) {
  const std::string u = upper(line);
  for (const char* q : {"VELOCITY", "DISPLACEMENT"})
    if (u.find(q) != std::string::npos)
      fail(where, std::string("the file is a ") + (q[0] == 'V' ? "velocity" : "displacement") + " time series ('" +
                      line + "'): a record is a ground acceleration in g");
  std::istringstream in(u);
  std::vector<std::string> words;
  for (std::string w; in >> w;) {
    while (!w.empty() && (w.back() == '.' || w.back() == ',' || w.back() == ')' || w.back() == ';')) w.pop_back();
    while (!w.empty() && w.front() == '(') w.erase(w.begin());
    words.push_back(w);
  }
  auto refuse = [&](const std::string& unit) {
    fail(where, "units '" + unit + "' ('" + line +
                    "'): blockdyn reads accelerations in units of g; convert the samples (cm/s^2: divide by 980.665) "
                    "and state UNITS OF G");
  };
  for (std::size_t i = 0; i + 2 < words.size(); ++i)
    if (words[i] == "UNITS" && words[i + 1] == "OF") {
      if (words[i + 2] != "G") refuse(words[i + 2]);
      return;
    }
  for (const std::string& w : words)
    if (w.rfind("CM/S", 0) == 0 || w.rfind("M/S", 0) == 0 || w.rfind("MM/S", 0) == 0 || w == "GAL" ||
        w == "CM/SEC/SEC" || w == "M/SEC/SEC")
      refuse(w);
}

// The columns a CSV header names, in order: {time column, acceleration column}; refuses a header
// that names anything else, or the acceleration in units other than g.
std::pair<int, int> csv_columns(const std::string& header, const std::string& where) {
  std::string h = header;
  if (const auto c = h.find('#'); c != std::string::npos) h.erase(c);
  const bool delimited = h.find_first_of(",;\t") != std::string::npos;
  std::vector<std::string> fields;
  std::string cur;
  auto flush = [&] {
    std::string f;
    for (char c : cur)
      if (!std::isspace(static_cast<unsigned char>(c))) f += char(std::tolower(static_cast<unsigned char>(c)));
    if (!f.empty()) fields.push_back(f);
    cur.clear();
  };
  for (char c : h) {
    if (c == ',' || c == ';' || c == '\t' || (!delimited && c == ' ')) {
      flush();
    } else {
      cur += c;
    }
  }
  flush();
  auto is_time = [](const std::string& f) {
    return f == "t" || f.rfind("t(", 0) == 0 || f.rfind("t[", 0) == 0 || f.rfind("t_", 0) == 0 ||
           f.rfind("time", 0) == 0;
  };
  auto is_acc = [](const std::string& f) {
    return f == "a" || f.rfind("a(", 0) == 0 || f.rfind("a[", 0) == 0 || f.rfind("a_", 0) == 0 ||
           f.rfind("acc", 0) == 0 || f.rfind("ag", 0) == 0;
  };
  const std::string why = "the header '" + header + "' must name the columns t (s) and a (g), in either order";
  if (fields.size() != 2) fail(where, why);
  for (const std::string& f : fields)
    if (is_acc(f))
      for (const char* unit : {"m/s", "cm/s", "mm/s", "gal", "m s", "ms^"})
        if (f.find(unit) != std::string::npos)
          fail(where, "the acceleration column '" + f + "' is not in g: give a in units of g");
  if (is_time(fields[0]) && is_acc(fields[1])) return {0, 1};
  if (is_acc(fields[0]) && is_time(fields[1])) return {1, 0};
  fail(where, why);
}

}  // namespace

Accelerogram::Accelerogram(std::vector<double> a, double dt, std::string source)
    : a_(std::move(a)), dt_(dt), uniform_(true), source_(std::move(source)) {
  if (!(dt >= kMinRecordDt) || !(dt <= kMaxRecordDt))
    fail(source_, "sample spacing dt = " + number_text(dt) + " s is out of range: must be in [1e-6, 1e3] s");
  inv_dt_ = 1.0 / dt_;
  check_values();
}

Accelerogram::Accelerogram(std::vector<double> t, std::vector<double> a, std::string source)
    : t_(std::move(t)), a_(std::move(a)), uniform_(false), source_(std::move(source)) {
  if (t_.size() != a_.size()) fail(source_, "times and values differ in number");
  check_values();
  for (std::size_t i = 0; i < t_.size(); ++i) {
    if (!std::isfinite(t_[i])) fail(source_, "sample " + std::to_string(i + 1) + ": time is not finite");
    if (i > 0 && !(t_[i] > t_[i - 1]))
      fail(source_, "sample " + std::to_string(i + 1) + ": times must be strictly increasing");
    if (i > 0 && !(t_[i] - t_[i - 1] >= kMinRecordDt))
      fail(source_, "sample " + std::to_string(i + 1) + ": the time step " + number_text(t_[i] - t_[i - 1]) +
                        " s is out of range: must be >= 1e-6 s");
  }
  if (t_.front() < 0) fail(source_, "the first sample time must be >= 0");
  if (!(t_.back() <= kMaxRecordDuration)) fail(source_, "the last sample time must be <= 1e7 s");
  // Equally spaced (to rounding): use the O(1) lookup of uniform records.
  const double d = (t_.back() - t_.front()) / double(t_.size() - 1);
  bool eq = t_.front() == 0.0;
  for (std::size_t i = 1; eq && i < t_.size(); ++i) eq = std::fabs(t_[i] - d * double(i)) <= 1e-9 * d;
  if (eq) {
    uniform_ = true;
    dt_ = d;
    inv_dt_ = 1.0 / d;
    t_.clear();
  }
}

void Accelerogram::check_values() const {
  if (a_.size() < 2) fail(source_, "a record needs at least 2 samples");
  if (a_.size() > kMaxRecordSamples) fail(source_, "more than " + std::to_string(kMaxRecordSamples) + " samples");
  for (std::size_t i = 0; i < a_.size(); ++i)
    if (!std::isfinite(a_[i]) || std::fabs(a_[i]) > 100.0)
      fail(source_, "sample " + std::to_string(i + 1) + " = " + number_text(a_[i]) +
                        " is out of range: must be finite, |a| <= 100 g");
}

double Accelerogram::at(double t) const {
  if (uniform_) {
    const double u = t * inv_dt_;
    if (!(u >= 0.0)) return 0.0;
    const std::size_t n = a_.size();
    if (u >= double(n - 1)) return u == double(n - 1) ? a_[n - 1] : 0.0;
    const std::size_t i = std::size_t(u);
    const double f = u - double(i);
    return a_[i] + f * (a_[i + 1] - a_[i]);
  }
  if (t < t_.front() || t > t_.back()) return 0.0;
  const std::size_t i = std::size_t(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin());
  if (i >= t_.size()) return a_.back();
  const double f = (t - t_[i - 1]) / (t_[i] - t_[i - 1]);
  return a_[i - 1] + f * (a_[i] - a_[i - 1]);
}

double Accelerogram::slope(double t) const {
  if (uniform_) {
    const double u = t * inv_dt_;
    if (!(u >= 0.0) || u >= double(a_.size() - 1)) return 0.0;
    const std::size_t i = std::size_t(u);
    return (a_[i + 1] - a_[i]) * inv_dt_;
  }
  if (t < t_.front() || t >= t_.back()) return 0.0;
  const std::size_t i = std::size_t(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin());
  return (a_[i] - a_[i - 1]) / (t_[i] - t_[i - 1]);
}

double Accelerogram::next_sample_after(double t) const {
  if (uniform_) {
    const double u = t * inv_dt_;
    if (u < 0.0) return 0.0;
    const double last = double(a_.size() - 1);
    if (!(u < last)) return INFINITY;
    double i = std::floor(u) + 1.0;
    // Rounding: the sample time computed from i must lie strictly after t (i < 2^25 here, so
    // each increment moves it).
    for (int k = 0; k < 4 && dt_ * i <= t; ++k) i += 1.0;
    if (i > last) return INFINITY;
    return dt_ * i;
  }
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  return it == t_.end() ? INFINITY : *it;
}

std::string Accelerogram::digest() const {
  std::uint64_t h = fnv1a(&dt_, sizeof dt_);
  h = fnv1a(t_.data(), t_.size() * sizeof(double), h);
  h = fnv1a(a_.data(), a_.size() * sizeof(double), h);
  return hex64(h);
}

double Accelerogram::peak() const {
  double m = 0;
  for (double v : a_) m = std::fmax(m, std::fabs(v));
  return m;
}

Accelerogram parse_at2(const std::string& text, const std::string& source) {
  const std::vector<std::string> lines = split_lines(text);
  if (lines.size() < 5) fail(source, "truncated AT2 file: 4 header lines and the values expected");
  check_at2_units(lines[2], source + ":3");
  long npts = 0;
  double dt = 0;
  parse_at2_counts(lines[3], source + ":4", npts, dt);
  std::vector<double> a;
  a.reserve(std::size_t(npts));
  for (std::size_t li = 4; li < lines.size(); ++li) {
    std::istringstream in(lines[li]);
    for (std::string tok; in >> tok;) {
      double v;
      if (!to_number(tok, v)) fail(source + ":" + std::to_string(li + 1), "'" + tok + "' is not a number");
      if (long(a.size()) >= npts)
        fail(source + ":" + std::to_string(li + 1), "more values than NPTS = " + std::to_string(npts));
      a.push_back(v);
    }
  }
  if (long(a.size()) < npts)
    fail(source,
         "truncated AT2 file: NPTS = " + std::to_string(npts) + " but " + std::to_string(a.size()) + " values found");
  return Accelerogram(std::move(a), dt, source);
}

Accelerogram parse_record_csv(const std::string& text, const std::string& source) {
  const std::vector<std::string> lines = split_lines(text);
  std::vector<double> t, a;
  bool first_data = true;
  std::pair<int, int> col{0, 1};  // the time and acceleration columns (a header may swap them)
  for (std::size_t li = 0; li < lines.size(); ++li) {
    std::string s = lines[li];
    if (const auto h = s.find('#'); h != std::string::npos) s.erase(h);
    for (char& c : s)
      if (c == ',' || c == ';' || c == '\t') c = ' ';
    std::istringstream in(s);
    std::vector<std::string> tok;
    for (std::string x; in >> x;) tok.push_back(x);
    if (tok.empty()) continue;
    double c0 = 0.0, c1 = 0.0;
    const bool numeric = tok.size() == 2 && to_number(tok[0], c0) && to_number(tok[1], c1);
    if (!numeric) {
      if (first_data && t.empty()) {  // a header line
        col = csv_columns(lines[li], source + ":" + std::to_string(li + 1));
        first_data = false;
        continue;
      }
      fail(source + ":" + std::to_string(li + 1), "expected two numbers 't, a' (s, g)");
    }
    const double tv = col.first == 0 ? c0 : c1, av = col.first == 0 ? c1 : c0;
    first_data = false;
    if (t.size() >= kMaxRecordSamples) fail(source, "more than " + std::to_string(kMaxRecordSamples) + " samples");
    t.push_back(tv);
    a.push_back(av);
  }
  if (t.size() < 2) fail(source, "a record needs at least 2 rows 't, a'");
  return Accelerogram(std::move(t), std::move(a), source);
}

Accelerogram load_accelerogram(const std::string& path, const std::string& field) {
  // A FIFO or a device would block the read or never end: only regular files are records.
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) throw std::invalid_argument(field + ": cannot read '" + path + "'");
  if (!S_ISREG(st.st_mode)) throw std::invalid_argument(field + ": '" + path + "' is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(field + ": cannot read '" + path + "'");
  note_input(path);
  // Bounded read: 20 M samples of ~16 characters at most.
  constexpr std::size_t kMaxBytes = 400u << 20;
  std::string text;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, std::size_t(in.gcount()));
    if (text.size() > kMaxBytes) throw std::invalid_argument(field + ": '" + path + "' is larger than 400 MB");
  }
  if (text.find('\0') != std::string::npos) throw std::invalid_argument(field + ": '" + path + "' is not a text file");
  std::string ext = path.size() >= 4 ? upper(path.substr(path.size() - 4)) : "";
  try {
    return ext == ".AT2" ? parse_at2(text, path) : parse_record_csv(text, path);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(field + ": " + e.what());
  }
}

}  // namespace blockdyn
