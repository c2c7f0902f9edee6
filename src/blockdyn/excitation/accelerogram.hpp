// SPDX-License-Identifier: Apache-2.0
#pragma once
// A recorded ground acceleration: samples (t_i, a_i) in seconds and units of g, linear between
// samples, zero outside [t_0, t_last]. Read from a PEER NGA .AT2 file or a two-column CSV.
// Sample times are breakpoints of the input (its slope jumps there).
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace blockdyn {

class Accelerogram {
 public:
  // Uniform samples a_i at t_i = i dt (dt > 0). Throws std::invalid_argument.
  Accelerogram(std::vector<double> a, double dt, std::string source);
  // Samples at strictly increasing times t_i. Throws std::invalid_argument.
  Accelerogram(std::vector<double> t, std::vector<double> a, std::string source);

  double at(double t) const;  // linear interpolation, 0 outside the record
  // Slope of the segment that starts at or before t and ends after it (0 outside the record).
  double slope(double t) const;
  // First sample time strictly after t (infinity past the last sample).
  double next_sample_after(double t) const;

  std::size_t size() const { return a_.size(); }
  double t_first() const { return uniform_ ? 0.0 : t_.front(); }
  double t_last() const { return uniform_ ? dt_ * double(a_.size() - 1) : t_.back(); }
  double peak() const;  // max |a_i| (g)
  bool uniform() const { return uniform_; }
  double dt() const { return dt_; }  // sample spacing (uniform records), else 0
  const std::string& source() const { return source_; }
  const std::vector<double>& values() const { return a_; }
  double time(std::size_t i) const { return uniform_ ? dt_ * double(i) : t_[i]; }
  // A hash of the samples and their times (16 hex digits): the record's identity in fingerprints.
  std::string digest() const;

 private:
  void check_values() const;
  std::vector<double> t_;  // empty when uniform
  std::vector<double> a_;
  double dt_ = 0.0, inv_dt_ = 0.0;
  bool uniform_ = true;
  std::string source_;
};

// Largest record accepted (samples): a guard against reading a runaway file into memory.
inline constexpr std::size_t kMaxRecordSamples = 20'000'000;
// Sample spacing accepted (s): strong-motion instruments sample at 50-1000 Hz; 1 MHz and one
// sample per 1000 s are far outside, and every sample is a breakpoint the integrator stops at.
inline constexpr double kMinRecordDt = 1e-6, kMaxRecordDt = 1e3;
inline constexpr double kMaxRecordDuration = 1e7;

// PEER NGA .AT2: 4 header lines, the 4th giving NPTS and DT ("NPTS=  7807, DT=   .00500 SEC",
// "3930   0.00500   NPTS, DT", ...), then NPTS free-format values in g.
// Throws std::invalid_argument "<field>: <what is wrong>" naming the file and line.
Accelerogram parse_at2(const std::string& text, const std::string& source);
// Two columns "t, a" (s, g), optional header line, '#' comments; times strictly increasing.
Accelerogram parse_record_csv(const std::string& text, const std::string& source);
// Reads FILE by its extension (.at2 / .AT2, else CSV). field names the option in errors.
Accelerogram load_accelerogram(const std::string& path, const std::string& field);

}  // namespace blockdyn
