// Segment events in the log (schema/FORMAT.md, "Wall segments"): replay rebuilds the engine's states bit for
// bit, the reference reader agrees, every residual is 0 (the predictions are the engine's own functions),
// verify reruns a segment scene identically, and the header's extra values reach replay.
#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>

#include "ede/log.hpp"
#include "ede/simulation.hpp"
#include "log_test_support.hpp"
#include "reference_compare.hpp"
#include "scene_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

// A funnel and an obstacle in a walled box, 60 disks: segment bodies and end points both get hit.
EngineOptions funnel_options(double xi) {
  EngineOptions o = walls_until(6.0);
  o.sample_interval = 0.5;
  o.physics.segments = {{{0.1, 0.9}, {0.45, 0.5}, xi}, {{0.9, 0.9}, {0.55, 0.5}, xi}, {{0.4, 0.2}, {0.6, 0.25}, 1.0}};
  o.physics.restitution = xi < 1 ? 0.95 : 1.0;
  o.physics.tc = xi < 1 ? 1e-4 : 0.0;
  return o;
}

InitialState funnel_gas() {
  InitialState s = box();
  for (int k = 0; k < 60; ++k)  // four rows above the funnel's mouth
    s.add(0.05 + 0.06 * (k % 15), 0.92 + 0.02 * (k / 15), std::cos(k * 2.1), std::sin(k * 2.1), 0.008, 1.0 + (k % 3), 0);
  return s;
}

template <class T>
void check_segment_log(double xi, const std::string& file) {
  auto run = run_logged<T>(funnel_gas(), funnel_options(xi), file);
  REQUIRE(run.recorder->of_kind(EventKind::Segment).size() > 50);
  // Replay: every sample's state, bit for bit.
  auto replay = replay_of<T>(run.path);
  for (std::size_t k = 0; k < run.recorder->sample_times.size(); ++k) {
    REQUIRE(replay->seek_time(run.recorder->sample_times[k]));
    const Particles<T>& p = replay->particles();
    const T t = run.recorder->sample_times[k];
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Disk<T>& want = run.recorder->sample_states[k][i];
      INFO("sample " << k << ", disk " << i);
      REQUIRE(same_bits(p.x_at(i, t), want.x));
      REQUIRE(same_bits(p.y_at(i, t), want.y));
      REQUIRE(same_bits(p.disk[i].vx, want.vx));
      REQUIRE(same_bits(p.disk[i].vy, want.vy));
    }
  }
  // The reference reader, written from FORMAT.md, agrees after every chunk.
  auto log = open_log(run.path);
  CHECK(compare_with_reference<T>(run.path) == log->total_events());
}

}  // namespace

TEST_CASE("segment log: replay and the reference reader rebuild an elastic funnel bit for bit", "[log][segment]") {
  check_segment_log<double>(1.0, "segments-elastic.ede");
}

TEST_CASE("segment log: inelastic segments with the TC model, in float and long double", "[log][segment]") {
  check_segment_log<double>(0.8, "segments-inelastic.ede");
  check_segment_log<float>(0.8, "segments-float.ede");
  check_segment_log<long double>(0.8, "segments-long-double.ede");
}

TEST_CASE("segment log: segment events cost about what wall events do", "[log][segment]") {
  // Every residual 0 and most times predicted: an elastic segment scene's log stays small per event.
  auto run = run_logged<double>(funnel_gas(), funnel_options(1.0), "segments-size.ede");
  auto log = open_log(run.path);
  const double bytes = double(std::filesystem::file_size(run.path));
  INFO(bytes / double(log->total_events()) << " bytes per event");
  CHECK(bytes / double(log->total_events()) < 6.0);
}

TEST_CASE("segment log: ede's verify reruns a segment scene identically", "[log][segment]") {
  GasToml gas = left_half_gas("300", "0.004");
  gas.seed = "11", gas.stop = "events = 30000\n[log]\nkeyframe_interval = 5000";
  const std::string text = gas.text() + divider_toml("0.45", "0.55", "restitution = 0.9\n");
  const std::string path = run_to_log(scene_of(text, "divider.toml"), "segments-verify.ede", RunStatus::ReachedEvents);
  auto log = Log::open(path);
  REQUIRE(log.ok());
  auto report = log.value().verify();
  REQUIRE(report.ok());
  INFO(report.value().text);
  CHECK(report.value().identical);
  CHECK(report.value().events_compared > 2000);  // logged events (cell crossings are not)
}
