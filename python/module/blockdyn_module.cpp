// SPDX-License-Identifier: Apache-2.0
// blockdyn._core: the command line, run in process without the GIL (blockdyn/__init__.py builds
// the arguments from keyword options and reads the outputs back as NumPy arrays).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "blockdyn/version.hpp"
#include "cli_run.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_core, m) {
  m.doc() = "blockdyn's command line, in process (use the functions of the blockdyn package)";
  m.attr("__version__") = blockdyn::kVersion;
  m.attr("git_describe") = blockdyn::kGitDescribe;
  m.def(
      "run_cli",
      [](const std::vector<std::string>& args) {
        blockdyn::cli::CliOutcome r;
        {
          py::gil_scoped_release release;  // simulations and sweeps run without the GIL
          r = blockdyn::cli::run_cli(args);
        }
        return py::make_tuple(r.code, r.error);
      },
      py::arg("args"),
      "Runs `blockdyn <args...>`; returns (exit code, error message). 2 means invalid input.");
}
