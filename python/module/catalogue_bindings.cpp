// SPDX-License-Identifier: Apache-2.0
// Records, limit analysis, the registries (families, studies) and the command line in process,
// from Python.
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "blockdyn/commands/limit_analysis_command.hpp"
#include "blockdyn/commands/motion_generate.hpp"
#include "blockdyn/commands/motion_info.hpp"
#include "blockdyn/commands/study_command.hpp"
#include "blockdyn/family/family.hpp"
#include "cli_run.hpp"
#include "python_options.hpp"

namespace blockdyn::python {

// Records, limit analysis, the registries (families, studies) and the command line in process.
void add_records_and_catalogues(py::module_& m) {
  m.def(
      "motion_generate",
      [](const OptionList& options) {
        return json_call([](const Settings& s) { return motion_generate(s); }, options);
      },
      py::arg("options"), "Writes a suite of synthetic records (`blockdyn motion generate`): motions.json's text.");
  m.def(
      "motion_info", [](const OptionList& options) { return json_call(motion_info, options); }, py::arg("options"),
      "A record's intensity measures and spectrum (`blockdyn motion info`): JSON text.");
  m.def(
      "limit_analysis", [](const OptionList& options) { return json_call(limit_analysis_run, options); },
      py::arg("options"), "Static limit analysis of an assembly (`blockdyn limit-analysis`): JSON text.");
  m.def(
      "families",
      [] {
        py::list l;
        for (const Family& f : families()) {
          py::dict d;
          d["name"] = f.name;
          d["description"] = f.description;
          d["scenario"] = f.scenario();
          d["rigid_ground"] = f.rigid_ground != nullptr;
          d["sweep"] = f.sweep != nullptr;
          d["forced"] = f.forced != nullptr;
          d["free_lyapunov"] = f.free_lyapunov != nullptr;
          py::list cols;
          for (std::string c, all = f.state_columns; !all.empty();) {
            const auto comma = all.find(',');
            c = all.substr(0, comma);
            all = comma == std::string::npos ? "" : all.substr(comma + 1);
            cols.append(c);
          }
          d["state_columns"] = cols;
          l.append(d);
        }
        return l;
      },
      "The registered model families, the default first: [{name, description, and what each takes part in}].");
  m.def(
      "studies",
      [] {
        py::dict d;
        for (const StudyCommand& c : study_commands()) {
          py::dict opts;
          for (const StudyOption& o : c.options)
            opts[py::str(o.name)] = py::make_tuple(o.default_value, python_text(o.help));
          d[py::str(c.name)] = py::make_tuple(python_text(c.description), opts);
        }
        return d;
      },
      "{study name: (description, {option: (default, help)})}");
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
      py::arg("args"), "Runs `blockdyn <args...>`; returns (exit code, error message). 2 means invalid input.");
}

}  // namespace blockdyn::python
