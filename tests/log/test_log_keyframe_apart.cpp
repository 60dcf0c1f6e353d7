// A large keyframe after the first is written apart from the log writer's copy of the state (the copy is
// dropped, the keyframe written, the copy made again from the engine's state): memory only. The log must
// be byte for byte the one written with both alive, for periodic and walled gases, dissipative runs with
// the TC model, gravity and rough disks, with periodic and resumable (rebuild) keyframes. The threshold is
// set to 0 here so that small test runs take the path the 10^6-disk runs take.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "log_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

LogSettings dense_keyframes(std::size_t apart_above) {
  LogSettings s;
  s.keyframe_interval = 1500;
  s.chunk_events = 700;
  s.keyframe_apart_above = apart_above;
  return s;
}

void check_apart_equals_together(const InitialState& s, const EngineOptions& o, const std::string& name) {
  auto together = run_logged<double>(s, o, name + "-together.ede", dense_keyframes(std::numeric_limits<std::size_t>::max()));
  auto apart = run_logged<double>(s, o, name + "-apart.ede", dense_keyframes(0));
  auto log = open_log(apart.path);
  INFO(name);
  REQUIRE(log->keyframes().size() >= 4);  // periodic and rebuild keyframes after the first
  const std::string a = file_bytes(apart.path), b = file_bytes(together.path);
  REQUIRE(!a.empty());
  CHECK(a == b);
}

InitialState spinning(InitialState s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    s.inertia.push_back(0.5 * s.mass[i] * s.radius[i] * s.radius[i]);
    s.omega.push_back((double(i % 5) - 2) * 20);
  }
  return s;
}

}  // namespace

TEST_CASE("a keyframe written apart from the writer's copy of the state leaves the log's bytes unchanged",
          "[log][keyframe]") {
  EngineOptions periodic = walls_until(6.0);
  periodic.boundary = BoundaryKind::Periodic;
  periodic.rebuild_interval = 2500;
  check_apart_equals_together(lattice_gas(14, 0.012, 1, 3), periodic, "apart-periodic");

  EngineOptions dissipative = walls_until(6.0);
  dissipative.rebuild_interval = 2300;
  dissipative.physics.restitution = 0.9;
  dissipative.physics.tc = 1e-4;
  dissipative.physics.gravity = {0, -0.5};
  check_apart_equals_together(lattice_gas(14, 0.012, 1, 4), dissipative, "apart-dissipative");

  EngineOptions rough = walls_until(6.0);
  rough.rebuild_interval = 2700;
  rough.rotation = true;
  rough.physics.roughness = 0.5;
  rough.physics.wall_roughness = 0.2;
  check_apart_equals_together(spinning(lattice_gas(14, 0.012, 1, 5)), rough, "apart-rough");
}
