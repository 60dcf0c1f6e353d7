// ede._ede: the extension module behind `import ede` (python/ede/__init__.py is the documented face).
#include "bindings.hpp"

PYBIND11_MODULE(_ede, m) {
  m.doc() = "ede's C++ library (use the package `ede`, not this module)";
  ede::python::bind_errors(m);
  ede::python::bind_log(m);
  ede::python::bind_events(m);
  ede::python::bind_run(m);
  ede::python::bind_analysis(m);
  ede::python::bind_structure(m);
}
