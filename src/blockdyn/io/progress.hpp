// SPDX-License-Identifier: Apache-2.0
#pragma once
// Progress report for long batch jobs: a redrawn bar with rate and ETA when the stream is a
// terminal, plain lines every few seconds otherwise (logs, CI), or nothing.
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>

namespace blockdyn {

enum class ProgressMode { Auto, Bar, Plain, None };
// "auto" | "bar" | "plain" | "none"; throws std::invalid_argument otherwise.
ProgressMode parse_progress_mode(const std::string& s);

class Progress {
 public:
  // `already_done` items (e.g. resumed) count toward the total but not toward the rate.
  // `unit`: what is counted, in the report's words ("points", "records").
  Progress(std::string label, std::size_t total, std::size_t already_done, ProgressMode mode, std::FILE* out = stderr,
           double plain_interval_seconds = 10.0, std::string unit = "points");
  ~Progress();  // finish() if not yet called

  void advance(std::size_t n = 1);  // not thread-safe: call under the caller's lock
  void finish();                    // final line (bar: newline after the last redraw)
  std::size_t done() const { return done_; }
  ProgressMode mode() const { return mode_; }

  // "ETA"-style durations: 45s, 3m05s, 2h07m, 3d04h.
  static std::string format_duration(double seconds);
  // The text of one report (without '\r' or '\n'); bar_width 0: no bar.
  std::string line(double elapsed_seconds, int bar_width) const;

 private:
  void report(bool final);
  std::string label_, unit_;
  std::size_t total_, start_done_, done_;
  ProgressMode mode_;
  std::FILE* out_;
  double interval_;
  std::chrono::steady_clock::time_point t0_, last_;
  bool finished_ = false;
};

}  // namespace blockdyn
