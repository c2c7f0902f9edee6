// SPDX-License-Identifier: Apache-2.0
#pragma once
// One axis of a parameter sweep: an explicit list of values or a range (linear or log-spaced)
// expanded once, so every consumer (points, CSV, sidecar, fingerprint) sees the same doubles.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace blockdyn {

enum class AxisSpacing { Linear, Log };

// Most values one axis may have, and most points a sweep may have.
inline constexpr long kMaxAxisPoints = 1'000'000;
inline constexpr std::size_t kMaxSweepPoints = 100'000'000;
const char* to_string(AxisSpacing s);

struct SweepAxis {
  std::string name;            // k, r, inv_r, mu
  std::vector<double> values;  // expanded, in sweep order
  bool is_range = false;       // how it was given (recorded in the sidecar)
  double min = 0, max = 0;
  long points = 0;
  AxisSpacing spacing = AxisSpacing::Linear;
};

// Range: `points` values from min to max inclusive (endpoints exact). Log spacing is uniform in
// log10 and needs min > 0. Throws std::invalid_argument naming `name`.
SweepAxis axis_range(const std::string& name, double min, double max, long points, AxisSpacing spacing);
SweepAxis axis_list(const std::string& name, std::vector<double> values);

// Text form used by CLI flags and TOML strings: "v1,v2,..." (a list, one value allowed) or
// "min:max:points" with an optional ":log" / ":lin" suffix (default `spacing`).
SweepAxis parse_axis(const std::string& name, const std::string& text, AxisSpacing default_spacing);

// Throws std::invalid_argument unless every value is finite and > lo (or >= lo if lo_incl).
void require_axis_range(const SweepAxis& a, double lo, bool lo_incl);

nlohmann::ordered_json to_json(const SweepAxis& a);

}  // namespace blockdyn
