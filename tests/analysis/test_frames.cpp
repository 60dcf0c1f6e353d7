// Frames on hand-made states: positions wrapped into a periodic box, displacements to the nearest image,
// speeds, one species alone; the speed classes' bounds; the marked disks by default and by name; the
// displacement scale's percentile; frame times exact in the scalar type. Then a frame of a logged run
// equals the log's state.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "ede/analysis.hpp"
#include "public_log_support.hpp"

using namespace ede;

namespace {

// Disks at (x, y) with velocity (vx, vy), radius r, of the given species.
struct Disk {
  double x, y, vx, vy, r;
  std::int32_t species;
};

State state_of(const std::vector<Disk>& disks, BoundaryKind boundary, double time = 0) {
  std::vector<double> x, y, vx, vy, r, m;
  State s;
  for (const Disk& d : disks) {
    x.push_back(d.x), y.push_back(d.y), vx.push_back(d.vx), vy.push_back(d.vy), r.push_back(d.r), m.push_back(1);
    s.species.push_back(d.species);
  }
  s.time = time;
  s.lx = 2, s.ly = 1;
  s.boundary = boundary;
  s.x = Column(x), s.y = Column(y), s.vx = Column(vx), s.vy = Column(vy), s.radius = Column(r), s.mass = Column(m);
  s.species_names = {"bed", "ball"};
  return s;
}

}  // namespace

TEST_CASE("disk_frame: positions, speeds, displacements, initial mean speed", "[analysis][frames]") {
  const State initial = state_of({{0.5, 0.5, 3, 4, 0.1, 0}, {1.0, 0.2, 0, 0, 0.1, 0}, {1.5, 0.5, 0, 1, 0.2, 1}},
                                 BoundaryKind::Walls);
  const State now = state_of({{0.8, 0.9, 0, 2, 0.1, 0}, {1.0, 0.2, 0, 0, 0.1, 0}, {1.5, 0.25, 0, -1, 0.2, 1}},
                             BoundaryKind::Walls, 0.25);
  const DiskFrame f = disk_frame(now, initial);
  REQUIRE(f.size() == 3);
  CHECK(f.time == 0.25L);
  CHECK(f.lx == 2);
  CHECK_FALSE(f.periodic);
  CHECK(f.x == std::vector<double>{0.8, 1.0, 1.5});
  CHECK(f.speed == std::vector<double>{2, 0, 1});
  CHECK(f.displacement[0] == std::hypot(0.8 - 0.5, 0.9 - 0.5));
  CHECK(f.displacement[1] == 0);
  CHECK(f.displacement[2] == 0.25);
  CHECK(f.initial_mean_speed == 2);  // (5 + 0 + 1) / 3
  CHECK(f.species_names == std::vector<std::string>{"bed", "ball"});

  const DiskFrame ball = disk_frame(now, initial, 1);
  REQUIRE(ball.size() == 1);
  CHECK(ball.species == std::vector<std::int32_t>{1});
  CHECK(ball.r == std::vector<double>{0.2});
  CHECK(ball.initial_mean_speed == 1);
}

TEST_CASE("disk_frame in a periodic box: wrapped positions, nearest-image displacements", "[analysis][frames]") {
  const State initial = state_of({{1.95, 0.5, 0, 0, 0.1, 0}, {0.5, 0.02, 0, 0, 0.1, 0}}, BoundaryKind::Periodic);
  const State now = state_of({{0.05, 0.5, 0, 0, 0.1, 0}, {0.5, 1.0, 0, 0, 0.1, 0}}, BoundaryKind::Periodic);
  const DiskFrame f = disk_frame(now, initial);
  CHECK(f.periodic);
  CHECK(f.y[1] == 0);  // y = ly wraps to 0
  CHECK(f.displacement[0] == Approx(0.1).epsilon(1e-12));   // 1.95 -> 0.05 across the edge: 0.1, not 1.9
  CHECK(f.displacement[1] == Approx(0.02).epsilon(1e-12));  // 0.02 -> 1.0 = 0.0: 0.02, not 0.98
}

TEST_CASE("speed_class: slow below half the reference, fast above 1.5 times, bounds medium", "[analysis][frames]") {
  CHECK(speed_class(0.49, 1) == SpeedClass::Slow);
  CHECK(speed_class(0.5, 1) == SpeedClass::Medium);
  CHECK(speed_class(1.5, 1) == SpeedClass::Medium);
  CHECK(speed_class(1.51, 1) == SpeedClass::Fast);
  CHECK(speed_class(0, 0) == SpeedClass::Medium);  // everything at rest: nothing stands out
}

