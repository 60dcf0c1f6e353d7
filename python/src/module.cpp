// ede._ede: the extension module behind `import ede` (python/ede/__init__.py is the documented face).
// __version__ is the version of the tree this file was compiled from (EDE_PYTHON_BUILT_FOR, the project
// version CMakeLists.txt passes), version() the library's it is linked with: the package compares them at
// import and refuses a mismatch with ede.Error (bindings compiled against one tree's headers could misread
// another version's structures). The comparison is in Python because an exception raised while a module
// initialises reaches the user as an ImportError, not as ede.Error.
#include <string>

#include "bindings.hpp"

PYBIND11_MODULE(_ede, m) {
  m.doc() = "ede's C++ library (use the package `ede`, not this module)";
  m.attr("__version__") = std::string(EDE_PYTHON_BUILT_FOR);
  // The event kinds' names by number, from the one list in ede/events.hpp (Log.events' kind column).
  pybind11::list kinds;
  for (int k = 0; k < ede::kEventKindCount; ++k) kinds.append(ede::to_string(static_cast<ede::EventKind>(k)));
  m.attr("EVENT_KINDS") = pybind11::tuple(kinds);
  ede::python::bind_errors(m);
  ede::python::bind_log(m);
  ede::python::bind_events(m);
  ede::python::bind_run(m);
  ede::python::bind_analysis(m);
  ede::python::bind_structure(m);
}
