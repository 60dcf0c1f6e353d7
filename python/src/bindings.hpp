// The pieces of the extension module ede._ede, one file each: errors (ede::Exception -> Python exception
// classes), arrays (library columns -> numpy without a copy), the Log, events, runs and analyses.
// Every binding goes through the public headers only (libede/include/ede), like the tools.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "ede/ede.hpp"

namespace ede::python {

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_log(py::module_& m);
void bind_events(py::module_& m);
void bind_run(py::module_& m);
void bind_analysis(py::module_& m);
void bind_structure(py::module_& m);

// The numpy dtype of a scalar kind: float32, float64 or longdouble.
py::dtype dtype_of(ScalarKind scalar);
// A column as a numpy array of its own type that shares the column's memory; `owner` keeps it alive.
py::array column_array(const Column& column, py::handle owner);
// A vector as a numpy array that takes the vector over (no copy).
template <class T>
py::array_t<T> take_vector(std::vector<T>&& values);
// A State as a dict of numpy arrays (x, y, vx, vy, radius, mass in the run's type; species, id) and
// its scalars; the arrays share one heap copy of the state.
py::dict state_dict(State&& state);
// A time the user gave (a float, an int, a numpy scalar, or a string in ede-replay's --at syntax) as the
// log's scalar type reads it: a float is read through its shortest repr, exactly as ede-replay --at reads
// the same text, so the two give the same state bit for bit.
Time time_argument(py::handle value, ScalarKind scalar, const char* what);
// A library result's value, or the library's error raised as the matching Python exception.
template <class T>
T value_or_raise(Result<T>&& result) {
  return std::move(result).value();  // ede::Exception is translated (errors.cpp)
}
// f() with the GIL released (the library call may take long; other Python threads run meanwhile), its
// result's value or the library's error raised.
template <class F>
auto released(F&& f) {
  auto result = [&] {
    py::gil_scoped_release release;
    return f();
  }();
  return value_or_raise(std::move(result));
}

template <class T>
py::array_t<T> take_vector(std::vector<T>&& values) {
  auto* heap = new std::vector<T>(std::move(values));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>({heap->size()}, {sizeof(T)}, heap->data(), owner);
}

}  // namespace ede::python
