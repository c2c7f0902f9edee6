// SPDX-License-Identifier: Apache-2.0
#include "python_options.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <stdexcept>

#include "blockdyn/commands/option_spec.hpp"
#include "blockdyn/excitation/accelerogram.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn::python {
namespace {}  // namespace

std::string python_text(std::string_view text) { return spell_options(text, "", true); }

Settings settings_of(const OptionList& options) {
  Settings s;
  for (const auto& [name, value] : options) {
    if (const auto* text = std::get_if<std::string>(&value)) {
      s.add(name, *text);
    } else {
      const auto& [t, a] = std::get<Samples>(value);
      const std::string field = "--" + Settings::canonical(name);
      if (t.size() != a.size())
        throw std::invalid_argument(field + ": times and accelerations differ in length (" + std::to_string(t.size()) +
                                    " and " + std::to_string(a.size()) + ")");
      s.add_record(name, std::make_shared<const Accelerogram>(t, a, field + " (arrays)"));
      s.add(name, "(arrays)");
    }
  }
  return s;
}

py::dict study_columns(const StudyTable& t) {
  // A column of numbers (empty cells NaN) is a NumPy array; a column holding a label is a list of
  // texts (numbers in it as the CSV writer writes them).
  py::dict cols;
  for (std::size_t j = 0; j < t.columns.size(); ++j) {
    bool numeric = true;
    for (const CellRow& row : t.rows) numeric = numeric && (j >= row.size() || row[j].empty() || row[j].is_number());
    if (numeric) {
      py::array_t<double> a(py::ssize_t(t.rows.size()));
      double* out = a.mutable_data();
      for (const CellRow& row : t.rows) *out++ = j < row.size() && !row[j].empty() ? row[j].number() : std::nan("");
      cols[py::str(t.columns[j])] = std::move(a);
    } else {
      std::vector<std::string> texts;
      texts.reserve(t.rows.size());
      for (const CellRow& row : t.rows) texts.push_back(j < row.size() ? row[j].text() : std::string());
      cols[py::str(t.columns[j])] = py::cast(texts);
    }
  }
  return cols;
}

StudyTable study_table_of(const Table& t) {
  StudyTable out;
  out.columns = t.columns;
  for (const TableRow& r : t.rows) out.rows.push_back(r.cells);
  return out;
}

std::string json_call(const std::function<nlohmann::ordered_json(const Settings&)>& call, const OptionList& options) {
  const Settings s = settings_of(options);
  nlohmann::ordered_json j;
  {
    py::gil_scoped_release release;
    j = call(s);
  }
  return dump_json(j);
}

}  // namespace blockdyn::python
