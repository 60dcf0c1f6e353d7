// Shear events in the log (format version 3, schema/FORMAT.md): a Lees-Edwards run writes version 3 with
// the header's boundary leesEdwards, decodes exactly with the reader and with the reference reader
// (pairs across the sliding edge included, coded against predictors that know no sliding image), is
// verified by a re-run, gives the same bytes twice and after an interrupted run is resumed, and names each
// crossing's disk, edge, new x and new vx.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "ede/ede.hpp"
#include "reference_compare.hpp"
#include "scene_test_support.hpp"  // run_to_log, interrupted_and_resumed
#include "tool_runner.hpp"  // temp_path, read_file

using namespace ede;
using namespace ede::test;

namespace {

// An inelastic gas sheared fast (u = 8 against thermal speeds ~0.7): many crossings and pairs across the
// edge; rebuilds (resumable keyframes) every 3000 events.
std::string scene_text(const std::string& scalar = "double") {
  return R"(seed = 8
[box]
size = [4.0, 4.0]
boundary = "lees-edwards"
shear_rate = 2.0
[physics]
restitution = 0.9
[engine]
scalar = ")" + scalar + R"("
rebuild_interval = 3000
[log]
chunk_events = 700
keyframe_interval = 2000
[[species]]
name = "gas"
count = 160
radius = 0.06
[species.velocity]
kind = "maxwell"
temperature = 0.5
[stop]
time = 6.0
)";
}

Scene scene(const std::string& scalar = "double") { return parse_scene_text(scene_text(scalar), "shear.toml").value(); }

std::string run_to_log(const std::string& name, const std::string& scalar = "double") {
  return ede::test::run_to_log(scene(scalar), name, RunStatus::ReachedTime);
}

}  // namespace

TEST_CASE("shear log: version 3, exact against the reference reader, verified by a re-run", "[log][shear]") {
  for (const std::string scalar : {"double", "float", "long double"}) {
    INFO(scalar);
    const std::string path = run_to_log("shear-" + std::to_string(scalar.size()) + ".ede", scalar);
    Log log = Log::open(path).value();
    CHECK(log.info().format_version == 3);
    CHECK(log.info().lees_edwards);
    CHECK(log.info().boundary == BoundaryKind::Periodic);
    CHECK(log.scene().value().shear_rate == 2.0);
    const EventCounts counts = log.count_events().value();
    CHECK(counts.of(EventKind::Shear) > 200);
    check_exact_and_verified(path, scalar);
  }
}

TEST_CASE("shear log: each crossing names its disk and edge, the state after it holds its new x and vx", "[log][shear]") {
  const std::string path = run_to_log("shear-events.ede");
  Log log = Log::open(path).value();
  std::size_t seen = 0;
  REQUIRE(log.for_each_event({}, [&](const Event& e) {
                if (e.kind != EventKind::Shear) return true;
                CHECK((e.j == kWrapTop || e.j == kWrapBottom));
                // vx moved by -u (top) or +u (bottom), u = 2 * 4, to round-off of the sum
                CHECK(std::abs(double(e.vix - e.vix_before) - (e.j == kWrapTop ? -8.0 : 8.0)) < 1e-12);
                CHECK(e.viy == e.viy_before);
                const State after = log.state_at_event(e.index + 1).value();
                CHECK(after.vx[std::size_t(e.i)] == double(e.vix));
                CHECK(after.x[std::size_t(e.i)] == double(e.xi));
                CHECK(after.x[std::size_t(e.i)] >= 0);
                CHECK(after.x[std::size_t(e.i)] <= 4);
                CHECK(std::abs(after.y[std::size_t(e.i)] - (e.j == kWrapTop ? 0.0 : 4.0)) < 1e-12);
                return ++seen < 20;
              }).ok());
  CHECK(seen == 20);
}

TEST_CASE("shear log: the same scene gives the same bytes, and an interrupted run resumes to them", "[log][shear][resume]") {
  const std::string whole = run_to_log("shear-whole.ede"), again = run_to_log("shear-again.ede");
  CHECK(read_file(whole) == read_file(again));
  CHECK(interrupted_and_resumed(scene(), "shear-cut.ede", 20000) == read_file(whole));
}

TEST_CASE("shear log: a Lees-Edwards log cannot become version 2", "[log][shear]") {
  const std::string path = run_to_log("shear-convert.ede");
  const auto refused = Log::open(path).value().convert(temp_path("shear-v2.ede"), 2);
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.error().message.find("version 3") != std::string::npos);
  const std::string again = temp_path("shear-v3.ede");
  REQUIRE(Log::open(path).value().convert(again, 3).ok());
  CHECK(Log::open(again).value().content_digest().value() == Log::open(path).value().content_digest().value());
}

TEST_CASE("shear log: the transport analyses and the viscosity refuse a sheared log with a message", "[log][shear]") {
  const Log log = Log::open(run_to_log("shear-transport.ede")).value();
  TransportOptions o;
  o.max_lag = 1, o.lag_step = 0.1;
  const auto msd = mean_square_displacement(log, o);
  REQUIRE_FALSE(msd.ok());
  CHECK(msd.error().message.find("Lees-Edwards") != std::string::npos);
  REQUIRE_FALSE(velocity_autocorrelation(log, o).ok());
  ViscosityOptions v;
  v.max_lag = 1, v.lag_step = 0.1;
  const auto eta = shear_viscosity(log, v);
  REQUIRE_FALSE(eta.ok());
  CHECK(eta.error().message.find("Lees-Edwards") != std::string::npos);
  // The analyses that pair disks by the plain periodic image (analysis/sheared_guard.hpp).
  auto refused = [](const auto& result) {
    return !result.ok() && result.error().message.find("Lees-Edwards") != std::string::npos;
  };
  PairCorrelationOptions g;
  g.r_max = 1;
  FrameTimes frames;
  frames.frames = 3;
  CHECK(refused(bond_order(log, g, frames)));  // g(r) follows the sliding image: test_structure_shear.cpp
  StructureFactorOptions k;
  k.k_max = 20;
  CHECK(refused(structure_factor(log, k, frames)));
  CHECK(refused(contact_values(log, frames)));
  CHECK(refused(measure_pressure(log)));
  CHECK(refused(impact_statistics(log)));
}
