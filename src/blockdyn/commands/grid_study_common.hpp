// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the harmonic grid studies share (survival_study.cpp, response_curve_study.cpp): the
// excitation's options, their reading, and the figure title of the model under it.
#include <string>
#include <vector>

#include "blockdyn/analysis/forced/survival_map.hpp"
#include "blockdyn/commands/forced_model_settings.hpp"
#include "blockdyn/commands/study_command.hpp"

namespace blockdyn {

// --excitation --phase --omega-min/max/points --t-end --periods --threads (survival, response-curve).
std::vector<StudyOption> excitation_grid_options();
SurvivalOptions excitation_grid_of(const StudyOptions& o);
std::string title_of(const ForcedModelChoice& m, const std::string& excitation);

// The grid studies of their own files (grid_study_commands() lists them).
GridStudyCommand spectrum_command();
GridStudyCommand survival_command();
GridStudyCommand response_curve_command();

}  // namespace blockdyn
