// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: a sweep journal resumed from arbitrary bytes (a file cut short, edited or
// corrupted): it is resumed, with every kept row valid, or refused with std::invalid_argument.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

#include "blockdyn/analysis/sweep/sweep_journal.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/blockdyn-fuzz-journal-" + std::to_string(::getpid());
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    // Most inputs keep the journal's first line, so that the search reaches the rows.
    if (size > 0 && data[0] % 2 == 0) out << blockdyn::SweepJournal::first_line("0123456789abcdef", 4) << "index,a\n";
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  try {
    blockdyn::SweepJournal j(path, "0123456789abcdef", "index,a\n", 4, true);
    if (j.done() > j.points()) std::abort();
    // Every kept row: the header's width, its index first, written back to one line.
    for (std::size_t i = 0; i < j.points(); ++i)
      if (const blockdyn::CellRow* r = j.row(i)) {
        if (r->size() != 2 || r->front().kind() != blockdyn::Cell::Kind::integer ||
            r->front().integer() != static_cast<long long>(i))
          std::abort();
        const std::string line = blockdyn::csv_line(*r);
        if (line.empty() || line.back() != '\n') std::abort();
      }
  } catch (const std::invalid_argument&) {
  }
  std::remove(path.c_str());
  return 0;
}
