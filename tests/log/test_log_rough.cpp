// Rough disks in the log (schema/FORMAT.md, "Rotation"): replay rebuilds the engine's states, spins
// included, bit for bit in every scalar type; the reference reader (written from FORMAT.md) agrees; every
// velocity and spin residual of an ordinary run is 0; the public Log shows omega in states and events;
// verify reruns a rough scene identically.
#include <catch2/catch.hpp>
#include <capnp/serialize.h>

#include <cstring>
#include <fstream>
#include <iterator>

#include "ede/log.hpp"
#include "ede/simulation.hpp"
#include "log/log_messages.hpp"
#include "log_test_support.hpp"
#include "reference_compare.hpp"
#include "scene_test_support.hpp"
#include "setup/setup_from_csv.hpp"

using namespace ede;
using namespace ede::test;

namespace {

// 144 spinning disks, partly rough pairs and walls, a little inelastic (TC model on), two species.
InitialState rough_gas() {
  InitialState s = lattice_gas(12, 0.01, 1, 5);
  s.species_names = {"a", "b"};
  for (std::size_t i = 0; i < s.size(); ++i) {
    s.species[i] = std::int32_t(i % 2);
    s.mass[i] = 1.0 + double(i % 3);
    s.inertia.push_back((i % 2 ? 0.4 : 0.5) * s.mass[i] * s.radius[i] * s.radius[i]);
    s.omega.push_back((double(i % 5) - 2) * 30);
  }
  return s;
}

EngineOptions rough_options(BoundaryKind boundary) {
  EngineOptions o = walls_until(4.0);
  o.boundary = boundary;
  o.sample_interval = 0.25;
  o.rotation = true;
  o.physics.roughness = 0.5;
  o.physics.wall_roughness = 0.2;
  o.physics.restitution = 0.95;
  o.physics.pairs = {{"a", "b", 0.9, -0.3}};
  o.physics.tc = 1e-5;
  return o;
}

template <class T>
void check_rough_log(BoundaryKind boundary, const std::string& file) {
  LogSettings settings;
  settings.keyframe_interval = 3000;
  settings.chunk_events = 1000;
  auto run = run_logged<T>(rough_gas(), rough_options(boundary), file, settings);
  REQUIRE(run.recorder->of_kind(EventKind::Pair).size() > 800);
  auto replay = replay_of<T>(run.path);
  for (std::size_t k = 0; k < run.recorder->sample_times.size(); ++k) {
    REQUIRE(replay->seek_time(run.recorder->sample_times[k]));
    const Particles<T>& p = replay->particles();
    const T t = run.recorder->sample_times[k];
    REQUIRE(p.omega.size() == p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Disk<T>& want = run.recorder->sample_states[k][i];
      INFO("sample " << k << ", disk " << i);
      REQUIRE(same_bits(p.x_at(i, t), want.x));
      REQUIRE(same_bits(p.y_at(i, t), want.y));
      REQUIRE(same_bits(p.disk[i].vx, want.vx));
      REQUIRE(same_bits(p.disk[i].vy, want.vy));
      REQUIRE(same_bits(p.omega[i], run.recorder->sample_omegas[k][i]));
    }
  }
  // The reference reader agrees after every chunk, spins included.
  auto log = open_log(run.path);
  REQUIRE(log->header().rotation());
  CHECK(compare_with_reference<T>(run.path) == log->total_events());
  // Every velocity and spin residual is 0: the predictions are the engine's own rules.
  std::size_t spin_bytes = 0;
  for (const LogRecordRef& c : log->chunks()) {
    auto words = log->load_message(c.offset, c.payload_size);
    REQUIRE(words.ok());
    capnp::FlatArrayMessageReader message(as_words(words.value()), reader_options(words.value()));
    const auto chunk = message.getRoot<logschema::Chunk>();
    for (const unsigned char b : chunk.getVelocityResiduals()) REQUIRE(b == 0);
    for (const unsigned char b : chunk.getSpinResiduals()) REQUIRE(b == 0);
    spin_bytes += chunk.getSpinResiduals().size();
  }
  CHECK(spin_bytes > 1600);
}

}  // namespace

TEST_CASE("rough log: replay and the reference reader rebuild a rough gas bit for bit, spins included", "[log][rough]") {
  check_rough_log<double>(BoundaryKind::Walls, "rough-walls.ede");
  check_rough_log<double>(BoundaryKind::Periodic, "rough-periodic.ede");
}

TEST_CASE("rough log: float and long double runs replay exactly too", "[log][rough]") {
  check_rough_log<float>(BoundaryKind::Walls, "rough-float.ede");
  check_rough_log<long double>(BoundaryKind::Periodic, "rough-long-double.ede");
}

