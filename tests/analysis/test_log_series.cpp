// Log series and snapshots on logs written in-process from small scenes: the energy series equals the sum
// over the replayed state at its grid times, is conserved when xi = 1 and never rises when xi < 1; the
// collision counts are the log's; a gas relaxed from one speed follows Maxwell-Boltzmann and a mixture
// shares its energy equally. Logs use small chunks and keyframe intervals, so every walk and seek
// crosses several of each.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "run/log_run_info.hpp"
#include "ede/analysis.hpp"
#include "ede/analysis.hpp"
#include "analysis/log_series.hpp"
#include "log/log_stats.hpp"
#include "ede/scene.hpp"
#include "setup/setup.hpp"
#include "log_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

// Runs a scene (TOML text) in T with a log at temp_path(file); returns the log's path.
template <class T>
std::string run_scene(const std::string& toml, const std::string& file) {
  auto scene = parse_scene_text(toml, file);
  INFO((scene ? "" : scene.error().message));
  REQUIRE(scene);
  auto initial = build_initial_state(scene.value());
  REQUIRE(initial);
  const EngineOptions options = engine_options_from(scene.value(), initial.value().size());
  const std::string path = temp_path(file);
  auto engine = test::engine<T>(initial.value(), options);
  LogSettings settings;
  settings.chunk_events = 256;
  settings.keyframe_interval = 1000;
  auto writer = LogWriter<T>::create(path, log_run_info(scene.value(), options, initial.value().species_names),
                                     settings);
  REQUIRE(writer);
  engine->add_sink(writer.value().get());
  engine->run();
  REQUIRE(writer.value()->error().empty());
  return path;
}

std::string gas_scene(const std::string& boundary, int count, double radius, const std::string& stop,
                      const std::string& extra = "") {
  return "seed = 7\n" + extra + "\n[box]\nsize = [1.0, 1.0]\nboundary = \"" + boundary +
         "\"\n\n[[species]]\nname = \"gas\"\ncount = " + std::to_string(count) + "\nradius = " + std::to_string(radius) +
         "\n\n[species.velocity]\nkind = \"speed\"\nspeed = 1.0\n\n[stop]\n" + stop + "\n";
}

std::vector<double> grid_of(const std::shared_ptr<LogReader>& log, int points) {
  auto o = log_overview(log);
  REQUIRE(o);
  std::vector<double> g;
  for (int k = 0; k <= points; ++k) g.push_back(o.value().end_time * k / points);
  return g;
}

LogSeries series_of(const std::shared_ptr<LogReader>& log, const std::vector<double>& times) {
  auto s = log_series(log, times);
  INFO((s ? "" : s.error().message));
  REQUIRE(s);
  return std::move(s).value();
}

// The series against fresh sums over the replayed state at each grid time.
template <class T>
void check_series_matches_replay(const std::string& path, int points) {
  const auto log = open_log(path);
  const std::vector<double> times = grid_of(log, points);
  const LogSeries s = series_of(log, times);
  REQUIRE(s.time == times);
  auto replay = replay_of<T>(path);
  for (std::size_t k = 0; k < times.size(); ++k) {
    REQUIRE(replay->seek_time(T(times[k])));
    const double fresh = kinetic_energy(replay->particles());
    INFO("t = " << times[k]);
    REQUIRE(std::abs(s.kinetic_energy[k] - fresh) <= 1e-13 * fresh);
    std::vector<long double> per_species(s.species_names.size(), 0);
    const Particles<T>& p = replay->particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const long double vx = p.disk[i].vx, vy = p.disk[i].vy;
      per_species[std::size_t(p.species_of(i))] += 0.5L * (long double)p.mass(i) * (vx * vx + vy * vy);
    }
    for (std::size_t sp = 0; sp < per_species.size(); ++sp)
      REQUIRE(std::abs(s.species_energy[sp][k] - double(per_species[sp])) <= 1e-13 * fresh);
  }
}

// Pooled snapshots of a log at `count` times spread over its second half (spacing several mean free
// times when the run lasts tens of them): the relaxed part of a run started far from equilibrium.
GasAverages pooled_second_half(const std::shared_ptr<LogReader>& log, int count, std::vector<double>* energies,
                               std::vector<double>* light_speeds = nullptr) {
  auto o = log_overview(log);
  REQUIRE(o);
  std::vector<double> times;
  for (int k = 0; k < count; ++k) times.push_back(o.value().end_time * (0.5 + 0.5 * k / (count - 1)));
  GasAverages avg;
  REQUIRE(for_each_snapshot(log, times, [&](const GasSnapshot& s) {
    avg.add(s);
    const std::vector<double> e = kinetic_energies(s);
    if (energies) energies->insert(energies->end(), e.begin(), e.end());
    if (light_speeds) {
      const std::vector<double> v = speeds(s, 0);
      light_speeds->insert(light_speeds->end(), v.begin(), v.end());
    }
  }));
  return avg;
}

}  // namespace

