// The __float128 engine (built where EDE_HAVE_FLOAT128 is set): it runs, its arithmetic is __float128
// throughout (energy kept to its own round-off, far below long double's), exact cases come out exact, and
// its first events are those of the long double engine to long double's round-off.
#if EDE_HAVE_FLOAT128

#include <catch2/catch.hpp>
#include <quadmath.h>

#include "engine_test_support.hpp"
#include "scalar_math.hpp"

namespace Catch {
template <>
struct StringMaker<__float128> {
  static std::string convert(__float128 v) {
    char text[64];
    quadmath_snprintf(text, sizeof text, "%.36Qg", v);
    return text;
  }
};
}  // namespace Catch

using namespace ede;
using namespace ede::test;
using Quad = __float128;

namespace {
// Kinetic energy summed in __float128 (ede::kinetic_energy sums in long double and returns a double).
Quad energy(const Particles<Quad>& p) {
  Quad sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Quad vx = p.disk[i].vx, vy = p.disk[i].vy;
    sum += p.mass[i] * (vx * vx + vy * vy) / 2;
  }
  return sum;
}

EngineOptions events(BoundaryKind boundary, std::uint64_t n) {
  EngineOptions o;
  o.boundary = boundary;
  o.stop.events = n;
  return o;
}
}  // namespace

TEST_CASE("the __float128 engine runs an elastic gas and keeps its energy to __float128 round-off",
          "[run][scalar][float128]") {
  const InitialState s = lattice_gas(20, 0.01, 1.0, 2);
  auto e = engine<Quad>(s, events(BoundaryKind::Periodic, 50000));
  const Quad e0 = energy(e->particles());
  REQUIRE(e->run() == RunStatus::ReachedEvents);
  // ~10^4 collisions each round the pair's velocities: the drift is a few eps (7 eps measured at 2 10^4
  // events). 1e4 eps is the factor the other types' test uses; it is 10^11 times below long double's eps,
  // so one step of the engine done in long double or double instead would show.
  const Quad eps = scalar_limits<Quad>::epsilon();
  CHECK(ede::abs(energy(e->particles()) - e0) / e0 < 1e4 * eps);
  // check_invariants measures distances in double whatever T is: it can only vouch to double's round-off.
  CHECK(e->check_invariants(1e3 * std::numeric_limits<double>::epsilon()) == "");
}

TEST_CASE("__float128: a head-on collision exchanges the velocities exactly", "[run][scalar][float128]") {
  // Equal masses along x, a common vy: contact at t = 1/8 (all numbers dyadic), after which the x
  // velocities are swapped to the last bit and vy is untouched (the normal is exactly (1, 0)).
  InitialState s = box();
  s.add(0.25, 0.5, 1.5, 0.25, 0.125, 1.0, 0);
  s.add(0.75, 0.5, -0.5, 0.25, 0.125, 1.0, 0);
  auto e = engine<Quad>(s, walls_until(0.2));
  Recorder<Quad> rec;
  e->add_sink(&rec);
  e->run();
  const auto pairs = rec.of_kind(EventKind::Pair);
  REQUIRE(pairs.size() == 1);
  CHECK(pairs[0].time == Quad(0.125));
  CHECK(pairs[0].vix == Quad(-0.5));
  CHECK(pairs[0].vjx == Quad(1.5));
  CHECK(pairs[0].viy == Quad(0.25));
  CHECK(pairs[0].vjy == Quad(0.25));
}

TEST_CASE("__float128: a wall reflection is exact", "[run][scalar][float128]") {
  // From x = 0.5 at vx = 0.75 to the right wall (x = 1 - r = 0.875) at t = 0.5 exactly: vx flips, vy stays.
  InitialState s = box();
  s.add(0.5, 0.5, 0.75, -0.375, 0.125, 1.0, 0);
  auto e = engine<Quad>(s, walls_until(0.6));
  Recorder<Quad> rec;
  e->add_sink(&rec);
  e->run();
  const auto walls = rec.of_kind(EventKind::Wall);
  REQUIRE(walls.size() == 1);
  CHECK(walls[0].time == Quad(0.5));
  CHECK(walls[0].j == kWallRight);
  CHECK(walls[0].vix == Quad(-0.75));
  CHECK(walls[0].viy == Quad(-0.375));
  CHECK(e->particles().x_at(0, Quad(0.5)) == Quad(0.875));
}

TEST_CASE("__float128 and long double engines agree on the first events to long double round-off",
          "[run][scalar][float128]") {
  // Both start from the same doubles (exact in either type). A first collision inherits position errors of
  // ~eps L (L = 1) through a contact distance 2r = 0.02: relative errors ~ eps L / 2r = 50 eps in the
  // normal, hence in the velocities; contact times t ~ 0.01 err by ~eps L / v, i.e. ~100 eps relative.
  // Measured over five seeds: at most 18 eps (times) and 55 eps (velocities) in the first 20 events. Later
  // the difference grows by the instability of the dynamics (about x10 per 100 events here) while the
  // sequence of events stays the same for the ~1100 events the sinks see in 5000.
  const InitialState s = lattice_gas(20, 0.01, 1.0, 1);
  auto quad = engine<Quad>(s, events(BoundaryKind::Walls, 5000));
  auto ld = engine<long double>(s, events(BoundaryKind::Walls, 5000));
  Recorder<Quad> rq;
  Recorder<long double> rl;
  quad->add_sink(&rq);
  ld->add_sink(&rl);
  quad->run();
  ld->run();
  REQUIRE(rq.events.size() == rl.events.size());
  const Quad tolerance = 4 * (1 / Quad(0.02)) * Quad(std::numeric_limits<long double>::epsilon());  // 4 L / 2r eps
  for (std::size_t k = 0; k < rq.events.size(); ++k) {
    const EventOutcome<Quad>& a = rq.events[k];
    const EventOutcome<long double>& b = rl.events[k];
    INFO("event " << k);
    REQUIRE(a.kind == b.kind);
    REQUIRE(a.i == b.i);
    REQUIRE(a.j == b.j);
    if (k >= 20) continue;
    CHECK(ede::abs(a.time - Quad(b.time)) <= tolerance * a.time);
    for (const Quad d : {a.vix - Quad(b.vix), a.viy - Quad(b.viy), a.vjx - Quad(b.vjx), a.vjy - Quad(b.vjy)})
      CHECK(ede::abs(d) <= tolerance);
  }
}

#endif  // EDE_HAVE_FLOAT128