TEST_CASE("marked_disks: one-disk species by default, named species, unknown names", "[analysis][frames]") {
  const State s = state_of({{0.5, 0.5, 0, 0, 0.1, 0}, {1.0, 0.5, 0, 0, 0.1, 0}, {1.5, 0.5, 0, 0, 0.2, 1}},
                           BoundaryKind::Walls);
  const DiskFrame f = disk_frame(s, s);
  CHECK(marked_disks(f, {}).value() == std::vector<bool>{false, false, true});
  CHECK(marked_disks(f, {"bed"}).value() == std::vector<bool>{true, true, false});
  auto bad = marked_disks(f, {"comet"});
  REQUIRE_FALSE(bad);
  CHECK(bad.error().message == "the log has no species 'comet'; its species are: bed, ball");
  const State singles = state_of({{0.5, 0.5, 0, 0, 0.1, 0}, {1.5, 0.5, 0, 0, 0.2, 1}}, BoundaryKind::Walls);
  CHECK(marked_disks(disk_frame(singles, singles), {}).value() == std::vector<bool>{false, false});
}

TEST_CASE("displacement_scale: the 95th percentile of the unmarked disks, else the mean radius", "[analysis][frames]") {
  DiskFrame f;
  for (int k = 1; k <= 20; ++k) {
    f.x.push_back(0), f.y.push_back(0), f.r.push_back(0.5), f.speed.push_back(0), f.species.push_back(0);
    f.displacement.push_back(k);
  }
  f.x.push_back(0), f.y.push_back(0), f.r.push_back(2.5), f.speed.push_back(0), f.species.push_back(1);
  f.displacement.push_back(1000);  // a projectile, marked
  std::vector<bool> marked(21, false);
  marked[20] = true;
  CHECK(displacement_scale(f, marked) == 19);  // the 19th of 20 sorted values: ceil(0.95 x 20)
  std::fill(f.displacement.begin(), f.displacement.end(), 0.0);
  CHECK(displacement_scale(f, marked) == Approx((20 * 0.5 + 2.5) / 21).epsilon(1e-15));
}

TEST_CASE("evenly_spaced_times and times_every: values of the scalar type within the range", "[analysis][frames]") {
  CHECK(evenly_spaced_times(0, 1, 5, ScalarKind::Double) == std::vector<Time>{0, 0.25, 0.5, 0.75, 1});
  CHECK(evenly_spaced_times(0.5, 1, 1, ScalarKind::Double) == std::vector<Time>{0.5});
  CHECK(evenly_spaced_times(1, 0.5, 3, ScalarKind::Double).empty());
  const Time t1 = Time(0.1f);
  const std::vector<Time> f = evenly_spaced_times(0, t1, 7, ScalarKind::Float);
  REQUIRE(f.size() == 7);
  CHECK(f.back() == t1);
  for (std::size_t k = 0; k < f.size(); ++k) {
    CHECK(Time(float(f[k])) == f[k]);  // a float
    if (k) CHECK(f[k] > f[k - 1]);
  }
  const Time third = Time(1.0L / 3);
  const std::vector<Time> l = evenly_spaced_times(0, 1, 4, ScalarKind::LongDouble);
  CHECK(l[1] == third);  // long double keeps every digit

  const std::vector<Time> e = times_every(0.5, 2, 0.5, ScalarKind::Double, 100);
  CHECK(e == std::vector<Time>{0.5, 1, 1.5, 2});
  const std::vector<Time> d = times_every(0, 1, Time(0.3), ScalarKind::Double, 100);
  REQUIRE(d.size() == 4);  // 0, 0.3, 0.6, 0.9: t0 + k every, each rounded to double from k
  CHECK(d[3] == Time(double(Time(0.3) * 3)));
  CHECK(times_every(0, 1, 1e-6, ScalarKind::Double, 1000).empty());
  CHECK(times_every(0, 1, 0, ScalarKind::Double, 1000).empty());
}

TEST_CASE("disk_frame of a logged run is the log's state, as doubles", "[analysis][frames]") {
  const Log log = test::public_log(test::gas_toml(50, 0.02, "time = 0.3", "", "periodic"), "frames-gas.ede");
  auto initial = log.state_at_event(0);
  auto now = log.state_at(0.3);
  REQUIRE(initial);
  REQUIRE(now);
  const DiskFrame f = disk_frame(now.value(), initial.value());
  REQUIRE(f.size() == 50);
  CHECK(f.time == Time(0.3));
  CHECK(f.initial_mean_speed == Approx(1).epsilon(1e-15));
  for (std::size_t i = 0; i < 50; ++i) {
    CHECK(f.x[i] == now.value().x[i]);  // the log's positions are already in the box
    CHECK(f.speed[i] == std::hypot(now.value().vx[i], now.value().vy[i]));
  }
}
