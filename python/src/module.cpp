/// \file module.cpp
/// gmcc._core: the pybind11 extension behind the Python package gmcc (docs/python.md). A thin
/// layer over the library: Python values are converted to exact C++ values (convert.h) while the
/// GIL is held, the library call runs with the GIL released, and its result is wrapped
/// (results.h). No geometry or selection is done here.

#include "bindings.h"
#include "docstrings.h"
#include "python_interrupt.h"
#include "photo.h"
#include "results.h"

#include <gmcc/input/build_info.h>

#include <string>

PYBIND11_MODULE(_core, m) {
  using namespace gmcc;
  using namespace gmcc::python;
  m.doc() = "gmcc._core: the compiled half of the Python module gmcc (docs/python.md).";
  register_interrupt(m);
  m.attr("__version__") = std::string(gmcc_version());
  m.attr("__commit__") = std::string(gmcc_commit());
  m.attr("__commit_date__") = std::string(gmcc_commit_date());
  m.attr("__data_dir__") = std::string(GMCC_DATA_DIR);  // the source tree's data/, at build time
  // The parameter docs the pure-Python wrappers share with the extension's functions (docstrings.h).
  py::dict doc_parts;
  doc_parts["pixel_rules"] = doc::pixel_rules;
  doc_parts["canonical_options"] = doc::canonical_options;
  m.attr("_doc_parts") = doc_parts;
  bind_results(m);
  bind_scene_functions(m);
  bind_rules(m);
  bind_lights_and_crule(m);
  bind_photo(m);
  bind_error_statistics(m);
  bind_experiments(m);
}
