// Running an engine: sampling, actions, stop conditions, determinism, scalar types, the all-pairs baseline.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>

#include "engine_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {
// A digest of every event's bits, to compare runs exactly.
template <class T>
std::uint64_t digest(const std::vector<EventOutcome<T>>& events) {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&](const void* p, std::size_t n) {
    const unsigned char* c = static_cast<const unsigned char*>(p);
    for (std::size_t k = 0; k < n; ++k) h = (h ^ c[k]) * 1099511628211ull;
  };
  for (const auto& e : events) {
    mix(&e.time, sizeof(T));
    mix(&e.kind, 1);
    mix(&e.i, 4);
    mix(&e.j, 4);
    for (const T* v : {&e.vix, &e.viy, &e.vjx, &e.vjy}) mix(v, sizeof(T));
  }
  return h;
}

EngineOptions periodic_events(std::uint64_t n) {
  EngineOptions o;
  o.boundary = BoundaryKind::Periodic;
  o.stop.events = n;
  return o;
}
}  // namespace

TEST_CASE("samples come at exact times and do not disturb the run", "[run][sample]") {
  const InitialState s = lattice_gas(20, 0.01, 1.0, 21);
  EngineOptions plain = walls_until(2.0);
  EngineOptions sampled = plain;
  sampled.sample_interval = 0.125;
  auto a = engine(s, plain);
  auto b = engine(s, sampled);
  Recorder<double> ra, rb;
  rb.keep_states = true;
  a->add_sink(&ra);
  b->add_sink(&rb);
  REQUIRE(a->run() == RunStatus::ReachedTime);
  REQUIRE(b->run() == RunStatus::ReachedTime);
  CHECK(digest(ra.events) == digest(rb.events));
  REQUIRE(rb.sample_times.size() == 16);
  for (std::size_t k = 0; k < 16; ++k) CHECK(rb.sample_times[k] == 0.125 * double(k + 1));
  // The state a sample sees at t is the state after every event at or before t.
  const auto& last = rb.sample_states.back();
  for (std::size_t i = 0; i < s.size(); ++i) {
    CHECK(last[i].x == b->particles().x_at(i, 2.0));
    CHECK(last[i].vx == b->particles().disk[i].vx);
  }
}

TEST_CASE("samples of a frozen state end the run instead of going on for ever", "[run][sample]") {
  // Disks at rest, an event-count stop that can never be reached, samples and a late action: the samples
  // up to the action are taken, the action is applied, and then, with nothing that can ever happen and no
  // stop time, the run ends (found by fuzz_scene as a hang).
  InitialState s = box();
  s.add(0.3, 0.5, 0.0, 0.0, 0.05, 1.0, 0);
  s.add(0.7, 0.5, 0.0, 0.0, 0.05, 1.0, 0);
  EngineOptions o;
  o.boundary = BoundaryKind::Periodic;
  o.stop.events = 450;
  o.sample_interval = 0.1;
  o.actions.push_back(ActionSpec{0.5, ActionKind::ReverseVelocities});
  Recorder<double> rec;
  auto e = engine(s, o);
  e->add_sink(&rec);
  CHECK(e->run(3) == RunStatus::Running);  // samples count towards run(n): a caller always gets control back
  CHECK(e->run() == RunStatus::NoMoreEvents);
  CHECK(rec.sample_times.size() == 5);  // 0.1 ... 0.5: the action at 0.5 comes first, its sample after
  CHECK(e->counts().of(EventKind::Action) == 1);
}

TEST_CASE("the same input gives the same events, bit for bit", "[run][determinism]") {
  const InitialState s = lattice_gas(30, 0.008, 1.0, 5);
  std::uint64_t first = 0;
  for (int rep = 0; rep < 2; ++rep) {
    auto e = engine(s, periodic_events(50000));
    Recorder<double> rec;
    e->add_sink(&rec);
    e->run();
    if (rep == 0) first = digest(rec.events);
    else CHECK(digest(rec.events) == first);
  }
}

TEST_CASE("running in slices gives the same events as one run", "[run][determinism]") {
  const InitialState s = lattice_gas(20, 0.01, 1.0, 8);
  auto whole = engine(s, periodic_events(20000));
  auto sliced = engine(s, periodic_events(20000));
  Recorder<double> rw, rs;
  whole->add_sink(&rw);
  sliced->add_sink(&rs);
  whole->run();
  while (sliced->run(777) == RunStatus::Running) {
  }
  CHECK(digest(rw.events) == digest(rs.events));
}

