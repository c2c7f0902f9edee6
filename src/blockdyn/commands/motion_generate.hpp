// SPDX-License-Identifier: Apache-2.0
#pragma once
// `blockdyn motion generate`: a suite of synthetic records (excitation/stochastic_motion.hpp)
// written as PEER .AT2 files (g) into a directory with `motions.json`: per record its file and
// measured pga, pgv, pgd, arias, d5_95, t_mid, mean period and end state, and the suite's
// medians against the targets. Same seed, the same bytes whatever the thread count.
#include <cstddef>
#include <functional>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/commands/option_spec.hpp"
#include "blockdyn/commands/settings.hpp"

namespace blockdyn {

const std::vector<StudyOption>& motion_generate_options();
// Checks every option first (std::invalid_argument naming it; the targets must fit the record, the
// work and the files a stated budget), then writes the records and motions.json into `out`
// (created if missing; an existing suite needs `overwrite`, which removes its records) and returns
// that document. Records are written under temporary names and renamed when all are made: an
// error leaves the directory as it was. `progress` (may be empty) is called as records complete (done of
// total), from one thread at a time.
nlohmann::ordered_json motion_generate(const Settings& s,
                                       const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace blockdyn
