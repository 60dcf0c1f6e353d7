// ede::Exception -> the Python exception class of its kind (ede.InvalidError, ede.IoError,
// ede.CorruptLogError, ede.UnsupportedError; all subclasses of ede.Error), with the library's message
// unchanged: a bad scene raises the very text ede-sim prints. The classes are defined in Python
// (ede/_errors.py) so that they document themselves and can also subclass ValueError / OSError.
// A request that does not fit in memory is Python's own MemoryError, with a message saying what was asked.
#include "bindings.hpp"
#include "shared_log.hpp"

namespace ede::python {

namespace {

const char* class_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Invalid: return "InvalidError";
    case ErrorKind::Io: return "IoError";
    case ErrorKind::Corrupt: return "CorruptLogError";
    case ErrorKind::Unsupported: return "UnsupportedError";
  }
  return "Error";
}

}  // namespace

void bind_errors(py::module_& m) {
  (void)m;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Exception& e) {
      py::object cls = py::module_::import("ede._errors").attr(class_name(e.kind()));
      PyErr_SetString(cls.ptr(), e.what());
    } catch (const OutOfMemory& e) {
      PyErr_SetString(PyExc_MemoryError, e.what());
    }
  });
}

}  // namespace ede::python
