// SPDX-License-Identifier: Apache-2.0
// blockdyn command-line program: subcommands register themselves in apps/cmd_*.cpp.
#include <iostream>
#include <string>
#include <vector>

#include "blockdyn/io/atomic_file.hpp"
#include "cli_run.hpp"

int main(int argc, char** argv) {
  // Interrupted runs leave no temporary files (a killed sweep keeps its journal, to resume).
  blockdyn::install_signal_cleanup();
  const std::vector<std::string> args(argv + 1, argv + argc);
  const blockdyn::cli::CliOutcome r = blockdyn::cli::run_cli(args);
  if (r.code != 0) std::cerr << "error: " << r.error << "\n";
  return r.code;
}
