// The accuracy study, the engine part: for one setting on one scene, the errors a long elastic run leaves
// (energy drift, largest overlap) and the cost (ns per event); then the log's bytes per event for that
// scalar type.
//
// Errors and cost come from different runs, each in its own child:
//   the error run: the scene's stop.events engine events (10^7) in plan.checkpoints slices, untimed. A sink looks at
//     every pair collision: how far inside each other the two disks are at the moment they collide, the
//     largest overlap the run ever produces (exact arithmetic: 0). Between slices the energy, summed in a
//     type wider than the run's (Wide<T>), is compared with the initial one, and EngineApi::
//     largest_overlap() (every near pair at that instant) is read.
//   timed runs: timing_events events (at most stop.events) in one run() call, no sink, nothing else timed. accuracy.cpp
//     interleaves them over all settings (round after round), so that a slow spell of the shared machine
//     hits every setting alike; ns/event is the median. Each reports the drift at its end, which must
//     equal the error run's at the same event (repeats_agree: the runs are deterministic).
// Rejected: timing the error run itself (the sink and the checkpoints would be in the time), reading the
// drift from the engine's own double energy (it rounds away the drift of a long double run), and checking
// overlaps at checkpoints only (in a gas few pairs are in contact at any given instant).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "study/accuracy_parts.hpp"
#include "study/measurement.hpp"
#include "study/log_measure.hpp"

namespace ede::study {

namespace {

// Enough for bytes per event to settle (keyframes included) without writing gigabytes per setting.
constexpr std::uint64_t kLogBytesEvents = 4000000;

// At every pair collision, (s^2 - d^2) / (2 s^2) ~ (s - d) / s in the run's own type: the overlap of the
// two disks at the moment they collide (d: distance of centres, minimum image; s: contact distance).
template <class T>
class ContactOverlap final : public Sink<T> {
 public:
  ContactOverlap(T lx, T ly, bool periodic) : lx_(lx), ly_(ly), periodic_(periodic) {}
  void on_event(const EventOutcome<T>& o, const Particles<T>& p) override {
    if (o.kind != EventKind::Pair) return;
    T dx = p.x_at(std::size_t(o.j), o.time) - p.x_at(std::size_t(o.i), o.time);
    T dy = p.y_at(std::size_t(o.j), o.time) - p.y_at(std::size_t(o.i), o.time);
    if (periodic_) dx = nearest_image(dx, lx_), dy = nearest_image(dy, ly_);
    const T s = p.disk[std::size_t(o.i)].r + p.disk[std::size_t(o.j)].r;
    largest = std::max(largest, double((s * s - (dx * dx + dy * dy)) / (2 * s * s)));
  }
  double largest = 0;

