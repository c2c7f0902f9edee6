// SPDX-License-Identifier: Apache-2.0
// The studies by name from Python (the thesis's analyses, the orbit studies, the grid analyses
// computed in memory): options by name, tables as NumPy columns, the summary as JSON text.
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "blockdyn/commands/grid_studies.hpp"
#include "blockdyn/commands/study_command.hpp"
#include "blockdyn/io/json_io.hpp"
#include "python_options.hpp"

namespace blockdyn::python {

// The studies and grid analyses by name, from memory; the command line in process for the rest.
void add_studies(py::module_& m) {
  m.def(
      "study",
      [](const std::string& name, const OptionList& options, bool table,
         const std::vector<std::string>& series_wanted) {
        const Settings s = settings_of(options);
        StudyRequest request;
        request.want_table = table;
        request.series = series_wanted;
        StudyReport r;
        {
          py::gil_scoped_release release;
          r = run_study(name, s, request);
        }
        nlohmann::ordered_json doc;
        doc["schema"] = schema_name(name, "summary");
        for (auto it = r.summary.begin(); it != r.summary.end(); ++it) doc[it.key()] = it.value();
        py::dict series;
        for (const NamedTable& t : r.series) series[py::str(t.name)] = study_columns(t.table);
        return py::make_tuple(study_columns(r.table), dump_json(doc), r.text, series);
      },
      py::arg("name"), py::arg("options"), py::arg("table") = true, py::arg("series") = std::vector<std::string>{},
      "Runs a study (blockdyn.studies()); returns ({column: array or list}, summary JSON text, text, "
      "{series name: {column: array}}).");
  m.def(
      "grid_study",
      [](const std::string& name, const OptionList& options) {
        const Settings s = settings_of(options);
        StudyReport r;
        {
          py::gil_scoped_release release;
          r = run_grid_study(name, s);
        }
        nlohmann::ordered_json doc;
        doc["schema"] = schema_name(name, "summary");
        for (auto it = r.summary.begin(); it != r.summary.end(); ++it) doc[it.key()] = it.value();
        return py::make_tuple(study_columns(r.table), dump_json(doc), r.text);
      },
      py::arg("name"), py::arg("options"),
      "Runs a grid analysis (survival) in memory on its threads; returns ({column: array}, summary JSON text, text).");
}

}  // namespace blockdyn::python
