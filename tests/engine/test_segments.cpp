// Wall segments (core/segment.hpp, engine/collide.hpp collide_segment, the WithSegments engine): exact
// reflections, end points as infinite masses, a disk trapped in a triangle, and the hard cases.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>

#include "engine/collide.hpp"
#include "engine/segment_cells.hpp"
#include "engine_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

EngineOptions with_segments(double t_end, std::vector<SegmentSpec> segments) {
  EngineOptions o = walls_until(t_end);
  o.physics.segments = std::move(segments);
  return o;
}

SegmentSpec seg(double ax, double ay, double bx, double by, double xi = 1) { return {{ax, ay}, {bx, by}, xi}; }

constexpr double kHuge = 0x1p60;  // an end point is a disk this many times heavier (collide.hpp)

}  // namespace

TEST_CASE("segment: an axis-aligned segment reflects exactly, from either side", "[segment]") {
  const Segment<double> h = make_segment(0.2, 0.5, 0.8, 0.5, 1.0);
  for (double sign : {1.0, -1.0}) {
    double vx = 0.3, vy = -0.7 * sign;
    collide_segment(h, 0.4, 0.5 + 0.05 * sign, 2.0, vx, vy);
    CHECK(same_bits(vx, 0.3));
    CHECK(same_bits(vy, 0.7 * sign));
  }
}

TEST_CASE("segment: angle in equals angle out off a slanted segment", "[segment]") {
  // Segments at many angles; the velocity's component along the segment is kept and the normal one
  // reversed, to a few units in the last place (the unit vectors are rounded; a 45 degree segment's
  // tangent is exact in neither component).
  for (int k = 1; k < 12; ++k) {
    const double angle = k * 0.27;
    const Segment<double> s = make_segment(0.5, 0.5, 0.5 + 0.3 * std::cos(angle), 0.5 + 0.3 * std::sin(angle), 1.0);
    const double vx0 = 0.9, vy0 = -0.4;
    const double along0 = vx0 * s.ux + vy0 * s.uy, normal0 = vx0 * s.nx + vy0 * s.ny;
    double vx = vx0, vy = vy0;
    const double x = 0.5 + 0.1 * s.ux - 0.05 * s.nx * (normal0 > 0 ? 1 : -1);
    const double y = 0.5 + 0.1 * s.uy - 0.05 * s.ny * (normal0 > 0 ? 1 : -1);
    collide_segment(s, x, y, 2.0, vx, vy);
    INFO("angle " << angle);
    CHECK(vx * s.ux + vy * s.uy == Approx(along0).margin(4e-16));
    CHECK(vx * s.nx + vy * s.ny == Approx(-normal0).margin(4e-16));
    CHECK(vx * vx + vy * vy == Approx(vx0 * vx0 + vy0 * vy0).epsilon(1e-15));
  }
}

TEST_CASE("segment: the engine reflects a disk off a slanted segment at the predicted time", "[segment]") {
  // A 45 degree segment through (0.5, 0.5); a disk coming straight down at x = 0.5 touches it when its
  // centre is r sqrt 2 above the line's point below it: v (0, -1) leaves as (-1, 0) (angle in = out).
  const double r = 0.05;
  InitialState s = box();
  s.add(0.5, 0.9, 0.0, -1.0, r, 1.0, 0);
  auto run = run_recorded(s, with_segments(0.5, {seg(0.3, 0.3, 0.7, 0.7)}));
  const auto hits = run.recorder->of_kind(EventKind::Segment);
  REQUIRE(hits.size() == 1);
  CHECK(hits[0].j == 0);
  CHECK(double(hits[0].time) == Approx(0.4 - r * std::sqrt(2.0)).epsilon(1e-14));
  CHECK(hits[0].vix == Approx(-1.0).margin(1e-15));
  CHECK(hits[0].viy == Approx(0.0).margin(1e-15));
  CHECK(run.engine->check_invariants(1e-12) == "");
}

TEST_CASE("segment: head-on at an end point is the disk-disk rule with an infinite mass", "[segment]") {
  // The disk comes along the segment's own line towards its end A: it reverses exactly.
  const double r = 0.05;
  InitialState s = box();
  s.add(0.2, 0.5, 1.0, 0.0, r, 1.0, 0);
  auto run = run_recorded(s, with_segments(0.3, {seg(0.5, 0.5, 0.9, 0.5)}));
  const auto hits = run.recorder->of_kind(EventKind::Segment);
  REQUIRE(hits.size() == 1);
  CHECK(hits[0].time == Approx(0.25).epsilon(1e-15));
  CHECK(same_bits(hits[0].vix, -1.0));
  CHECK(same_bits(hits[0].viy, 0.0));
}

