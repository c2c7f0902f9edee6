// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the command-line tests use unqualified: JSON, and the sweep tests' helpers to run the
// program in a scratch directory and read what it wrote.
#include <nlohmann/json.hpp>

#include "test_sweep_util.hpp"

using nlohmann::json;
using sweep_test::exists;
using sweep_test::expect_usage_errors;
using sweep_test::run_cli;
using sweep_test::slurp;
using sweep_test::TmpDir;

// Runs the program (expecting success) and parses its standard output as JSON; null on failure.
inline json cli_json(const std::vector<std::string>& args, const std::string& dir) {
  const sweep_test::CliResult r = run_cli(args, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  return r.code == 0 ? json::parse(r.out) : json();
}
