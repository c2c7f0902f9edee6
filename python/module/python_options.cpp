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
namespace {

// A cell as a CSV reader gives it: a quoted cell without its quotes ("" read as ").
std::string unquoted(const std::string& c) {
  if (c.size() < 2 || c.front() != '"' || c.back() != '"') return c;
  std::string s;
  for (std::size_t i = 1; i + 1 < c.size(); ++i) {
    s += c[i];
    if (c[i] == '"' && c[i + 1] == '"') ++i;
  }
  return s;
}

}  // namespace

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
  py::dict cols;
  for (std::size_t j = 0; j < t.columns.size(); ++j) {
    std::vector<double> numbers;
    std::vector<std::string> texts;
    bool numeric = true;
    for (const auto& row : t.rows) {
      const std::string c = unquoted(j < row.size() ? row[j] : std::string());
      char* end = nullptr;
      const double v = c.empty() ? std::nan("") : std::strtod(c.c_str(), &end);
      numeric = numeric && (c.empty() || end == c.c_str() + c.size());
      numbers.push_back(v);
      texts.push_back(c);
    }
    if (numeric)
      cols[py::str(t.columns[j])] = py::array_t<double>(py::ssize_t(numbers.size()), numbers.data());
    else
      cols[py::str(t.columns[j])] = py::cast(texts);
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
