// SPDX-License-Identifier: Apache-2.0
#pragma once
// A suite of ground motions by component and the incidences they arrive at: what the record
// studies (fragility, the rocking spectrum) read from their options.
#include <string>
#include <vector>

#include "blockdyn/commands/settings.hpp"

namespace blockdyn {

// A suite's record files: h1 (or the records), and h2 and v where it has those components.
struct SuiteRecords {
  std::vector<std::string> h1, h2, v;
  std::vector<std::string> component_names() const {
    std::vector<std::string> c{"h1"};
    if (!h2.empty()) c.push_back("h2");
    if (!v.empty()) c.push_back("v");
    return c;
  }
};
// The records of a `motion generate` directory (its motions.json); std::invalid_argument naming
// `suite`.
SuiteRecords suite_records(const std::string& dir);
// `incidence` as one angle or A:B:N / a list (degrees, in [-360, 360]); one 0 where not given.
std::vector<double> incidences_of(const Settings& given);

}  // namespace blockdyn