TEST_CASE("segment: off-centre at an end point, bit for bit the pair rule with mass ratio 2^60", "[segment]") {
  const double r = 0.05;
  for (double b : {0.01, 0.03, -0.045, 0.0499}) {
    InitialState s = box();
    s.add(0.2, 0.5 + b, 1.0, 0.0, r, 1.0, 0);
    auto run = run_recorded(s, with_segments(0.3, {seg(0.5, 0.5, 0.9, 0.5)}));
    const auto hits = run.recorder->of_kind(EventKind::Segment);
    REQUIRE(hits.size() == 1);
    const Disk<double>& d = run.engine->particles().disk[0];  // its record is at the hit (no event after)
    REQUIRE(d.t == hits[0].time);
    double vix = 1.0, viy = 0.0, vjx = 0.0, vjy = 0.0;
    collide_pair(0.5 - d.x, 0.5 - d.y, 1.0, kHuge, 2.0, vix, viy, vjx, vjy);
    INFO("impact parameter " << b);
    CHECK(same_bits(hits[0].vix, vix));
    CHECK(same_bits(hits[0].viy, viy));
    CHECK(std::hypot(d.x - 0.5, d.y - 0.5) == Approx(r).epsilon(1e-13));  // it touched the end point
  }
}

TEST_CASE("segment: hitting an end point from any side", "[segment]") {
  // Eight directions onto end B of a short segment, each aimed at B itself: the disk comes straight back.
  const double r = 0.04;
  for (int k = 0; k < 8; ++k) {
    const double a = k * M_PI / 4 + 0.1;
    const double bx = 0.5, by = 0.5;
    InitialState s = box();
    s.add(bx - 0.3 * std::cos(a), by - 0.3 * std::sin(a), std::cos(a), std::sin(a), r, 1.0, 0);
    auto run = run_recorded(s, with_segments(0.3, {seg(0.3, 0.42, bx, by)}));
    const auto hits = run.recorder->of_kind(EventKind::Segment);
    INFO("direction " << k);
    REQUIRE(hits.size() >= 1);
    const double speed = std::hypot(hits[0].vix, hits[0].viy);
    CHECK(speed == Approx(1.0).epsilon(1e-14));
    CHECK(run.engine->check_invariants(1e-9) == "");
  }
}

TEST_CASE("segment: a disk trapped in a triangle keeps its energy and never leaves", "[segment][long]") {
  // 2 10^5 bounces inside a triangle of three elastic segments (a closed polygon): the speed is kept to
  // round-off (each slanted reflection rounds: measured drift below 1e-12 relative), the disk stays inside.
  const double r = 0.02;
  InitialState s = box();
  s.add(0.5, 0.4, 0.731, 0.459, r, 1.0, 0);
  EngineOptions o = with_segments(1e9, {seg(0.1, 0.1, 0.9, 0.15), seg(0.9, 0.15, 0.45, 0.85), seg(0.45, 0.85, 0.1, 0.1)});
  o.stop.time.reset();
  o.stop.events = 200000;
  o.rebuild_interval = 50000;
  auto e = engine(s, o);
  const double e0 = kinetic_energy(e->particles());
  double worst = 0;
  for (int k = 0; k < 20; ++k) {
    e->run(10000);
    REQUIRE(e->check_invariants(1e-9) == "");
    worst = std::max(worst, std::abs(kinetic_energy(e->particles()) / e0 - 1));
    const double x = x_now(*e, 0), y = y_now(*e, 0);
    // Inside: on the inner side of each edge (counter-clockwise triangle: left of every edge).
    const double c1 = (0.9 - 0.1) * (y - 0.1) - (0.15 - 0.1) * (x - 0.1);
    const double c2 = (0.45 - 0.9) * (y - 0.15) - (0.85 - 0.15) * (x - 0.9);
    const double c3 = (0.1 - 0.45) * (y - 0.85) - (0.1 - 0.85) * (x - 0.45);
    REQUIRE((c1 > 0 && c2 > 0 && c3 > 0));
  }
  CHECK(e->counts().of(EventKind::Segment) > 50000);
  CHECK(e->counts().of(EventKind::Wall) == 0);
  CHECK(worst < 1e-12);
}

