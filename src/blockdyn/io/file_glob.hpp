// SPDX-License-Identifier: Apache-2.0
#pragma once
// The files a shell pattern names ('suite/*.AT2'), sorted as glob(3) sorts them.
#include <cstddef>
#include <string>
#include <vector>

namespace blockdyn {

// Throws std::invalid_argument naming `field` when the pattern matches no file or more than
// `max_files`.
std::vector<std::string> expand_glob(const std::string& field, const std::string& pattern, std::size_t max_files);

}  // namespace blockdyn
