// ede._ede.Simulation: a scene run from Python. The library runs with the GIL released; every progress
// report (a few times a second) takes the GIL back to call the user's callback and to let Python see a
// pending Ctrl-C: a KeyboardInterrupt (or an exception from the callback) interrupts the run at its next
// check, and is raised once run() has returned, so the log keeps every complete record and the run can
// be continued or closed. Scenes arrive as TOML text or a file name: the Python layer turns a dict into
// TOML (python/ede/_toml.py), so every scene goes through the one loader and its messages.
// finish() and impulses() are Simulation::finish (the log complete where the run is) and
// Simulation::impulses (running sums of wall impulses and the pair virial, kept when the Simulation was
// made with impulses=True). Rejected: checking signals from a second thread (timing-dependent) and running with the GIL held
// (Ctrl-C would wait for the end of the run, and no other thread could run meanwhile).
#include <memory>

#include "bindings.hpp"

namespace ede::python {

py::dict counts_to_dict(const EventCounts& c);  // bind_log.cpp

namespace {

// What the library's progress callback reaches: the Python callback and what it raised.
struct ProgressHook {
  py::object callback = py::none();
  Simulation* simulation = nullptr;
  std::unique_ptr<py::error_already_set> raised;
};

class PySimulation {
 public:
  PySimulation(const std::string& scene, bool is_file, const std::string& source_name,
               const std::vector<std::string>& overrides, const std::string& log_path, bool impulses)
      : hook_(std::make_shared<ProgressHook>()), impulses_(impulses) {
    std::vector<Override> set;
    for (const std::string& o : overrides) set.push_back(Override{o});
    Result<Scene> loaded = is_file ? load_scene_file(scene, set) : parse_scene_text(scene, source_name, set);
    const Scene& s = value_or_raise(std::move(loaded));
    start(s, log_path);
  }

  explicit PySimulation(const std::string& resume_path) : hook_(std::make_shared<ProgressHook>()) {
    adopt(released([&] { return Simulation::resume(resume_path, options()); }));
  }

  std::string run(py::object max_events, py::object callback) {
    const std::uint64_t budget =
        max_events.is_none() ? std::numeric_limits<std::uint64_t>::max() : max_events.cast<std::uint64_t>();
    hook_->callback = std::move(callback);
    RunStatus status;
    {
      py::gil_scoped_release release;
      status = sim_->run(budget);
    }
    finish_call();
    return to_string(status);
  }

  std::string advance_to(py::handle t, py::object callback) {
    const Time at = time_argument(t, sim_->scene().scalar, "advance_to(t)");
    hook_->callback = std::move(callback);
    Result<RunStatus> status = [&] {
      py::gil_scoped_release release;
      return sim_->advance_to(at);
    }();
    finish_call();
    return to_string(value_or_raise(std::move(status)));
  }

  void interrupt() { sim_->interrupt(); }
  std::string status() const { return to_string(sim_->status()); }
  double time() const { return double(sim_->time()); }
  std::string time_text() const { return exact_text(sim_->time(), scalar()); }
  py::dict state() const { return state_dict(sim_->state()); }
  py::dict counts() const { return counts_to_dict(sim_->counts()); }
  std::string summary_json() const { return to_json(sim_->summary()); }
  std::string summary_text() const { return to_text(sim_->summary()); }
  std::string message() const { return sim_->message(); }
  std::string scene_text() const { return sim_->scene().source_text; }
  void write_state_csv(const std::string& path) const { value_or_raise(sim_->write_state_csv(path)); }
  // Simulation::finish: the log closed complete at the current time (not resumable).
  void finish() { released([&] { return sim_->finish(); }); }
  py::dict impulses() const {
    const ImpulseSums p = sim_->impulses();
    py::dict d;
    d["time"] = p.time, d["wall"] = take_vector(std::vector<double>(p.wall.begin(), p.wall.end()));
    d["virial"] = p.virial, d["pair_collisions"] = p.pair_collisions, d["wall_collisions"] = p.wall_collisions;
    return d;
  }
  void close() { released([&] { return sim_->close(); }); }
  py::dict log_kept() const {
    const LogKept k = value_or_raise(sim_->log_kept());
    py::dict d;
    d["path"] = k.path, d["events"] = k.events, d["last_event_time"] = k.last_event_time;
    d["complete"] = k.complete, d["resumable"] = k.resumable, d["resume_event"] = k.resume_event;
    d["resume_time"] = k.resume_time, d["bytes"] = k.bytes;
    return d;
  }

