// SPDX-License-Identifier: Apache-2.0
#pragma once
// A 64-bit FNV-1a hash of bytes, as 16 hex digits: fingerprints of definitions and of records'
// contents (a journal resumed against edited inputs must not pass for the same run).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace blockdyn {

inline std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t h = 1469598103934665603ull) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
  }
  return h;
}

inline std::string hex64(std::uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace blockdyn
