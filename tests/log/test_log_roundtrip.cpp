// Engine -> log -> replay: the replayed state is the engine's, bit for bit, at every sample and at the
// end, for every scalar type and effect; the decoded events are the engine's events.
#include <catch2/catch.hpp>
#include <cstring>

#include "log/id_lookahead.hpp"
#include "log_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

template <class T>
bool same_bits(T a, T b) {
  return std::memcmp(&a, &b, sizeof(T) == 16 ? 10 : sizeof(T)) == 0;
}

EngineOptions rich_options(BoundaryKind bc, double xi, double tc) {
  EngineOptions o;
  o.boundary = bc;
  o.physics.restitution = xi;
  o.physics.wall_restitution = xi;
  o.physics.tc = tc;
  o.stop.time = 0.6;
  o.sample_interval = 0.05;
  o.actions.push_back({0.3, ActionKind::ReverseVelocities});
  o.rebuild_interval = 3000;
  return o;
}

// Small chunks and keyframes so a short run exercises many of each.
LogSettings small_records() {
  LogSettings s;
  s.chunk_events = 500;
  s.keyframe_interval = 1700;
  return s;
}

template <class T>
void check_samples_replay_exactly(const InitialState& s, const EngineOptions& o, const std::string& file) {
  const LoggedRun<T> run = run_logged<T>(s, o, file, small_records());
  REQUIRE(run.status == RunStatus::ReachedTime);
  auto replay = replay_of<T>(run.path);
  const Recorder<T>& rec = *run.recorder;
  REQUIRE(rec.sample_times.size() >= 10);
  // Out of order on purpose: seeking backwards reloads a keyframe, forwards continues.
  for (std::size_t k : {std::size_t(3), std::size_t(0), rec.sample_times.size() - 1, std::size_t(5), std::size_t(6)}) {
    const T t = rec.sample_times[k];
    REQUIRE(replay->seek_time(t));
    const Particles<T>& p = replay->particles();
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Disk<T>& e = rec.sample_states[k][i];
      REQUIRE(same_bits(p.x_at(i, t), e.x));
      REQUIRE(same_bits(p.y_at(i, t), e.y));
      REQUIRE(same_bits(p.disk[i].vx, e.vx));
      REQUIRE(same_bits(p.disk[i].vy, e.vy));
    }
  }
  // The end: the engine's own records, field by field.
  REQUIRE(replay->seek_time(replay->final_time()));
  CHECK(same_bits(replay->final_time(), run.engine->time()));
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Disk<T>& a = replay->particles().disk[i];
    const Disk<T>& b = run.engine->particles().disk[i];
    REQUIRE((same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.vx, b.vx) && same_bits(a.vy, b.vy) &&
             same_bits(a.t, b.t)));
  }
}

}  // namespace

TEMPLATE_TEST_CASE("replayed states are bit-identical to the engine's at every sample", "[log][replay]", float,
                   double, long double) {
  const InitialState s = lattice_gas(15, 0.012, 1.0, 77);
  SECTION("walls, elastic") { check_samples_replay_exactly<TestType>(s, rich_options(BoundaryKind::Walls, 1, 0), "rt-walls.ede"); }
  SECTION("periodic, elastic (wraps)") {
    check_samples_replay_exactly<TestType>(s, rich_options(BoundaryKind::Periodic, 1, 0), "rt-periodic.ede");
  }
  SECTION("walls, inelastic with TC") {
    check_samples_replay_exactly<TestType>(s, rich_options(BoundaryKind::Walls, 0.7, 1e-4), "rt-tc.ede");
  }
}

