// Log.events(...) -> a numpy structured array, one row per logged event: index, time, kind, i, j and
// the velocities after the event, in the log's own scalar type; on request the positions at the event,
// the velocities before it, the impulse on disk i (m_i (v_i' - v_i)) and the collision's statistics in
// float64 (ede/collision_stats.hpp: impulse, impact_parameter, relative_speed, normal_speed,
// tangential_speed; the library's collision_record of each row, the numbers `ede-replay events --full` prints).
// Rotating (rough) logs add omega_i and omega_j (after; and before with before=True).
// The library writes the rows straight into numpy's buffer (Log::event_rows, on every core with the GIL
// released): the memory is touched once, which matters here: a first touch of a page costs several
// microseconds on these virtual machines, and the earlier path (typed columns, then an array per column,
// then a strided copy into the rows) touched three times as much and ran at a third of the walk's speed.
// Rejected: an array of Python Event objects (two orders of magnitude slower) and a dict of columns as
// the result (the issue asks for one array whose rows are events).
#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <limits>
#include <optional>

#include "bindings.hpp"
#include "shared_log.hpp"
#include "ede/collision_stats.hpp"

namespace ede::python {

namespace {

struct EventRequest {
  EventRange range;
  bool positions = false, before = false, impulse = false, collision = false;
};

// The row layout of one request: the fields in the order the user sees them, each at its byte offset
// (packed), then the fields only the derived columns need (velocities before, for impulses and collision
// statistics) after them, where the dtype has no name for them: numpy keeps those bytes as padding.
struct RowPlan {
  EventRowLayout layout;
  py::list names, formats, offsets;
  std::size_t visible = 0;  // bytes of the named fields
  std::ptrdiff_t impulse_x = -1, impulse_y = -1, stats = -1;  // derived float64/T columns, filled after the walk
};

template <class T>
RowPlan plan_rows(const EventRequest& q, bool rotates) {
  RowPlan p;
  std::size_t at = 0;
  const auto field = [&](const char* name, py::dtype dt, std::size_t bytes, bool named = true) {
    const std::ptrdiff_t offset = std::ptrdiff_t(at);
    at += bytes;
    if (named) p.names.append(name), p.formats.append(dt), p.offsets.append(offset);
    return offset;
  };
  const py::dtype rd = py::dtype::of<T>(), f64 = py::dtype::of<double>();
  const std::size_t r = sizeof(T);
  EventRowLayout& l = p.layout;
  l.index = field("index", py::dtype::of<std::uint64_t>(), 8), l.time = field("time", rd, r);
  l.kind = field("kind", py::dtype::of<std::uint8_t>(), 1);
  l.i = field("i", py::dtype::of<std::int32_t>(), 4), l.j = field("j", py::dtype::of<std::int32_t>(), 4);
  l.vix = field("vix", rd, r), l.viy = field("viy", rd, r), l.vjx = field("vjx", rd, r), l.vjy = field("vjy", rd, r);
  if (rotates) l.omega_i = field("omega_i", rd, r), l.omega_j = field("omega_j", rd, r);
  const bool at_event = q.positions || q.collision;
  if (at_event) {
    l.xi = field("xi", rd, r, q.positions), l.yi = field("yi", rd, r, q.positions);
    l.xj = field("xj", rd, r, q.positions), l.yj = field("yj", rd, r, q.positions);
  }
  if (q.before || q.impulse || q.collision) {
    l.vix_before = field("vix_before", rd, r, q.before), l.viy_before = field("viy_before", rd, r, q.before);
    l.vjx_before = field("vjx_before", rd, r, q.before), l.vjy_before = field("vjy_before", rd, r, q.before);
    if (rotates)
      l.omega_i_before = field("omega_i_before", rd, r, q.before),
      l.omega_j_before = field("omega_j_before", rd, r, q.before);
  }
  if (q.impulse) p.impulse_x = field("px", rd, r), p.impulse_y = field("py", rd, r);
  if (q.collision) {
    p.stats = field("impulse", f64, 8);
    for (const char* n : {"impact_parameter", "relative_speed", "normal_speed", "tangential_speed"}) field(n, f64, 8);
  }
  l.row_bytes = at;
  return p;
}

// A field of row k (offset >= 0), read or written whatever the row's alignment.
template <class V>
V get(const unsigned char* rows, std::size_t row_bytes, std::size_t k, std::ptrdiff_t offset) {
  V v{};
  if (offset >= 0) std::memcpy(&v, rows + k * row_bytes + std::size_t(offset), sizeof v);
  return v;
}
template <class V>
void set(unsigned char* rows, std::size_t row_bytes, std::size_t k, std::ptrdiff_t offset, V v) {
  std::memcpy(rows + k * row_bytes + std::size_t(offset), &v, sizeof v);
}

// Row k as the library's event record (the fields collision_record reads).
template <class T>
Event event_at(const unsigned char* rows, const EventRowLayout& l, std::size_t k) {
  const std::size_t w = l.row_bytes;
  const auto real = [&](std::ptrdiff_t offset) { return Time(get<T>(rows, w, k, offset)); };
  Event e;
  e.kind = static_cast<EventKind>(get<std::uint8_t>(rows, w, k, l.kind));
  e.i = get<std::int32_t>(rows, w, k, l.i), e.j = get<std::int32_t>(rows, w, k, l.j);
  e.xi = real(l.xi), e.yi = real(l.yi), e.xj = real(l.xj), e.yj = real(l.yj);
  e.vix = real(l.vix), e.viy = real(l.viy), e.vjx = real(l.vjx), e.vjy = real(l.vjy);
  e.vix_before = real(l.vix_before), e.viy_before = real(l.viy_before);
  e.vjx_before = real(l.vjx_before), e.vjy_before = real(l.vjy_before);
  e.omega_i = real(l.omega_i), e.omega_j = real(l.omega_j);
  e.omega_i_before = real(l.omega_i_before), e.omega_j_before = real(l.omega_j_before);
  return e;
}

// The derived columns of n rows: the impulse on disk i, m_i (v_i' - v_i), for pair, wall, segment and step
// events (0 for the others), and the collision's statistics (collision_record).
// False if Ctrl-C stopped it (asked every 2^16 rows).
template <class T>
bool derive(unsigned char* rows, std::size_t n, const RowPlan& p, const std::vector<T>& mass,
            const CollisionDisks* disks, SharedLog& shared) {
  if (p.impulse_x < 0 && !disks) return true;  // nothing derived: the rows are as the library wrote them
  const EventRowLayout& l = p.layout;
  const std::size_t w = l.row_bytes;
  for (std::size_t k = 0; k < n; ++k) {
    if (k % 65536 == 0 && shared.interrupted()) return false;
    if (p.impulse_x >= 0) {
      const auto kind = static_cast<EventKind>(get<std::uint8_t>(rows, w, k, l.kind));
      const std::int32_t i = get<std::int32_t>(rows, w, k, l.i);
      T px(0), py(0);
      if ((kind == EventKind::Pair || kind == EventKind::Wall || kind == EventKind::Segment || kind == EventKind::Step) &&
          i >= 0) {
        const T m = mass[std::size_t(i)];
        px = m * (get<T>(rows, w, k, l.vix) - get<T>(rows, w, k, l.vix_before));
        py = m * (get<T>(rows, w, k, l.viy) - get<T>(rows, w, k, l.viy_before));
      }
      set(rows, w, k, p.impulse_x, px), set(rows, w, k, p.impulse_y, py);
    }
    if (disks) {
      const CollisionRecord c = collision_record(event_at<T>(rows, l, k), *disks);
      const double v[] = {c.impulse, c.impact_parameter, c.relative_speed, c.normal_speed, c.tangential_speed};
      for (int f = 0; f < 5; ++f) set(rows, w, k, p.stats + 8 * f, v[f]);
    }
  }
  return true;
}

// The events as a numpy structured array written by the library straight into numpy's buffer
// (Log::event_rows: one pass, the memory touched once, the walk on every core with the GIL released).
// `out`, when given, must be exactly what this request would allocate (a 1-D, C-contiguous, writable array
// of the request's dtype); its length is checked once the range's size is known.
void check_out(const py::object& out, const py::object& dtype) {
  if (!py::isinstance<py::array>(out))
    throw py::type_error("events(out=...): expected a numpy array made by an earlier events() call with the same "
                         "arguments, got " + std::string(py::str(py::type::of(out).attr("__name__"))));
  const py::array a = py::reinterpret_borrow<py::array>(out);
  if (!a.dtype().equal(dtype))
    throw py::type_error("events(out=...): the array's dtype " + std::string(py::str(a.dtype())) +
                         " is not the one these arguments give, " + std::string(py::str(dtype)) +
                         ": pass an array returned by events() with the same positions/before/impulse/collision");
  if (a.ndim() != 1 || !(a.flags() & py::array::c_style) || !a.writeable())
    throw py::value_error("events(out=...): expected a writable, contiguous 1-D array (not a slice with a step)");
}

// The rows of n events must fit before numpy allocates them: Linux grants a request larger than the memory
// left and kills the process when the rows are written.
std::string rows_do_not_fit(const LogInfo& info, std::uint64_t n, std::size_t row_bytes) {
  const double need = double(n) * double(row_bytes);
  std::uint64_t left = 0;
  if (!may_not_fit(need, left)) return "";
  return info.path + ": events(): the range holds " + std::to_string(n) + " events, " + byte_text(need) +
         " as rows of " + std::to_string(row_bytes) + " bytes, more than the " + byte_text(double(left)) +
         " this process may still allocate: read it window by window (first=, last=, into one array with out=), "
         "or ask for fewer fields";
}

template <class T>
py::array events_in(SharedLog& shared, const EventRequest& request, const py::object& out) {
  const LogInfo& info = shared.info();
  const RowPlan plan = plan_rows<T>(request, info.rotates);
  py::module_ np = py::module_::import("numpy");
  py::dict spec;
  spec["names"] = plan.names, spec["formats"] = plan.formats, spec["offsets"] = plan.offsets;
  spec["itemsize"] = plan.layout.row_bytes;
  const py::object dtype = np.attr("dtype")(spec);
  if (!out.is_none()) check_out(out, dtype);
  py::array rows;
  unsigned char* data = nullptr;
  // What the allocator refused (an `out` too short, rows that do not fit), raised once the library returns.
  std::string too_short, no_memory;
  const std::uint64_t kept = shared.read("events()", [&](const Log& log) -> Result<std::uint64_t> {
    std::vector<T> mass;
    if (request.impulse) mass = value_or_raise(log.state_at_event(0)).mass.values<T>();
    std::optional<CollisionDisks> disks;
    if (request.collision) disks = value_or_raise(collision_disks(log));
    auto written = log.event_rows(request.range, plan.layout, [&](std::uint64_t n) -> void* {
      py::gil_scoped_acquire hold;
      if (!out.is_none()) {
        // A reused array: its pages are already mapped, so a window of a long log costs no page faults.
        rows = py::reinterpret_borrow<py::array>(out);
        if (std::uint64_t(rows.shape(0)) < n) {
          too_short = "events(out=...): the range holds " + std::to_string(n) + " events, the array " +
                      std::to_string(rows.shape(0)) + " rows: pass a longer array or a shorter range (first/last)";
          return nullptr;
        }
      } else {
        no_memory = rows_do_not_fit(info, n, plan.layout.row_bytes);
        if (!no_memory.empty()) return nullptr;
        try {
          rows = np.attr("empty")(n, dtype);
        } catch (py::error_already_set& e) {
          if (!e.matches(PyExc_MemoryError)) throw;
          no_memory = info.path + ": events(): numpy could not allocate " + std::to_string(n) + " rows of " +
                      std::to_string(plan.layout.row_bytes) + " bytes (" + std::string(py::str(e.value())) +
                      "): read the range window by window (first=, last=, out=)";
          return nullptr;
        }
      }
      data = static_cast<unsigned char*>(rows.mutable_data());
      return data;
    });
    if (!too_short.empty()) throw py::value_error(too_short);
    if (!no_memory.empty()) throw OutOfMemory(no_memory);
    if (!written) return written;
    if (!derive<T>(data, written.value(), plan, mass, disks ? &*disks : nullptr, shared))
      return Error{info.path + ": events(): interrupted"};
    return written;
  });
  if (std::uint64_t(rows.shape(0)) != kept) rows = rows[py::slice(0, py::ssize_t(kept), 1)];
  return rows;
}

}  // namespace

void bind_events(py::module_& m) {
  m.def(
      "events",
      [](SharedLog& log, py::object t0, py::object t1, py::object first, py::object last, bool positions,
         bool before, bool impulse, bool collision, py::object out) {
        const ScalarKind scalar = log.info().scalar;
        EventRequest r;
        if (!t0.is_none()) r.range.from_time = time_argument(t0, scalar, "events(t0)");
        if (!t1.is_none()) r.range.to_time = time_argument(t1, scalar, "events(t1)");
        if (!first.is_none()) r.range.from_event = first.cast<std::uint64_t>();
        if (!last.is_none()) r.range.to_event = last.cast<std::uint64_t>();
        r.positions = positions, r.before = before, r.impulse = impulse, r.collision = collision;
        switch (scalar) {
          case ScalarKind::Float: return events_in<float>(log, r, out);
          case ScalarKind::LongDouble:
          case ScalarKind::Float128: return events_in<long double>(log, r, out);
          case ScalarKind::Double: break;
        }
        return events_in<double>(log, r, out);
      },
      py::arg("log"), py::arg("t0"), py::arg("t1"), py::arg("first"), py::arg("last"), py::arg("positions"),
      py::arg("before"), py::arg("impulse"), py::arg("collision"), py::arg("out") = py::none());
  // For the benchmark: the library's own Log::for_each_event over the whole log with a callback that
  // does nothing (events per second): the ceiling of any binding built on it.
  m.def("_time_for_each_event", [](SharedLog& log) {
    return log.read("_time_for_each_event()", [](const Log& l) -> Result<double> {
      std::uint64_t n = 0;
      const auto t0 = std::chrono::steady_clock::now();
      Status s = l.for_each_event({}, [&](const Event&) { return ++n, true; });
      const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (!s) return s.error();
      return dt > 0 ? double(n) / dt : 0.0;
    });
  });
}

}  // namespace ede::python
