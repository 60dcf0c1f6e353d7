// Energy conservation of stepped potentials over 10^7 events (issue 38): a square-well gas and a
// square-shoulder gas in a periodic box, and the square-well gas between walls. The total energy
// (kinetic + the step table's potential) is checked at 100 points along each run against a round-off
// bound, so that a bias of one unit in the last place per crossing fails where honest round-off passes.
//
// The bound. The potential energy is a sum of the steps' energies (1, -1, 1/2 here: exact in binary), so
// all the error is in the kinetic energy. Each event rounds the pair's new velocities: a few units of
// epsilon of kT (the mean kinetic energy per disk), of either sign, adding like a random walk, 8 eps
// sqrt(n) kT after n events. On top of that the rules have a small bias, measured over these runs as the
// sum of each event's kinetic energy change less the potential's (long double, from the events' velocities
// before and after): -0.04 eps kT per hard-core collision (-0.05 in the same gas without steps: it is
// collide.hpp's rounding, not the steps'), +0.01 per bounce off a step, +0.003 per crossing. The
// tests allow 0.05 eps kT per event for it, plus N^2 eps kT for summing the kinetic energy of N disks.
// Measured (10^7 events, 64 disks): well 6.5 10^4 eps kT, shoulder 0.9 10^4, well between walls
// 7.8 10^4, against bounds of 5.3 10^5. Making every crossing's new normal speed one ulp larger
// (std::nextafter in step_velocity_change) drifts by 4.3-5.2 10^6 eps kT and fails all three.
// Small N on purpose: it is the events that count, and summing fewer disks rounds less. Rejected: a
// relative tolerance on the total energy (the total of a well gas is near zero, and 1e-11 relative lets a
// one-ulp bias through).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "core/energy.hpp"
#include "engine_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

struct Drift {
  double largest = 0;  // the largest |E(t) - E(0)| at the checkpoints
  double kt = 0;       // the mean kinetic energy per disk over the checkpoints
  std::uint64_t steps = 0, pairs = 0;
};

// Runs `events` events in 100 slices and measures the total energy after each.
Drift energy_drift(const InitialState& s, const EngineOptions& o, std::uint64_t events) {
  auto e = engine(s, o);
  e->run(0);
  const auto total = [&] { return kinetic_energy(e->particles(), e->time()) + e->potential_energy(); };
  const double e0 = total();
  Drift d;
  for (int k = 0; k < 100; ++k) {
    REQUIRE(e->run(events / 100) == RunStatus::Running);
    d.largest = std::max(d.largest, std::abs(total() - e0));
    d.kt += kinetic_energy(e->particles(), e->time()) / double(s.size()) / 100;
  }
  d.steps = e->counts().of(EventKind::Step);
  d.pairs = e->counts().of(EventKind::Pair);
  CHECK(e->largest_overlap() < 1e-12);
  return d;
}

void check_drift(const Drift& d, std::size_t n, std::uint64_t events) {
  const double eps = std::numeric_limits<double>::epsilon();
  const double bound = (0.05 * double(events) + 8 * std::sqrt(double(events)) + double(n * n)) * eps * d.kt;
  INFO("largest |E - E0| " << d.largest << " (" << d.largest / (eps * d.kt) << " eps kT), bound " << bound
                           << ", kT " << d.kt << ", step events " << d.steps << ", pair collisions " << d.pairs);
  CHECK(d.steps > events / 4);
  CHECK(d.largest <= bound);
}

constexpr std::uint64_t kEvents = 10000000;

// 64 disks of radius 0.01 (sigma = 0.02) on a jittered lattice in a box of side 0.4 (area fraction 0.13).
InitialState gas() { return lattice_gas(8, 0.01, 0.4, 38); }

EngineOptions stepped(BoundaryKind boundary, double energy) {
  EngineOptions o;
  o.boundary = boundary;
  o.physics.steps.push_back({"", "", {0.03}, {energy}});  // lambda = 1.5
  return o;
}

}  // namespace

TEST_CASE("steps: the total energy of a periodic square-well gas is kept to round-off over 10^7 events",
          "[steps][slow]") {
  check_drift(energy_drift(gas(), stepped(BoundaryKind::Periodic, -1.0), kEvents), 64, kEvents);
}

TEST_CASE("steps: the total energy of a periodic square-shoulder gas is kept to round-off over 10^7 events",
          "[steps][slow]") {
  check_drift(energy_drift(gas(), stepped(BoundaryKind::Periodic, 0.5), kEvents), 64, kEvents);
}

TEST_CASE("steps: the total energy of a square-well gas between walls is kept to round-off over 10^7 events",
          "[steps][slow]") {
  check_drift(energy_drift(gas(), stepped(BoundaryKind::Walls, -1.0), kEvents), 64, kEvents);
}

