// Library data -> numpy. A State's columns already hold the run's own numbers in its own type; numpy
// gets views of them (the State moves to the heap once and a capsule frees it with the last view), so a
// state of 10^6 disks reaches Python without copying or converting a number.
// Rejected: converting to float64 (a long double run would lose its digits) and copying into fresh
// arrays (doubles the time of state(t) for large N).
#include <cmath>
#include <memory>

#include "bindings.hpp"

namespace ede::python {

py::dtype dtype_of(ScalarKind scalar) {
  switch (scalar) {
    case ScalarKind::Float: return py::dtype::of<float>();
    case ScalarKind::LongDouble:
    case ScalarKind::Float128: return py::dtype::of<long double>();
    case ScalarKind::Double: break;
  }
  return py::dtype::of<double>();
}

py::array column_array(const Column& column, py::handle owner) {
  const py::dtype dt = dtype_of(column.scalar());
  const auto itemsize = static_cast<py::ssize_t>(dt.itemsize());
  return py::array(dt, {static_cast<py::ssize_t>(column.size())}, {itemsize}, column.data(), owner);
}

py::dict state_dict(State&& state) {
  auto* heap = new State(std::move(state));
  py::capsule owner(heap, [](void* p) { delete static_cast<State*>(p); });
  py::dict d;
  const State& s = *heap;
  d["time"] = s.scalar == ScalarKind::LongDouble ? py::object(py::dtype::of<long double>().attr("type")(s.time))
                                                  : py::object(py::float_(double(s.time)));
  d["time_text"] = exact_text(s.time, s.scalar);
  d["events"] = s.events;
  d["scalar"] = to_string(s.scalar);
  d["lx"] = s.lx, d["ly"] = s.ly;
  d["boundary"] = to_string(s.boundary);
  d["shear_offset"] = s.shear_offset;
  d["x"] = column_array(s.x, owner), d["y"] = column_array(s.y, owner);
  d["vx"] = column_array(s.vx, owner), d["vy"] = column_array(s.vy, owner);
  d["radius"] = column_array(s.radius, owner), d["mass"] = column_array(s.mass, owner);
  d["species"] = py::array_t<std::int32_t>({s.species.size()}, {sizeof(std::int32_t)}, s.species.data(), owner);
  d["species_names"] = s.species_names;
  if (s.rotates()) {  // rough or spinning disks: angular velocity and moment of inertia per disk
    d["omega"] = column_array(s.omega, owner);
    d["inertia"] = column_array(s.inertia, owner);
  }
  return d;
}

Time time_argument(py::handle value, ScalarKind scalar, const char* what) {
  std::string text;
  if (py::isinstance<py::str>(value)) {
    text = value.cast<std::string>();
  } else if (py::isinstance<py::bool_>(value)) {
    throw py::type_error(std::string(what) + ": expected a time (a number or a string such as \"0.5\"), got a bool");
  } else if (py::isinstance<py::float_>(value) && py::type::of(value).is(py::type::of(py::float_(0.0)))) {
    text = py::repr(value).cast<std::string>();  // a Python float: its shortest repr, what one would type
  } else if (py::isinstance<py::int_>(value)) {
    text = py::str(value).cast<std::string>();
  } else if (py::hasattr(value, "dtype")) {
    // numpy scalars (float32, float64, longdouble): the shortest text that reads back to the same value
    // of their own type, so a numpy.longdouble keeps its digits.
    text = py::str(py::module_::import("numpy").attr("format_float_scientific")(value, py::arg("unique") = true))
               .cast<std::string>();
  } else {
    throw py::type_error(std::string(what) + ": expected a time (a number or a string such as \"0.5\"), got " +
                         py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  }
  const ScalarKind read_as = scalar == ScalarKind::Float128 ? ScalarKind::LongDouble : scalar;
  return value_or_raise(parse_exact(text, read_as));
}

}  // namespace ede::python
