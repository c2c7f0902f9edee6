// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the AT2 writer and reader round trip. The bytes are read as doubles (any
// pattern: subnormals, signed zeros, the largest magnitudes); those a record may hold (finite,
// |a| <= 100 g) are written as AT2 text and read back: every sample must come back bit for bit.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "blockdyn/excitation/accelerogram.hpp"
#include "blockdyn/io/at2_writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<double> a;
  for (std::size_t i = 0; i + 8 <= size; i += 8) {
    double v;
    std::memcpy(&v, data + i, 8);
    if (std::isfinite(v) && std::fabs(v) <= 100.0) a.push_back(v);
  }
  if (a.size() < 2) return 0;
  const std::string text = blockdyn::at2_text(a, 0.01, "fuzz");
  const blockdyn::Accelerogram r = blockdyn::parse_at2(text, "fuzz.AT2");
  if (r.size() != a.size()) std::abort();
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::memcmp(&r.values()[i], &a[i], sizeof(double)) != 0) std::abort();
  return 0;
}
