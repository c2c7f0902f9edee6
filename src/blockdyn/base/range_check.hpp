// SPDX-License-Identifier: Apache-2.0
#pragma once
// The range check of an option's value: std::invalid_argument "<field> = <v> is out of range:
// must be finite and in [lo, hi]" (brackets as the bounds are included or not).
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace blockdyn {

inline void require_in_range(const std::string& field, double v, double lo, double hi, bool lo_incl = true,
                             bool hi_incl = true) {
  const bool ok = std::isfinite(v) && (lo_incl ? v >= lo : v > lo) && (hi_incl ? v <= hi : v < hi);
  if (ok) return;
  std::ostringstream os;
  os << field << " = " << v << " is out of range: must be finite and in " << (lo_incl ? "[" : "(") << lo << ", " << hi
     << (hi_incl ? "]" : ")");
  throw std::invalid_argument(os.str());
}

// A sampling interval that would give more than max_samples samples over `span` (a trajectory with
// output-interval 1e-300) is refused naming the field; interval <= 0 (every step) is left to the
// caller.
inline void require_sample_count(const std::string& field, double interval, double span, double max_samples) {
  if (!(interval > 0.0) || !std::isfinite(span)) return;
  const double n = span / interval;
  if (n <= max_samples) return;
  std::ostringstream os;
  os << field << " = " << interval << " gives " << n << " samples over " << span << ": at most " << max_samples
     << " allowed (give a larger " << field << ")";
  throw std::invalid_argument(os.str());
}

}  // namespace blockdyn
