// ede-bench accuracy, the time-stepped part: what the event-driven approach avoids. A time-stepped
// simulation (ede::TimeStepped: move by v dt, resolve the overlapping pairs found) of the same scene at
// several dt, against the event-driven engine (double, stable root) from the same initial state:
//   elastic gas (accuracy/gas): the pair collision rate over ts_collisions mean free times, error
//     |rate / event-driven rate - 1|, and the largest overlap. Energy is no test here: the time-stepped
//     method conserves it by construction (impulses).
//   inelastic gas (accuracy/cooling, xi = 0.9): the cooling curve E(t)/E0 at cooling_points times over
//     cooling_collisions initial mean free times, error max_k |E_ts(t_k) / E_ed(t_k) - 1|.
// dt is given in mean free times tau (time per collision per disk, from a probe run of each gas). Times are
// CPU seconds of the run's thread (getrusage), medians over repeats, each run in its own child. The
// event-driven rate's own noise is shown by 10 blocks of its run (standard error of the block rates).
// Rejected: comparing with Enskog's collision rate (its error
// at these densities is larger than the differences we want to show).
#include <cmath>
#include <cstdio>
#include <sstream>

#include "accuracy_parts.hpp"
#include "bench_common.hpp"
#include "log_measure.hpp"

#include "ede/time_stepped.hpp"

namespace ede::bench {

namespace {

constexpr int kBlocks = 10;
const Setting kReference{Precision::Double, ContactRoot::Stable};

// Records at each sample the pair collisions so far and the energy ratio; the engine is read, never changed.
class Recorder final : public Sink<double> {
 public:
  explicit Recorder(const EngineApi<double>& e) : e_(e), e0_(kinetic_energy_wide(e.particles())) {}
  void on_event(const EventOutcome<double>&, const Particles<double>&) override {}
  void on_sample(double, const Particles<double>& p) override {
    pairs.push_back(double(e_.counts().of(EventKind::Pair)));
    energy.push_back(double(kinetic_energy_wide(p) / e0_));
    overlap = std::max(overlap, e_.largest_overlap());
  }
  std::vector<double> pairs, energy;
  double overlap = 0;