TEST_CASE("stop conditions: events, collisions per particle, energy fraction, time", "[run][stop]") {
  const InitialState s = lattice_gas(20, 0.01, 1.0, 9);
  SECTION("events") {
    auto e = engine(s, periodic_events(12345));
    CHECK(e->run() == RunStatus::ReachedEvents);
    CHECK(e->counts().events() == 12345);
  }
  SECTION("collisions per particle") {
    EngineOptions o;
    o.boundary = BoundaryKind::Periodic;
    o.stop.collisions_per_particle = 5;
    auto e = engine(s, o);
    CHECK(e->run() == RunStatus::ReachedCollisions);
    CHECK(e->counts().of(EventKind::Pair) == 1000);  // 5 * 400 / 2
  }
  SECTION("energy fraction") {
    EngineOptions o;
    o.boundary = BoundaryKind::Walls;
    o.physics.restitution = 0.8;
    o.physics.tc = 1e-5;
    o.stop.energy_fraction = 0.1;
    auto e = engine(s, o);
    CHECK(e->run() == RunStatus::ReachedEnergy);
    const double left = kinetic_energy(e->particles()) / e->initial_kinetic_energy();
    CHECK(left <= 0.1);
    CHECK(left > 0.09);  // stopped at the first event below 10 %, not later
  }
  SECTION("time") {
    auto e = engine(s, walls_until(0.3));
    CHECK(e->run() == RunStatus::ReachedTime);
    CHECK(e->time() == 0.3);
  }
}

TEST_CASE("time reversal: reversing every velocity retraces the path back to the start", "[run][action]") {
  // Forward to T, reverse, forward another T: the disks come back to where they started, up to the
  // round-off amplified by the chaos of a short run (a few collisions per disk keep it small).
  const InitialState s = lattice_gas(10, 0.02, 1.0, 4);
  EngineOptions o = walls_until(0.2);
  o.actions.push_back({0.1, ActionKind::ReverseVelocities});
  auto e = engine(s, o);
  Recorder<double> rec;
  e->add_sink(&rec);
  REQUIRE(e->run() == RunStatus::ReachedTime);
  CHECK(e->counts().of(EventKind::Action) == 1);
  CHECK(e->counts().of(EventKind::Pair) > 20);
  double worst = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    worst = std::max(worst, std::hypot(x_now(*e, i) - s.x[i], y_now(*e, i) - s.y[i]));
    CHECK(-e->particles().disk[i].vx == Approx(s.vx[i]).margin(1e-9));
  }
  CHECK(worst < 1e-9);
}

TEST_CASE("the branch-free neighbour scan gives the same events, bit for bit", "[run][determinism][slow]") {
  // EngineOptions::branch_free_scan_up_to is a speed choice: both scans must pick the same winner among
  // the same candidates. Walled and periodic, float and double, a dilute and a dense lattice.
  for (BoundaryKind bc : {BoundaryKind::Walls, BoundaryKind::Periodic})
    for (const double r : {0.015, 0.0249}) {
      const InitialState s = lattice_gas(20, r, 1.0, 9);
      EngineOptions branching = periodic_events(60000), selecting = branching;
      branching.boundary = selecting.boundary = bc;
      branching.branch_free_scan_up_to = 0;
      selecting.branch_free_scan_up_to = s.size();
      auto a = engine(s, branching);
      auto b = engine(s, selecting);
      auto fa = engine<float>(s, branching);
      auto fb = engine<float>(s, selecting);
      Recorder<double> ra, rb;
      Recorder<float> rfa, rfb;
      a->add_sink(&ra);
      b->add_sink(&rb);
      fa->add_sink(&rfa);
      fb->add_sink(&rfb);
      a->run();
      b->run();
      fa->run();
      fb->run();
      INFO("boundary " << int(bc) << ", radius " << r);
      CHECK(ra.of_kind(EventKind::Pair).size() > 10000);  // 60 000 events counting cell crossings
      CHECK(digest(ra.events) == digest(rb.events));
      CHECK(digest(rfa.events) == digest(rfb.events));
    }
}