TEST_CASE("rough log: the public Log shows omega in states and events, and verify reruns it identically", "[log][rough]") {
  const std::string text = R"(seed = 5
[box]
size = [1.0, 1.0]
boundary = "periodic"
[physics]
restitution = 0.9
roughness = 0.4
[[species]]
name = "gas"
count = 200
radius = 0.01
inertia_factor = 0.4
spin_temperature = 1.0
[species.placement]
kind = "random"
region = [0.0, 0.0, 1.0, 1.0]
[species.velocity]
kind = "maxwell"
temperature = 1.0
[stop]
events = 20000
[log]
keyframe_interval = 4000
[sampling]
interval = 0.5
)";
  auto scene = parse_scene_text(text, "rough.toml");
  REQUIRE(scene.ok());
  const std::string path = temp_path("rough-public.ede");
  State end;
  {
    auto sim = Simulation::create(scene.value(), {path, {}});
    REQUIRE(sim.ok());
    const State start = sim.value().state();
    REQUIRE(start.rotates());
    CHECK(start.inertia[0] == Approx(0.4 * start.mass[0] * start.radius[0] * start.radius[0]).epsilon(1e-15));
    CHECK(sim.value().run() == RunStatus::ReachedEvents);
    end = sim.value().state();
    REQUIRE(sim.value().close().ok());
  }
  auto log = Log::open(path);
  REQUIRE(log.ok());
  auto state = log.value().state_at_end();
  REQUIRE(state.ok());
  REQUIRE(state.value().rotates());
  for (std::size_t i = 0; i < end.size(); ++i) {
    REQUIRE(state.value().omega[i] == end.omega[i]);
    REQUIRE(state.value().vx[i] == end.vx[i]);
  }
  // The state CSV carries omega and inertia, and a start from it reads them back exactly.
  const std::string csv = temp_path("rough-state.csv");
  REQUIRE(write_state_csv(csv, state.value()).ok());
  std::ifstream in(csv);
  const std::string csv_text((std::istreambuf_iterator<char>(in)), {});
  CHECK(csv_text.rfind("id,species,x,y,vx,vy,radius,mass,omega,inertia\n", 0) == 0);
  auto back = parse_state_csv(csv_text, csv);
  REQUIRE(back.ok());
  REQUIRE(back.value().omega.size() == end.size());
  for (std::size_t i = 0; i < end.size(); ++i) {
    REQUIRE(back.value().omega[i] == end.omega[i]);
    REQUIRE(back.value().inertia[i] == end.inertia[i]);
  }
  auto events = log.value().events({});
  REQUIRE(events.ok());
  std::size_t spun = 0;
  for (const Event& e : events.value())
    if (e.kind == EventKind::Pair && e.omega_i != e.omega_i_before) ++spun;
  CHECK(spun > 1000);
  auto report = log.value().verify();
  REQUIRE(report.ok());
  INFO(report.value().text);
  CHECK(report.value().identical);
}

TEST_CASE("rough log: convert rewrites it as version 2 with the same content, and refuses version 1", "[log][rough]") {
  GasToml g = logged_gas("7", "0.5");
  g.tables += "[physics]\nrestitution = 0.9\nroughness = 0.4\n";
  g.velocity = "kind = \"maxwell\"\ntemperature = 1.0";
  const std::string path = run_to_log(scene_of(g.text() + "[[actions]]\ntime = 0.25\nkind = \"reverse_velocities\"\n",
                                               "rough-convert.toml"),
                                      "rough-convert.ede");
  auto log = Log::open(path);
  REQUIRE(log.ok());
  REQUIRE(log.value().info().rotates);
  const std::string copy = temp_path("rough-convert-v2.ede");
  REQUIRE(log.value().convert(copy, 2).ok());
  auto converted = Log::open(copy);
  REQUIRE(converted.ok());
  CHECK(converted.value().content_digest().value() == log.value().content_digest().value());
  CHECK(compare_with_reference<double>(copy) == log.value().info().events);
  const State a = log.value().state_at(0.3).value(), b = converted.value().state_at(0.3).value();
  bool same = a.size() == b.size();
  for (std::size_t i = 0; same && i < a.size(); ++i)
    same = a.omega.exact(i) == b.omega.exact(i) && a.vx.exact(i) == b.vx.exact(i) && a.x.exact(i) == b.x.exact(i);
  CHECK(same);
  const Status v1 = log.value().convert(temp_path("rough-convert-v1.ede"), 1);
  REQUIRE_FALSE(v1.ok());
  CHECK(v1.error().message.find("no angular velocities; convert it to version 2") != std::string::npos);
}
