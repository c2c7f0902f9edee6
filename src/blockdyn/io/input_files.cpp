// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/input_files.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace blockdyn {
namespace {

struct Input {
  std::string path;
  dev_t dev;
  ino_t ino;
};

std::mutex g_lock;
std::vector<Input> g_inputs;

std::string absolute_name(const std::string& p) {
  std::error_code ec;
  const auto a = std::filesystem::weakly_canonical(std::filesystem::absolute(p, ec), ec);
  return ec ? p : a.string();
}

}  // namespace

void note_input(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return;
  const std::lock_guard<std::mutex> lock(g_lock);
  for (const Input& i : g_inputs)
    if (i.dev == st.st_dev && i.ino == st.st_ino) return;
  g_inputs.push_back({path, st.st_dev, st.st_ino});
}

void clear_inputs() {
  const std::lock_guard<std::mutex> lock(g_lock);
  g_inputs.clear();
}

std::optional<std::string> input_at(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;  // a new file overwrites nothing
  const std::lock_guard<std::mutex> lock(g_lock);
  for (const Input& i : g_inputs)
    if (i.dev == st.st_dev && i.ino == st.st_ino) return i.path;
  return std::nullopt;
}

void require_not_input(const std::string& field, const std::string& path) {
  if (const auto in = input_at(path))
    throw std::invalid_argument(field + " = '" + path + "' is an input of this run ('" + *in +
                                "'): an output never overwrites an input; give another name");
}

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {
  }, sb{};
  const bool ea = ::stat(a.c_str(), &sa) == 0, eb = ::stat(b.c_str(), &sb) == 0;
  if (ea && eb) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  if (ea != eb) return false;
  return absolute_name(a) == absolute_name(b);
}

}  // namespace blockdyn
