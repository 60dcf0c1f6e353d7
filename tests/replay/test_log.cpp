// ede::Log, the public way to read a run: info, states at times and events, events with full data,
// verify and diff, and exact numbers in and out.
#include <catch2/catch.hpp>
#include <atomic>
#include <cmath>
#include <cstring>

#include "ede/ede.hpp"
#include "scene_test_support.hpp"  // scene_of, run_to_log
#include "tool_runner.hpp"  // temp_path

using ede::test::temp_path;

namespace {

const char* kScene = R"(seed = 3
[box]
size = [1.0, 1.0]
boundary = "periodic"
[[species]]
name = "small"
count = 150
radius = 0.01
mass = 1.0
[[species]]
name = "big"
count = 50
radius = 0.02
mass = 4.0
[species.velocity]
kind = "speed"
speed = 1.0
[stop]
time = 1.0
)";

ede::Log logged(const std::string& name, const std::vector<ede::Override>& overrides = {}) {
  return ede::Log::open(ede::test::run_to_log(ede::test::scene_of(kScene, "log-test", overrides), name)).value();
}

}  // namespace

TEST_CASE("Log::info describes the run", "[replay][log]") {
  const ede::Log log = logged("log-info.ede");
  const ede::LogInfo& i = log.info();
  CHECK(i.complete);
  CHECK_FALSE(i.damaged);
  CHECK(i.disks == 200);
  CHECK(i.species_names == std::vector<std::string>{"small", "big"});
  CHECK(i.species_counts == std::vector<std::uint64_t>{150, 50});
  CHECK(i.boundary == ede::BoundaryKind::Periodic);
  CHECK(i.end_time == 1.0L);
  CHECK(i.final_status == "reached stop.time");
  CHECK(i.events > 0);
  const ede::EventCounts c = log.count_events().value();
  CHECK(c.of(ede::EventKind::Pair) + c.of(ede::EventKind::Wrap) == i.events);
  CHECK(log.scene().value().seed == 3);
}

TEST_CASE("Log states: by time, by event, at the end", "[replay][log]") {
  const ede::Log log = logged("log-states.ede");
  const ede::State start = log.state_at(0).value();
  CHECK(start.events == 0);
  CHECK(start.mass[0] == 1.0);
  CHECK(start.mass[199] == 4.0);
  const ede::State end = log.state_at_end().value();
  CHECK(end.time == 1.0L);
  CHECK(end.events == log.info().events);
  // The state after n events is the state at that event's time when no other event shares the time.
  const std::vector<ede::Event> ev = log.events({.from_event = 100, .to_event = 101}).value();
  REQUIRE(ev.size() == 1);
  const ede::State by_event = log.state_at_event(101).value();
  const ede::State by_time = log.state_at(ev[0].time).value();
  CHECK(by_event.events == by_time.events);
  for (std::size_t i = 0; i < by_event.size(); ++i) REQUIRE(by_event.x.values<double>()[i] == by_time.x.values<double>()[i]);
  // Seeking backwards after forwards gives the same state again.
  const ede::State again = log.state_at(0).value();
  CHECK(again.x.values<double>() == start.x.values<double>());
  CHECK_FALSE(log.state_at(1.5));  // after the end
  CHECK_FALSE(log.state_at_event(log.info().events + 1));
}

