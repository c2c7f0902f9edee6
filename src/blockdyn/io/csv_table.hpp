// SPDX-License-Identifier: Apache-2.0
#pragma once
// A trajectory table written as CSV: a header line, then numbers with 17 significant digits (they
// read back to the same doubles) and texts as they are.
#include <ostream>

#include "blockdyn/simulation/trajectory_table.hpp"

namespace blockdyn {

class CsvTable final : public TrajectoryTable {
 public:
  explicit CsvTable(std::ostream& out) : out_(out) {}
  void columns(const std::vector<std::string>& names) override;
  void row(const TableCell* cells) override;
  long rows() const { return rows_; }

 private:
  std::ostream& out_;
  std::size_t n_ = 0;
  long rows_ = 0;
};

}  // namespace blockdyn