TEST_CASE("energy series equals the sum over the replayed state at its grid times", "[analysis]") {
  const std::string path =
      run_scene<double>(gas_scene("walls", 300, 0.01, "collisions_per_particle = 20"), "series-walls.ede");
  check_series_matches_replay<double>(path, 150);
}

TEST_CASE("energy series of float and long double logs equals their replayed sums", "[analysis]") {
  const auto scene = [](const char* scalar) {
    return gas_scene("periodic", 200, 0.01, "collisions_per_particle = 10",
                     std::string("[engine]\nscalar = \"") + scalar + "\"\n");
  };
  check_series_matches_replay<float>(run_scene<float>(scene("float"), "series-float.ede"), 50);
  check_series_matches_replay<long double>(run_scene<long double>(scene("long double"), "series-long.ede"), 50);
}

TEST_CASE("an action (velocity reversal) resynchronises the energy walk", "[analysis]") {
  const std::string toml = gas_scene("walls", 200, 0.01, "time = 0.6", "[physics]\nrestitution = 0.9\n") +
                           "\n[[actions]]\ntime = 0.3\nkind = \"reverse_velocities\"\n";
  const std::string path = run_scene<double>(toml, "series-action.ede");
  check_series_matches_replay<double>(path, 60);
}

TEST_CASE("energy is conserved to 1e-12 when xi = 1 and never rises when xi < 1", "[analysis]") {
  SECTION("elastic") {
    const auto log = open_log(
        run_scene<double>(gas_scene("walls", 300, 0.01, "collisions_per_particle = 30"), "series-elastic.ede"));
    const LogSeries s = series_of(log, grid_of(log, 2000));
    for (const double e : s.kinetic_energy) REQUIRE(std::abs(e / s.kinetic_energy[0] - 1) <= 1e-12);
  }
  SECTION("inelastic, xi = 0.8") {
    const auto log = open_log(run_scene<double>(
        gas_scene("walls", 300, 0.01, "collisions_per_particle = 15", "[physics]\nrestitution = 0.8\n"),
        "series-inelastic.ede"));
    const LogSeries s = series_of(log, grid_of(log, 2000));
    // Each collision loses (1 - xi^2) of its normal relative energy: the series falls step by step. A
    // grazing collision loses almost nothing, so a step may only be round-off: 1e-14 relative allows that.
    for (std::size_t k = 1; k < s.time.size(); ++k) REQUIRE(s.kinetic_energy[k] <= s.kinetic_energy[k - 1] * (1 + 1e-14));
    CHECK(s.kinetic_energy.back() < 0.5 * s.kinetic_energy.front());
  }
}

TEST_CASE("collision counts equal the log's pair and wall events", "[analysis]") {
  const std::string path = run_scene<double>(gas_scene("walls", 300, 0.01, "collisions_per_particle = 20"), "series-counts.ede");
  const auto log = open_log(path);
  const std::vector<double> times = grid_of(log, 40);
  const LogSeries s = series_of(log, times);
  auto kinds = count_logged_kinds(*log);
  REQUIRE(kinds);
  CHECK(s.pair_collisions.back() == kinds.value().of(EventKind::Pair));
  CHECK(s.wall_collisions.back() == kinds.value().of(EventKind::Wall));
  CHECK(s.collisions_per_particle(times.size() - 1) == Approx(20).margin(0.01));
  // At every grid time: the events with time <= t, counted directly.
  auto replay = replay_of<double>(path);
  std::vector<std::uint64_t> pairs(times.size(), 0);
  REQUIRE(replay->for_each_event(0, log->total_events(), [&](const ReplayedEvent<double>& e) {
    for (std::size_t k = 0; k < times.size(); ++k) pairs[k] += (e.kind == EventKind::Pair && e.time <= times[k]) ? 1 : 0;
    return true;
  }));
  CHECK(s.pair_collisions == pairs);
  auto o = log_overview(log);
  REQUIRE(o);
  CHECK(o.value().mean_free_time() == Approx(300 * o.value().end_time / (2.0 * double(pairs.back()))));
}

TEST_CASE("snapshots are the replayed velocities, speed classes sum to 100%", "[analysis]") {
  const std::string path = run_scene<double>(gas_scene("periodic", 200, 0.01, "time = 0.5"), "series-snap.ede");
  const auto log = open_log(path);
  const std::vector<double> times = {0, 0.1, 0.1, 0.37, 0.5};
  auto replay = replay_of<double>(path);
  double v0 = 0;
  std::size_t k = 0;
  REQUIRE(for_each_snapshot(log, times, [&](const GasSnapshot& s) {
    REQUIRE(replay->seek_time(times[k]));
    CHECK(s.time == times[k++]);
    for (std::size_t i = 0; i < s.size(); ++i) {
      REQUIRE(s.vx[i] == replay->particles().disk[i].vx);
      REQUIRE(s.vy[i] == replay->particles().disk[i].vy);
    }
    if (s.time == 0) v0 = mean_speed(s);
    const SpeedClasses c = speed_classes(s, v0);
    CHECK(c.slow + c.medium + c.fast == s.size());
    CHECK(c.slow_percent + c.medium_percent + c.fast_percent == Approx(100).epsilon(1e-13));
  }));
  CHECK(k == times.size());
  CHECK(v0 == Approx(1).epsilon(1e-15));  // every disk starts at speed 1
}