TEST_CASE("Log events carry positions at contact and velocities before and after", "[replay][log][events]") {
  const ede::Log log = logged("log-events.ede");
  const ede::State s0 = log.state_at(0).value();
  std::size_t pairs = 0;
  REQUIRE(log.for_each_event({.from_time = 0.2, .to_time = 0.6}, [&](const ede::Event& e) {
    CHECK(e.time >= 0.2L);
    CHECK(e.time <= 0.6L);
    if (e.kind != ede::EventKind::Pair) return true;
    ++pairs;
    // At a collision the two disks touch (minimum image in the periodic box).
    double dx = double(e.xj - e.xi), dy = double(e.yj - e.yi);
    dx -= std::round(dx), dy -= std::round(dy);
    const double contact = s0.radius[std::size_t(e.i)] + s0.radius[std::size_t(e.j)];
    CHECK(std::hypot(dx, dy) == Approx(contact).epsilon(1e-9));
    // Momentum is conserved by the collision, energy too (elastic).
    const double mi = s0.mass[std::size_t(e.i)], mj = s0.mass[std::size_t(e.j)];
    CHECK(double(mi * e.vix + mj * e.vjx) == Approx(double(mi * e.vix_before + mj * e.vjx_before)).margin(1e-12));
    const double before = mi * double(e.vix_before * e.vix_before + e.viy_before * e.viy_before) +
                          mj * double(e.vjx_before * e.vjx_before + e.vjy_before * e.vjy_before);
    const double after = mi * double(e.vix * e.vix + e.viy * e.viy) + mj * double(e.vjx * e.vjx + e.vjy * e.vjy);
    CHECK(after == Approx(before).epsilon(1e-12));
    return true;
  }));
  CHECK(pairs > 50);
  const auto all = log.events({}).value();
  CHECK(all.size() == log.info().events);
  for (std::size_t k = 0; k < all.size(); ++k) REQUIRE(all[k].index == k);
}

TEST_CASE("Log::verify and Log::diff", "[replay][log][verify]") {
  const ede::Log a = logged("log-a.ede"), b = logged("log-b.ede"), other = logged("log-c.ede", {{"seed=4"}});
  const ede::VerifyReport v = a.verify().value();
  CHECK(v.identical);
  CHECK(v.events_compared == a.info().events);
  CHECK(v.text.rfind("verified: ", 0) == 0);
  const ede::DiffReport same = a.diff(b).value();
  CHECK(same.identical);
  CHECK_FALSE(same.first_difference);
  const ede::DiffReport differ = a.diff(other).value();
  CHECK_FALSE(differ.identical);
  REQUIRE(differ.first_difference);
  CHECK(*differ.first_difference == 0);  // another seed: another start
  CHECK(a.content_digest().value() == b.content_digest().value());
  CHECK(a.content_digest().value() != other.content_digest().value());
}

TEST_CASE("Log::event_columns hold exactly what the events hold", "[replay][log][events]") {
  for (const char* scalar : {"double", "float", "\"long double\""}) {
    const ede::Log log = logged(std::string("log-columns-") + std::to_string(std::strlen(scalar)) + ".ede", {{std::string("engine.scalar=") + scalar}});
    const ede::EventRange range{.from_time = 0.1, .to_time = 0.5};
    const auto events = log.events(range).value();
    const ede::EventColumns c = log.event_columns(range, true, true).value();
    REQUIRE(c.size() == events.size());
    REQUIRE(c.size() > 100);
    CHECK(c.time.scalar() == log.info().scalar);
    for (std::size_t k = 0; k < c.size(); ++k) {
      const ede::Event& e = events[k];
      REQUIRE(c.index[k] == e.index);
      REQUIRE(c.kind[k] == static_cast<std::uint8_t>(e.kind));
      REQUIRE((c.i[k] == e.i && c.j[k] == e.j));
      REQUIRE(c.time.exact(k) == e.time);
      REQUIRE((c.vix.exact(k) == e.vix && c.viy.exact(k) == e.viy && c.vjx.exact(k) == e.vjx && c.vjy.exact(k) == e.vjy));
      REQUIRE((c.xi.exact(k) == e.xi && c.yj.exact(k) == e.yj));
      REQUIRE((c.vix_before.exact(k) == e.vix_before && c.vjy_before.exact(k) == e.vjy_before));
    }
    const ede::EventColumns narrow = log.event_columns({.from_event = 5, .to_event = 9}).value();
    CHECK(narrow.index == std::vector<std::uint64_t>{5, 6, 7, 8});
    CHECK(narrow.xi.empty());
    CHECK(narrow.vix_before.empty());
  }
}

