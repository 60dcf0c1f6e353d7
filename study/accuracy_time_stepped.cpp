// The accuracy study, the time-stepped part: what the event-driven approach avoids. A time-stepped
// simulation (ede::TimeStepped: move by v dt, resolve the overlapping pairs found) of the same scene at
// several dt, against the event-driven engine (double, stable root) from the same initial state:
//   elastic gas (accuracy/gas): the pair collision rate over ts_collisions mean free times, error
//     |rate / event-driven rate - 1|; the energy drift (the time-stepped method conserves energy by
//     construction: impulses along the line of centres) and the largest overlap.
//   inelastic gas (accuracy/cooling, xi = 0.9): the cooling curve E(t)/E0 at cooling_points times over
//     cooling_collisions initial mean free times, error max_k |E_ts(t_k) / E_ed(t_k) - 1|.
// dt is given in mean free times tau (time per collision per disk, from a probe run of each gas), and as
// v_rms dt / d, the distance a disk moves in one step in diameters, which sets the error. Times are CPU
// seconds of the run's thread (getrusage), medians over repeats, each run in its own child; the ratios
// are to the event-driven runs of the same study. The event-driven engine also runs from another seed
// (another sample of the same gas): its "errors" are how much the rate and the cooling curve differ
// between samples. The collision rate over 300 tau forgets the start, so that is its floor; the cooling
// curve over 20 tau does not (the time-stepped run starts from the reference's own state and can come
// closer). The event-driven rate's own noise is also shown by 10 blocks of its run (standard error of
// the block rates).
// Rejected: comparing with Enskog's collision rate (its error at these densities is larger than the
// differences we want to show).
#include <cmath>
#include <cstdio>
#include <sstream>

#include "study/accuracy_parts.hpp"
#include "study/measurement.hpp"
#include "study/log_measure.hpp"

#include "study/time_stepped.hpp"

