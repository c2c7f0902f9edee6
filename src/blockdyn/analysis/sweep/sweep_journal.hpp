// SPDX-License-Identifier: Apache-2.0
#pragma once
// Crash-safe record of finished sweep rows: `<csv>.journal` holds a first line tying it to the
// definition, the CSV header, then one row per finished point in completion order, each with a
// checksum (a journal with a row that does not match it is refused as corrupt). Each row is
// appended with a single write() (no user-space buffer), so a killed sweep loses only the points
// in flight. The final CSV (header + rows sorted by index) is written atomically at the end, so
// its bytes do not depend on the order points finished in, on threads, ranks or interruptions.
// In memory the rows are cells: text only on disk, written by the CSV writer and read back by its
// reader on a resume (cells that write the same bytes again).
#include <cstddef>
#include <string>
#include <vector>

#include "blockdyn/io/table_cell.hpp"

namespace blockdyn {

class SweepJournal {
 public:
  // resume = false: creates a fresh journal (replacing any old one).
  // resume = true: reads an existing journal (it must carry the same fingerprint and header;
  // a trailing partial row is cut off) or creates one if there is none.
  // Throws std::invalid_argument if the journal belongs to another definition or is corrupt.
  SweepJournal(std::string path, std::string fingerprint, std::string header, std::size_t points, bool resume);
  ~SweepJournal();
  SweepJournal(const SweepJournal&) = delete;
  SweepJournal& operator=(const SweepJournal&) = delete;

  std::size_t points() const { return rows_.size(); }
  std::size_t done() const { return done_; }
  std::size_t resumed() const { return resumed_; }  // rows found on opening
  bool has(std::size_t index) const { return !rows_[index].empty(); }
  const CellRow* row(std::size_t index) const { return rows_[index].empty() ? nullptr : &rows_[index]; }
  std::vector<std::size_t> pending() const;  // indices without a row, ascending

  // Records the row of `index` (its first cell the index). Not thread-safe.
  void append(std::size_t index, CellRow row);
  // Writes header + all rows sorted by index to csv_path atomically; needs done() == points()
  // unless `sparse` (an adaptive plan computes only some points).
  void write_csv(const std::string& csv_path, bool sparse = false) const;
  void remove_file();  // closes and deletes the journal (after the CSV is safely written)

  static std::string first_line(const std::string& fingerprint, std::size_t points);

 private:
  void load();
  std::string path_, fingerprint_, header_;
  std::vector<CellRow> rows_;
  std::size_t done_ = 0, resumed_ = 0;
  int fd_ = -1;
};

// Index in the first field of a CSV row; throws std::invalid_argument if malformed.
std::size_t row_index(const std::string& row);

}  // namespace blockdyn
