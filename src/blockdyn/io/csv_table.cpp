// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/csv_table.hpp"

#include <cstdio>
#include <cstring>

namespace blockdyn {

void CsvTable::columns(const std::vector<std::string>& names) {
  n_ = names.size();
  for (std::size_t i = 0; i < n_; ++i) {
    if (i) out_ << ',';
    out_ << names[i];
  }
  out_ << '\n';
}

void CsvTable::row(const TableCell* cells) {
  char buf[40];
  for (std::size_t i = 0; i < n_; ++i) {
    if (i) out_.put(',');
    if (cells[i].text) {
      out_.write(cells[i].text, std::streamsize(std::strlen(cells[i].text)));
    } else {
      const int n = std::snprintf(buf, sizeof buf, "%.17g", cells[i].value);
      out_.write(buf, n);
    }
  }
  out_.put('\n');
  ++rows_;
}

}  // namespace blockdyn
