// The energy walk (crater_energy.cpp) and measuring from a log (crater_measure.cpp, crater_bed.cpp), on
// tiny inelastic runs logged in-process: the crossing must be exactly the one found by summing the
// replayed state after every event, the curve must match the replayed states at its times.
#include <catch2/catch.hpp>
#include <cmath>

#include "analysis/crater.hpp"
#include "log_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

// 64 disks cooling in a box (xi = 0.8, TC on), small chunks and keyframes so that seeks cross several.
EngineOptions cooling(double until) {
  EngineOptions o = walls_until(until);
  o.physics.restitution = 0.8;
  o.physics.wall_restitution = 0.8;
  o.physics.tc = 1e-5;
  return o;
}

LogSettings small_records() {
  LogSettings s;
  s.chunk_events = 64;
  s.keyframe_interval = 256;
  return s;
}

template <class T>
std::string cooling_log(const std::string& name) {
  return run_logged<T>(lattice_gas(8, 0.03, 1, 3), cooling(40), name, small_records()).path;
}

}  // namespace

TEST_CASE("crater energy: the crossing is the first event whose replayed state is below the fraction",
          "[analysis][crater]") {
  const std::string path = cooling_log<double>("crater-energy.ede");
  const Log log = open_public_log(path);
  REQUIRE(log.info().events > 1000);
  auto curve = energy_fraction_curve(log, 0.3, 101);
  REQUIRE(curve);
  const EnergyFractionCurve& c = curve.value();
  REQUIRE(c.reached);

  auto replay = replay_of<double>(path);
  REQUIRE(replay->seek_event(0));
  CHECK(c.initial_energy == kinetic_energy(replay->particles()));
  CHECK(c.initial_energy == log.info().initial_energy);
  const double threshold = 0.3 * c.initial_energy;
  std::uint64_t first = 0;
  REQUIRE(replay->for_each_event(0, log.info().events, [&](const ReplayedEvent<double>&) {
    if (kinetic_energy(replay->particles()) <= threshold) return first = replay->events_applied(), false;
    return true;
  }));
  CHECK(c.event == first);
  REQUIRE(replay->seek_event(c.event));
  CHECK(c.time == replay->time());
  CHECK(kinetic_energy(replay->particles()) <= threshold);
  REQUIRE(replay->seek_event(c.event - 1));
  CHECK(kinetic_energy(replay->particles()) > threshold);

  // The curve: E/E0 of the state after every event with time <= t, at 101 times from 0 to the end.
  REQUIRE(c.t.size() == 101);
  CHECK(c.t.front() == 0);
  CHECK(c.t.back() == c.end_time);
  for (std::size_t k = 0; k < c.t.size(); ++k) {
    REQUIRE(replay->seek_time(c.t[k]));
    CHECK(c.f[k] == Approx(kinetic_energy(replay->particles()) / c.initial_energy).epsilon(1e-12));
  }
  CHECK(c.end_fraction == kinetic_energy(replay->particles()) / c.initial_energy);
}

TEST_CASE("crater energy: a fraction never reached ends at the log's end, fraction 1 at event 0",
          "[analysis][crater]") {
  const std::string path = cooling_log<double>("crater-energy-end.ede");
  const Log log = open_public_log(path);
  auto never = energy_fraction_curve(log, 1e-9);
  REQUIRE(never);
  CHECK_FALSE(never.value().reached);
  CHECK(never.value().event == log.info().events);
  CHECK(never.value().time == never.value().end_time);
  CHECK(never.value().end_fraction > 1e-9);

  auto at_once = energy_fraction_curve(log, 1.0);
  REQUIRE(at_once);
  CHECK(at_once.value().reached);
  CHECK(at_once.value().event == 0);
  CHECK(at_once.value().time == 0);

  CHECK_FALSE(energy_fraction_curve(log, 0));
  CHECK_FALSE(energy_fraction_curve(log, 1.5));
  CHECK_FALSE(energy_fraction_curve(log, 0.5, 1));
}

