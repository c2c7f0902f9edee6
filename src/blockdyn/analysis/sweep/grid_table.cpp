// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/grid_table.hpp"

#include <fstream>
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
  SweepRow r;
  r.cells.reserve(columns_.size());
  r.cells.emplace_back(index);
  cells_(index, r.cells);
  if (r.cells.size() != columns_.size())
    throw std::logic_error(kind_ + ": point " + std::to_string(index) + " has a row of the wrong width");
  return r;
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
    r.cells = parse_csv_row(line);
    if (r.cells.size() != t.columns.size())
      throw std::runtime_error("'" + path + "': a row has " + std::to_string(r.cells.size()) + " cells, the header " +
                               std::to_string(t.columns.size()));
    r.index = std::size_t(r.cells[0].integer());
    t.rows.push_back(std::move(r));
  }
  return t;
}

std::string csv_text(const Table& t) {
  std::string out = csv_header(t.columns);
  for (const TableRow& r : t.rows) append_csv_row(out, r.cells);
  return out;
}

}  // namespace blockdyn
