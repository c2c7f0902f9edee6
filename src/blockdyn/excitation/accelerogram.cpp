// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/excitation/accelerogram.hpp"

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

// Parses one number (Fortran 'D' exponents accepted); false if tok is not entirely a number.
bool to_number(std::string tok, double& v) {
  if (tok.empty()) return false;
  for (char& c : tok)
    if (c == 'D' || c == 'd') c = 'E';
  char* end = nullptr;
  errno = 0;
  v = std::strtod(tok.c_str(), &end);
  return end == tok.c_str() + tok.size() && errno != ERANGE;
}

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
    fail(where, "NPTS = " + std::to_string(n) + " is out of range: must be an integer in [2, " +
                    std::to_string(kMaxRecordSamples) + "]");
  if (!(d > 0) || !std::isfinite(d) || d > 10.0)
    fail(where, "DT = " + std::to_string(d) + " is out of range: must be in (0, 10] s");
  npts = long(n);
  dt = d;
}

}  // namespace

Accelerogram::Accelerogram(std::vector<double> a, double dt, std::string source)
    : a_(std::move(a)), dt_(dt), uniform_(true), source_(std::move(source)) {
  if (!(dt >= kMinRecordDt) || !(dt <= kMaxRecordDt))
    fail(source_, "sample spacing dt = " + std::to_string(dt) + " s is out of range: must be in [1e-6, 1e3] s");
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
      fail(source_, "sample " + std::to_string(i + 1) + ": the time step " + std::to_string(t_[i] - t_[i - 1]) +
                        " s is out of range: must be >= 1e-6 s");
  }
  if (t_.front() < 0) fail(source_, "the first sample time must be >= 0");
  if (!(t_.back() <= kMaxRecordDuration)) fail(source_, "the last sample time must be <= 1e7 s");
  // Equally spaced (to rounding): use the O(1) lookup of uniform records.
  const double d = (t_.back() - t_.front()) / double(t_.size() - 1);
  bool eq = t_.front() == 0.0;
  for (std::size_t i = 1; eq && i < t_.size(); ++i)
    eq = std::fabs(t_[i] - d * double(i)) <= 1e-9 * d;
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
      fail(source_, "sample " + std::to_string(i + 1) + " = " + std::to_string(a_[i]) +
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

double Accelerogram::peak() const {
  double m = 0;
  for (double v : a_) m = std::fmax(m, std::fabs(v));
  return m;
}

Accelerogram parse_at2(const std::string& text, const std::string& source) {
  const std::vector<std::string> lines = split_lines(text);
  if (lines.size() < 5) fail(source, "truncated AT2 file: 4 header lines and the values expected");
  long npts = 0;
  double dt = 0;
  parse_at2_counts(lines[3], source + ":4", npts, dt);
  std::vector<double> a;
  a.reserve(std::size_t(npts));
  for (std::size_t li = 4; li < lines.size(); ++li) {
    std::istringstream in(lines[li]);
    for (std::string tok; in >> tok;) {
      double v;
      if (!to_number(tok, v))
        fail(source + ":" + std::to_string(li + 1), "'" + tok + "' is not a number");
      if (long(a.size()) >= npts)
        fail(source + ":" + std::to_string(li + 1), "more values than NPTS = " + std::to_string(npts));
      a.push_back(v);
    }
  }
  if (long(a.size()) < npts)
    fail(source, "truncated AT2 file: NPTS = " + std::to_string(npts) + " but " + std::to_string(a.size()) +
                     " values found");
  return Accelerogram(std::move(a), dt, source);
}

Accelerogram parse_record_csv(const std::string& text, const std::string& source) {
  const std::vector<std::string> lines = split_lines(text);
  std::vector<double> t, a;
  bool first_data = true;
  for (std::size_t li = 0; li < lines.size(); ++li) {
    std::string s = lines[li];
    if (const auto h = s.find('#'); h != std::string::npos) s.erase(h);
    for (char& c : s)
      if (c == ',' || c == ';' || c == '\t') c = ' ';
    std::istringstream in(s);
    std::vector<std::string> tok;
    for (std::string x; in >> x;) tok.push_back(x);
    if (tok.empty()) continue;
    double tv = 0.0, av = 0.0;
    const bool numeric = tok.size() == 2 && to_number(tok[0], tv) && to_number(tok[1], av);
    if (!numeric) {
      if (first_data && t.empty()) {  // a header line
        first_data = false;
        continue;
      }
      fail(source + ":" + std::to_string(li + 1), "expected two numbers 't, a' (s, g)");
    }
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
  // Bounded read: 20 M samples of ~16 characters at most.
  constexpr std::size_t kMaxBytes = 400u << 20;
  std::string text;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, std::size_t(in.gcount()));
    if (text.size() > kMaxBytes) throw std::invalid_argument(field + ": '" + path + "' is larger than 400 MB");
  }
  if (text.find('\0') != std::string::npos)
    throw std::invalid_argument(field + ": '" + path + "' is not a text file");
  std::string ext = path.size() >= 4 ? upper(path.substr(path.size() - 4)) : "";
  try {
    return ext == ".AT2" ? parse_at2(text, path) : parse_record_csv(text, path);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(field + ": " + e.what());
  }
}

}  // namespace blockdyn
