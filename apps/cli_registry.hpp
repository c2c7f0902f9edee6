// SPDX-License-Identifier: Apache-2.0
#pragma once
// Subcommands register themselves (one file per subcommand under apps/), so adding a command
// never touches main.cpp.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace blockdyn::cli {

// Under an mpirun launch of more than one rank a command either distributes its points over the
// ranks (dispatch_points) or refuses to run (exit 2): never every point on every rank.
enum class MpiUse { Refuses, Distributes };

struct CommandEntry {
  int order;  // position in --help
  std::function<void(CLI::App&)> add;
  MpiUse mpi = MpiUse::Refuses;
};

std::vector<CommandEntry>& command_registry();

struct RegisterCommand {
  RegisterCommand(int order, std::function<void(CLI::App&)> add, MpiUse mpi = MpiUse::Refuses) {
    command_registry().push_back({order, std::move(add), mpi});
  }
};

}  // namespace blockdyn::cli
