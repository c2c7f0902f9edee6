// SPDX-License-Identifier: Apache-2.0
#pragma once
// A record as PEER .AT2 text (samples in g): the four header lines, then five samples per line,
// each the shortest decimal that reads back to the same double, right-aligned in a field of 25
// characters so that columns line up and neighbours never touch (the largest double, negative,
// takes 24). parse_at2 reads every such file back to the very samples written.
#include <string>
#include <vector>

namespace blockdyn {

std::string at2_text(const std::vector<double>& a, double dt, const std::string& title);

}  // namespace blockdyn