TEST_CASE("crater energy: a float log is walked in float", "[analysis][crater]") {
  const std::string path = cooling_log<float>("crater-energy-float.ede");
  const Log log = open_public_log(path);
  auto curve = energy_fraction_curve(log, 0.3);
  REQUIRE(curve);
  REQUIRE(curve.value().reached);
  auto replay = replay_of<float>(path);
  REQUIRE(replay->seek_event(curve.value().event));
  CHECK(kinetic_energy(replay->particles()) <= 0.3 * curve.value().initial_energy);
  REQUIRE(replay->seek_event(curve.value().event - 1));
  CHECK(kinetic_energy(replay->particles()) > 0.3 * curve.value().initial_energy);
}

TEST_CASE("crater measure: the state at the crossing, at a time, the bed by species", "[analysis][crater]") {
  const std::string path = cooling_log<double>("crater-measure.ede");
  const Log log = open_public_log(path);

  CraterRequest req;
  req.energy_fraction = 0.3;
  auto m = measure_crater(log, req);
  REQUIRE(m);
  CHECK(m.value().source == CraterTimeSource::EnergyFraction);
  CHECK(m.value().events == m.value().energy.event);
  CHECK(m.value().time == m.value().energy.time);
  CHECK(m.value().energy_fraction <= 0.3);
  CHECK(m.value().bed.disks == 64);  // no species 'bed': every species of more than one disk
  CHECK(m.value().bed.reason.find("no species is named 'bed'") != std::string::npos);
  CHECK(m.value().report.bed_disks == 64);

  // At a time: the positions are the replayed ones at that time.
  req.at = 1.0;
  auto at = measure_crater(log, req);
  REQUIRE(at);
  CHECK(at.value().source == CraterTimeSource::Requested);
  CHECK(at.value().time == 1.0);
  auto replay = replay_of<double>(path);
  REQUIRE(replay->seek_event(0));
  std::vector<double> x0, y0;
  for (std::size_t i = 0; i < 64; ++i) x0.push_back(replay->particles().x_at(i, 0.0)), y0.push_back(replay->particles().y_at(i, 0.0));
  REQUIRE(replay->seek_time(1.0));
  std::size_t moved = 0;
  for (std::size_t i = 0; i < 64; ++i)
    moved += std::hypot(replay->particles().x_at(i, 1.0) - x0[i], replay->particles().y_at(i, 1.0) - y0[i]) >
             0.5 * 0.03;
  CHECK(at.value().report.displaced.size() == moved);

  req.at = 1e6;
  auto late = measure_crater(log, req);
  REQUIRE_FALSE(late);
  CHECK(late.error().message.find("after the end of the log") != std::string::npos);

  req.at.reset();
  req.bed_species = "sand";
  auto unknown = measure_crater(log, req);
  REQUIRE_FALSE(unknown);
  CHECK(unknown.error().message.find("no species 'sand'") != std::string::npos);
  CHECK(unknown.error().message.find("'disks' (64 disks)") != std::string::npos);

  req.bed_species.clear();
}

TEST_CASE("crater bed: 'bed' by name, else the species of more than one disk", "[analysis][crater]") {
  LogHeaderInfo h;
  h.species_names = {"projectile", "bed", "dust"};
  h.species = {0, 1, 1, 2, 2, 2};
  auto named = select_bed(h, "");
  REQUIRE(named);
  CHECK(named.value().is_bed == std::vector<bool>{false, true, true, false, false, false});
  h.species_names = {"projectile", "sand", "dust"};
  auto multi = select_bed(h, "");
  REQUIRE(multi);
  CHECK(multi.value().is_bed == std::vector<bool>{false, true, true, true, true, true});
  CHECK(multi.value().species == std::vector<std::string>{"sand", "dust"});
  auto asked = select_bed(h, "dust");
  REQUIRE(asked);
  CHECK(asked.value().disks == 3);
  h.species = {0, 1, 2};
  auto none = select_bed(h, "");
  REQUIRE_FALSE(none);
  CHECK(none.error().message.find("--species") != std::string::npos);
}