// Every column of a and b, bit for bit (exact() widens each scalar exactly).
static void require_same_columns(const ede::EventColumns& a, const ede::EventColumns& b) {
  REQUIRE(a.size() == b.size());
  REQUIRE(a.index == b.index);
  REQUIRE(a.kind == b.kind);
  REQUIRE((a.i == b.i && a.j == b.j));
  const auto same = [](const ede::Column& x, const ede::Column& y) {
    if (x.size() != y.size()) return false;
    for (std::size_t k = 0; k < x.size(); ++k)
      if (x.exact(k) != y.exact(k)) return false;
    return true;
  };
  CHECK(same(a.time, b.time));
  CHECK((same(a.vix, b.vix) && same(a.viy, b.viy) && same(a.vjx, b.vjx) && same(a.vjy, b.vjy)));
  CHECK((same(a.xi, b.xi) && same(a.yi, b.yi) && same(a.xj, b.xj) && same(a.yj, b.yj)));
  CHECK((same(a.vix_before, b.vix_before) && same(a.vjy_before, b.vjy_before)));
}

TEST_CASE("Log::event_columns gives the same bits on any number of threads", "[replay][log][events][threads]") {
  // Keyframes every 100 events: a range is cut into pieces, each replayed from its own keyframe.
  const ede::Log log = logged("log-columns-threads.ede", {{"log.keyframe_interval=100"}});
  REQUIRE(log.info().keyframes > 5);
  const std::vector<ede::EventRange> ranges = {
      {}, {.from_time = 0.1, .to_time = 0.5}, {.from_event = 250, .to_event = 1201}, {.to_time = 0.2},
      {.from_time = 0.7}, {.from_event = 3, .to_event = 4}};
  for (const ede::EventRange& range : ranges) {
    const ede::EventColumns one = log.event_columns(range, true, true, 1).value();
    const auto events = log.events(range).value();
    REQUIRE(one.size() == events.size());
    REQUIRE(one.size() > 0);
    for (const unsigned threads : {2u, 3u, 8u}) {
      INFO("threads " << threads << ", events " << one.size());
      require_same_columns(one, log.event_columns(range, true, true, threads).value());
    }
  }
}

TEST_CASE("Log::event_rows writes the columns' bits into packed rows, on any number of threads", "[replay][log][events]") {
  const ede::Log log = logged("log-rows.ede", {{"log.keyframe_interval=100"}});
  // A packed, unaligned layout: index, kind, time, i, j, the velocities after, x_i and vjy before.
  ede::EventRowLayout l;
  l.index = 0, l.kind = 8, l.time = 9, l.i = 17, l.j = 21, l.vix = 25, l.viy = 33, l.vjx = 41, l.vjy = 49;
  l.xi = 57, l.vjy_before = 65, l.row_bytes = 73;
  for (const ede::EventRange& range : {ede::EventRange{}, ede::EventRange{.from_time = 0.1, .to_time = 0.5}}) {
    const ede::EventColumns c = log.event_columns(range, true, true, 1).value();
    for (const unsigned threads : {1u, 2u, 3u}) {
      INFO("threads " << threads);
      std::vector<unsigned char> rows;
      std::uint64_t room = 0;
      const std::uint64_t n = log.event_rows(range, l, [&](std::uint64_t r) {
                                                  room = r, rows.assign(r * l.row_bytes + 1, 0xAB);
                                                  return static_cast<void*>(rows.data());
                                                }, threads).value();
      REQUIRE(n == c.size());
      REQUIRE(room >= n);
      CHECK(rows.back() == 0xAB);  // nothing written past the rows
      const auto at = [&]<class V>(std::uint64_t k, std::ptrdiff_t offset, V) {
        V v;
        std::memcpy(&v, rows.data() + k * l.row_bytes + offset, sizeof v);
        return v;
      };
      bool same = true;
      for (std::uint64_t k = 0; k < n; ++k)
        same = same && at(k, l.index, std::uint64_t{}) == c.index[k] && at(k, l.kind, std::uint8_t{}) == c.kind[k] &&
               at(k, l.i, std::int32_t{}) == c.i[k] && at(k, l.j, std::int32_t{}) == c.j[k] &&
               at(k, l.time, 0.0) == c.time.exact(k) && at(k, l.vix, 0.0) == c.vix.exact(k) &&
               at(k, l.vjy, 0.0) == c.vjy.exact(k) && at(k, l.xi, 0.0) == c.xi.exact(k) &&
               at(k, l.vjy_before, 0.0) == c.vjy_before.exact(k);
      CHECK(same);
    }
  }
  // A field reaching past the row is refused before anything is written.
  ede::EventRowLayout bad = l;
  bad.vjy_before = 70;
  bool called = false;
  auto refused = log.event_rows({}, bad, [&](std::uint64_t) { return called = true, static_cast<void*>(nullptr); });
  REQUIRE_FALSE(refused);
  CHECK_FALSE(called);
  CHECK(refused.error().message.find("does not fit a row of 73 bytes") != std::string::npos);
}

