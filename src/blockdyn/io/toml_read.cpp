// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/toml_read.hpp"

#include "blockdyn/io/input_files.hpp"

#include <sys/stat.h>
#include <cmath>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace blockdyn::toml_read {

void fail(const std::string& field, const std::string& msg) { throw std::invalid_argument(field + ": " + msg); }

std::string read_file(const std::string& path, const std::string& what) {
  // A definition is a small text file: not a directory, a device (/dev/zero) or megabytes.
  constexpr std::size_t kMaxBytes = 1u << 20;
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw std::invalid_argument(what + " '" + path + "' cannot be read: " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw std::invalid_argument(what + " '" + path + "' is not a regular file");
  if (std::size_t(st.st_size) > kMaxBytes)
    throw std::invalid_argument(what + " '" + path + "' is larger than 1 MiB: not a definition file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(what + " '" + path + "' cannot be read");
  std::string text(std::size_t(st.st_size), '\0');
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(std::size_t(in.gcount()));
  if (text.find('\0') != std::string::npos) throw std::invalid_argument(what + " '" + path + "' is not a text file");
  note_input(path);
  return text;
}

std::optional<long long> opt_integer(const toml::table& t, const std::string& where, const char* key, long long lo,
                                     long long hi) {
  const toml::node* n = t.get(key);
  if (!n) return std::nullopt;
  const std::string field = where + "." + key;
  const std::string range = "must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (n->is_integer()) {
    const long long v = *n->value<std::int64_t>();
    if (v < lo || v > hi) fail(field, std::to_string(v) + " is out of range: " + range);
    return v;
  }
  const double v = number(*n, field);
  if (v != std::floor(v) || v < double(lo) || v > double(hi)) {
    std::ostringstream os;
    os << v << " is out of range: " << range;
    fail(field, os.str());
  }
  return static_cast<long long>(v);
}

toml::table parse(const std::string& text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << source << ":" << e.source().begin.line << ": " << e.description();
    throw std::invalid_argument(os.str());
  }
}

std::string first_unknown_key(const toml::table& t, const std::set<std::string>& allowed) {
  for (const auto& [k, v] : t)
    if (!allowed.count(std::string(k.str()))) return std::string(k.str());
  return {};
}

std::string joined(const std::set<std::string>& allowed) {
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  return list;
}

double number(const toml::node& n, const std::string& field) {
  std::optional<double> v = n.value<double>();
  if (!v || !(n.is_floating_point() || n.is_integer())) fail(field, "must be a number");
  if (!std::isfinite(*v)) fail(field, "must be finite");
  return *v;
}

std::string string(const toml::node& n, const std::string& field) {
  if (!n.is_string()) fail(field, "must be a string");
  return *n.value<std::string>();
}

std::optional<double> opt_number(const toml::table& t, const std::string& where, const char* key) {
  const toml::node* n = t.get(key);
  if (!n) return std::nullopt;
  return number(*n, where + "." + key);
}

std::optional<std::string> opt_string(const toml::table& t, const std::string& where, const char* key) {
  const toml::node* n = t.get(key);
  if (!n) return std::nullopt;
  return string(*n, where + "." + key);
}

Method method(const std::string& name, const std::string& field) {
  if (const auto m = method_from_string(name)) return *m;
  fail(field, "must be one of auto, dopri5, dop853 (got '" + name + "')");
}

const toml::table* sub_table(const toml::table& t, const char* key, const std::string& field, const std::string& hint) {
  const toml::node* n = t.get(key);
  if (!n) return nullptr;
  if (!n->is_table()) fail(field, "must be a table" + hint);
  return n->as_table();
}

}  // namespace blockdyn::toml_read
