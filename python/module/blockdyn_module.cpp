// SPDX-License-Identifier: Apache-2.0
// blockdyn._core: the library for Python. Runs are made from memory: options go to the library as
// Settings (the same vocabulary and validation as the command line), results come back as NumPy
// columns and the JSON summary's text, and the integration runs without the GIL. Runs that write
// files (a trajectory CSV, a JSON summary, figures) go through the command line's writers, called
// directly, in the same run that fills the columns. The functions are added by
// run_bindings.cpp, study_bindings.cpp, table_bindings.cpp and catalogue_bindings.cpp.
#include <pybind11/pybind11.h>

#include <exception>
#include <stdexcept>

#include "blockdyn/version.hpp"
#include "python_options.hpp"

namespace py = pybind11;
using namespace blockdyn::python;

PYBIND11_MODULE(_core, m) {
  m.doc() = "blockdyn's library for Python (use the functions of the blockdyn package)";
  // The library's messages name options in backticks: Python spells them as keywords (t_end).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, python_text(e.what()).c_str());
    } catch (const std::out_of_range& e) {
      PyErr_SetString(PyExc_IndexError, python_text(e.what()).c_str());
    } catch (const std::range_error& e) {
      PyErr_SetString(PyExc_ValueError, python_text(e.what()).c_str());
    } catch (const std::runtime_error& e) {
      PyErr_SetString(PyExc_RuntimeError, python_text(e.what()).c_str());
    }
  });
  m.attr("__version__") = blockdyn::kVersion;
  m.attr("git_describe") = blockdyn::kGitDescribe;
  add_runs(m);
  add_studies(m);
  add_tables(m);
  add_records_and_catalogues(m);
}