 private:
  static T nearest_image(T d, T length) { return d > length / 2 ? d - length : d < -length / 2 ? d + length : d; }
  T lx_, ly_;
  bool periodic_;
};

template <class T>
int error_child(const StudyScene& s, const StudyPlan& plan, std::string& out) {
  const std::uint64_t events = StudyPlan::long_events(s), timing_events = plan.timed_events(s);
  if (events == 0) return out = "the study runs each scene for its stop.events: set it (--set stop.events=N)", 1;
  EngineOptions options = s.options;
  options.stop = StopSpec{};
  options.stop.events = events;
  auto made = s.engine<T>(options);
  if (!made) return out = made.error().message, 1;
  EngineApi<T>& engine = *made.value();
  ContactOverlap<T> contact(T(s.initial.lx), T(s.initial.ly), s.options.boundary == BoundaryKind::Periodic);
  engine.add_sink(&contact);
  const auto e0 = kinetic_energy_wide(engine.particles());
  const std::uint64_t slice = std::max<std::uint64_t>(1, events / std::uint64_t(plan.checkpoints));
  double drift = 0, drift_max = 0, snapshot = 0, drift_at_timing = -1;
  RunStatus status = RunStatus::Running;
  while (status == RunStatus::Running && engine.counts().events() < events) {
    const std::uint64_t done = engine.counts().events();
    // Slices end at the timed runs' length too, where their drift is compared with this run's.
    std::uint64_t next = std::min(done + slice, events);
    if (done < timing_events) next = std::min(next, timing_events);
    status = engine.run(next - done);
    drift = relative_change(kinetic_energy_wide(engine.particles()), e0);
    drift_max = std::max(drift_max, drift);
    snapshot = std::max(snapshot, engine.largest_overlap());
    if (engine.counts().events() == timing_events) drift_at_timing = drift;
  }
  if (status == RunStatus::Stalled) return out = engine.stall_message(), 1;
  std::ostringstream o;
  o.precision(17);
  o << "disks=" << s.initial.size() << " events=" << engine.counts().events()
    << " collisions=" << engine.counts().collisions() << " drift=" << drift << " drift_max=" << drift_max
    << " overlap=" << contact.largest << " overlap_snapshot=" << snapshot << " drift_at_timing=" << drift_at_timing
    << " timing_events=" << timing_events;
  out = o.str();
  return 0;
}

template <class T>
int timed_child(const StudyScene& s, const StudyPlan& plan, std::string& out) {
  const std::uint64_t events = plan.timed_events(s);
  EngineOptions options = s.options;
  options.stop = StopSpec{};
  options.stop.events = events;
  auto made = s.engine<T>(options);
  if (!made) return out = made.error().message, 1;
  EngineApi<T>& engine = *made.value();
  const auto e0 = kinetic_energy_wide(engine.particles());
  const auto t0 = std::chrono::steady_clock::now();
  const RunStatus status = engine.run(events);
  const double seconds = seconds_since(t0);
  if (status == RunStatus::Stalled) return out = engine.stall_message(), 1;
  std::ostringstream o;
  o.precision(17);
  o << "events=" << engine.counts().events() << " seconds=" << seconds
    << " drift=" << relative_change(kinetic_energy_wide(engine.particles()), e0);
  out = o.str();
  return 0;
}

void measure_log_bytes(const StudyPlan& plan, EngineRow& row) {
  if (!has_log(row.setting.precision)) return;
  RunConfig c;
  c.label = row.scene + "-" + precision_name(row.setting.precision);
  c.scene = plan.scene(row.scene);
  c.events = std::min(std::uint64_t(row.events), kLogBytesEvents);
  c.overrides = plan.overrides;
  c.overrides.push_back(scalar_override(row.setting.precision));
  c.variant.contact = row.setting.contact;
  c.log = true;
  c.log_path = plan.tmp_dir + "/accuracy-" + std::to_string(::getpid()) + ".ede";
  const RunResult r = run_measured(c);
  std::filesystem::remove(c.log_path);
  if (!r.ok) row.failure = "log run: " + r.failure;
  else if (r.logged > 0) row.log_bytes_per_event = r.bytes / r.logged;
}

}  // namespace

const std::vector<std::string>& engine_scenes() {
  static const std::vector<std::string> names = {"gas", "dense", "crystal"};
  return names;
}

void measure_engine_errors(const StudyPlan& plan, EngineRow& row) {
  const ChildMeasurement m = in_child(plan, row, [&]<class T>(const StudyScene& s, std::string& out) {
    return error_child<T>(s, plan, out);
  });
  if (!m.ok) {
    row.failure = m.failure;
    return;
  }
  const KeyValues& kv = m.values;
  row.disks = get(kv, "disks"), row.events = get(kv, "events"), row.collisions = get(kv, "collisions");
  row.drift = get(kv, "drift"), row.drift_max = get(kv, "drift_max");
  row.overlap = get(kv, "overlap"), row.overlap_snapshot = get(kv, "overlap_snapshot");
  row.drift_at_timing = get(kv, "drift_at_timing"), row.timing_events = get(kv, "timing_events");
  std::fprintf(stderr, "  %-8s %-26s %.3g events: drift %.3g, overlap %.3g\n", row.scene.c_str(),
               row.setting.label().c_str(), row.events, row.drift, row.overlap);
  measure_log_bytes(plan, row);
}

void measure_engine_time(const StudyPlan& plan, EngineRow& row) {
  const ChildMeasurement m = in_child(plan, row, [&]<class T>(const StudyScene& s, std::string& out) {
    return timed_child<T>(s, plan, out);
  });
  if (!m.ok) {
    row.failure = "timed run: " + m.failure;
    return;
  }
  const double events = get(m.values, "events");
  row.ns_runs.push_back(1e9 * get(m.values, "seconds") / std::max(1.0, events));
  row.ns_per_event = median(row.ns_runs);
  if (get(m.values, "drift") != row.drift_at_timing || events != row.timing_events)
    row.repeats_agree = false;
  std::fprintf(stderr, "  %-8s %-26s timed run %zu: %.0f ns/event\n", row.scene.c_str(), row.setting.label().c_str(),
               row.ns_runs.size(), row.ns_runs.back());
}

}  // namespace ede::study