// Log::set_interrupt_check: a seek or walk stops at a chunk when asked, says so, and the Log reads on as if
// nothing had happened (the binding's Ctrl-C, python/src/shared_log.hpp).
TEST_CASE("Log::set_interrupt_check stops seeks and walks at a chunk and leaves the Log usable", "[replay][log][interrupt]") {
  ede::Log log = logged("log-interrupt.ede", {{"log.chunk_events=16"}, {"log.keyframe_interval=512"}});
  const ede::Log fresh = ede::Log::open(log.info().path).value();
  const std::uint64_t end = log.info().events;
  REQUIRE(end > 1000);  // a seek to the end replays ~20 chunks from its keyframe; a walk has ~3 pieces
  std::atomic<int> asked{0};
  std::atomic<int> allow{3};  // chunks decoded before the check says stop
  log.set_interrupt_check([&] { return ++asked > allow; });

  const auto seek = log.state_at_event(end);
  REQUIRE_FALSE(seek);
  CHECK(seek.error().message.find("interrupted at event") != std::string::npos);
  CHECK(asked == 4);  // asked before each chunk: three decoded, the fourth refused

  asked = 0;
  std::vector<unsigned char> rows;
  ede::EventRowLayout l;
  l.index = 0, l.row_bytes = 8;
  const auto walk = log.event_rows({}, l, [&](std::uint64_t r) { return rows.resize(r * 8), static_cast<void*>(rows.data()); }, 2);
  REQUIRE_FALSE(walk);
  CHECK(walk.error().message.find("interrupted") != std::string::npos);

  allow = 1 << 30;  // no longer interrupted: the same calls give what a fresh Log gives
  const ede::State a = log.state_at_event(end).value(), b = fresh.state_at_event(end).value();
  CHECK(a.x.values<double>() == b.x.values<double>());
  CHECK(a.vy.values<double>() == b.vy.values<double>());
  const ede::State mid = log.state_at(0.5).value(), mid_fresh = fresh.state_at(0.5).value();
  CHECK(mid.x.values<double>() == mid_fresh.x.values<double>());
  CHECK(log.event_columns({}, false, false, 2).value().index == fresh.event_columns({}).value().index);
}

// A walk that writes neither positions nor velocities before computes neither (EventExtras); what an event
// leaves unchanged (a wrap's velocities, a rough disk's spin in a wrap) must still be filled in.
TEST_CASE("Narrow event rows hold the same velocities and spins after each event as the full events", "[replay][log][events]") {
  const std::vector<std::vector<ede::Override>> runs = {
      {}, {{"box.boundary=\"walls\""}}, {{"physics.roughness=0.5"}, {"physics.restitution=0.9"}}};
  int variant = 0;
  for (const auto& overrides : runs) {
    const ede::Log log = logged("log-narrow-" + std::to_string(variant++) + ".ede", overrides);
    const bool rough = log.info().rotates;
    ede::EventRowLayout l;
    l.index = 0, l.kind = 8, l.i = 9, l.j = 13, l.vix = 17, l.viy = 25, l.vjx = 33, l.vjy = 41, l.row_bytes = 49;
    if (rough) l.omega_i = 49, l.omega_j = 57, l.row_bytes = 65;
    const auto events = log.events({}).value();
    std::vector<unsigned char> rows;
    const std::uint64_t n = log.event_rows({}, l, [&](std::uint64_t r) {
                                  rows.assign(r * l.row_bytes, 0);
                                  return static_cast<void*>(rows.data());
                                }).value();
    REQUIRE(n == events.size());
    const auto at = [&](std::uint64_t k, std::ptrdiff_t offset) {
      double v;
      std::memcpy(&v, rows.data() + k * l.row_bytes + offset, sizeof v);
      return v;
    };
    std::size_t wraps = 0, mismatches = 0;
    for (std::uint64_t k = 0; k < n; ++k) {
      const ede::Event& e = events[k];
      wraps += e.kind == ede::EventKind::Wrap;
      const bool same = at(k, l.vix) == e.vix && at(k, l.viy) == e.viy && at(k, l.vjx) == e.vjx &&
                        at(k, l.vjy) == e.vjy && (!rough || (at(k, l.omega_i) == e.omega_i && at(k, l.omega_j) == e.omega_j));
      mismatches += !same;
    }
    INFO("variant " << variant << ", events " << n << ", wraps " << wraps);
    CHECK(mismatches == 0);
    CHECK((wraps > 0) == (variant != 2));  // the periodic runs wrap, the walled one cannot
  }
}

