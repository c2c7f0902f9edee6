// SPDX-License-Identifier: Apache-2.0
#pragma once
// One invocation of the blockdyn command line, in process: used by the program's main() and by
// the Python module, so that both parse the same options and run the same code.
#include <string>
#include <vector>

namespace blockdyn::cli {

struct CliOutcome {
  int code = 0;       // 0 success, 2 usage error (bad input), 1 other failure
  std::string error;  // the message of a failed run (without the "error: " prefix)
};

// args: the command line without the program name, e.g. {"simulate", "--r", "0.2"}. --help and
// --version print to stdout and return 0.
CliOutcome run_cli(const std::vector<std::string>& args);

}  // namespace blockdyn::cli