TEST_CASE("prefetching the next events' disks changes no event", "[run][determinism]") {
  // EngineOptions::prefetch_upcoming_from only warms the cache; a run with it on from the first disk must
  // give the run without it, bit for bit (walls and periodic; a rebuild every 20 000 events restarts the
  // queue, and with it the prefetch's place).
  for (BoundaryKind bc : {BoundaryKind::Walls, BoundaryKind::Periodic}) {
    const InitialState s = lattice_gas(30, 0.012, 1.0, 4);
    EngineOptions off = periodic_events(80000), on = off;
    off.boundary = on.boundary = bc;
    off.rebuild_interval = on.rebuild_interval = 20000;
    off.prefetch_upcoming_from = s.size() + 1;
    on.prefetch_upcoming_from = 0;
    const RecordedRun a = run_recorded(s, off), b = run_recorded(s, on);
    CHECK(a.pairs().size() > 10000);
    CHECK(digest(a.events()) == digest(b.events()));
  }
}

TEST_CASE("both neighbour scans break an exact tie between two partners by the lower id", "[run][determinism]") {
  // A disk moving up between two disks at rest, placed symmetrically on dyadic coordinates: both contacts
  // come at exactly the same time (the same b and c bit for bit), and the disks at rest predict nothing,
  // so the moving disk's own choice is the first collision. Candidate's order says the lower id wins.
  for (const bool lower_on_the_left : {true, false}) {
    InitialState s = box();
    const double r = 1.0 / 32, off = 3.0 / 64, up = 1.0 / 16;  // off < 2 r: both are hit
    s.add(0.5, 0.28125, 0, 1, r, 1.0, 0);
    s.add(0.5 + (lower_on_the_left ? -off : off), 0.28125 + up, 0, 0, r, 1.0, 0);
    s.add(0.5 + (lower_on_the_left ? off : -off), 0.28125 + up, 0, 0, r, 1.0, 0);
    for (const std::size_t up_to : {std::size_t(0), s.size()}) {
      EngineOptions o = walls_until(0.1);
      o.branch_free_scan_up_to = up_to;
      const RecordedRun run = run_recorded(s, o);
      INFO((up_to ? "branch-free" : "branching") << " scan, lower id on the " << (lower_on_the_left ? "left" : "right"));
      REQUIRE(!run.pairs().empty());
      const EventOutcome<double> first = run.pairs().front();  // a copy: pairs() returns a new vector
      CHECK(std::min(first.i, first.j) == 0);
      CHECK(std::max(first.i, first.j) == 1);
    }
  }
}

TEST_CASE("the all-pairs baseline and the cell engine agree", "[run][baseline][slow]") {
  // Both predict with the same functions; they differ in when predictions are made (cell crossings), so
  // event times agree to round-off and the sequences agree until chaos amplifies that round-off.
  for (BoundaryKind bc : {BoundaryKind::Walls, BoundaryKind::Periodic}) {
    const InitialState s = lattice_gas(12, 0.015, 1.0, 6);
    EngineOptions o;
    o.boundary = bc;
    o.stop.events = 100000;
    EngineOptions naive = o;
    naive.algorithm = Algorithm::AllPairs;
    auto a = engine(s, o);
    auto b = engine(s, naive);
    Recorder<double> ra, rb;
    a->add_sink(&ra);
    b->add_sink(&rb);
    a->run();
    b->run();
    const auto pa = ra.of_kind(EventKind::Pair), pb = rb.of_kind(EventKind::Pair);
    // The pair is unordered: either disk may own the prediction, depending on who predicted it first.
    const auto same_pair = [](const EventOutcome<double>& x, const EventOutcome<double>& y) {
      return std::min(x.i, x.j) == std::min(y.i, y.j) && std::max(x.i, x.j) == std::max(y.i, y.j);
    };
    std::size_t same = 0;
    while (same < std::min(pa.size(), pb.size()) && same_pair(pa[same], pb[same]) &&
           std::abs(pa[same].time - pb[same].time) < 1e-9)
      ++same;
    INFO("boundary " << (bc == BoundaryKind::Periodic ? "periodic" : "walls") << ": first " << same << " pair collisions agree");
    CHECK(same >= 300);  // ~2.5 collisions per disk before the sequences part
  }
}

