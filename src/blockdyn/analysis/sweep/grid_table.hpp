// SPDX-License-Identifier: Apache-2.0
#pragma once
// A grid analysis as a PointTable: N points, each computed by a pure function of its index and
// written as CSV cells after the `index` column. Any grid analysis (spectrum, survival,
// response-curve, ...) plugs into the sweep runner this way - threads, MPI, journal, resume,
// progress and the JSON sidecar come with it - and reads the finished table back (read_table)
// to build its own JSON and figures: %.17g doubles read back to the same bits, so what it
// reports is identical for any thread or rank count and after a resume.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/analysis/sweep/point_table.hpp"

namespace blockdyn {

class GridTable final : public PointTable {
 public:
  // Adds the cells of point `index` (one per column, after the index). Thread-safe and pure:
  // the same cells for the same index, whoever computes them and whenever.
  using Cells = std::function<void(std::size_t index, RowBuilder& row)>;

  // `columns`: without the leading "index". `definition` (what the points are: model, axes,
  // options) goes to the sidecar and into the fingerprint that ties a journal to this table.
  GridTable(std::string kind, std::vector<std::string> columns, std::size_t size, Cells cells,
            nlohmann::ordered_json definition, nlohmann::ordered_json tolerances, std::string output);

  std::size_t size() const override { return size_; }
  const std::vector<std::string>& columns() const override { return columns_; }
  const std::string& header() const override { return header_; }
  const std::string& fingerprint() const override { return fingerprint_; }
  SweepRow row(std::size_t index) const override;
  nlohmann::ordered_json definition() const override { return definition_; }
  nlohmann::ordered_json tolerances() const override { return tolerances_; }
  const std::string& output() const override { return output_; }
  std::string kind() const override { return kind_; }

 private:
  std::string kind_;
  std::vector<std::string> columns_;
  std::size_t size_;
  Cells cells_;
  nlohmann::ordered_json definition_, tolerances_;
  std::string output_, header_, fingerprint_;
};

// A finished table read back: rows in index order (all of them, or those an adaptive plan
// computed), each cell by column name.
struct TableRow {
  std::size_t index = 0;
  std::vector<std::string> cells;  // cells[0] is the index
};
class Table {
 public:
  std::vector<std::string> columns;
  std::vector<TableRow> rows;
  std::size_t column(const std::string& name) const;  // throws std::invalid_argument if absent
};
// Reads a CSV written by the sweep runner; throws std::runtime_error if the file is unreadable
// or its header differs from `expected_header` (with '\n').
Table read_table(const std::string& path, const std::string& expected_header);

// The same table from rows held in memory (each ending in '\n', in index order; null: not computed):
// what the runner wrote, without reading its output back (which may be a FIFO or a device).
Table table_of_rows(const std::string& header, const std::vector<const std::string*>& rows);
// The table as CSV text (the header and the rows, cells quoted where they need it).
std::string csv_text(const Table& t);

// Splits one CSV line (RFC 4180 quoting; no trailing '\n').
std::vector<std::string> split_csv_line(const std::string& line);

// Cells as written by RowBuilder: %.17g doubles (empty: absent), integers, flags "0"/"1".
double cell_double(const std::string& cell);
std::optional<double> cell_optional_double(const std::string& cell);
long long cell_integer(const std::string& cell);

}  // namespace blockdyn
