// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/sweep_axis.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace blockdyn {

const char* to_string(AxisSpacing s) { return s == AxisSpacing::Log ? "log" : "linear"; }

namespace {

[[noreturn]] void fail(const std::string& name, const std::string& msg) {
  throw std::invalid_argument("axes." + name + ": " + msg);
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) out.push_back(trim(cur));
  if (!s.empty() && s.back() == sep) out.push_back("");
  return out;
}

double to_double(const std::string& name, const std::string& tok) {
  double v = 0;
  const char* end = tok.data() + tok.size();
  auto [p, ec] = std::from_chars(tok.data(), end, v);
  if (tok.empty() || ec != std::errc() || p != end)
    fail(name, "'" + tok + "' is not a number (expected \"v1,v2,...\" or \"min:max:points[:log|:lin]\")");
  return v;
}

}  // namespace

SweepAxis axis_range(const std::string& name, double min, double max, long points, AxisSpacing spacing) {
  if (!std::isfinite(min) || !std::isfinite(max)) fail(name, "min and max must be finite");
  if (points < 1 || points > kMaxAxisPoints)
    fail(name, "points = " + std::to_string(points) + " is out of range: must be in [1, 1e6]");
  if (min > max) fail(name, "min must be <= max");
  if (points == 1 && min != max) fail(name, "points = 1 needs min == max (or give a list of values)");
  if (spacing == AxisSpacing::Log && !(min > 0)) fail(name, "log spacing needs min > 0");
  SweepAxis a;
  a.name = name;
  a.is_range = true;
  a.min = min;
  a.max = max;
  a.points = points;
  a.spacing = spacing;
  a.values.resize(std::size_t(points));
  // Endpoints are set exactly; interior values from the index (no accumulated increments).
  const double lo = spacing == AxisSpacing::Log ? std::log10(min) : min;
  const double hi = spacing == AxisSpacing::Log ? std::log10(max) : max;
  for (long i = 0; i < points; ++i) {
    double v;
    if (i == 0)
      v = min;
    else if (i == points - 1)
      v = max;
    else {
      const double u = lo + (hi - lo) * double(i) / double(points - 1);
      v = spacing == AxisSpacing::Log ? std::pow(10.0, u) : u;
    }
    a.values[std::size_t(i)] = v;
  }
  return a;
}

SweepAxis axis_list(const std::string& name, std::vector<double> values) {
  if (values.size() > std::size_t(kMaxAxisPoints)) fail(name, "more than 1e6 values");
  if (values.empty()) fail(name, "the list of values is empty");
  for (double v : values)
    if (!std::isfinite(v)) fail(name, "values must be finite");
  SweepAxis a;
  a.name = name;
  a.values = std::move(values);
  return a;
}

SweepAxis parse_axis(const std::string& name, const std::string& text, AxisSpacing default_spacing) {
  const std::string t = trim(text);
  if (t.find(':') != std::string::npos) {
    auto parts = split(t, ':');
    AxisSpacing sp = default_spacing;
    if (parts.size() == 4) {
      if (parts[3] == "log")
        sp = AxisSpacing::Log;
      else if (parts[3] == "lin" || parts[3] == "linear")
        sp = AxisSpacing::Linear;
      else
        fail(name, "spacing '" + parts[3] + "' is not one of: log, lin");
      parts.pop_back();
    }
    if (parts.size() != 3) fail(name, "'" + t + "' is not of the form min:max:points[:log|:lin]");
    const double n = to_double(name, parts[2]);
    // Checked as a double before the conversion (1e300 points must not wrap to a negative long).
    if (n != std::floor(n) || !(n >= 1) || n > double(kMaxAxisPoints))
      fail(name, "points = " + parts[2] + " is out of range: must be an integer in [1, 1e6]");
    return axis_range(name, to_double(name, parts[0]), to_double(name, parts[1]), long(n), sp);
  }
  std::vector<double> v;
  for (const auto& tok : split(t, ',')) v.push_back(to_double(name, tok));
  return axis_list(name, std::move(v));
}

void require_axis_range(const SweepAxis& a, double lo, bool lo_incl) {
  for (double v : a.values) {
    if (std::isfinite(v) && (lo_incl ? v >= lo : v > lo)) continue;
    std::ostringstream os;
    os.precision(17);
    os << "value " << v << " is out of range: must be finite and " << (lo_incl ? ">= " : "> ") << lo;
    fail(a.name, os.str());
  }
}

nlohmann::ordered_json to_json(const SweepAxis& a) {
  nlohmann::ordered_json j;
  if (a.is_range) {
    j["min"] = a.min;
    j["max"] = a.max;
    j["points"] = a.points;
    j["spacing"] = to_string(a.spacing);
  }
  j["values"] = a.values;
  return j;
}

}  // namespace blockdyn
