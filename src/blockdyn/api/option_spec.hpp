// SPDX-License-Identifier: Apache-2.0
#pragma once
// An option as the library describes it to its front ends: the command line registers it as a
// flag (--name, with the help and the default shown), Python takes it as a keyword argument.
#include <string>
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

}  // namespace blockdyn