namespace ede::study {

namespace {

constexpr int kBlocks = 10;
constexpr int kOtherSeed = 9001;  // the noise-floor runs' seed (the study's scenes use 101 to 104)
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
  auto made = s.engine<double>(opt);
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
  TimeSteppedOptions options;
  options.dt = dt;
  options.boundary = s.scene.boundary;
  options.restitution = ph.restitution;
  options.wall_restitution = ph.wall_restitution;
  auto made = TimeStepped::create(s.initial, options);
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
    << " overlap=" << ts.largest_overlap() << " drift=" << double(std::fabs(ts.kinetic_energy() / e0 - 1));
  for (std::size_t k = 0; k < energy.size(); ++k) o << " energy_" << k << "=" << energy[k];
  out = o.str();
  return 0;
}

// A child on the scene `name` (double, stable root); the median CPU over `repeat` runs in "cpu".
template <class Body>
ChildMeasurement repeated(const StudyPlan& plan, const std::string& name, Body body,
                          const std::vector<std::string>& overrides = {}) {
  ChildMeasurement first;
  std::vector<double> cpu;
  for (int k = 0; k < plan.repeat; ++k) {
    ChildMeasurement m = run_child_measurement([&](std::string& out) {
      auto s = plan.load(name, kReference, overrides);
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

// Mean free time tau (time per collision per disk, over the first two) of the scene `name`, its mean
// diameter and its rms speed.
Result<KeyValues> mean_free_time(const StudyPlan& plan, const std::string& name) {
  const ChildMeasurement m = run_child_measurement([&](std::string& out) {
    auto s = plan.load(name, kReference);
    if (!s) return out = s.error().message, 1;
    const Result<double> t = time_at_collisions<double>(s.value(), 2);
    if (!t) return out = t.error().message, 1;
    std::ostringstream o;
    o.precision(17);
    const InitialState& in = s.value().initial;
    double d = 0, e2 = 0, m = 0;
    for (std::size_t i = 0; i < in.size(); ++i)
      d += 2 * in.radius[i] / double(in.size()), e2 += in.mass[i] * (in.vx[i] * in.vx[i] + in.vy[i] * in.vy[i]),
          m += in.mass[i];
    o << "tau=" << t.value() / 2 << " diameter=" << d << " v_rms=" << std::sqrt(e2 / m);
    out = o.str();
    return 0;
  });
  if (!m.ok) return Error{m.failure};
  return m.values;
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
  const Result<KeyValues> gas = mean_free_time(plan, "gas"), cool = mean_free_time(plan, "cooling");
  if (!gas || !cool) {
    SteppedRow failed;
    failed.method = "event-driven";
    failed.failure = (gas ? cool : gas).error().message;
    st.rows.push_back(failed);
    return st;
  }
  st.tau = get(gas.value(), "tau"), st.tau_cooling = get(cool.value(), "tau");
  st.diameter = get(gas.value(), "diameter"), st.v_rms = get(gas.value(), "v_rms");
  st.span = plan.ts_collisions * st.tau;
  st.cooling_span = plan.cooling_collisions * st.tau_cooling;
  const int points = plan.cooling_points;
  std::fprintf(stderr, "  time-stepped: tau %.4g, span %.4g; cooling span %.4g\n", st.tau, st.span, st.cooling_span);

  // The event-driven runs: the reference, then the same gases from another seed (the spread between samples).
  const auto event_driven = [&](const std::string& method, const std::vector<std::string>& overrides) {
    SteppedRow row;
    row.method = method;
    const ChildMeasurement g = repeated(plan, "gas", [&](const StudyScene& s, std::string& out) {
      return event_driven_child(s, st.span, kBlocks, out);
    }, overrides);
    const ChildMeasurement c = repeated(plan, "cooling", [&](const StudyScene& s, std::string& out) {
      return event_driven_child(s, st.cooling_span, points, out);
    }, overrides);
    if (!g.ok || !c.ok) row.failure = g.ok ? c.failure : g.failure;
    row.cpu_seconds = get(g.values, "cpu"), row.cooling_cpu_seconds = get(c.values, "cpu");
    row.pair_collisions = get(g.values, "pairs"), row.overlap = get(g.values, "overlap");
    row.energy_drift = std::fabs(get(g.values, "energy_" + std::to_string(kBlocks - 1)) - 1);
    return std::make_pair(row, std::make_pair(g.values, c.values));
  };
  // Named variables, not structured bindings: Clang 14 (Debian 12) cannot capture bindings in a lambda.
  const auto reference = event_driven("event-driven", {});
  const SteppedRow& ref = reference.first;
  const KeyValues& ed = reference.second.first;
  const KeyValues& ed_cool = reference.second.second;
  st.rows.push_back(ref);
  if (!ref.failure.empty()) return st;
  st.rows.back().cpu_ratio = 1, st.rows.back().cooling_cpu_ratio = 1;
  st.rate = ref.pair_collisions / st.span;
  st.rate_stderr = block_stderr(ed, st.span) / st.rate;
  st.energy_end = get(ed_cool, "energy_" + std::to_string(points - 1));
  // Against the reference: the errors and cost ratios of a row (its pair collisions and CPU set, its cooling run).
  const auto compare = [&](SteppedRow& row, const KeyValues& cool_run) {
    row.rate_error = std::fabs(row.pair_collisions / ref.pair_collisions - 1);
    row.cooling_error = cooling_error(cool_run, ed_cool, points);
    row.cpu_ratio = row.cpu_seconds / ref.cpu_seconds;
    row.cooling_cpu_ratio = row.cooling_cpu_seconds / ref.cooling_cpu_seconds;
  };
  {
    auto [other, values] = event_driven("event-driven (other seed)", {"seed=" + std::to_string(kOtherSeed)});
    if (other.failure.empty()) compare(other, values.second);
    st.rows.push_back(other);
  }

  for (const double f : plan.ts_dt_fractions) {
    SteppedRow row;
    row.method = "time-stepped";
    row.dt_over_tau = f;
    row.dt = f * st.tau;
    row.step_over_diameter = st.v_rms * row.dt / st.diameter;
    const ChildMeasurement g = repeated(plan, "gas", [&](const StudyScene& s, std::string& out) {
      return time_stepped_child(s, f * st.tau, st.span, 1, out);
    });
    const ChildMeasurement c = repeated(plan, "cooling", [&](const StudyScene& s, std::string& out) {
      return time_stepped_child(s, f * st.tau_cooling, st.cooling_span, points, out);
    });
    if (!g.ok || !c.ok) {
      row.failure = g.ok ? c.failure : g.failure;
    } else {
      row.cpu_seconds = get(g.values, "cpu"), row.cooling_cpu_seconds = get(c.values, "cpu");
      row.pair_collisions = get(g.values, "pairs"), row.overlap = get(g.values, "overlap");
      row.energy_drift = get(g.values, "drift");
      compare(row, c.values);
    }
    std::fprintf(stderr, "  time-stepped dt = %g tau: rate error %.3g, cooling error %.3g, cpu x%.3g\n", f,
                 row.rate_error, row.cooling_error, row.cpu_ratio);
    st.rows.push_back(row);
  }
  return st;
}

}  // namespace ede::study
