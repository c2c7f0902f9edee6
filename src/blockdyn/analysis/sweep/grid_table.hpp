// SPDX-License-Identifier: Apache-2.0
#pragma once
// A grid analysis as a PointTable: N points, each computed by a pure function of its index and
// a row of cells after the `index` column. Any grid analysis (spectrum, survival,
// response-curve, ...) plugs into the sweep runner this way - threads, MPI, journal, resume,
// progress and the JSON sidecar come with it - and reads the finished table back (read_table)
// to build its own JSON and figures from the same cells, in memory or read from the CSV (%.17g
// doubles read back to the same bits), so what it reports is identical for any thread or rank
// count and after a resume.
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
  using Cells = std::function<void(std::size_t index, CellRow& row)>;

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

// A finished table: rows in index order (all of them, or those an adaptive plan computed), each
// cell by column name.
struct TableRow {
  std::size_t index = 0;
  CellRow cells;  // cells[0] is the index
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
// The table as CSV text (the header and the rows, through the writer).
std::string csv_text(const Table& t);

}  // namespace blockdyn
