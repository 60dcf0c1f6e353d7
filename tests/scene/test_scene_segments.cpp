// The [walls] table: segments and polygons as plain data, and every error naming file, line, key and fix;
// setup's random placement keeps disks off the segments; a disk placed across one is refused.
#include <catch2/catch.hpp>
#include <string>

#include "core/segment.hpp"
#include "ede/scene.hpp"
#include "scene_test_support.hpp"
#include "setup/setup.hpp"

namespace {

using Catch::Matchers::Contains;

// 400 disks of radius 0.01 at speed 1, placed at random in a [2, 1] box.
const std::string kScene = [] {
  ede::test::GasToml g;
  g.seed = "3", g.size = "[2.0, 1.0]", g.placement = "kind = \"random\"";
  return g.text();
}();

std::string error_of(const std::string& text) {
  const std::string message = ede::test::scene_error(text);  // refused, with a fix
  CHECK_THAT(message, Contains("scene.toml:"));
  return message;
}

}  // namespace

TEST_CASE("scene segments: segments and a polygon become a list of segments", "[scene][segment]") {
  auto scene = ede::parse_scene_text(kScene + R"(
[[walls.segments]]
from = [1.0, 0.0]
to = [1.0, 0.45]
restitution = 0.5
[[walls.polygons]]
points = [[0.2, 0.2], [0.4, 0.2], [0.3, 0.4]]
)",
                                     "scene.toml");
  REQUIRE(scene.ok());
  const auto& segs = scene.value().physics.segments;
  REQUIRE(segs.size() == 4);
  CHECK(segs[0].to[1] == 0.45);
  CHECK(segs[0].restitution == 0.5);
  CHECK(segs[3].from == std::array<double, 2>{0.3, 0.4});
  CHECK(segs[3].to == std::array<double, 2>{0.2, 0.2});  // closed by default
  CHECK(!scene.value().physics.elastic());
  CHECK_THAT(scene.value().source_text, Contains("walls"));
}

TEST_CASE("scene segments: errors name the file, the key and the fix", "[scene][segment]") {
  CHECK_THAT(error_of(kScene + "[[walls.segments]]\nfrom = [0.5, 0.5]\nto = [0.5, 0.5]\n"),
             Contains("zero length"));
  CHECK_THAT(error_of(kScene + "[[walls.segments]]\nfrom = [0.5, 0.5]\nto = [2.5, 0.5]\n"),
             Contains("outside the box"));
  CHECK_THAT(error_of(kScene + "[[walls.segments]]\nfrom = [0.5, nan]\nto = [1.5, 0.5]\n"), Contains("walls.segments[0].from"));
  CHECK_THAT(error_of(kScene + "[[walls.segments]]\nfrom = [0.5, 0.5]\n"), Contains("walls.segments[0].to"));
  CHECK_THAT(error_of(kScene + "[[walls.segments]]\nfrom = [0.5, 0.5]\nto = [1.5, 0.5]\nrestitution = 2\n"),
             Contains("restitution"));
  CHECK_THAT(error_of(kScene + "[[walls.segments]]\nfrom = [0.5, 0.5]\nto = [1.5, 0.5]\nxi = 1\n"), Contains("xi"));
  CHECK_THAT(error_of(kScene + "[[walls.polygons]]\npoints = [[0.5, 0.5]]\n"), Contains("at least two"));
  std::string periodic = kScene;
  periodic.replace(periodic.find("size = [2.0, 1.0]"), 17, "size = [2.0, 1.0]\nboundary = \"periodic\"");
  CHECK_THAT(error_of(periodic + "[[walls.segments]]\nfrom = [0.5, 0.5]\nto = [1.5, 0.5]\n"), Contains("walls"));
  CHECK_THAT(error_of(kScene + "[physics]\ngravity = [0, -1]\n[[walls.segments]]\nfrom = [0.5, 0.5]\nto = [1.5, 0.5]\n"),
             Contains("gravity"));
}

TEST_CASE("scene segments: random placement keeps every disk off the segments", "[scene][segment][setup]") {
  // A comb of vertical segments across the region: many candidates land on one and are drawn again.
  std::string text = kScene;
  for (int k = 1; k < 20; ++k)
    text += "[[walls.segments]]\nfrom = [" + std::to_string(0.1 * k) + ", 0.05]\nto = [" + std::to_string(0.1 * k) +
            ", 0.95]\n";
  auto scene = ede::parse_scene_text(text, "scene.toml");
  REQUIRE(scene.ok());
  auto state = ede::build_initial_state(scene.value());
  REQUIRE(state.ok());
  for (const ede::SegmentSpec& s : scene.value().physics.segments) {
    const auto g = ede::make_segment(s.from[0], s.from[1], s.to[0], s.to[1], 1.0);
    for (std::size_t i = 0; i < state.value().size(); ++i)
      REQUIRE(ede::segment_distance(g, state.value().x[i], state.value().y[i]) >= state.value().radius[i]);
  }
}

TEST_CASE("scene segments: a disk placed across a segment is refused with the disk and the segment", "[scene][segment][setup]") {
  const std::string text = R"(seed = 3
[box]
size = [1.0, 1.0]
[[species]]
name = "gas"
count = 1
radius = 0.05
placement = { kind = "explicit", positions = [[0.5, 0.52]] }
[stop]
time = 1.0
[[walls.segments]]
from = [0.1, 0.5]
to = [0.9, 0.5]
)";
  auto scene = ede::parse_scene_text(text, "scene.toml");
  REQUIRE(scene.ok());
  auto state = ede::build_initial_state(scene.value());
  REQUIRE_FALSE(state.ok());
  CHECK_THAT(state.error().message, Contains("scene.toml"));
  CHECK_THAT(state.error().message, Contains("disk 0"));
  CHECK_THAT(state.error().message, Contains("wall segment 0"));
  CHECK_THAT(state.error().message, Contains("move the disk or the segment"));
}