TEST_CASE("segment: many disks in a triangle, with pair collisions, stay inside and apart", "[segment]") {
  InitialState s = box();
  for (int k = 0; k < 12; ++k) s.add(0.35 + 0.05 * (k % 4), 0.3 + 0.06 * (k / 4), std::cos(k * 1.3), std::sin(k * 1.3), 0.012, 1.0, 0);
  EngineOptions o = with_segments(1e9, {seg(0.1, 0.1, 0.9, 0.15), seg(0.9, 0.15, 0.45, 0.85), seg(0.45, 0.85, 0.1, 0.1)});
  o.stop.time.reset();
  o.stop.events = 100000;
  auto e = engine(s, o);
  const double e0 = kinetic_energy(e->particles());
  for (int k = 0; k < 10; ++k) {
    e->run(10000);
    REQUIRE(e->check_invariants(1e-9) == "");
  }
  CHECK(e->counts().of(EventKind::Pair) > 1000);
  CHECK(e->counts().of(EventKind::Wall) == 0);
  CHECK(kinetic_energy(e->particles()) == Approx(e0).epsilon(1e-12));
}

TEST_CASE("segment hard case: grazing an end point collides or misses", "[segment][hard]") {
  const double r = 0.05;
  for (double rel : {-1e-12, 1e-12}) {
    InitialState s = box();
    s.add(0.2, 0.5 + r * (1 + rel), 1.0, 0.0, r, 1.0, 0);  // passes end A of a vertical segment below it
    auto run = run_recorded(s, with_segments(0.6, {seg(0.5, 0.1, 0.5, 0.5)}));
    INFO("impact parameter (1 + " << rel << ") r");
    CHECK(run.recorder->of_kind(EventKind::Segment).size() == (rel < 0 ? 1u : 0u));
    CHECK(run.engine->check_invariants(1e-9) == "");
    CHECK(kinetic_energy(run.engine->particles()) == Approx(0.5).epsilon(1e-15));
  }
}

TEST_CASE("segment hard case: a disk touching two segments at once in a corner", "[segment][hard]") {
  // A symmetric V (two segments meeting at (0.5, 0.2)); a disk falling straight into it touches both
  // bodies at the same instant (to round-off: the two heights round differently): two events, one per
  // segment, and the disk leaves straight up (both reflections, one after the other).
  const double r = 0.05;
  InitialState s = box();
  s.add(0.5, 0.8, 0.0, -1.0, r, 1.0, 0);
  auto run = run_recorded(s, with_segments(0.9, {seg(0.2, 0.5, 0.5, 0.2), seg(0.5, 0.2, 0.8, 0.5)}));
  const auto hits = run.recorder->of_kind(EventKind::Segment);
  REQUIRE(hits.size() >= 2);
  CHECK(double(hits[1].time - hits[0].time) < 1e-15);
  CHECK(hits[0].j != hits[1].j);
  CHECK(hits[1].vix == Approx(0.0).margin(1e-15));
  CHECK(hits[1].viy == Approx(1.0).epsilon(1e-15));
  CHECK(run.engine->check_invariants(1e-9) == "");
}

TEST_CASE("segment hard case: a disk resting against a segment, or sliding along it", "[segment][hard]") {
  const double r = 0.05;
  InitialState s = box();
  s.add(0.15, 0.55, 0.0, 0.0, r, 1.0, 0);   // at rest, touching the segment from above
  s.add(0.3, 0.45, 0.25, 0.0, r, 1.0, 0);   // sliding along its underside
  auto run = run_recorded(s, with_segments(2.0, {seg(0.1, 0.5, 0.9, 0.5)}));
  CHECK(run.status == RunStatus::ReachedTime);
  CHECK(run.recorder->of_kind(EventKind::Segment).empty());
  CHECK(run.engine->check_invariants(1e-12) == "");
}

