// SPDX-License-Identifier: Apache-2.0
#pragma once
// Between Python and the library: keyword options to Settings (a record given as arrays becomes
// an Accelerogram), the library's messages with Python's option names, tables to NumPy columns.
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "blockdyn/analysis/sweep/grid_table.hpp"
#include "blockdyn/commands/settings.hpp"
#include "blockdyn/commands/study_command.hpp"

namespace blockdyn::python {

namespace py = pybind11;

using Samples = std::pair<std::vector<double>, std::vector<double>>;
using OptionValue = std::variant<std::string, Samples>;
using OptionList = std::vector<std::pair<std::string, OptionValue>>;

// Option names in the library's text, as Python's keywords.
std::string python_text(std::string_view text);
Settings settings_of(const OptionList& options);
// A study's table as columns, as blockdyn's CSV reader gives them: numbers (empty cells NaN) where
// every cell is a number or empty, else text.
py::dict study_columns(const StudyTable& t);
// A runner table's rows, as a study's table.
StudyTable study_table_of(const Table& t);
// A library call from options by name to a JSON document, without the GIL: the document's text.
std::string json_call(const std::function<nlohmann::ordered_json(const Settings&)>& call, const OptionList& options);

// The module's parts, each adding its functions.
void add_runs(py::module_& m);
void add_studies(py::module_& m);
void add_tables(py::module_& m);
void add_records_and_catalogues(py::module_& m);

}  // namespace blockdyn::python
