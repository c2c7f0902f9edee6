// SPDX-License-Identifier: Apache-2.0
// blockdyn command-line program: subcommands register themselves in apps/cmd_*.cpp.
#include <iostream>
#include <string>
#include <vector>

#include "cli_run.hpp"

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  const blockdyn::cli::CliOutcome r = blockdyn::cli::run_cli(args);
  if (r.code != 0) std::cerr << "error: " << r.error << "\n";
  return r.code;
}
