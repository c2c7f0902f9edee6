// SPDX-License-Identifier: Apache-2.0
// blockdyn command-line program: subcommands register themselves in apps/cmd_*.cpp.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <stdexcept>

#include "blockdyn/version.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"

int main(int argc, char** argv) {
  CLI::App app{"blockdyn: nonsmooth dynamics of rigid blocks (Winkler foundation, rigid ground)"};
  app.set_version_flag("--version", std::string(blockdyn::kVersion) + " (" + blockdyn::kGitDescribe + ")");
  app.require_subcommand(1);
  auto& reg = blockdyn::cli::command_registry();
  std::sort(reg.begin(), reg.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
  for (const auto& c : reg) c.add(app);
  // The subcommand names the schema of its JSON outputs.
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (!a.empty() && a[0] != '-') {
      blockdyn::cli::current_command() = a;
      break;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help / --version are "errors" with exit code 0: let CLI11 print them.
    if (e.get_exit_code() == 0) return app.exit(e);
    // Usage errors: one line, same form as the other input errors, exit status 2 like every
    // usage error (CLI11's own codes are not part of the contract).
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
