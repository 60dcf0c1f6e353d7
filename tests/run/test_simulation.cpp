// ede::Simulation, the public way to run a scene: runs to a stop, pauses that change nothing, the state at
// the current time, interrupt and resume, summaries, and errors as values.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>
#include <thread>

#include "ede/ede.hpp"
#include "scene_test_support.hpp"
#include "tool_runner.hpp"  // temp_path, read_file

using ede::test::read_file;
using ede::test::temp_path;

namespace {

// The shared test gas (scene_test_support.hpp), with a few overrides.
ede::Scene gas(const std::vector<ede::Override>& overrides = {}) {
  return ede::parse_scene_text(ede::test::logged_gas("5", "2.0").text(), "gas-test", overrides).value();
}

std::string bytes_of(const std::string& path) { return read_file(path); }

}  // namespace

TEST_CASE("Simulation runs a scene to its stop and reports it", "[run][simulation]") {
  auto sim = ede::Simulation::create(gas()).value();
  CHECK(sim.status() == ede::RunStatus::Running);
  CHECK(sim.run() == ede::RunStatus::ReachedTime);
  CHECK(sim.time() == 2.0L);
  const ede::RunSummary s = sim.summary();
  CHECK(s.disks == 400);
  CHECK(s.status == "reached stop.time");
  CHECK(s.counts.of(ede::EventKind::Pair) > 1000);
  CHECK(std::abs(s.energy_final - s.energy_initial) / s.energy_initial < 1e-13);  // elastic
  CHECK(s.effects.rfind("walls, elastic", 0) == 0);
  // Running a finished run does nothing more.
  CHECK(sim.run() == ede::RunStatus::ReachedTime);
  CHECK(sim.summary().counts.events() == s.counts.events());
}

TEST_CASE("Simulation::advance_to pauses at a time without changing the run", "[run][simulation]") {
  const std::string paused_log = temp_path("sim-paused.ede"), plain_log = temp_path("sim-plain.ede");
  {
    auto plain = ede::Simulation::create(gas(), {.log_path = plain_log}).value();
    REQUIRE(plain.run() == ede::RunStatus::ReachedTime);
  }
  auto sim = ede::Simulation::create(gas(), {.log_path = paused_log}).value();
  std::vector<ede::State> states;
  for (const double t : {0.25, 0.5, 0.5, 1.0, 1.75}) {
    REQUIRE(sim.advance_to(t).value() == ede::RunStatus::Running);
    CHECK(sim.time() == ede::Time(t));
    states.push_back(sim.state());
  }
  CHECK_FALSE(sim.advance_to(1.0));  // a run only goes forward
  CHECK(sim.advance_to(5.0).value() == ede::RunStatus::ReachedTime);  // the stop time comes first
  CHECK(sim.time() == 2.0L);
  REQUIRE(sim.close());
  // The pauses changed nothing: the same log bytes as a run without them.
  CHECK(bytes_of(paused_log) == bytes_of(plain_log));
  // And the states seen at the pauses are the log's states at those times, bit for bit.
  auto log = ede::Log::open(paused_log).value();
  for (const ede::State& s : states) {
    const ede::State r = log.state_at(s.time).value();
    REQUIRE(r.size() == s.size());
    for (std::size_t i = 0; i < s.size(); i += 7) {
      CHECK(r.x.values<double>()[i] == s.x.values<double>()[i]);
      CHECK(r.vy.values<double>()[i] == s.vy.values<double>()[i]);
    }
  }
}

