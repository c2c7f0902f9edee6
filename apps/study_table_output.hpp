// SPDX-License-Identifier: Apache-2.0
#pragma once
// A study's table as CSV, written atomically, with its JSON sidecar <path>.json.
#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

#include "blockdyn/commands/study_command.hpp"

namespace blockdyn::cli {

// The header line and the rows.
void write_study_rows(std::ostream& os, const StudyTable& t);
// The sidecar as given.
void write_study_csv(const std::string& path, const StudyTable& t, const nlohmann::ordered_json& sidecar);
// The sidecar `meta` plus the CSV's path ("csv") and its column names ("columns").
void write_study_table(const std::string& path, const StudyTable& t, nlohmann::ordered_json meta);

}  // namespace blockdyn::cli