// Every event replay decodes from `run`'s log is the event the engine reported, bit for bit.
void require_decoded_events_are_the_engines(const LoggedRun<double>& run) {
  std::vector<EventOutcome<double>> logged_kinds;
  for (const auto& e : run.recorder->events)
    if (e.kind != EventKind::Cell) logged_kinds.push_back(e);
  auto log = open_log(run.path);
  CHECK(log->complete());
  REQUIRE(log->total_events() == logged_kinds.size());
  auto replay = replay_of<double>(run.path);
  std::size_t k = 0;
  REQUIRE(replay->for_each_event(0, log->total_events(), [&](const ReplayedEvent<double>& e) {
    const EventOutcome<double>& o = logged_kinds[k];
    REQUIRE(e.index == k);
    REQUIRE(e.time == o.time);
    REQUIRE(e.kind == o.kind);
    REQUIRE(e.i == o.i);
    REQUIRE(e.j == o.j);
    if (e.kind == EventKind::Pair || e.kind == EventKind::Wall) {
      REQUIRE(e.vix == o.vix);
      REQUIRE(e.viy == o.viy);
    }
    if (e.kind == EventKind::Pair) {
      REQUIRE(e.vjx == o.vjx);
      REQUIRE(e.vjy == o.vjy);
    }
    ++k;
    return true;
  }));
  CHECK(k == logged_kinds.size());
}

TEST_CASE("decoded events are the engine's events", "[log][replay]") {
  const InitialState s = lattice_gas(15, 0.012, 1.0, 78);
  require_decoded_events_are_the_engines(
      run_logged<double>(s, rich_options(BoundaryKind::Periodic, 0.9, 0), "events.ede", small_records()));
}

// Above IdLookahead::kMinDisks the decoder reads the id columns ahead and prefetches: nothing decoded changes.
TEST_CASE("decoded events are the engine's events with the decoder's lookahead on", "[log][replay]") {
  const int side = 182;  // 33124 disks
  REQUIRE(std::size_t(side * side) >= IdLookahead::kMinDisks);
  const InitialState s = lattice_gas(side, 0.3 / side, 1.0, 80);
  EngineOptions o = rich_options(BoundaryKind::Periodic, 0.9, 0);
  o.stop = {};
  o.stop.events = 40000;
  o.actions.clear();
  o.sample_interval.reset();  // the recorder keeps no 33 000-disk states
  require_decoded_events_are_the_engines(run_logged<double>(s, o, "events-large.ede", small_records()));
}

TEST_CASE("seeking by event and by time agree, forwards and backwards", "[log][replay]") {
  const InitialState s = lattice_gas(12, 0.015, 1.0, 79);
  EngineOptions o = rich_options(BoundaryKind::Walls, 1, 0);
  o.stop.time = 6;
  const LoggedRun<double> run = run_logged<double>(s, o, "seek.ede", small_records());
  auto log = open_log(run.path);
  REQUIRE(log->keyframes().size() >= 4);
  auto a = replay_of<double>(run.path);
  auto b = replay_of<double>(run.path);
  const std::uint64_t total = log->total_events();
  for (std::uint64_t n : {total / 2, std::uint64_t(10), total, std::uint64_t(1700), total / 3 + 1, std::uint64_t(0)}) {
    const Status sought = a->seek_event(n);
    INFO((sought ? std::string() : sought.error().message));
    REQUIRE(sought.ok());
    CHECK(a->events_applied() == n);
    REQUIRE(b->seek_event(0));
    REQUIRE(b->for_each_event(0, n, [](const ReplayedEvent<double>&) { return true; }));
    for (std::size_t i = 0; i < s.size(); ++i) REQUIRE(a->particles().disk[i].x == b->particles().disk[i].x);
  }
  CHECK_FALSE(a->seek_event(log->total_events() + 1));
  CHECK_FALSE(a->seek_time(a->final_time() * 2));
}

TEST_CASE("a run with a log and one without give the same events", "[log][determinism]") {
  const InitialState s = lattice_gas(12, 0.015, 1.0, 80);
  const EngineOptions o = rich_options(BoundaryKind::Periodic, 1, 0);
  const LoggedRun<double> logged = run_logged<double>(s, o, "with-log.ede", small_records());
  const RecordedRun plain = run_recorded(s, o);
  REQUIRE(plain.events().size() == logged.recorder->events.size());
  for (std::size_t k = 0; k < plain.events().size(); ++k) {
    REQUIRE(plain.events()[k].time == logged.recorder->events[k].time);
    REQUIRE(plain.events()[k].vix == logged.recorder->events[k].vix);
  }
}
