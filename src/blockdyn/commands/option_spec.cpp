// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/option_spec.hpp"

namespace blockdyn {

namespace {
bool option_char(char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_'; }
}  // namespace

std::string spell_options(std::string_view text, std::string_view prefix, bool underscores) {
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t close = text[i] == '`' ? text.find('`', i + 1) : std::string_view::npos;
    bool name = close != std::string_view::npos && close > i + 1;
    for (std::size_t k = i + 1; name && k < close; ++k) name = option_char(text[k]);
    if (!name) {
      out += text[i++];
      continue;
    }
    out += prefix;
    for (std::size_t k = i + 1; k < close; ++k) out += underscores && text[k] == '-' ? '_' : text[k];
    i = close + 1;
  }
  return out;
}

}  // namespace blockdyn