TEST_CASE("series and snapshots refuse times after the end or out of order", "[analysis]") {
  const auto log = open_log(run_scene<double>(gas_scene("periodic", 50, 0.01, "time = 0.2"), "series-bad.ede"));
  const auto after = log_series(log, {0, 0.3});
  REQUIRE_FALSE(after);
  CHECK_THAT(after.error().message, Catch::Contains("after the end of the log"));
  CHECK_FALSE(log_series(log, {0.1, 0.05}));
  CHECK_FALSE(for_each_snapshot(log, {0.25}, [](const GasSnapshot&) {}));
  CHECK_FALSE(for_each_snapshot(log, {-1}, [](const GasSnapshot&) {}));
  CHECK(log_series(log, {}));
}

TEST_CASE("a gas relaxed from one speed follows Maxwell-Boltzmann, the initial state does not", "[analysis]") {
  // 400 disks, phi = 0.13, periodic, 50 collisions per disk. Energies of 6 snapshots in the second half
  // (~5 mean free times apart, so nearly independent) pooled: 2400 samples. A true MB sample has p
  // uniform on [0, 1]; p > 1e-3 fails for one seed in a thousand and the run is deterministic, so the
  // threshold is a floor against a wrong distribution, not a flaky statistic. kT is measured on the
  // sample (as ede-stats does), which only makes p larger.
  const auto log = open_log(
      run_scene<double>(gas_scene("periodic", 400, 0.01, "collisions_per_particle = 50"), "series-relax.ede"));
  std::vector<double> e;
  const GasAverages avg = pooled_second_half(log, 6, &e);
  const double kT = avg.stats().back().kT;
  CHECK(kT == Approx(0.5).epsilon(1e-12));  // elastic, periodic: the mean energy stays 1/2
  const KsResult relaxed = ks_test_mb_energies(e, kT);
  INFO("D = " << relaxed.statistic << ", p = " << relaxed.p_value);
  CHECK(relaxed.p_value > 1e-3);
  std::vector<double> e0;
  REQUIRE(for_each_snapshot(log, {0.0}, [&](const GasSnapshot& s) { e0 = kinetic_energies(s); }));
  CHECK(ks_test_mb_energies(e0, kT).p_value < 1e-100);
}

TEST_CASE("a mixture of masses m0 and 4 m0 shares its energy equally, mean speeds in ratio 2", "[analysis]") {
  // 300 light (m = 1) and 300 heavy (m = 4) disks, both from speed 1 (mean energies 0.5 and 2), periodic,
  // 60 collisions per disk; 6 snapshots of the second half pooled (1800 samples per species). Tolerances:
  // 4 standard errors, from the samples' own spread, treating the snapshots as independent.
  const std::string toml =
      "seed = 12\n[box]\nsize = [1.0, 1.0]\nboundary = \"periodic\"\n"
      "[[species]]\nname = \"light\"\ncount = 300\nradius = 0.01\nmass = 1.0\n"
      "[species.velocity]\nkind = \"speed\"\nspeed = 1.0\n"
      "[[species]]\nname = \"heavy\"\ncount = 300\nradius = 0.01\nmass = 4.0\n"
      "[species.velocity]\nkind = \"speed\"\nspeed = 1.0\n"
      "[stop]\ncollisions_per_particle = 60\n";
  const auto log = open_log(run_scene<double>(toml, "series-mixture.ede"));
  const std::vector<SpeciesStats> st = pooled_second_half(log, 6, nullptr).stats();
  REQUIRE(st.size() == 3);
  const SpeciesStats &light = st[0], &heavy = st[1];
  CHECK(light.n == 1800);
  const double e_err = std::hypot(light.mean_kinetic_energy_error, heavy.mean_kinetic_energy_error);
  INFO("<E> light " << light.mean_kinetic_energy << ", heavy " << heavy.mean_kinetic_energy << " +- " << e_err);
  CHECK(std::abs(light.mean_kinetic_energy - heavy.mean_kinetic_energy) < 4 * e_err);
  const double ratio = light.mean_speed / heavy.mean_speed;
  const double ratio_err =
      ratio * std::hypot(light.mean_speed_error / light.mean_speed, heavy.mean_speed_error / heavy.mean_speed);
  INFO("<v> ratio " << ratio << " +- " << ratio_err);
  CHECK(std::abs(ratio - 2) < 4 * ratio_err);
  // The initial state is far from it: mean energies 0.5 and 2.
  std::vector<SpeciesStats> st0;
  REQUIRE(for_each_snapshot(log, {0.0}, [&](const GasSnapshot& s) { st0 = species_stats(s); }));
  CHECK(st0[0].mean_kinetic_energy == Approx(0.5));
  CHECK(st0[1].mean_kinetic_energy == Approx(2));
}
