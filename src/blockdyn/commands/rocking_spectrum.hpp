// SPDX-License-Identifier: Apache-2.0
#pragma once
// `blockdyn rocking-spectrum` (Makris & Konstantinidis 2003): for one record and one slenderness
// alpha, the largest rotation over alpha and overturning as functions of the block's size through
// its frequency parameter p = sqrt(3 g / (4 R)), optionally over record scale factors too (the
// overturning scale of a record); for a body in space (rigid3d) over a suite of one- to
// three-component records and incidences, with the critical incidence. A grid study: threads, MPI, journal on the
// command line; in memory from Python.
#include <string>
#include <vector>

#include "blockdyn/commands/grid_studies.hpp"
#include "blockdyn/commands/study_command.hpp"
#include "blockdyn/family/family.hpp"

namespace blockdyn {

GridStudyCommand rocking_spectrum_command();

// The spectrum of a body in space (a family whose forced model is `spatial`: rigid3d) over a suite
// and incidences (rocking_spectrum_3d.cpp); `so` the command's options as given.
GridStudy rocking_grid_3d(const StudyOptions& so, const Family& family, const std::string& output);
// The command's p values (`p-values`, or `p-min` `p-max` `p-points`), checked.
std::vector<double> rocking_p_values(const StudyOptions& o);

}  // namespace blockdyn
