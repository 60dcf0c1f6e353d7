// ede._ede.Log: a log opened for reading. Thin: each method calls one public Log function and hands the
// result to Python as plain data (dicts, numpy arrays); the Python class ede.Log (python/ede/log.py)
// adds the conveniences (info as attributes, states over a grid, the scene as a dict).
// The GIL is released while the library replays, so other Python threads run meanwhile.
#include <algorithm>
#include <chrono>

#include "bindings.hpp"

namespace ede::python {

namespace {

py::dict info_dict(const LogInfo& i) {
  py::dict d;
  d["path"] = i.path;
  d["format_version"] = i.format_version;
  d["engine_version"] = i.engine_version, d["compiler"] = i.compiler, d["compile_flags"] = i.compile_flags;
  d["scalar"] = to_string(i.scalar);
  d["seed"] = i.seed;
  d["scene_name"] = i.scene_name, d["scene_text"] = i.scene_text;
  d["disks"] = i.disks;
  d["species_names"] = i.species_names, d["species_counts"] = i.species_counts;
  d["lx"] = i.lx, d["ly"] = i.ly;
  d["boundary"] = to_string(i.boundary);
  d["tc_model"] = i.tc_model;
  d["gravity"] = py::make_tuple(i.gx, i.gy);
  d["initial_energy"] = i.initial_energy;
  d["chunk_events"] = i.chunk_events, d["keyframe_interval"] = i.keyframe_interval;
  d["rebuild_interval"] = i.rebuild_interval;
  d["events"] = i.events, d["chunks"] = i.chunks, d["keyframes"] = i.keyframes;
  d["resumable_keyframes"] = i.resumable_keyframes;
  d["file_size"] = i.file_size;
  d["start_time"] = i.start_time;
  d["end_time"] = double(i.end_time);
  d["end_time_text"] = exact_text(i.end_time, i.scalar == ScalarKind::Float128 ? ScalarKind::LongDouble : i.scalar);
  d["first_event_time"] = i.first_event_time, d["last_event_time"] = i.last_event_time;
  d["complete"] = i.complete, d["damaged"] = i.damaged;
  d["incomplete_reason"] = i.incomplete_reason, d["final_status"] = i.final_status;
  return d;
}

py::dict counts_dict(const EventCounts& c) {
  py::dict d;
  for (int k = 0; k < kEventKindCount; ++k) d[to_string(static_cast<EventKind>(k))] = c.by_kind[k];
  d["stale"] = c.stale, d["tc_elastic"] = c.tc_elastic;
  return d;
}

Log open_log(const std::string& path) {
  return released([&] { return Log::open(path); });
}

}  // namespace

py::dict counts_to_dict(const EventCounts& c) { return counts_dict(c); }

void bind_log(py::module_& m) {
  py::class_<Log>(m, "Log", "An event log opened for reading (use ede.open)")
      .def(py::init(&open_log), py::arg("path"))
      .def("info", [](const Log& log) { return info_dict(log.info()); })
      .def("state_at",
           [](const Log& log, py::handle t) {
             const Time at = time_argument(t, log.info().scalar, "state(t)");
             return state_dict(released([&] { return log.state_at(at); }));
           })
      .def("state_at_event",
           [](const Log& log, std::uint64_t n) {
             return state_dict(released([&] { return log.state_at_event(n); }));
           })
      .def("state_at_end",
           [](const Log& log) {
             return state_dict(released([&] { return log.state_at_end(); }));
           })
      .def("count_events", [](const Log& log) { return counts_dict(value_or_raise(log.count_events())); })
      .def("events_after_collisions",
           [](const Log& log, const std::vector<double>& c) {
             return released([&] { return log.events_after_collisions(c); });
           })
      .def("verify",
           [](const Log& log) {
             const VerifyReport& v = released([&] { return log.verify(); });
             py::dict d;
             d["identical"] = v.identical, d["partial"] = v.partial, d["events_compared"] = v.events_compared;
             d["keyframes_checked"] = v.keyframes_checked, d["difference"] = v.difference, d["text"] = v.text;
             return d;
           })
      .def("diff",
           [](const Log& log, const Log& other, bool full) {
             const DiffReport& v = released([&] { return log.diff(other, full); });
             py::dict d;
             d["identical"] = v.identical;
             d["first_difference"] = v.first_difference ? py::object(py::int_(*v.first_difference)) : py::none();
             d["text"] = v.text;
             return d;
           },
           py::arg("other"), py::arg("full") = false)
      .def("content_digest",
           [](const Log& log) {
             return released([&] { return log.content_digest(); });
           })
      // For the benchmark: the library's own time for state_at(t) on a fresh Log, without any Python
      // conversion (seconds, median of `repeats` fresh opens), the baseline the module is measured against.
      .def_static("_time_state_at",
                  [](const std::string& path, py::handle t, int repeats) {
                    std::vector<double> seconds;
                    for (int k = 0; k < repeats; ++k) {
                      Log log = open_log(path);
                      const Time at = time_argument(t, log.info().scalar, "t");
                      py::gil_scoped_release release;
                      const auto t0 = std::chrono::steady_clock::now();
                      State s = std::move(log.state_at(at)).value();
                      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                    }
                    std::sort(seconds.begin(), seconds.end());
                    return seconds.empty() ? 0.0 : seconds[seconds.size() / 2];
                  });
}

}  // namespace ede::python
