// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/file_glob.hpp"

#include <glob.h>

#include <stdexcept>

namespace blockdyn {

std::vector<std::string> expand_glob(const std::string& field, const std::string& pattern, std::size_t max_files) {
  glob_t g{};
  const int rc = ::glob(pattern.c_str(), 0, nullptr, &g);
  std::vector<std::string> files;
  if (rc == 0)
    for (std::size_t i = 0; i < g.gl_pathc; ++i) files.emplace_back(g.gl_pathv[i]);
  ::globfree(&g);
  if (files.empty()) throw std::invalid_argument(field + " = '" + pattern + "' matches no file");
  if (files.size() > max_files)
    throw std::invalid_argument(field + ": at most " + std::to_string(max_files) + " files");
  return files;
}

}  // namespace blockdyn
