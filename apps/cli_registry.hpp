// SPDX-License-Identifier: Apache-2.0
#pragma once
// Subcommands register themselves (one file per subcommand under apps/), so adding a command
// never touches main.cpp.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace blockdyn::cli {

struct CommandEntry {
  int order;  // position in --help
  std::function<void(CLI::App&)> add;
};

std::vector<CommandEntry>& command_registry();

struct RegisterCommand {
  RegisterCommand(int order, std::function<void(CLI::App&)> add) {
    command_registry().push_back({order, std::move(add)});
  }
};

}  // namespace blockdyn::cli
