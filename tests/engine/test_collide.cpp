// Collision rules: conservation laws, restitution, and the course's wall rule.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/collide.hpp"

using namespace ede;

namespace {
struct PairState {
  double vix, viy, vjx, vjy;
};
double energy(const PairState& s, double mi, double mj) {
  return 0.5 * mi * (s.vix * s.vix + s.viy * s.viy) + 0.5 * mj * (s.vjx * s.vjx + s.vjy * s.vjy);
}
}  // namespace

TEST_CASE("collide_pair conserves momentum always and energy when elastic", "[collide]") {
  const double dx = 0.3, dy = 0.4, mi = 1.0, mj = 3.0;  // |dx| = 0.5
  PairState s{1.0, 0.2, -0.5, -0.3};
  const double px = mi * s.vix + mj * s.vjx, py = mi * s.viy + mj * s.vjy, e0 = energy(s, mi, mj);
  collide_pair(dx, dy, mi, mj, 2.0, s.vix, s.viy, s.vjx, s.vjy);
  CHECK(mi * s.vix + mj * s.vjx == Approx(px).epsilon(1e-15));
  CHECK(mi * s.viy + mj * s.vjy == Approx(py).epsilon(1e-15));
  CHECK(energy(s, mi, mj) == Approx(e0).epsilon(1e-15));
  // The normal relative velocity is reversed; the tangential one is untouched.
  const double vn = ((s.vjx - s.vix) * dx + (s.vjy - s.viy) * dy) / 0.5;
  const double vn0 = ((-0.5 - 1.0) * dx + (-0.3 - 0.2) * dy) / 0.5;
  CHECK(vn == Approx(-vn0).epsilon(1e-14));
}

TEST_CASE("collide_pair with restitution xi scales the normal relative velocity by -xi", "[collide]") {
  for (double xi : {0.0, 0.25, 0.5, 0.9}) {
    const double dx = 0.6, dy = -0.8, mi = 2.0, mj = 0.5;
    PairState s{0.7, -0.1, -0.2, 0.9};
    const auto normal = [&](const PairState& p) { return (p.vjx - p.vix) * dx + (p.vjy - p.viy) * dy; };
    const auto tangential = [&](const PairState& p) { return -(p.vjx - p.vix) * dy + (p.vjy - p.viy) * dx; };
    const double vn0 = normal(s), vt0 = tangential(s);
    collide_pair(dx, dy, mi, mj, 1.0 + xi, s.vix, s.viy, s.vjx, s.vjy);
    CHECK(normal(s) == Approx(-xi * vn0).margin(1e-15));
    CHECK(tangential(s) == Approx(vt0).epsilon(1e-14));
  }
}

TEST_CASE("collide_pair: xi = 0 head-on leaves equal disks exactly at rest", "[collide]") {
  PairState s{1.0, 0.0, -1.0, 0.0};
  collide_pair(0.2, 0.0, 1.0, 1.0, 1.0, s.vix, s.viy, s.vjx, s.vjy);
  CHECK(s.vix == 0.0);
  CHECK(s.vjx == 0.0);
}

TEST_CASE("collide_pair: mass ratio 1e6 (a wall-like heavy disk)", "[collide]") {
  // A light disk bouncing head-on off a resting heavy one leaves at nearly -v; the heavy one takes 2v m/M.
  PairState s{1.0, 0.0, 0.0, 0.0};
  collide_pair(0.5, 0.0, 1.0, 1e6, 2.0, s.vix, s.viy, s.vjx, s.vjy);
  CHECK(s.vix == Approx(-(1e6 - 1) / (1e6 + 1)).epsilon(1e-15));
  CHECK(s.vjx == Approx(2.0 / (1e6 + 1)).epsilon(1e-15));
}

TEST_CASE("collide_wall: the course's rule, tangential factor included", "[collide]") {
  double vx = 1.0, vy = 0.5;
  collide_wall(true, 0.5, vx, vy);
  CHECK(vx == -0.5);
  CHECK(vy == 0.25);
  vx = 1.0, vy = 0.5;
  collide_wall(false, 0.5, vx, vy);
  CHECK(vx == 0.5);
  CHECK(vy == -0.25);
  vx = 1.0, vy = 0.5;
  collide_wall_elastic(true, vx, vy);
  CHECK(vx == -1.0);
  CHECK(vy == 0.5);
}
