// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/settings.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace blockdyn {

namespace {
std::string canonical_alias(const std::string& a) { return Settings::canonical(a); }
}  // namespace

std::string Settings::canonical(std::string_view name) {
  std::string s(name);
  while (!s.empty() && s.front() == '-') s.erase(s.begin());
  for (char& c : s)
    if (c == '_') c = '-';
  return s;
}

std::string Settings::exact(double v) { return number_text(v); }

void Settings::add(std::string_view name, std::string value) {
  entries_[canonical(name)].values.push_back(std::move(value));
}

void Settings::set(std::string_view name, std::string value) {
  Entry& e = entries_[canonical(name)];
  e.values.assign(1, std::move(value));
}

void Settings::add_record(std::string_view name, std::shared_ptr<const Accelerogram> record) {
  entries_[canonical(name)].record = std::move(record);
}

const Settings::Entry* Settings::find(std::string_view name) const {
  const auto it = entries_.find(name);
  return it == entries_.end() ? nullptr : &it->second;
}

bool Settings::has(std::string_view name) const { return find(name) != nullptr; }

namespace {
std::invalid_argument bad(std::string_view name, const std::string& value, const char* what) {
  return std::invalid_argument(std::string("`") + std::string(name) + "` = '" + value + "' is not " + what);
}
}  // namespace

std::optional<double> Settings::number(std::string_view name) const {
  const Entry* e = find(name);
  if (!e || e->values.empty()) return std::nullopt;
  const std::string& v = e->values.back();
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || end != v.c_str() + v.size()) throw bad(name, v, "a number");
  return x;
}

double Settings::number(std::string_view name, double fallback) const { return number(name).value_or(fallback); }

long Settings::integer(std::string_view name, long fallback) const {
  const Entry* e = find(name);
  if (!e || e->values.empty()) return fallback;
  const std::string& v = e->values.back();
  char* end = nullptr;
  errno = 0;
  const long x = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || end != v.c_str() + v.size() || errno == ERANGE) throw bad(name, v, "an integer");
  return x;
}

int Settings::small_integer(std::string_view name, int fallback) const {
  const long v = integer(name, fallback);
  if (v < -2147483647L || v > 2147483647L)
    throw std::invalid_argument(std::string(name) + " = " + std::to_string(v) +
                                " is out of range: must be at most 2147483647 in size");
  return int(v);
}

std::string Settings::text(std::string_view name, const std::string& fallback) const {
  const Entry* e = find(name);
  return e && !e->values.empty() ? e->values.back() : fallback;
}

bool Settings::flag(std::string_view name) const {
  const Entry* e = find(name);
  if (!e) return false;
  if (e->values.empty()) return true;
  const std::string& v = e->values.back();
  if (v == "true" || v == "1" || v == "True") return true;
  if (v == "false" || v == "0" || v == "False") return false;
  throw bad(name, v, "true or false");
}

std::vector<std::string> Settings::values(std::string_view name) const {
  const Entry* e = find(name);
  return e ? e->values : std::vector<std::string>{};
}

std::shared_ptr<const Accelerogram> Settings::record(std::string_view name) const {
  const Entry* e = find(name);
  return e ? e->record : nullptr;
}

std::vector<std::string> Settings::names() const {
  std::vector<std::string> n;
  for (const auto& [k, v] : entries_) n.push_back(k);
  return n;
}

void Settings::require_known(const std::vector<std::string>& known, const std::string& what) const {
  for (const auto& [k, v] : entries_) {
    bool ok = false;
    for (const std::string& n : known) ok = ok || n == k;
    if (!ok) throw std::invalid_argument(std::string("`") + k + "`: not an option of " + what);
  }
}

void Settings::require_known(const std::vector<StudyOption>& specs, const std::vector<std::string>& extra,
                             const std::string& what) const {
  std::vector<std::string> known = extra;
  for (const StudyOption& o : specs) {
    known.push_back(o.name);
    known.insert(known.end(), o.aliases.begin(), o.aliases.end());
  }
  require_known(known, what);
}

Settings with_canonical_names(const Settings& s, const std::vector<StudyOption>& specs) {
  Settings out;
  for (const std::string& n : s.names()) {
    std::string name = n;
    for (const StudyOption& o : specs)
      for (const std::string& a : o.aliases)
        if (canonical_alias(a) == n) {
          if (s.has(o.name))
            throw std::invalid_argument(std::string("`") + n + "` and `" + o.name + "`: the same option, give one");
          name = o.name;
        }
    for (const std::string& v : s.values(n)) out.add(name, v);
    if (s.values(n).empty() && !s.record(n)) out.add(name, "true");
    if (const auto r = s.record(n)) out.add_record(name, r);
  }
  return out;
}

void apply_integrator_settings(const Settings& s, IntegratorOptions& o) {
  o.rtol = s.number("rtol", o.rtol);
  o.atol = s.number("atol", o.atol);
  if (s.has("method")) {
    const std::string v = s.text("method");
    const auto m = method_from_string(v);
    if (!m) throw std::invalid_argument("`method` = '" + v + "' is not one of: auto, dopri5, dop853");
    o.method = *m;
  }
}

}  // namespace blockdyn
