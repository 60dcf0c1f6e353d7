// Helpers shared by the engine tests: hand-made states, a recording sink, one-call runs.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "engine/engine.hpp"
#include "core/initial_state.hpp"

namespace ede::test {

// Records every event and sample the engine reports.
template <class T>
class Recorder final : public Sink<T> {
 public:
  std::vector<EventOutcome<T>> events;
  std::vector<T> sample_times;
  std::vector<std::vector<Disk<T>>> sample_states;  // positions drifted to the sample time
  std::vector<std::vector<T>> sample_omegas;        // rough engines: the spins at each sample
  bool keep_states = false;

  void on_event(const EventOutcome<T>& e, const Particles<T>&) override { events.push_back(e); }
  void on_sample(T t, const Particles<T>& p) override {
    sample_times.push_back(t);
    if (!keep_states) return;
    std::vector<Disk<T>> s(p.disk);
    for (std::size_t i = 0; i < s.size(); ++i) {
      s[i].x = p.x_at(i, t);
      s[i].y = p.y_at(i, t);
      s[i].t = t;
    }
    sample_states.push_back(s);
    sample_omegas.push_back(p.omega);
  }
  std::vector<EventOutcome<T>> of_kind(EventKind k) const {
    std::vector<EventOutcome<T>> out;
    for (const auto& e : events)
      if (e.kind == k) out.push_back(e);
    return out;
  }
};

inline InitialState box(double lx = 1, double ly = 1) {
  InitialState s;
  s.lx = lx;
  s.ly = ly;
  s.species_names = {"disks"};
  return s;
}

inline EngineOptions walls_until(double t) {
  EngineOptions o;
  o.boundary = BoundaryKind::Walls;
  o.stop.time = t;
  return o;
}

template <class T = double>
std::unique_ptr<EngineApi<T>> engine(const InitialState& s, const EngineOptions& o) {
  auto made = make_engine<T>(s, o);
  if (!made) throw std::runtime_error(made.error().message);
  return std::move(made).value();
}

// An engine run to its end with a Recorder attached (the recorder lives on the heap: the engine keeps a
// pointer to it).
struct RecordedRun {
  std::unique_ptr<EngineApi<double>> engine;
  std::unique_ptr<Recorder<double>> recorder = std::make_unique<Recorder<double>>();
  RunStatus status = RunStatus::Running;
  const std::vector<EventOutcome<double>>& events() const { return recorder->events; }
  std::vector<EventOutcome<double>> pairs() const { return recorder->of_kind(EventKind::Pair); }
};

inline RecordedRun run_recorded(const InitialState& s, const EngineOptions& o) {
  RecordedRun r;
  r.engine = engine(s, o);
  r.engine->add_sink(r.recorder.get());
  r.status = r.engine->run();
  return r;
}

// A disk's position at the engine's current time.
template <class T>
double x_now(const EngineApi<T>& e, std::size_t i) { return double(e.particles().x_at(i, e.time())); }
template <class T>
double y_now(const EngineApi<T>& e, std::size_t i) { return double(e.particles().y_at(i, e.time())); }

// A gas of n disks of radius r on a jittered square lattice (non-overlapping by construction) with unit
// speed in directions from a simple deterministic sequence: for tests that do not want setup's code.
inline InitialState lattice_gas(int n_side, double r, double lx, std::uint64_t seed, double speed = 1) {
  InitialState s = box(lx, lx);
  const double a = lx / n_side;
  std::uint64_t state = seed * 0x9E3779B97F4A7C15ull + 1;
  const auto next = [&]() {  // SplitMix64 -> [0, 1)
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  };
  const double room = a / 2 - r;  // how far a centre may move off its site
  for (int iy = 0; iy < n_side; ++iy)
    for (int ix = 0; ix < n_side; ++ix) {
      const double x = (ix + 0.5) * a + (2 * next() - 1) * room * 0.9;
      const double y = (iy + 0.5) * a + (2 * next() - 1) * room * 0.9;
      const double angle = 2 * M_PI * next();
      s.add(x, y, speed * std::cos(angle), speed * std::sin(angle), r, 1.0, 0);
    }
  return s;
}

}  // namespace ede::test
