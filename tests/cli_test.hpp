// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the command-line tests use unqualified: JSON, and the sweep tests' helpers to run the
// program in a scratch directory and read what it wrote.
#include <nlohmann/json.hpp>

#include "test_sweep_util.hpp"

using nlohmann::json;
using sweep_test::exists;
using sweep_test::run_cli;
using sweep_test::slurp;
using sweep_test::TmpDir;