TEST_CASE("Log::events_after_collisions finds where a collisions-per-disk schedule acts", "[replay][log][schedule]") {
  // 200 disks: an action scheduled at 2.5 collisions per disk acts right after pair collision 250, and is
  // logged as the event at the index events_after_collisions gives.
  const std::string text = std::string(kScene) + "[[actions]]\ncollisions_per_disk = 2.5\nkind = \"reverse_velocities\"\n";
  const ede::Log log = ede::Log::open(ede::test::run_to_log(ede::test::scene_of(text, "schedule-test"),
                                                            "log-schedule.ede")).value();
  const auto events = log.events({}).value();
  std::uint64_t action = 0;
  for (const ede::Event& e : events)
    if (e.kind == ede::EventKind::Action) action = e.index;
  REQUIRE(action > 0);
  const auto n = log.events_after_collisions({0, 0.005, 2.5}).value();
  CHECK(n[0] == 0);
  CHECK(n[2] == action);
  // 0.005 collisions per disk: ceil(0.5) = the first pair collision.
  std::uint64_t first_pair = 0;
  while (events[first_pair].kind != ede::EventKind::Pair) ++first_pair;
  CHECK(n[1] == first_pair + 1);
  std::uint64_t pairs = 0;
  for (std::uint64_t k = 0; k < n[2]; ++k) pairs += events[k].kind == ede::EventKind::Pair ? 1 : 0;
  CHECK(pairs == 250);
  CHECK(events[n[2] - 1].kind == ede::EventKind::Pair);
  // Past the log's last pair collision, and out of order: refused.
  const auto past = log.events_after_collisions({1e6});
  REQUIRE_FALSE(past);
  CHECK(past.error().message.find("pair collisions, fewer than the 100000000 asked for") != std::string::npos);
  CHECK_FALSE(log.events_after_collisions({2, 1}));
}

TEST_CASE("Log::open refuses what is not a log, naming the file", "[replay][log][errors]") {
  auto missing = ede::Log::open(temp_path("missing.ede"));
  REQUIRE_FALSE(missing);
  CHECK(missing.error().kind == ede::ErrorKind::Io);
  CHECK(missing.error().message.find("missing.ede") != std::string::npos);
  CHECK_THROWS_AS(ede::Log::open(temp_path("missing.ede")).value(), ede::Exception);
}

TEST_CASE("exact_text and parse_exact read and print every scalar type exactly", "[core][state]") {
  CHECK(ede::exact_text(0.1, ede::ScalarKind::Double) == "0.10000000000000001");
  CHECK(ede::exact_text(0.1, ede::ScalarKind::Float) == "0.100000001");
  CHECK(ede::parse_exact("0.1", ede::ScalarKind::Float).value() == ede::Time(0.1f));
  CHECK(ede::parse_exact("0.1", ede::ScalarKind::Double).value() == ede::Time(0.1));
  CHECK(ede::parse_exact("0.1", ede::ScalarKind::LongDouble).value() == 0.1L);
  CHECK(ede::parse_exact(ede::exact_text(0.1L, ede::ScalarKind::LongDouble), ede::ScalarKind::LongDouble).value() ==
        0.1L);
  CHECK_FALSE(ede::parse_exact("0.1x", ede::ScalarKind::Double));
  CHECK_FALSE(ede::parse_exact("nan", ede::ScalarKind::Double));
  CHECK_FALSE(ede::parse_exact("1e400", ede::ScalarKind::Double));
}
