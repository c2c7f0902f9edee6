// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/grid_table.hpp"

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "blockdyn/analysis/sweep/point_table.hpp"
#include "blockdyn/analysis/sweep/sweep_spec.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

GridTable::GridTable(std::string kind, std::vector<std::string> columns, std::size_t size, Cells cells,
                     nlohmann::ordered_json definition, nlohmann::ordered_json tolerances, std::string output)
    : kind_(std::move(kind)),
      size_(size),
      cells_(std::move(cells)),
      definition_(std::move(definition)),
      tolerances_(std::move(tolerances)),
      output_(std::move(output)) {
  columns_.push_back("index");
  columns_.insert(columns_.end(), columns.begin(), columns.end());
  header_ = csv_header(columns_);
  fingerprint_ =
      fingerprint_hex(kind_ + "\n" + dump_json(definition_, -1) + "\n" + dump_json(tolerances_, -1) + "\n" + header_);
}

SweepRow GridTable::row(std::size_t index) const {
  RowBuilder b;
  b.add(index);
  cells_(index, b);
  SweepRow r{b.finish(), ""};
  if (split_csv_line(r.text.substr(0, r.text.size() - 1)).size() != columns_.size())
    throw std::logic_error(kind_ + ": point " + std::to_string(index) + " has a row of the wrong width");
  return r;
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        out.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

std::size_t Table::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  throw std::invalid_argument("table has no column '" + name + "'");
}

Table read_table(const std::string& path, const std::string& expected_header) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read '" + path + "'");
  std::string line;
  if (!std::getline(in, line) || line + "\n" != expected_header)
    throw std::runtime_error("'" + path + "' does not hold the expected columns");
  Table t;
  t.columns = split_csv_line(line);
  // Rows never hold quoted newlines here: the cells are numbers and short labels.
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    TableRow r;
    r.cells = split_csv_line(line);
    if (r.cells.size() != t.columns.size())
      throw std::runtime_error("'" + path + "': a row has " + std::to_string(r.cells.size()) + " cells, the header " +
                               std::to_string(t.columns.size()));
    r.index = std::size_t(cell_integer(r.cells[0]));
    t.rows.push_back(std::move(r));
  }
  return t;
}

Table table_of_rows(const std::string& header, const std::vector<const std::string*>& rows) {
  Table t;
  t.columns = split_csv_line(header.substr(0, header.size() - 1));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i]) continue;
    TableRow r;
    r.cells = split_csv_line(rows[i]->substr(0, rows[i]->size() - 1));
    r.index = i;
    t.rows.push_back(std::move(r));
  }
  return t;
}

std::string csv_text(const Table& t) {
  auto line = [](const std::vector<std::string>& cells) {
    std::string s;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (i > 0) s += ',';
      s += csv_escape(cells[i]);
    }
    s += '\n';
    return s;
  };
  std::string out = line(t.columns);
  for (const TableRow& r : t.rows) out += line(r.cells);
  return out;
}

double cell_double(const std::string& cell) {
  const auto v = cell_optional_double(cell);
  if (!v) throw std::runtime_error("table: an empty cell where a number is needed");
  return *v;
}

std::optional<double> cell_optional_double(const std::string& cell) {
  if (cell.empty()) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(cell.c_str(), &end);
  if (end != cell.c_str() + cell.size()) throw std::runtime_error("table: '" + cell + "' is not a number");
  return v;
}

long long cell_integer(const std::string& cell) {
  char* end = nullptr;
  const long long v = std::strtoll(cell.c_str(), &end, 10);
  if (cell.empty() || end != cell.c_str() + cell.size())
    throw std::runtime_error("table: '" + cell + "' is not an integer");
  return v;
}

}  // namespace blockdyn
