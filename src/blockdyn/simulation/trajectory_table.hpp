// SPDX-License-Identifier: Apache-2.0
#pragma once
// A trajectory as a table: the columns a model family names, then one row per output instant or
// event. The family's row writer fills cells; where they go (a CSV stream, NumPy columns in
// memory) is the table's business, so every family is written once for every destination.
#include <cstddef>
#include <string>
#include <vector>

namespace blockdyn {

// A number, or a text when `text` is set (mode names, event kinds, contact states).
struct TableCell {
  double value = 0.0;
  const char* text = nullptr;
};

class TrajectoryTable {
 public:
  virtual ~TrajectoryTable() = default;
  // Once, before the first row.
  virtual void columns(const std::vector<std::string>& names) = 0;
  // One cell per column.
  virtual void row(const TableCell* cells) = 0;
};

// The cells of the row being written: sized once (at the start of a run), then refilled per row
// without allocating.
class RowBuffer {
 public:
  void resize(std::size_t n) { cells_.assign(n, TableCell{}); }
  void clear() { n_ = 0; }
  void number(double v) { cells_[n_++] = {v, nullptr}; }
  void text(const char* s) { cells_[n_++] = {0.0, s}; }
  void write_to(TrajectoryTable& t) const { t.row(cells_.data()); }

 private:
  std::vector<TableCell> cells_;
  std::size_t n_ = 0;
};

// Columns kept in memory: numbers as doubles, texts as strings (a column is text when its first
// row's cell is).
class ColumnTable final : public TrajectoryTable {
 public:
  struct Column {
    std::string name;
    bool is_text = false;
    std::vector<double> numbers;
    std::vector<std::string> texts;
  };
  void columns(const std::vector<std::string>& names) override {
    cols_.clear();
    for (const auto& n : names) cols_.push_back(Column{n, false, {}, {}});
    rows_ = 0;
  }
  void row(const TableCell* cells) override {
    for (std::size_t i = 0; i < cols_.size(); ++i) {
      Column& c = cols_[i];
      if (rows_ == 0) {
        c.is_text = cells[i].text != nullptr;
        // Room for a short run's rows at once (growing cell by cell costs a short run most).
        if (c.is_text)
          c.texts.reserve(kFirstRows);
        else
          c.numbers.reserve(kFirstRows);
      }
      if (c.is_text)
        c.texts.emplace_back(cells[i].text ? cells[i].text : "");
      else
        c.numbers.push_back(cells[i].value);
    }
    ++rows_;
  }
  const std::vector<Column>& data() const { return cols_; }
  std::vector<Column>& data() { return cols_; }  // to move the columns out (the table is then empty)
  std::size_t rows() const { return rows_; }

 private:
  static constexpr std::size_t kFirstRows = 64;
  std::vector<Column> cols_;
  std::size_t rows_ = 0;
};

// The same rows to two tables (a CSV file and NumPy columns from one run).
class TableTee final : public TrajectoryTable {
 public:
  TableTee(TrajectoryTable& a, TrajectoryTable& b) : a_(a), b_(b) {}
  void columns(const std::vector<std::string>& names) override {
    a_.columns(names);
    b_.columns(names);
  }
  void row(const TableCell* cells) override {
    a_.row(cells);
    b_.row(cells);
  }

 private:
  TrajectoryTable& a_;
  TrajectoryTable& b_;
};

}  // namespace blockdyn
