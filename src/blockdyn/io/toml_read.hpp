// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading helpers shared by the TOML inputs (scenarios, sweeps): every error is a
// std::invalid_argument "field: what is wrong", naming the offending key.
#include <toml++/toml.h>

#include <optional>
#include <set>
#include <string>

#include "blockdyn/integrate/integrator_options.hpp"

namespace blockdyn::toml_read {

[[noreturn]] void fail(const std::string& field, const std::string& msg);

// The whole file as text; throws "<what> '<path>' cannot be read".
std::string read_file(const std::string& path, const std::string& what);
// Parses TOML; a syntax error becomes "source:line: description".
toml::table parse(const std::string& text, const std::string& source);

// The first key of t not in allowed (empty when all are), and allowed as "a, b, c".
std::string first_unknown_key(const toml::table& t, const std::set<std::string>& allowed);
std::string joined(const std::set<std::string>& allowed);

double number(const toml::node& n, const std::string& field);  // finite number
std::string string(const toml::node& n, const std::string& field);
// t[key] when present; field names it in errors.
std::optional<double> opt_number(const toml::table& t, const std::string& where, const char* key);
std::optional<std::string> opt_string(const toml::table& t, const std::string& where, const char* key);
// t[key] as a whole number in [lo, hi] (a TOML integer, or a float with an integral value);
// "where.key: must be a whole number in [lo, hi]" otherwise. Checked before any conversion.
std::optional<long long> opt_integer(const toml::table& t, const std::string& where, const char* key, long long lo,
                                     long long hi);
// The sub-table t[key] or nullptr when absent; "field: must be a table<hint>" when not a table.
const toml::table* sub_table(const toml::table& t, const char* key, const std::string& field,
                             const std::string& hint = "");

// A Runge-Kutta method name (auto, dopri5, dop853); "field: must be ..." otherwise.
Method method(const std::string& name, const std::string& field);

// The state overrides x0, y0, vx0, vy0, vw0 of the table [where] into the same-named optionals of in.
template <class Initial>
void read_state_overrides(const toml::table& t, const std::string& where, Initial& in) {
  in.x0 = opt_number(t, where, "x0");
  in.y0 = opt_number(t, where, "y0");
  in.vx0 = opt_number(t, where, "vx0");
  in.vy0 = opt_number(t, where, "vy0");
  in.vw0 = opt_number(t, where, "vw0");
}

}  // namespace blockdyn::toml_read
