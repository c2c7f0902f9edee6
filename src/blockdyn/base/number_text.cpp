// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/base/number_text.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace blockdyn {

std::string number_text(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string number_text(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string scientific_text(double v) {
  if (!std::isfinite(v)) return number_text(v);
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
  std::string s(buf, r.ptr);
  for (char& c : s)
    if (c == 'e') c = 'E';
  return s;
}

namespace {

std::size_t digits(const std::string& s, std::size_t i) {
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  return i;
}

}  // namespace

bool parse_decimal(const std::string& token, double& value) {
  std::string s = token;
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  const std::size_t int_end = digits(s, i);
  std::size_t j = int_end;
  std::size_t frac = 0;
  if (j < s.size() && s[j] == '.') {
    const std::size_t frac_end = digits(s, j + 1);
    frac = frac_end - (j + 1);
    j = frac_end;
  }
  if (int_end == i && frac == 0) return false;  // no digits at all
  if (j < s.size() && (s[j] == 'e' || s[j] == 'E' || s[j] == 'd' || s[j] == 'D')) {
    s[j] = 'E';
    std::size_t k = j + 1;
    if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
    const std::size_t exp_end = digits(s, k);
    if (exp_end == k) return false;
    j = exp_end;
  }
  if (j != s.size()) return false;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || std::isinf(v)) return false;
  value = v;
  return true;
}

}  // namespace blockdyn
