// ede._ede.Log: a log opened for reading. Thin: each method calls one public Log function and hands the
// result to Python as plain data (dicts, numpy arrays); the Python class ede.Log (python/ede/log.py)
// adds the conveniences (info as attributes, states over a grid, the scene as a dict).
// Every read goes through SharedLog (shared_log.hpp): the GIL released while the library replays, one call
// at a time per Log, close(), Ctrl-C and out-of-memory.
#include <algorithm>
#include <chrono>

#include "bindings.hpp"
#include "shared_log.hpp"

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
  d["lees_edwards"] = i.lees_edwards;  // periodic with sliding images
  d["shear_rate"] = i.shear_rate;      // the scene's box.shear_rate (0 when not sheared)
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

// A state of the log's disks must fit before the library builds it: its columns and the replay's own copy.
void check_state_fits(const SharedLog& log, const char* what) {
  const LogInfo& i = log.info();
  const double real = i.scalar == ScalarKind::Float ? 4 : i.scalar == ScalarKind::Double ? 8 : 16;
  const double need = double(i.disks) * (2 * 8 * real + 8);
  std::uint64_t left = 0;
  if (may_not_fit(need, left))
    throw OutOfMemory(i.path + ": " + what + ": a state of " + std::to_string(i.disks) + " disks needs about " +
                      byte_text(need) + ", more than the " + byte_text(double(left)) +
                      " this process may still allocate (free memory or raise ulimit -v)");
}

py::dict counts_dict(const EventCounts& c) {
  py::dict d;
  for (int k = 0; k < kEventKindCount; ++k)
    if (is_event_kind(k)) d[to_string(static_cast<EventKind>(k))] = c.by_kind[k];
  d["stale"] = c.stale, d["tc_elastic"] = c.tc_elastic;
  return d;
}

}  // namespace

py::dict counts_to_dict(const EventCounts& c) { return counts_dict(c); }

void bind_log(py::module_& m) {
  py::class_<SharedLog>(m, "Log", "An event log opened for reading (use ede.open)")
      .def(py::init<const std::string&>(), py::arg("path"))
      .def("close", &SharedLog::close)
      .def_property_readonly("closed", &SharedLog::closed)
      .def_property_readonly("path", &SharedLog::path)
      .def("info", [](const SharedLog& log) { return info_dict(log.info()); })
      .def("state_at",
           [](SharedLog& log, py::handle t) {
             const Time at = time_argument(t, log.info().scalar, "state(t)");
             check_state_fits(log, "state(t)");
             return state_dict(log.read("state(t)", [&](const Log& l) { return l.state_at(at); }));
           })
      .def("state_at_event",
           [](SharedLog& log, std::uint64_t n) {
             check_state_fits(log, "state(event=n)");
             return state_dict(log.read("state(event=n)", [&](const Log& l) { return l.state_at_event(n); }));
           })
      .def("state_at_end",
           [](SharedLog& log) {
             check_state_fits(log, "state()");
             return state_dict(log.read("state()", [&](const Log& l) { return l.state_at_end(); }));
           })
      .def("count_events",
           [](SharedLog& log) { return counts_dict(log.read("count_events()", [](const Log& l) { return l.count_events(); })); })
      .def("events_after_collisions",
           [](SharedLog& log, const std::vector<double>& c) {
             return log.read("events_after_collisions()", [&](const Log& l) { return l.events_after_collisions(c); });
           })
      .def("verify",
           [](SharedLog& log) {
             const VerifyReport v = log.read("verify()", [](const Log& l) { return l.verify(); });
             py::dict d;
             d["identical"] = v.identical, d["partial"] = v.partial, d["events_compared"] = v.events_compared;
             d["keyframes_checked"] = v.keyframes_checked, d["difference"] = v.difference, d["text"] = v.text;
             return d;
           })
      .def("diff",
           [](SharedLog& log, SharedLog& other, bool full) {
             const Log theirs = other.handle();  // keeps its file open even if `other` is closed meanwhile
             const DiffReport v = log.read("diff()", [&](const Log& l) { return l.diff(theirs, full); });
             py::dict d;
             d["identical"] = v.identical;
             d["first_difference"] = v.first_difference ? py::object(py::int_(*v.first_difference)) : py::none();
             d["text"] = v.text;
             return d;
           },
           py::arg("other"), py::arg("full") = false)
      .def("content_digest",
           [](SharedLog& log) { return log.read("content_digest()", [](const Log& l) { return l.content_digest(); }); })
      // For the benchmark: the library's own time for state_at(t) on a fresh Log, without any Python
      // conversion (seconds, median of `repeats` fresh opens), the baseline the module is measured against.
      .def_static("_time_state_at",
                  [](const std::string& path, py::handle t, int repeats) {
                    std::vector<double> seconds;
                    for (int k = 0; k < repeats; ++k) {
                      Log log = value_or_raise(Log::open(path));
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
