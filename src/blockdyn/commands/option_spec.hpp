// SPDX-License-Identifier: Apache-2.0
#pragma once
// An option as the library describes it to its front ends: the command line registers it as a
// flag (--name, with the help and the default shown), Python takes it as a keyword argument.
#include <string>
#include <string_view>
#include <vector>

namespace blockdyn {

struct StudyOption {
  std::string name;                    // without dashes: "r-min"
  std::string help;                    // for --help
  std::string default_value{};         // as the user would write it; empty: none
  bool is_flag = false;                // given without a value
  bool is_list = false;                // numbers: "a,b,c", or the option repeated
  std::vector<std::string> aliases{};  // other names accepted for it ("d595" for "d5-95")
};

// The library's messages and help name its options in backticks (`t-end`), not as any front
// end spells them; each front end spells them its own way: `prefix` before the name (the
// command line's "--"), and Python's underscores for dashes (t_end). Text in backticks that is
// not an option name (it holds a space or other characters) is left as it is.
std::string spell_options(std::string_view text, std::string_view prefix, bool underscores);

}  // namespace blockdyn