TEST_CASE("Simulation::state and write_state_csv agree with the log's exact CSV", "[run][simulation][state]") {
  const std::string logp = temp_path("sim-csv.ede"), a = temp_path("sim-a.csv"), b = temp_path("sim-b.csv"),
                    c = temp_path("sim-c.csv");
  auto sim = ede::Simulation::create(gas({{"engine.scalar=float"}}), {.log_path = logp}).value();
  sim.run();
  REQUIRE(sim.write_state_csv(a));
  REQUIRE(ede::write_state_csv(b, sim.state()));
  REQUIRE(sim.close());
  REQUIRE(ede::write_state_csv(c, ede::Log::open(logp).value().state_at_end().value()));
  CHECK(read_file(a) == read_file(b));
  CHECK(read_file(a) == read_file(c));
  const ede::State s = sim.state();
  CHECK(s.scalar == ede::ScalarKind::Float);
  CHECK(s.x.scalar() == ede::ScalarKind::Float);
  CHECK(s.x[3] == double(s.x.values<float>()[3]));
  CHECK_THROWS_AS(s.x.values<double>(), ede::Exception);
}

TEST_CASE("Simulation::interrupt stops a run that resume() finishes identically", "[run][simulation][resume]") {
  const std::string whole = temp_path("sim-whole.ede"), cut = temp_path("sim-cut.ede");
  {
    auto sim = ede::Simulation::create(gas(), {.log_path = whole}).value();
    REQUIRE(sim.run() == ede::RunStatus::ReachedTime);
  }
  {
    auto sim = ede::Simulation::create(gas(), {.log_path = cut}).value();
    REQUIRE(sim.run(20000) == ede::RunStatus::Running);  // part of the way
    sim.interrupt();
    CHECK(sim.run() == ede::RunStatus::Running);  // noticed before any further event
    CHECK(sim.interrupted());
    CHECK(sim.summary().status == "interrupted");
    REQUIRE(sim.close());
    const ede::LogKept k = sim.log_kept().value();
    CHECK_FALSE(k.complete);
    CHECK(k.resumable);
    CHECK(k.resume_event > 0);
    CHECK(k.resume_event <= k.events);
  }
  auto resumed = ede::Simulation::resume(cut).value();
  CHECK(resumed.summary().events_before > 0);
  REQUIRE(resumed.run() == ede::RunStatus::ReachedTime);
  const ede::RunSummary s = resumed.summary();
  CHECK(s.events_per_second() > 0);
  CHECK(double(s.counts.events() - s.events_before) / s.wall_seconds == Approx(s.events_per_second()));
  REQUIRE(resumed.close());
  CHECK(bytes_of(cut) == bytes_of(whole));
}

TEST_CASE("Simulation reports progress and can be interrupted from another thread", "[run][simulation]") {
  int calls = 0;
  double last = -1;
  ede::SimulationOptions options;
  options.progress = [&](const ede::Progress& p) {
    ++calls;
    CHECK(p.fraction >= last);
    CHECK(p.fraction <= 1.0);
    last = p.fraction;
  };
  auto sim = ede::Simulation::create(gas({{"stop.time=1e9"}}), options).value();
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    sim.interrupt();
  });
  CHECK(sim.run() == ede::RunStatus::Running);
  stopper.join();
  CHECK(sim.interrupted());
  CHECK(calls > 0);
}

TEST_CASE("Simulation gives errors as values: a bad scene, an unwritable log, a missing log to resume",
          "[run][simulation][errors]") {
  auto bad = ede::parse_scene_text("[box]\nsize = [1.0, 1.0]\n[[species]]\nname = \"a\"\ncount = 5000\nradius = 0.05\n"
                                   "[stop]\ntime = 1\n",
                                   "crowded.toml");
  REQUIRE(bad);  // loads; cannot be placed
  auto made = ede::Simulation::create(bad.value());
  REQUIRE_FALSE(made);
  CHECK(made.error().message.find("crowded.toml") != std::string::npos);
  CHECK_THROWS_AS(made.value(), ede::Exception);

  auto unwritable = ede::Simulation::create(gas(), {.log_path = "/nonexistent-dir/x.ede"});
  REQUIRE_FALSE(unwritable);
  CHECK(unwritable.error().kind == ede::ErrorKind::Io);
  CHECK(unwritable.error().message.find("/nonexistent-dir/x.ede") != std::string::npos);

  auto missing = ede::Simulation::resume(temp_path("no-such-log.ede"));
  REQUIRE_FALSE(missing);
  CHECK(missing.error().message.find("no-such-log.ede") != std::string::npos);
}