 private:
  const EngineApi<double>& e_;
  long double e0_;
};

// The event-driven run to `span` with `samples` samples, timed: cpu, pairs, overlap, sample_k, energy_k.
int event_driven_child(const StudyScene& s, double span, int samples, std::string& out) {
  EngineOptions opt = s.options;
  opt.stop = StopSpec{};
  opt.sample_interval = span / samples;
  opt.stop.time = double(samples) * *opt.sample_interval;  // the engine's own expression for the last sample
  auto made = make_engine<double>(s.initial, opt);
  if (!made) return out = made.error().message, 1;
  Recorder rec(*made.value());
  made.value()->add_sink(&rec);
  const double cpu0 = cpu_times().thread;
  if (made.value()->run() == RunStatus::Stalled) return out = made.value()->stall_message(), 1;
  std::ostringstream o;
  o.precision(17);
  o << "cpu=" << cpu_times().thread - cpu0 << " pairs=" << made.value()->counts().of(EventKind::Pair)
    << " overlap=" << rec.overlap;
  for (std::size_t k = 0; k < rec.pairs.size(); ++k) o << " pairs_" << k << "=" << rec.pairs[k];
  for (std::size_t k = 0; k < rec.energy.size(); ++k) o << " energy_" << k << "=" << rec.energy[k];
  out = o.str();
  return 0;
}

// The time-stepped run to span in `points` stops (1: straight through), timed: cpu, pairs, overlap, energy_k.
int time_stepped_child(const StudyScene& s, double dt, double span, int points, std::string& out) {
  const PhysicsSpec& ph = s.scene.physics;
  auto made = TimeStepped::create(s.initial, TimeSteppedOptions{dt, s.scene.boundary, ph.restitution,
                                                                ph.wall_restitution});
  if (!made) return out = made.error().message, 1;
  TimeStepped& ts = made.value();
  const long double e0 = ts.kinetic_energy();
  std::ostringstream o;
  o.precision(17);
  const double cpu0 = cpu_times().thread;
  std::vector<double> energy;
  for (int k = 1; k <= points; ++k) {
    ts.run_until(span * k / points);
    energy.push_back(double(ts.kinetic_energy() / e0));
  }
  o << "cpu=" << cpu_times().thread - cpu0 << " pairs=" << ts.counts().pair_collisions
    << " overlap=" << ts.largest_overlap();
  for (std::size_t k = 0; k < energy.size(); ++k) o << " energy_" << k << "=" << energy[k];
  out = o.str();
  return 0;
}

// A child on the scene `name` (double, stable root); the median CPU over `repeat` runs in "cpu".
template <class Body>
ChildMeasurement repeated(const StudyPlan& plan, const std::string& name, Body body) {
  ChildMeasurement first;
  std::vector<double> cpu;
  for (int k = 0; k < plan.repeat; ++k) {
    ChildMeasurement m = run_child_measurement([&](std::string& out) {
      auto s = load_study_scene(plan.scene(name), kReference);
      if (!s) return out = s.error().message, 1;
      return body(s.value(), out);
    });
    if (!m.ok) return m;
    cpu.push_back(get(m.values, "cpu"));
    if (k == 0) first = std::move(m);
  }
  first.values["cpu"] = median(cpu);
  return first;
}

// Mean free time tau (time per collision per disk, over the first two) of the scene `name`.
Result<double> mean_free_time(const StudyPlan& plan, const std::string& name) {
  const ChildMeasurement m = run_child_measurement([&](std::string& out) {
    auto s = load_study_scene(plan.scene(name), kReference);
    if (!s) return out = s.error().message, 1;
    const Result<double> t = time_at_collisions<double>(s.value(), 2);
    if (!t) return out = t.error().message, 1;
    std::ostringstream o;
    o.precision(17);
    o << "tau=" << t.value() / 2 << " disks=" << s.value().initial.size();
    out = o.str();
    return 0;
  });
  if (!m.ok) return Error{m.failure};
  return get(m.values, "tau");
}

// Standard error of the rate over the blocks between successive samples.
double block_stderr(const KeyValues& kv, double span) {
  std::vector<double> rates;
  double before = 0;
  for (int k = 0; k < kBlocks; ++k) {
    const double now = get(kv, "pairs_" + std::to_string(k));
    rates.push_back((now - before) / (span / kBlocks));
    before = now;
  }
  double mean = 0, var = 0;
  for (double r : rates) mean += r / kBlocks;
  for (double r : rates) var += (r - mean) * (r - mean) / (kBlocks - 1);
  return std::sqrt(var / kBlocks);
}

double cooling_error(const KeyValues& ts, const KeyValues& ed, int points) {
  double worst = 0;
  for (int k = 0; k < points; ++k) {
    const std::string key = "energy_" + std::to_string(k);
    worst = std::max(worst, std::fabs(get(ts, key) / get(ed, key) - 1));
  }
  return worst;
}

}  // namespace

SteppedStudy measure_time_stepped(const StudyPlan& plan) {
  SteppedStudy st;
  const Result<double> tau = mean_free_time(plan, "gas"), tau_cool = mean_free_time(plan, "cooling");
  if (!tau || !tau_cool) {
    st.rows.push_back({"event-driven", 0, 0, 0, 0, 0, 0, 0, 0, (tau ? tau_cool : tau).error().message});
    return st;
  }
  st.tau = tau.value();
  st.span = plan.ts_collisions * st.tau;
  st.cooling_span = plan.cooling_collisions * tau_cool.value();
  const int points = plan.cooling_points;
  std::fprintf(stderr, "  time-stepped: tau %.4g, span %.4g; cooling span %.4g\n", st.tau, st.span, st.cooling_span);

  const ChildMeasurement ed = repeated(plan, "gas", [&](const StudyScene& s, std::string& out) {
    return event_driven_child(s, st.span, kBlocks, out);
  });
  const ChildMeasurement ed_cool = repeated(plan, "cooling", [&](const StudyScene& s, std::string& out) {
    return event_driven_child(s, st.cooling_span, points, out);
  });
  SteppedRow ref{"event-driven", 0, 0, get(ed.values, "cpu"), get(ed.values, "pairs"), 0, 0,
                 get(ed_cool.values, "cpu"), get(ed.values, "overlap"), ""};
  if (!ed.ok || !ed_cool.ok) ref.failure = ed.ok ? ed_cool.failure : ed.failure;
  st.rows.push_back(ref);
  if (!ref.failure.empty()) return st;
  st.rate = ref.pair_collisions / st.span;
  st.rate_stderr = block_stderr(ed.values, st.span) / st.rate;
  st.energy_end = get(ed_cool.values, "energy_" + std::to_string(points - 1));

  for (const double f : plan.ts_dt_fractions) {
    SteppedRow row{"time-stepped", f, f * st.tau, 0, 0, 0, 0, 0, 0, ""};
    const ChildMeasurement gas = repeated(plan, "gas", [&](const StudyScene& s, std::string& out) {
      return time_stepped_child(s, f * st.tau, st.span, 1, out);
    });
    const ChildMeasurement cool = repeated(plan, "cooling", [&](const StudyScene& s, std::string& out) {
      return time_stepped_child(s, f * tau_cool.value(), st.cooling_span, points, out);
    });
    if (!gas.ok || !cool.ok) {
      row.failure = gas.ok ? cool.failure : gas.failure;
    } else {
      row.cpu_seconds = get(gas.values, "cpu");
      row.pair_collisions = get(gas.values, "pairs");
      row.rate_error = std::fabs(row.pair_collisions / ref.pair_collisions - 1);
      row.overlap = get(gas.values, "overlap");
      row.cooling_cpu_seconds = get(cool.values, "cpu");
      row.cooling_error = cooling_error(cool.values, ed_cool.values, points);
    }
    std::fprintf(stderr, "  time-stepped dt = %g tau: rate error %.3g, cooling error %.3g\n", f, row.rate_error,
                 row.cooling_error);
    st.rows.push_back(row);
  }
  return st;
}

}  // namespace ede::bench
