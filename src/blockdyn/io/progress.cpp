// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <stdexcept>

namespace blockdyn {

ProgressMode parse_progress_mode(const std::string& s) {
  if (s == "auto") return ProgressMode::Auto;
  if (s == "bar") return ProgressMode::Bar;
  if (s == "plain") return ProgressMode::Plain;
  if (s == "none") return ProgressMode::None;
  throw std::invalid_argument("progress = '" + s + "' is not one of: auto, bar, plain, none");
}

Progress::Progress(std::string label, std::size_t total, std::size_t already_done, ProgressMode mode, std::FILE* out,
                   double plain_interval_seconds, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      start_done_(already_done),
      done_(already_done),
      mode_(mode),
      out_(out),
      interval_(plain_interval_seconds),
      t0_(std::chrono::steady_clock::now()),
      last_(t0_) {
  if (mode_ == ProgressMode::Auto) mode_ = ::isatty(::fileno(out_)) ? ProgressMode::Bar : ProgressMode::Plain;
  if (mode_ == ProgressMode::Plain) {
    std::fprintf(out_, "%s: %zu %s, %zu already done\n", label_.c_str(), total_, unit_.c_str(), start_done_);
    std::fflush(out_);
  }
}

Progress::~Progress() {
  if (!finished_) finish();
}

std::string Progress::format_duration(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  char buf[32];
  const long t = std::lround(s);
  if (t < 60)
    std::snprintf(buf, sizeof buf, "%lds", t);
  else if (t < 3600)
    std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  else if (t < 86400)
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", t / 3600, (t % 3600) / 60);
  else
    std::snprintf(buf, sizeof buf, "%ldd%02ldh", t / 86400, (t % 86400) / 3600);
  return buf;
}

std::string Progress::line(double elapsed, int bar_width) const {
  const double frac = total_ ? double(done_) / double(total_) : 1.0;
  const double rate = elapsed > 0 ? double(done_ - start_done_) / elapsed : 0.0;
  const double eta = rate > 0 ? double(total_ - done_) / rate : NAN;
  std::string s = label_ + ": ";
  if (bar_width > 0) {
    const int fill = int(frac * bar_width);
    s += '[';
    s.append(std::size_t(fill), '#');
    s.append(std::size_t(bar_width - fill), ' ');
    s += "] ";
  }
  char buf[160];
  std::snprintf(buf, sizeof buf, "%zu/%zu (%.1f%%), %.3g %s/s, elapsed %s, ETA %s", done_, total_, 100.0 * frac, rate,
                unit_.c_str(), format_duration(elapsed).c_str(), done_ == total_ ? "0s" : format_duration(eta).c_str());
  return s + buf;
}

void Progress::advance(std::size_t n) {
  done_ += n;
  report(false);
}

void Progress::report(bool final) {
  if (mode_ == ProgressMode::None) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_).count();
  const double elapsed = std::chrono::duration<double>(now - t0_).count();
  if (mode_ == ProgressMode::Bar) {
    if (!final && since < 0.1 && done_ != total_) return;  // redraw at most 10 times a second
    std::fprintf(out_, "\r%s\033[K%s", line(elapsed, 30).c_str(), final ? "\n" : "");
  } else {
    if (!final && since < interval_) return;
    std::fprintf(out_, "%s\n", line(elapsed, 0).c_str());
  }
  std::fflush(out_);
  last_ = now;
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  report(true);
}

}  // namespace blockdyn
