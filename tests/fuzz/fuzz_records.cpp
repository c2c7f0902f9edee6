// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the record readers (PEER .AT2 and two-column CSV) on arbitrary bytes. A reader
// either returns a record that satisfies its own invariants or throws std::invalid_argument; it
// never crashes, hangs or returns a record with a non-finite or out-of-range sample.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "blockdyn/excitation/accelerogram.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (int kind = 0; kind < 2; ++kind) {
    try {
      const blockdyn::Accelerogram r =
          kind == 0 ? blockdyn::parse_at2(text, "fuzz.AT2") : blockdyn::parse_record_csv(text, "fuzz.csv");
      if (r.size() < 2) std::abort();
      for (double v : r.values())
        if (!std::isfinite(v) || std::fabs(v) > 100.0) std::abort();
      for (std::size_t i = 1; i < r.size(); ++i)
        if (!(r.time(i) > r.time(i - 1))) std::abort();
      // Interpolation stays within the samples' range.
      const double t = 0.5 * (r.t_first() + r.t_last());
      if (!(std::fabs(r.at(t)) <= r.peak())) std::abort();
    } catch (const std::invalid_argument&) {
    }
  }
  return 0;
}