 private:
  ScalarKind scalar() const {
    const ScalarKind s = sim_->scene().scalar;
    return s == ScalarKind::Float128 ? ScalarKind::LongDouble : s;
  }

  SimulationOptions options() {
    SimulationOptions o;
    o.progress = [hook = hook_](const Progress& p) {
      py::gil_scoped_acquire acquire;
      if (hook->raised) return;
      try {
        if (!hook->callback.is_none()) {
          py::dict d;
          d["fraction"] = p.fraction, d["events"] = p.events, d["time"] = p.time;
          d["wall_seconds"] = p.wall_seconds;
          hook->callback(d);
        }
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      } catch (py::error_already_set& e) {
        hook->raised = std::make_unique<py::error_already_set>(std::move(e));
        if (hook->simulation) hook->simulation->interrupt();
      }
    };
    return o;
  }

  void start(const Scene& scene, const std::string& log_path) {
    SimulationOptions o = options();
    o.log_path = log_path;
    o.impulses = impulses_;
    adopt(released([&] { return Simulation::create(scene, o); }));
  }

  void adopt(Simulation&& sim) {
    sim_ = std::make_unique<Simulation>(std::move(sim));
    hook_->simulation = sim_.get();
  }

  // After run() or advance_to(): raise what the callback or a signal raised, once.
  void finish_call() {
    hook_->callback = py::none();
    if (hook_->raised) {
      std::unique_ptr<py::error_already_set> e = std::move(hook_->raised);
      throw std::move(*e);
    }
  }

  std::shared_ptr<ProgressHook> hook_;
  bool impulses_ = false;  // SimulationOptions::impulses
  std::unique_ptr<Simulation> sim_;
};

}  // namespace

void bind_run(py::module_& m) {
  py::class_<PySimulation>(m, "Simulation")
      .def(py::init<const std::string&, bool, const std::string&, const std::vector<std::string>&,
                    const std::string&, bool>(),
           py::arg("scene"), py::arg("is_file"), py::arg("source_name"), py::arg("overrides"), py::arg("log_path"),
           py::arg("impulses") = false)
      .def(py::init<const std::string&>(), py::arg("resume_path"))
      .def("run", &PySimulation::run, py::arg("max_events"), py::arg("callback"))
      .def("advance_to", &PySimulation::advance_to, py::arg("t"), py::arg("callback"))
      .def("interrupt", &PySimulation::interrupt)
      .def("status", &PySimulation::status)
      .def("time", &PySimulation::time)
      .def("time_text", &PySimulation::time_text)
      .def("state", &PySimulation::state)
      .def("counts", &PySimulation::counts)
      .def("summary_json", &PySimulation::summary_json)
      .def("summary_text", &PySimulation::summary_text)
      .def("message", &PySimulation::message)
      .def("scene_text", &PySimulation::scene_text)
      .def("write_state_csv", &PySimulation::write_state_csv)
      .def("finish", &PySimulation::finish)
      .def("impulses", &PySimulation::impulses)
      .def("close", &PySimulation::close)
      .def("log_kept", &PySimulation::log_kept);
  m.def("check_scene",
        [](const std::string& scene, bool is_file, const std::string& source_name,
           const std::vector<std::string>& overrides) {
          std::vector<Override> set;
          for (const std::string& o : overrides) set.push_back(Override{o});
          Result<Scene> loaded = is_file ? load_scene_file(scene, set) : parse_scene_text(scene, source_name, set);
          return value_or_raise(std::move(loaded)).source_text;
        },
        "The effective scene (TOML after overrides), or the loader's error", py::arg("scene"), py::arg("is_file"),
        py::arg("source_name"), py::arg("overrides"));
  m.def("version", [] { return std::string(version()); });
}

}  // namespace ede::python