TEST_CASE("segment: a disk placed across a segment is refused", "[segment]") {
  InitialState s = box();
  s.add(0.5, 0.52, 0.0, 0.0, 0.05, 1.0, 0);
  auto made = make_engine<double>(s, with_segments(1, {seg(0.1, 0.5, 0.9, 0.5)}));
  REQUIRE(!made);
  CHECK_THAT(made.error().message, Catch::Contains("crosses wall segment 0"));
  auto periodic = with_segments(1, {seg(0.1, 0.5, 0.9, 0.5)});
  periodic.boundary = BoundaryKind::Periodic;
  InitialState ok = box();
  ok.add(0.5, 0.8, 0.0, 0.0, 0.05, 1.0, 0);
  auto refused = make_engine<double>(ok, periodic);
  REQUIRE(!refused);
  CHECK_THAT(refused.error().message, Catch::Contains("walls"));
}

TEST_CASE("segment cells: a segment is listed in exactly the cells within reach", "[segment]") {
  SegmentCells cells;
  cells.build({{0.05, 0.05, 0.95, 0.95}}, 10, 10, 1.0, 1.0, 0.02);
  int listed = 0;
  for (int c = 0; c < 100; ++c) {
    const int cx = c % 10, cy = c / 10;
    const bool has = cells.begin(c) != cells.end(c);
    listed += has;
    // Cells on the diagonal and its direct neighbours' corners within 0.02: |cx - cy| <= 1 only.
    if (std::abs(cx - cy) > 1) CHECK(!has);
    if (cx == cy) CHECK(has);
  }
  CHECK(listed < 30);  // not the whole 10 x 10 bounding box
  CHECK(SegmentCells::rect_distance({0, 0, 1, 0}, 0.2, 0.1, 0.3, 0.2) == Approx(0.1));
}

TEST_CASE("segment engine without segments runs bit for bit what the walls engine runs", "[segment][table]") {
  // The WithSegments engine differs only by code behind if constexpr and an empty segment list: with no
  // segments, the same events and the same bits as the elastic walls engine.
  const InitialState s = lattice_gas(12, 0.015, 1.0, 7);
  EngineOptions o = walls_until(1e9);
  o.stop.time.reset();
  o.stop.events = 20000;
  auto plain = make_engine_as<double>(EngineKind::WallsElastic, s, o);
  auto seg = make_engine_as<double>(EngineKind::WallsSegments, s, o);
  REQUIRE(plain.ok());
  REQUIRE(seg.ok());
  plain.value()->run();
  seg.value()->run();
  REQUIRE(plain.value()->time() == seg.value()->time());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Disk<double>&a = plain.value()->particles().disk[i], &b = seg.value()->particles().disk[i];
    REQUIRE((same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.vx, b.vx) && same_bits(a.vy, b.vy)));
  }
}

TEST_CASE("segment: far segments are never looked at (cell lists)", "[segment]") {
  // A disk bouncing between two walls of a small pen in one corner of a big box with 400 segments
  // elsewhere: its events touch only the pen's segments, and the run computes the same as with the pen
  // alone (the far segments cannot change a prediction).
  const double r = 0.005;
  InitialState s = box(4.0, 4.0);
  s.add(0.2, 0.2, 0.7, 0.3, r, 1.0, 0);
  for (int k = 0; k < 40; ++k) s.add(0.1 + 0.09 * k, 3.9, 0.0, 0.0, r, 1.0, 0);  // a row of resting disks: a finer grid
  std::vector<SegmentSpec> pen = {seg(0.05, 0.05, 0.35, 0.05), seg(0.35, 0.05, 0.35, 0.35), seg(0.35, 0.35, 0.05, 0.35),
                                  seg(0.05, 0.35, 0.05, 0.05)};
  std::vector<SegmentSpec> many = pen;
  for (int k = 0; k < 400; ++k) {
    const double x = 1.0 + 0.14 * (k % 20), y = 1.0 + 0.14 * (k / 20);
    many.push_back(seg(x, y, x + 0.1, y + 0.05));
  }
  EngineOptions a = with_segments(50.0, pen), b = with_segments(50.0, many);
  auto ra = run_recorded(s, a);
  auto rb = run_recorded(s, b);
  REQUIRE(ra.events().size() == rb.events().size());
  REQUIRE(ra.events().size() > 50);
  for (std::size_t k = 0; k < ra.events().size(); ++k) {
    CHECK(ra.events()[k].j == rb.events()[k].j);
    CHECK(same_bits(ra.events()[k].time, rb.events()[k].time));
  }
}