TEMPLATE_TEST_CASE("float, double and long double engines run and conserve energy", "[run][scalar]", float,
                   double, long double) {
  const InitialState s = lattice_gas(20, 0.01, 1.0, 2);
  auto e = engine<TestType>(s, periodic_events(50000));
  REQUIRE(e->run() == RunStatus::ReachedEvents);
  // Relative energy drift: round-off of the type times a generous factor for 2.5 10^4 collisions.
  const double tolerance = 1e4 * double(std::numeric_limits<TestType>::epsilon());
  CHECK(std::abs(kinetic_energy(e->particles()) - e->initial_kinetic_energy()) / e->initial_kinetic_energy() <
        tolerance);
  CHECK(e->check_invariants(1e3 * double(std::numeric_limits<TestType>::epsilon())) == "");
}

TEST_CASE("disks at rest cost nothing until something hits them", "[run][lazy]") {
  // A bed of 2500 resting disks and one moving disk far above: until it arrives, the only events are the
  // mover's own; resting disks are never touched (their record time stays 0).
  InitialState s = box(1.0, 1.0);
  for (int j = 0; j < 50; ++j)
    for (int i = 0; i < 50; ++i) s.add((i + 0.5) / 50, (j + 0.5) / 100, 0.0, 0.0, 0.004, 1.0, 0);
  s.add(0.5, 0.9, 0.0, -1.0, 0.01, 1.0, 0);
  auto e = engine(s, walls_until(0.35));  // reaches the bed top (y ~ 0.5) at t ~ 0.386
  e->run();
  CHECK(e->counts().of(EventKind::Pair) == 0);
  CHECK(e->counts().events() < 100);
  for (std::size_t i = 0; i + 1 < s.size(); ++i) REQUIRE(e->particles().disk[i].t == 0.0);
}

namespace {
// Keeps the k-th rebuild point as a ResumePoint, and counts the events seen before it.
template <class T>
class RebuildCatcher final : public Sink<T> {
 public:
  explicit RebuildCatcher(int which) : which_(which) {}
  ResumePoint<T> point;
  std::size_t events_before = 0;
  bool caught = false;
  std::size_t events_seen = 0;

  void on_event(const EventOutcome<T>&, const Particles<T>&) override { ++events_seen; }
  void on_rebuild(const RebuildPoint<T>& r) override {
    if (seen_++ != which_) return;
    caught = true;
    events_before = events_seen;
    point.time = r.time;
    point.disks = r.particles.disk;
    point.last_collision = r.particles.last_collision;
    point.counts = r.counts;
    point.next_sample_index = r.next_sample_index;
    point.next_action_index = r.next_action_index;
    point.same_time_events = r.same_time_events;
    point.initial_energy = r.initial_energy;
  }

 private:
  int which_, seen_ = 0;
};
}  // namespace

TEST_CASE("a run resumed from a rebuild point produces exactly the original's remaining events", "[run][resume]") {
  // Inelastic with TC, walls, samples and a reverse action: every piece of state a resume must carry.
  const InitialState s = lattice_gas(20, 0.01, 1.0, 31);
  EngineOptions o;
  o.boundary = BoundaryKind::Walls;
  o.physics.restitution = 0.9;
  o.physics.tc = 1e-4;
  o.stop.events = 60000;
  o.sample_interval = 0.01;
  o.actions.push_back({0.05, ActionKind::ReverseVelocities});
  o.rebuild_interval = 5000;

  auto original = engine(s, o);
  Recorder<double> all;
  RebuildCatcher<double> catcher(4);
  original->add_sink(&all);
  original->add_sink(&catcher);
  REQUIRE(original->run() == RunStatus::ReachedEvents);
  REQUIRE(catcher.caught);
  REQUIRE(catcher.events_before > 0);

  auto made = make_engine<double>(s, o, &catcher.point);
  REQUIRE(made.ok());
  auto& resumed = *made.value();
  Recorder<double> rest;
  resumed.add_sink(&rest);
  REQUIRE(resumed.run() == RunStatus::ReachedEvents);
  const std::vector<EventOutcome<double>> tail(all.events.begin() + std::ptrdiff_t(catcher.events_before),
                                               all.events.end());
  REQUIRE(rest.events.size() == tail.size());
  CHECK(digest(rest.events) == digest(tail));
  CHECK(resumed.time() == original->time());
  CHECK(resumed.counts().events() == original->counts().events());
  for (std::size_t i = 0; i < s.size(); ++i) REQUIRE(resumed.particles().disk[i].x == original->particles().disk[i].x);
}
